// Vulkan formats of the internal images; the images themselves are listed once, API-neutral, in
// sdk/src/ffx_dof_passes.h (kInternalImages).
#pragma once

#include "ffx_dof_passes.h"

#include <vulkan/vulkan.h>

namespace ffxdof::vk {

constexpr VkFormat toVkFormat(InternalFormat format) {
    switch (format) {
        case InternalFormat::R11G11B10Float:
            return VK_FORMAT_B10G11R11_UFLOAT_PACK32;
        case InternalFormat::R16Float:
            return VK_FORMAT_R16_SFLOAT;
        case InternalFormat::R16G16B16A16Float:
            return VK_FORMAT_R16G16B16A16_SFLOAT;
        case InternalFormat::R8Unorm:
            return VK_FORMAT_R8_UNORM;
        case InternalFormat::R32G32Uint:
            return VK_FORMAT_R32G32_UINT;
    }
    return VK_FORMAT_UNDEFINED;
}

}  // namespace ffxdof::vk
