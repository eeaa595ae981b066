// The internal images of a Vulkan context: the one table of their creation parameters. Names,
// formats and slots follow shaders_common/ffx_dof_resources.h, which is the source of truth.
#pragma once

#include "ffx_dof_passes.h"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace ffxdof::vk {

enum class ImageExtent : uint32_t {
    Half,   // ceil(W / 2) x ceil(H / 2)
    Tiles,  // ceil(half / FFX_DOF_TILE_SIZE)
};

struct InternalImageSpec {
    const char* name;
    VkFormat format;
    ImageExtent extent;
    bool mipChain;         // kMipCount levels (fewer where the half-resolution image is too small)
    uint32_t sampledSlot;  // FFX_DOF_SRV_*: all levels, sampled
    uint32_t storageSlot;  // FFX_DOF_UAV_*: level 0; a mip chain has one consecutive slot per level
};

constexpr InternalImageSpec kInternalImages[] = {
    {"COLOR_MIPS", VK_FORMAT_B10G11R11_UFLOAT_PACK32, ImageExtent::Half, true, FFX_DOF_SRV_COLOR_MIPS,
     FFX_DOF_UAV_COLOR_MIP0},
    {"COC_MIPS", VK_FORMAT_R16_SFLOAT, ImageExtent::Half, true, FFX_DOF_SRV_COC_MIPS, FFX_DOF_UAV_COC_MIP0},
    {"TILES", VK_FORMAT_R16G16_SFLOAT, ImageExtent::Tiles, false, FFX_DOF_SRV_TILES, FFX_DOF_UAV_TILES},
    {"DILATED_TILES", VK_FORMAT_R16G16_SFLOAT, ImageExtent::Tiles, false, FFX_DOF_SRV_DILATED_TILES,
     FFX_DOF_UAV_DILATED_TILES},
    {"NEAR_COLOR", VK_FORMAT_B10G11R11_UFLOAT_PACK32, ImageExtent::Half, false, FFX_DOF_SRV_NEAR_COLOR,
     FFX_DOF_UAV_NEAR_COLOR},
    {"FAR_COLOR", VK_FORMAT_B10G11R11_UFLOAT_PACK32, ImageExtent::Half, false, FFX_DOF_SRV_FAR_COLOR,
     FFX_DOF_UAV_FAR_COLOR},
    {"LAYER_ALPHA", VK_FORMAT_R8G8_UNORM, ImageExtent::Half, false, FFX_DOF_SRV_LAYER_ALPHA, FFX_DOF_UAV_LAYER_ALPHA},
};
constexpr uint32_t kInternalImageCount = sizeof(kInternalImages) / sizeof(kInternalImages[0]);

// The GLOBALS storage buffer (FFX_DOF_UAV_BUFFER_GLOBALS).
constexpr VkDeviceSize kGlobalsBufferBytes = 16;

// Levels of an image of this size: kMipCount for a mip chain, clamped to the full chain of a
// small image (a 4x3 half-resolution image has 3 levels).
inline uint32_t mipLevelsFor(const InternalImageSpec& spec, uint32_t width, uint32_t height) {
    if (!spec.mipChain) return 1;
    uint32_t levels = 1;
    for (uint32_t largest = width > height ? width : height; largest > 1 && levels < kMipCount; largest /= 2) {
        ++levels;
    }
    return levels;
}

}  // namespace ffxdof::vk
