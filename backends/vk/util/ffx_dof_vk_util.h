// Small Vulkan helpers shared by the backend and the application-side tools (tools/vkrun): structure
// initialisation, names for messages, and the engine formats ffx-dof accepts. No entry points.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace ffxdof::vk {

// A Vulkan structure with its sType set and every other member zero. (Brace-initialising only
// sType trips -Wmissing-field-initializers.)
template <typename T>
T makeInfo(VkStructureType type) {
    T info{};
    info.sType = type;
    return info;
}

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" for messages.
const char* resultName(VkResult result);
// "VK_FORMAT_R16G16B16A16_SFLOAT" for the formats ffx-dof knows, "VkFormat 123" for others.
std::string formatName(VkFormat format);
// "VK_IMAGE_LAYOUT_GENERAL" and so on, "VkImageLayout 123" for unknown values.
std::string layoutName(VkImageLayout layout);
// Depth formats read through a depth-aspect view (D32, D24S8, D16).
bool isDepthAspectFormat(VkFormat format);
// The engine formats ffx-dof accepts (docs/integration-vulkan.md): color and output, and depth.
bool isColorFormat(VkFormat format);
bool isDepthFormat(VkFormat format);
// The memory type for a resource: one allowed by `typeBits` with the `required` properties, device-local
// where one is; UINT32_MAX when none. The first type that fits is system memory on discrete GPUs (on an
// NVIDIA H100 the harness's images sat there and every pass touching them ran over PCIe).
uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& properties, uint32_t typeBits,
                          VkMemoryPropertyFlags required = 0);

}  // namespace ffxdof::vk
