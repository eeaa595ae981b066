#!/usr/bin/env bash
# Times the shader permutation build of ffx-dof: every permutation of the five passes in GLSL and
# HLSL (ffx-dof-shaderc, then compiling the generated tables), and the rebuild after touching one
# pass header. Prints the figures; docs/permutations.md records them.
#
#   tools/shaderc/bench_permutations.sh [build-dir]      (default build/bench-shaderc)
#
# Environment: JOBS (default: nproc), TARGETS (default: the Vulkan backend's shader libraries),
# TOUCHED (the header to touch, default shaders_common/ffx_dof_dilate.h).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$repo/build/bench-shaderc}"
jobs="${JOBS:-$(nproc)}"
targets="${TARGETS:-ffx_dof_vk_shaders_glsl ffx_dof_vk_shaders_hlsl}"
touched="${TOUCHED:-$repo/shaders_common/ffx_dof_dilate.h}"

cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFFX_DOF_BUILD_TESTS=OFF \
      -DFFX_DOF_BUILD_TOOLS=OFF >/dev/null
# The tool itself is not part of the measurement.
cmake --build "$build" -j "$jobs" --target ffx-dof-shaderc >/dev/null

# A full permutation build: remove every generated table and its objects, then build them again.
for target in $targets; do
  generated="$(find "$build" -type d -name "$target" -not -path '*/CMakeFiles/*' | head -n 1)"
  if [[ -z "$generated" ]]; then
    echo "bench_permutations: no generated folder for target '$target' (is it defined?)" >&2
    exit 1
  fi
  # Keep the aggregate (<target>.h/.cpp, written at configure time); remove the per-pass outputs.
  find "$generated" -maxdepth 1 -type f -name 'ffx_dof_*' ! -name "$target.h" ! -name "$target.cpp" -delete
done

seconds() { date +%s.%N; }
start=$(seconds)
cmake --build "$build" -j "$jobs" --target $targets >/dev/null
full=$(echo "$(seconds) - $start" | bc)

# Counts from the manifests the tool wrote.
python3 - "$build" $targets <<'PY'
import glob, json, os, sys
for target in sys.argv[2:]:
    for path in sorted(glob.glob(os.path.join(sys.argv[1], "**", target, "ffx_dof_*.json"), recursive=True)):
        m = json.load(open(path))
        print(f"  {m['pass']:<17} {m['language']}: {m['permutations']:3} permutations, "
              f"{m['uniqueBlobs']:3} unique blobs, {m['bytes']:7} bytes")
PY

touch "$touched"
commands=$(ninja -C "$build" -n $targets | grep -c 'ffx-dof-shaderc:' || true)
start=$(seconds)
cmake --build "$build" -j "$jobs" --target $targets >/dev/null
rebuild=$(echo "$(seconds) - $start" | bc)

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), -j $jobs"
printf "full permutation build (5 passes x glsl+hlsl, shaderc + C++ tables): %.1f s\n" "$full"
printf "rebuild after touching %s: %.1f s (%s pass compilations)\n" "${touched#$repo/}" "$rebuild" "$commands"
