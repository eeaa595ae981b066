#!/usr/bin/env bash
# Cross-compiles the SDK and the Direct3D 12 backend for Windows with Debian's MinGW-w64 toolchain
# (CMake preset "mingw", toolchain cmake/mingw-w64-x86_64.cmake), warnings as errors, so that D3D12
# breakage shows without a Windows machine. The outputs cannot run here (no Windows, no wine).
#
#   tools/ci/build-mingw.sh [build-dir]      default build-dir: build/mingw
#   FFX_DOF_JOBS=N                           parallel jobs (default 2)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$(realpath -m "${1:-$root/build/mingw}")"
jobs="${FFX_DOF_JOBS:-2}"

for tool in x86_64-w64-mingw32-g++-posix cmake ninja; do
  if ! command -v "$tool" >/dev/null; then
    echo "build-mingw: '$tool' not found; run tools/setup.sh" >&2
    exit 1
  fi
done
if [ ! -f /usr/include/glm/glm.hpp ]; then
  echo "build-mingw: GLM not found (/usr/include/glm); run tools/setup.sh" >&2
  exit 1
fi

# GLM is header-only and portable, but Debian installs it for the host only. Expose that one folder
# to the cross compiler: adding /usr/include itself would shadow MinGW's C library with glibc's.
host_headers="$build/host-headers"
mkdir -p "$host_headers"
ln -sfn /usr/include/glm "$host_headers/glm"

cd "$root"
cmake --preset mingw -B "$build" -DCMAKE_CXX_FLAGS="-isystem $host_headers" >"$build/configure.log" 2>&1 || {
  cat "$build/configure.log" >&2
  echo "build-mingw: configure failed" >&2
  exit 1
}
cmake --build "$build" -j "$jobs"

# The build must have produced the Windows artefacts, not just succeeded vacuously.
for artefact in sdk/libffx_dof.a backends/dx12/libffx_dof_dx12.a backends/dx12/ffx_dof_dx12_link_check.exe; do
  if [ ! -f "$build/$artefact" ]; then
    echo "build-mingw: expected $build/$artefact, not built" >&2
    exit 1
  fi
done
imports="$(x86_64-w64-mingw32-objdump -p "$build/backends/dx12/ffx_dof_dx12_link_check.exe")"
if ! grep -q "DLL Name: d3d12.dll" <<<"$imports"; then
  echo "build-mingw: the link check does not import d3d12.dll" >&2
  exit 1
fi
echo "build-mingw: OK ($build)"
