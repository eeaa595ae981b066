#!/usr/bin/env bash
# Installs every Debian 12 package ffx-dof needs to build and test. Idempotent:
# when everything is present it changes nothing and exits 0.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format
  glslang-dev glslang-tools spirv-tools spirv-headers libspirv-cross-c-shared-dev
  libvulkan-dev libvulkan-volk-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  libglm-dev libopenexr-dev libimath-dev libpng-dev libstb-dev
  catch2 libcli11-dev nlohmann-json3-dev
  g++-mingw-w64-x86-64
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
