#!/usr/bin/env bash
# tools/bench-commits.sh without building anything: stand-in binaries that print what `ffx-dof bench`
# prints check the table it makes of them, and its errors for bad input.
set -uo pipefail
script="${1:?usage: bench_commits_test.sh path/to/bench-commits.sh}"
# shellcheck source=tool_test_support.sh
. "$(dirname "$0")/tool_test_support.sh"

mkdir -p "$work/bin"
# What ffx-dof bench prints, with the times a stand-in chooses; the arguments echoed in the header.
cat >"$work/bin/ffx-dof-aaaaaaa" <<'STUB'
#!/bin/sh
echo "ffx-dof bench, args: $*"
echo "  downsample_depth              1.500 ms"
echo "  blur                        270.125 ms"
echo "  total                       300.000 ms"
echo "  copy pass (floor)            11.250 ms"
echo "  ratio total / copy            26.67"
echo "  internal memory             9959232 bytes (9.50 MiB), aliasable 9959184 bytes"
echo "  host record                    94.1 us (median of 1000 ffxDofContextDispatch calls)"
STUB
cat >"$work/bin/ffx-dof-bbbbbbb" <<'STUB'
#!/bin/sh
echo "ffx-dof: error: --scene: unknown scene" >&2
exit 3
STUB
chmod +x "$work/bin/"*

output=$(bash "$script" --dir "$work" --run-only --rounds 2 aaaaaaa -- --width 64 2>&1)
expect "exit status of a good run" 0 $?
expect "one line per round and commit" \
  "1 aaaaaaa downsample_depth=1.500 blur=270.125 total=300.000 copy=11.250|2 aaaaaaa downsample_depth=1.500 blur=270.125 total=300.000 copy=11.250" \
  "$(printf '%s\n' "$output" | grep '^[12] ' | paste -sd '|')"

output=$(bash "$script" --dir "$work" --run-only aaaaaaa bbbbbbb 2>&1)
expect "a failing bench fails the run" 1 $?
expect "a failing bench names its error" "1 bbbbbbb failed: ffx-dof: error: --scene: unknown scene" \
  "$(printf '%s\n' "$output" | grep '^1 bbbbbbb')"

bash "$script" --dir "$work" --run-only ccccccc >/dev/null 2>"$work/err"
expect "a missing binary is an error" 1 $?
expect "a missing binary is named" "bench-commits: no binary $work/bin/ffx-dof-ccccccc (build it first, without --run-only)" \
  "$(cat "$work/err")"

bash "$script" --dir "$work" not-a-commit-anywhere >/dev/null 2>"$work/err"
expect "an unknown commit is an error" 1 $?
expect "an unknown commit is named" "bench-commits: 'not-a-commit-anywhere' is not a commit of this repository" \
  "$(head -1 "$work/err")"

bash "$script" --rounds 0 aaaaaaa >/dev/null 2>"$work/err"
expect "zero rounds is an error" 1 $?
bash "$script" --build-only --run-only aaaaaaa >/dev/null 2>"$work/err"
expect "build-only with run-only is an error" 1 $?
bash "$script" --frobnicate aaaaaaa >/dev/null 2>"$work/err"
expect "an unknown option is an error" "bench-commits: unknown option --frobnicate" "$(head -1 "$work/err")"
bash "$script" >/dev/null 2>"$work/err"
expect "no commit is an error" "bench-commits: name at least one commit" "$(head -1 "$work/err")"

finish bench-commits
