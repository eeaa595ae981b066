#!/usr/bin/env bash
# Builds everything and runs every test: the README's test command, and what CI runs.
#   1. installs missing Debian packages (tools/setup.sh) and checks formatting (tools/check-format.sh),
#   2. Release build + every CTest test (CPU tests, Vulkan tests on lavapipe with validation, and
#      the install tree consumed by a separate project through find_package); right after each configure,
#      tools/check-packages.sh fails if CMake found a system file no package of tools/setup.sh provides,
#   3. the host-code tests again under AddressSanitizer + UndefinedBehaviorSanitizer,
#   4. the Direct3D 12 backend cross-compiled with MinGW-w64 (warnings as errors).
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/setup.sh
if [ -z "${XDG_RUNTIME_DIR:-}" ] || [ ! -w "${XDG_RUNTIME_DIR}" ]; then
  export XDG_RUNTIME_DIR="$(mktemp -d)"
fi
jobs="$(nproc)"
step() { printf '\n== %s (%ss elapsed)\n' "$1" "$SECONDS"; }

step "formatting (clang-format)"
bash tools/check-format.sh

# Both builds file their shader permutations in one cache (docs/permutations.md, "The permutation cache"):
# the sanitizer build, whose shaders are the Release build's, compiles none of them again.
shader_cache="$PWD/build/shader-cache"

step "configure + build (Release)"
cmake --preset default -DFFX_DOF_SHADER_CACHE_DIR="$shader_cache" >/dev/null
bash tools/check-packages.sh build/default   # every system file CMake found comes from a tools/setup.sh package
cmake --build --preset default -j "$jobs"

step "tests (Release)"
ctest --preset default -j "$jobs"

step "host tests under ASan + UBSan"
# The shader permutations are compiled by the Release build's ffx-dof-shaderc (FFX_DOF_SHADERC): the
# same blobs, five times faster than the instrumented tool; the tool's own tests still run it under ASan.
cmake --preset asan -DFFX_DOF_SHADERC="$PWD/build/default/tools/shaderc/ffx-dof-shaderc" \
  -DFFX_DOF_SHADER_CACHE_DIR="$shader_cache" >/dev/null
bash tools/check-packages.sh build/asan
cmake --build --preset asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --preset asan -j "$jobs"

step "Direct3D 12 backend, cross-compiled with MinGW-w64"
bash tools/ci/build-mingw.sh

step "done"
