#!/usr/bin/env bash
# Every figure of docs/performance.md's "On hardware" sections, in one run on a machine with a GPU, from a
# folder made by tools/device-bundle.sh (run there, from a copy of this repository's tools/):
#
#   bash tools/device-check.sh [--budget SECONDS] BUNDLE LOGS
#
# Writes into LOGS (a new or empty folder), each step under its own time limit so that a short lease still
# brings back what finished:
#   bench.txt      the device, tools/bench-matrix.sh with BUNDLE/bin/ffx-dof (50 repeats), and the mid-lights scene
#   commits.txt    tools/bench-commits.sh --run-only over the bundle's ffx-dof-<hash> binaries, if any: two rounds
#                  at 1080p 16-bit, one in 32-bit, one at 4K
#   vk-tests.txt   the Vulkan tests (validation on, if the bundle was made --with-layer)
#   quality.txt    the quality tests (validation on, likewise)
# --budget (default 300) splits the seconds between the steps in that order of priority; a step cut short says so
# in its log. Exit status: 0 when every step ran to its end (its own verdict is in its log), 1 otherwise.
set -uo pipefail

usage() {
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
  exit "${1:-1}"
}

budget=300
positional=()
while [ $# -gt 0 ]; do
  case "$1" in
    --budget) budget="${2:?--budget needs a number of seconds}"; shift 2 ;;
    -h|--help) usage 0 ;;
    -*) echo "device-check: unknown option $1" >&2; usage 1 ;;
    *) positional+=("$1"); shift ;;
  esac
done
if [ ${#positional[@]} -ne 2 ]; then
  echo "device-check: name the bundle and the folder for the logs" >&2
  usage 1
fi
bundle="${positional[0]}"
logs="${positional[1]}"
case "$budget" in
  ''|*[!0-9]*) echo "device-check: --budget must be a whole number of seconds, got '$budget'" >&2; exit 1 ;;
esac
if [ ! -f "$bundle/env.sh" ] || [ ! -x "$bundle/bin/ffx-dof" ]; then
  echo "device-check: $bundle is not a folder of tools/device-bundle.sh (no env.sh or bin/ffx-dof)" >&2
  exit 1
fi
if [ -e "$logs" ] && [ -n "$(ls -A "$logs" 2>/dev/null)" ]; then
  echo "device-check: $logs exists and is not empty; name a new folder (nothing was written)" >&2
  exit 1
fi
mkdir -p "$logs" || exit 1
tools="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=/dev/null
. "$bundle/env.sh"

status=0
# Runs a step under `timeout` with its share of the budget (percent), appending to a log.
step() {
  local share="$1" log="$2"
  shift 2
  local seconds=$((budget * share / 100))
  [ "$seconds" -ge 5 ] || seconds=5
  echo "\$ $* (at most ${seconds} s)" >>"$log"
  timeout "$seconds" "$@" >>"$log" 2>&1
  local code=$?
  if [ "$code" -eq 124 ]; then
    echo "device-check: cut short after ${seconds} s" >>"$log"
    status=1
  fi
  echo >>"$log"
}

{
  nvidia-smi --query-gpu=name,driver_version --format=csv 2>/dev/null || echo "(no nvidia-smi)"
  date
} >"$logs/bench.txt"
step 25 "$logs/bench.txt" bash "$tools/bench-matrix.sh" "$bundle/bin/ffx-dof" 50
step 3 "$logs/bench.txt" "$bundle/bin/ffx-dof" bench --scene mid-lights --width 1920 --height 1080 --quality 10 \
  --repeat 50

commits=()
for binary in "$bundle"/bin/ffx-dof-*; do
  [ -x "$binary" ] && commits+=("${binary##*/ffx-dof-}")
done
if [ ${#commits[@]} -gt 0 ]; then
  step 12 "$logs/commits.txt" bash "$tools/bench-commits.sh" --dir "$bundle" --run-only --rounds 2 "${commits[@]}" -- \
    --width 1920 --height 1080 --quality 10 --repeat 50
  step 6 "$logs/commits.txt" bash "$tools/bench-commits.sh" --dir "$bundle" --run-only --rounds 1 "${commits[@]}" -- \
    --width 1920 --height 1080 --quality 10 --repeat 50 --float32
  step 8 "$logs/commits.txt" bash "$tools/bench-commits.sh" --dir "$bundle" --run-only --rounds 1 "${commits[@]}" -- \
    --width 3840 --height 2160 --quality 10 --repeat 20
fi

[ -x "$bundle/bin/ffx_dof_vk_tests" ] && step 16 "$logs/vk-tests.txt" "$bundle/bin/ffx_dof_vk_tests"
[ -x "$bundle/bin/ffx_dof_quality_tests" ] && step 30 "$logs/quality.txt" "$bundle/bin/ffx_dof_quality_tests"
exit "$status"
