#!/usr/bin/env bash
# tools/device-check.sh with a stand-in bundle: every step's log, a step cut short by its share of the budget,
# and its errors for bad input.
set -uo pipefail
script="${1:?usage: device_check_test.sh path/to/device-check.sh}"
# shellcheck source=tool_test_support.sh
. "$(dirname "$0")/tool_test_support.sh"

bundle="$work/bundle"
mkdir -p "$bundle/bin"
echo "export DEVICE_CHECK_TEST_ENV=sourced" >"$bundle/env.sh"
# ffx-dof and a commit's binary print what `ffx-dof bench` prints (and whether env.sh was sourced).
for name in ffx-dof ffx-dof-aaaaaaa; do
  cat >"$bundle/bin/$name" <<'STUB'
#!/bin/sh
echo "stand-in bench ($DEVICE_CHECK_TEST_ENV): $*"
echo "  blur                        270.125 ms"
echo "  total                       300.000 ms"
echo "  copy pass (floor)            11.250 ms"
STUB
done
# The Vulkan tests take longer than their share; the quality tests pass at once.
printf '#!/bin/sh\nsleep 30\n' >"$bundle/bin/ffx_dof_vk_tests"
printf '#!/bin/sh\necho "All tests passed"\n' >"$bundle/bin/ffx_dof_quality_tests"
chmod +x "$bundle/bin/"*

bash "$script" --budget 20 "$bundle" "$work/logs" >/dev/null 2>&1
expect "a step cut short fails the run" 1 $?
expect "the logs, one a step" "bench.txt commits.txt quality.txt vk-tests.txt" "$(ls "$work/logs" | sort | paste -sd ' ')"
# tools/bench-matrix.sh's eleven benches and the mid-lights scene, with the bundle's environment.
expect "every bench of the matrix, and mid-lights" 12 \
  "$(grep -c '^stand-in bench (sourced): bench' "$work/logs/bench.txt")"
expect "the mid-lights scene" 1 "$(grep -c '^stand-in bench (sourced): bench --scene mid-lights' "$work/logs/bench.txt")"
expect "the commit's rounds: two at 1080p, one in 32-bit, one at 4K" 4 \
  "$(grep -c '^[12] aaaaaaa blur=270.125 total=300.000 copy=11.250' "$work/logs/commits.txt")"
expect "the slow step says it was cut short" 1 "$(grep -c 'device-check: cut short after' "$work/logs/vk-tests.txt")"
expect "the quality tests' verdict" 1 "$(grep -c '^All tests passed' "$work/logs/quality.txt")"

printf '#!/bin/sh\nexit 0\n' >"$bundle/bin/ffx_dof_vk_tests"
bash "$script" --budget 20 "$bundle" "$work/logs2" >/dev/null 2>&1
expect "every step to its end" 0 $?

bash "$script" "$bundle" "$work/logs" >/dev/null 2>"$work/err"
expect "a folder of logs is never written over" 1 $?
expect "the folder is named" "device-check: $work/logs exists and is not empty; name a new folder (nothing was written)" \
  "$(cat "$work/err")"
bash "$script" "$work/nothing" "$work/logs3" >/dev/null 2>"$work/err"
expect "a folder that is no bundle is an error" 1 $?
expect "no logs for a bad bundle" "" "$(ls "$work/logs3" 2>/dev/null)"
bash "$script" --budget soon "$bundle" "$work/logs4" >/dev/null 2>&1
expect "a budget that is no number is an error" 1 $?
bash "$script" "$bundle" >/dev/null 2>&1
expect "the logs' folder is needed" 1 $?

finish device-check
