#!/usr/bin/env bash
# A folder that runs this build's Vulkan programs on another x86-64 Linux machine that has a GPU driver
# but none of Debian 12's libraries (how docs/performance.md's "On hardware" figures were measured).
#
#   bash tools/device-bundle.sh [--build DIR] [--with-layer] OUT [EXTRA_BINARY...]
#
# OUT receives, stripped: bin/ffx-dof, bin/ffx_dof_vk_tests, bin/ffx_dof_quality_tests,
# bin/ffx_dof_quality_report_tool (those the build has) and any EXTRA_BINARY (for instance the binaries
# of tools/bench-commits.sh --build-only); lib/ with the shared libraries they load that are not the C
# and C++ runtimes (OpenEXR, Imath, stb, the Vulkan loader); with --with-layer, layer/ with the Khronos
# validation layer and a manifest that finds it beside itself (about 20 MB more); and env.sh, which
# sets LD_LIBRARY_PATH, VK_LAYER_PATH, XDG_RUNTIME_DIR and, where the NVIDIA driver's manifest is in
# /usr/local/nvidia (as on the lent machines), VK_DRIVER_FILES. There:
#
#   . OUT/env.sh && OUT/bin/ffx-dof bench --width 1920 --height 1080 --quality 10 --repeat 50
#
# NVIDIA's Vulkan driver also needs libglvnd (Debian: libglvnd0, libglx0, libegl1, libgl1): without
# it vkCreateInstance fails with VkResult -9.
set -euo pipefail

usage() {
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
  exit "${1:-1}"
}

build=build/default
layer=0
out=""
extras=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="${2:?--build needs a directory}"; shift 2 ;;
    --with-layer) layer=1; shift ;;
    -h|--help) usage 0 ;;
    -*) echo "device-bundle: unknown option $1" >&2; usage 1 ;;
    *) if [ -z "$out" ]; then out="$1"; else extras+=("$1"); fi; shift ;;
  esac
done
if [ -z "$out" ]; then
  echo "device-bundle: name the output folder" >&2
  usage 1
fi
if [ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null)" ]; then
  echo "device-bundle: $out exists and is not empty; name a new folder (nothing was written)" >&2
  exit 1
fi

binaries=()
for candidate in tools/cli/ffx-dof tests/vk/ffx_dof_vk_tests tests/quality/ffx_dof_quality_tests \
                 tests/quality/ffx_dof_quality_report_tool; do
  [ -x "$build/$candidate" ] && binaries+=("$build/$candidate")
done
for extra in "${extras[@]}"; do
  if [ ! -x "$extra" ] || [ -d "$extra" ]; then
    echo "device-bundle: $extra is not an executable file" >&2
    exit 1
  fi
  binaries+=("$extra")
done
if [ ${#binaries[@]} -eq 0 ]; then
  echo "device-bundle: no programs in $build (build first: cmake --build --preset default)" >&2
  exit 1
fi

mkdir -p "$out/bin" "$out/lib"
for binary in "${binaries[@]}"; do
  cp "$binary" "$out/bin/"
  strip "$out/bin/$(basename "$binary")"
  # The libraries the loader resolves here, less the C and C++ runtimes every Linux has.
  ldd "$binary" |
    awk '$2 == "=>" && $3 ~ /^\// && $3 !~ /\/(libc|libm|libstdc\+\+|libgcc_s|libpthread|libdl|librt)\.so/ { print $3 }' |
    while read -r library; do cp -L -n "$library" "$out/lib/"; done
done

if [ "$layer" = 1 ]; then
  manifest=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
  library=$(find /usr/lib -name libVkLayer_khronos_validation.so -print -quit)
  if [ ! -f "$manifest" ] || [ -z "$library" ]; then
    echo "device-bundle: the validation layer is not installed (Debian: vulkan-validationlayers)" >&2
    exit 1
  fi
  mkdir -p "$out/layer"
  cp "$library" "$out/layer/"
  strip "$out/layer/libVkLayer_khronos_validation.so"
  sed 's#"library_path": *"[^"]*"#"library_path": "./libVkLayer_khronos_validation.so"#' "$manifest" \
    >"$out/layer/VkLayer_khronos_validation.json"
fi

cat >"$out/env.sh" <<'ENV'
# Sourced on the device machine: the bundle's libraries and layer, a runtime directory, NVIDIA's driver.
bundle="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export LD_LIBRARY_PATH="$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if [ -d "$bundle/layer" ]; then export VK_LAYER_PATH="$bundle/layer"; fi
if [ -z "${XDG_RUNTIME_DIR:-}" ] || [ ! -w "${XDG_RUNTIME_DIR}" ]; then export XDG_RUNTIME_DIR="$(mktemp -d)"; fi
nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [ -f "$nvidia_icd" ] && [ -z "${VK_DRIVER_FILES:-}" ]; then export VK_DRIVER_FILES="$nvidia_icd"; fi
ENV

echo "device-bundle: $out: $(ls "$out/bin" | tr '\n' ' ')($(du -sh "$out" | cut -f1))"
