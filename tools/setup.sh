#!/usr/bin/env bash
# Installs every Debian 12 package ffx-dof needs to build, test, run the demo and regenerate the docs. Idempotent:
# when everything is present it changes nothing and exits 0.
set -euo pipefail

# The one list of the Debian packages ffx-dof uses. tools/check-packages.sh (run by tools/test.sh right after
# configure) fails when CMake finds a system file that no package here, nor any of their dependencies,
# provides; add the package it names here.
packages=(
  # build: compilers, CMake, and every find_package / find_path / find_library / pkg_check_modules
  build-essential cmake ninja-build pkg-config
  glslang-dev glslang-tools spirv-tools spirv-headers libspirv-cross-c-shared-dev
  libvulkan-dev libvulkan-volk-dev
  libglm-dev libopenexr-dev libimath-dev libpng-dev libstb-dev
  libcli11-dev nlohmann-json3-dev
  libxxhash-dev  # ffx-dof-shaderc's permutation cache keys (XXH3-128)
  # tests: Catch2, formatting check (clang-format over `git ls-files`), Vulkan on lavapipe with validation,
  # the Direct3D 12 backend cross-compiled with MinGW-w64
  catch2 clang-format git
  mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  g++-mingw-w64-x86-64
  # tests: the SLURM job-array script of docs/cli.md on a one-node SLURM started on localhost (issue 16)
  slurm-wlm munge
  # docs: tools/shaderc/bench_permutations.sh (docs/permutations.md) and docs/technique.md's arithmetic;
  # docs/quality.md and docs/performance.md come from the project's own C++ tools (ffx_dof_quality_report,
  # ffx-dof bench)
  python3 bc
  # profiling: tools/profile-lavapipe.py (docs/performance.md, "Where the time goes on lavapipe")
  linux-perf gdb
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then sudo_cmd=(sudo); else
    echo "setup: not root and no sudo; install as root: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
