#!/usr/bin/env bash
# tools/device-bundle.sh on this build: the bundle's programs start with its libraries alone on the
# library path, and bad input changes nothing.
set -uo pipefail
script="${1:?usage: device_bundle_test.sh path/to/device-bundle.sh BUILD_DIR}"
build="${2:?usage: device_bundle_test.sh path/to/device-bundle.sh BUILD_DIR}"
# shellcheck source=tool_test_support.sh
. "$(dirname "$0")/tool_test_support.sh"

check "a bundle is made" bash "$script" --build "$build" "$work/bundle"
check "ffx-dof is in it" test -x "$work/bundle/bin/ffx-dof"
check "the Vulkan loader is in it" test -f "$work/bundle/lib/libvulkan.so.1"
check "the C runtime is not" test ! -e "$work/bundle/lib/libc.so.6"
# Every library ffx-dof loads resolves inside the bundle or is one of the runtimes left out.
unresolved=$(. "$work/bundle/env.sh" && ldd "$work/bundle/bin/ffx-dof" |
  awk '$2 == "=>" && $3 !~ /^\// { print $1 }')
check "ffx-dof finds every library (missing: $unresolved)" test -z "$unresolved"
outside=$(. "$work/bundle/env.sh" && ldd "$work/bundle/bin/ffx-dof" |
  awk -v bundle="$work/bundle/lib/" '$2 == "=>" && index($3, bundle) != 1 { print $1 }' |
  grep -Ev '^(libc|libm|libstdc\+\+|libgcc_s|libpthread|libdl|librt|libasan|libubsan)\.so' || true)
check "ffx-dof loads its libraries from the bundle (outside: $outside)" test -z "$outside"
check "the bundled ffx-dof runs" bash -c ". '$work/bundle/env.sh' && '$work/bundle/bin/ffx-dof' --help"

before=$(ls -lR "$work/bundle" | md5sum)
check "an existing bundle is refused" bash -c "! bash '$script' --build '$build' '$work/bundle'"
check "an existing bundle is left as it was" test "$before" = "$(ls -lR "$work/bundle" | md5sum)"
check "a missing extra program is refused" bash -c "! bash '$script' --build '$build' '$work/other' /nonexistent/ffx-dof"
check "nothing is written for a refused extra" test ! -e "$work/other"
check "an empty build folder is refused" bash -c "! bash '$script' --build '$work/empty-build' '$work/third'"

if [ -f /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json ]; then
  check "a bundle with the layer is made" bash "$script" --build "$build" --with-layer "$work/with-layer"
  check "the layer's manifest finds the library beside it" \
    grep -q '"library_path": "./libVkLayer_khronos_validation.so"' "$work/with-layer/layer/VkLayer_khronos_validation.json"
  check "the layer's library is there" test -f "$work/with-layer/layer/libVkLayer_khronos_validation.so"
fi

finish device-bundle
