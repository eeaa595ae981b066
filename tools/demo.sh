#!/usr/bin/env bash
# The README's main job: installs missing packages, builds, and renders the built-in scene with depth of
# field on Vulkan (lavapipe without a GPU). Images go to ./demo-out (or the directory given as $1).
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
out="$(realpath -m "${1:-demo-out}")"
bash "$repo/tools/setup.sh"
if [ -z "${XDG_RUNTIME_DIR:-}" ] || [ ! -w "${XDG_RUNTIME_DIR}" ]; then
  export XDG_RUNTIME_DIR="$(mktemp -d)"
fi
(cd "$repo" && cmake --preset default >/dev/null)
cmake --build "$repo/build/default" -j "$(nproc)" --target ffx-dof
"$repo/build/default/tools/cli/ffx-dof" demo --out "$out"
