#include "ffx_dof_vk_util.h"

#include <string>

namespace ffxdof::vk {

const char* resultName(VkResult result) {
    switch (result) {
#define FFX_DOF_VK_CASE(value) \
    case value:                \
        return #value;
        FFX_DOF_VK_CASE(VK_SUCCESS)
        FFX_DOF_VK_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        FFX_DOF_VK_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        FFX_DOF_VK_CASE(VK_ERROR_INITIALIZATION_FAILED)
        FFX_DOF_VK_CASE(VK_ERROR_DEVICE_LOST)
        FFX_DOF_VK_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        FFX_DOF_VK_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        FFX_DOF_VK_CASE(VK_ERROR_FRAGMENTED_POOL)
        FFX_DOF_VK_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        FFX_DOF_VK_CASE(VK_ERROR_INVALID_SHADER_NV)
        FFX_DOF_VK_CASE(VK_ERROR_UNKNOWN)
        default:
            return "an unexpected VkResult";
    }
}

std::string formatName(VkFormat format) {
    switch (format) {
        FFX_DOF_VK_CASE(VK_FORMAT_UNDEFINED)
        FFX_DOF_VK_CASE(VK_FORMAT_R16G16B16A16_SFLOAT)
        FFX_DOF_VK_CASE(VK_FORMAT_R32G32B32A32_SFLOAT)
        FFX_DOF_VK_CASE(VK_FORMAT_B10G11R11_UFLOAT_PACK32)
        FFX_DOF_VK_CASE(VK_FORMAT_R8G8B8A8_UNORM)
        FFX_DOF_VK_CASE(VK_FORMAT_R8G8B8A8_SRGB)
        FFX_DOF_VK_CASE(VK_FORMAT_B8G8R8A8_UNORM)
        FFX_DOF_VK_CASE(VK_FORMAT_B8G8R8A8_SRGB)
        FFX_DOF_VK_CASE(VK_FORMAT_D32_SFLOAT)
        FFX_DOF_VK_CASE(VK_FORMAT_D32_SFLOAT_S8_UINT)
        FFX_DOF_VK_CASE(VK_FORMAT_D24_UNORM_S8_UINT)
        FFX_DOF_VK_CASE(VK_FORMAT_D16_UNORM)
        FFX_DOF_VK_CASE(VK_FORMAT_R32_SFLOAT)
        FFX_DOF_VK_CASE(VK_FORMAT_R16_SFLOAT)
        FFX_DOF_VK_CASE(VK_FORMAT_R16G16_SFLOAT)
        FFX_DOF_VK_CASE(VK_FORMAT_R8G8_UNORM)
        FFX_DOF_VK_CASE(VK_FORMAT_R8_UNORM)
        default:
            return "VkFormat " + std::to_string(static_cast<int>(format));
    }
}

std::string layoutName(VkImageLayout layout) {
    switch (layout) {
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_UNDEFINED)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_GENERAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_PREINITIALIZED)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL)
        FFX_DOF_VK_CASE(VK_IMAGE_LAYOUT_PRESENT_SRC_KHR)
#undef FFX_DOF_VK_CASE
        default:
            return "VkImageLayout " + std::to_string(static_cast<int>(layout));
    }
}

bool isDepthAspectFormat(VkFormat format) {
    return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D16_UNORM;
}

bool isColorFormat(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R16G16B16A16_SFLOAT:
        case VK_FORMAT_R32G32B32A32_SFLOAT:
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SRGB:
            return true;
        default:
            return false;
    }
}

bool isDepthFormat(VkFormat format) { return isDepthAspectFormat(format) || format == VK_FORMAT_R32_SFLOAT; }

uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& properties, uint32_t typeBits,
                          VkMemoryPropertyFlags required) {
    for (VkMemoryPropertyFlags wanted :
         {VkMemoryPropertyFlags(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | required), required}) {
        for (uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
            if ((typeBits & (1u << i)) && (properties.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
        }
    }
    return UINT32_MAX;
}

}  // namespace ffxdof::vk
