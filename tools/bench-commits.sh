#!/usr/bin/env bash
# Pass times of several commits, measured in turn in one run: the method of docs/performance.md for
# "what did this change cost" (a figure from one process says little; see the page's introduction).
#
#   bash tools/bench-commits.sh [options] COMMIT...
#
# Builds the CLI (`ffx-dof`, Release, no tests) at each commit in a git worktree under DIR/src, keeps
# the binary as DIR/bin/ffx-dof-<short hash>, then runs `ffx-dof bench` with each binary in turn, for
# --rounds rounds, and prints one line per run: round, commit, then every pass's time in ms.
#
# Options:
#   --dir DIR          where worktrees and binaries go (default build/bench-commits)
#   --rounds N         rounds of the whole list (default 2)
#   --build-only       build the binaries and stop (to carry DIR/bin to another machine)
#   --run-only         run the binaries already in DIR/bin (on a machine without the sources' toolchain)
#   -- ARGS...         arguments for `ffx-dof bench` (default: --width 1920 --height 1080 --quality 10
#                      --repeat 5); each set of ARGS runs as given, so `--float32` can be added here
#
# An old commit's bench may lack options of a newer one: its error is printed and the line says so.
set -uo pipefail

usage() {
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
  exit "${1:-1}"
}

dir=build/bench-commits
rounds=2
build=1
run=1
commits=()
bench_args=(--width 1920 --height 1080 --quality 10 --repeat 5)
while [ $# -gt 0 ]; do
  case "$1" in
    --dir) dir="${2:?--dir needs a directory}"; shift 2 ;;
    --rounds) rounds="${2:?--rounds needs a number}"; shift 2 ;;
    --build-only) run=0; shift ;;
    --run-only) build=0; shift ;;
    -h|--help) usage 0 ;;
    --) shift; bench_args=("$@"); break ;;
    -*) echo "bench-commits: unknown option $1" >&2; usage 1 ;;
    *) commits+=("$1"); shift ;;
  esac
done
if [ ${#commits[@]} -eq 0 ]; then
  echo "bench-commits: name at least one commit" >&2
  usage 1
fi
if ! [[ "$rounds" =~ ^[1-9][0-9]*$ ]]; then
  echo "bench-commits: --rounds must be a positive whole number, not '$rounds'" >&2
  exit 1
fi
if [ "$build" = 0 ] && [ "$run" = 0 ]; then
  echo "bench-commits: --build-only and --run-only exclude each other" >&2
  exit 1
fi

# Commits by short hash, so that a name (HEAD, a branch) and its hash share one binary.
hashes=()
for commit in "${commits[@]}"; do
  if [ "$build" = 1 ]; then
    hash=$(git rev-parse --short=7 --verify --quiet "$commit^{commit}") || {
      echo "bench-commits: '$commit' is not a commit of this repository" >&2
      exit 1
    }
  else
    hash="$commit"
  fi
  hashes+=("$hash")
done

mkdir -p "$dir/bin" || exit 1
if [ "$build" = 1 ]; then
  for hash in "${hashes[@]}"; do
    binary="$dir/bin/ffx-dof-$hash"
    if [ -x "$binary" ]; then
      echo "bench-commits: $hash already built ($binary)"
      continue
    fi
    source_dir="$dir/src/$hash"
    if [ ! -d "$source_dir" ]; then
      git worktree add --force --detach "$source_dir" "$hash" >/dev/null || exit 1
    fi
    started=$(date +%s)
    if cmake -S "$source_dir" -B "$source_dir/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFFX_DOF_BUILD_TESTS=OFF \
         >"$source_dir/configure.log" 2>&1 &&
       cmake --build "$source_dir/build" --target ffx-dof >"$source_dir/build.log" 2>&1; then
      cp "$(find "$source_dir/build" -name ffx-dof -type f -perm -u+x | head -1)" "$binary" || exit 1
      echo "bench-commits: built $hash in $(( $(date +%s) - started )) s"
    else
      echo "bench-commits: the build of $hash failed; see $source_dir/configure.log and build.log" >&2
      exit 1
    fi
  done
fi
[ "$run" = 1 ] || exit 0

for hash in "${hashes[@]}"; do
  if [ ! -x "$dir/bin/ffx-dof-$hash" ]; then
    echo "bench-commits: no binary $dir/bin/ffx-dof-$hash (build it first, without --run-only)" >&2
    exit 1
  fi
done
if [ -z "${XDG_RUNTIME_DIR:-}" ] || [ ! -w "${XDG_RUNTIME_DIR}" ]; then
  export XDG_RUNTIME_DIR="$(mktemp -d)"
fi
echo "bench-commits: ffx-dof bench ${bench_args[*]}; $rounds rounds of ${hashes[*]}"
status=0
for round in $(seq 1 "$rounds"); do
  for hash in "${hashes[@]}"; do
    if output=$("$dir/bin/ffx-dof-$hash" bench "${bench_args[@]}" 2>&1); then
      # "  blur    12.345 ms" lines, one field per pass.
      times=$(printf '%s\n' "$output" | awk '$NF == "ms" && $1 != "copy" { printf " %s=%s", $1, $(NF - 1) }
                                           $1 == "copy" { printf " copy=%s", $(NF - 1) }')
      echo "$round $hash$times"
    else
      echo "$round $hash failed: $(printf '%s' "$output" | tail -1)"
      status=1
    fi
  done
done
exit "$status"
