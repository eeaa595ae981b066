#!/usr/bin/env bash
# The benchmark matrix of docs/performance.md ("On hardware"): ffx-dof bench at 1080p and 4K, 16- and
# 32-bit, two CoC limits, six blades against the round aperture, then two validated bench runs.
# Usage: bash tools/bench-matrix.sh [path/to/ffx-dof] [repeat]
# Every figure is printed by `ffx-dof bench` itself; this script only chooses the settings, so any row of
# the page can be rerun with the command printed above it.
set -uo pipefail
ffx_dof="${1:-build/default/tools/cli/ffx-dof}"
repeat="${2:-50}"
if [ ! -x "$ffx_dof" ]; then
  echo "bench-matrix: no executable at $ffx_dof (build first: cmake --build --preset default)" >&2
  exit 1
fi
if [ -z "${XDG_RUNTIME_DIR:-}" ] || [ ! -w "${XDG_RUNTIME_DIR}" ]; then
  export XDG_RUNTIME_DIR="$(mktemp -d)"
fi

status=0
run() {
  echo
  echo "\$ ffx-dof $*"
  "$ffx_dof" "$@" || { echo "bench-matrix: exit $? from: ffx-dof $*"; status=1; }
}

for size in "1920 1080" "3840 2160"; do
  set -- $size
  for limit in 0.05 0.01; do
    run bench --width "$1" --height "$2" --quality 10 --coc-limit "$limit" --repeat "$repeat"
    run bench --width "$1" --height "$2" --quality 10 --coc-limit "$limit" --repeat "$repeat" --float32
  done
done
run bench --width 1920 --height 1080 --quality 10 --coc-limit 0.05 --repeat "$repeat" --blades 6 --against-round
# Validation: the Khronos layer with synchronization validation; any message fails the run (exit 4).
run bench --width 1920 --height 1080 --quality 10 --coc-limit 0.05 --repeat 3 --validate
run bench --width 1920 --height 1080 --quality 10 --coc-limit 0.05 --repeat 3 --validate --float32
exit "$status"
