#!/usr/bin/env bash
# Fails when a tracked C, C++ or shader header differs from clang-format's output (.clang-format at the
# root; shaders_common/.clang-format for the shader headers). Fix with:
#   git ls-files '*.cpp' '*.h' '*.c' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.h' '*.c')
if ! clang-format --dry-run --Werror "${files[@]}" 2>/tmp/ffx-dof-format.$$; then
  grep -E "^[^ ].*: (error|warning):" /tmp/ffx-dof-format.$$ | cut -d: -f1 | sort -u | sed 's/^/  not formatted: /' >&2
  rm -f /tmp/ffx-dof-format.$$
  echo "check-format: run: git ls-files '*.cpp' '*.h' '*.c' | xargs clang-format -i" >&2
  exit 1
fi
rm -f /tmp/ffx-dof-format.$$
echo "check-format: ${#files[@]} files formatted"
