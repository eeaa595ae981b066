// The Vulkan entry points the backend calls, loaded from the engine's vkGetInstanceProcAddr and
// vkGetDeviceProcAddr into one table per backend.
//
// Why not volk: volk keeps its function pointers in global symbols (vkCreateImage, ...). A library
// embedded in an engine that itself uses volk (or links the loader) would then define those
// symbols twice, or silently share state with the engine. VolkDeviceTable avoids the globals, but
// filling it needs volk.c, which brings the globals back. A small table of the ~40 functions used
// here, loaded with the engine's own loaders, has neither problem.
#pragma once

#include "ffx_dof_vk_util.h"

#include <vulkan/vulkan.h>

namespace ffxdof::vk {

// X(name): every function loaded with vkGetInstanceProcAddr (physical-device queries).
#define FFX_DOF_VK_INSTANCE_FUNCTIONS(X)   \
    X(vkGetPhysicalDeviceProperties)       \
    X(vkGetPhysicalDeviceMemoryProperties) \
    X(vkGetPhysicalDeviceFormatProperties)

// Optional instance functions: the backend works without them (no wave64 detection).
#define FFX_DOF_VK_OPTIONAL_INSTANCE_FUNCTIONS(X) X(vkGetPhysicalDeviceProperties2)

// X(name): every function loaded with vkGetDeviceProcAddr.
#define FFX_DOF_VK_DEVICE_FUNCTIONS(X) \
    X(vkCreateImage)                   \
    X(vkDestroyImage)                  \
    X(vkGetImageMemoryRequirements)    \
    X(vkBindImageMemory)               \
    X(vkCreateBuffer)                  \
    X(vkDestroyBuffer)                 \
    X(vkGetBufferMemoryRequirements)   \
    X(vkBindBufferMemory)              \
    X(vkAllocateMemory)                \
    X(vkFreeMemory)                    \
    X(vkCreateImageView)               \
    X(vkDestroyImageView)              \
    X(vkCreateDescriptorSetLayout)     \
    X(vkDestroyDescriptorSetLayout)    \
    X(vkCreatePipelineLayout)          \
    X(vkDestroyPipelineLayout)         \
    X(vkCreateShaderModule)            \
    X(vkDestroyShaderModule)           \
    X(vkCreateComputePipelines)        \
    X(vkDestroyPipeline)               \
    X(vkCreatePipelineCache)           \
    X(vkDestroyPipelineCache)          \
    X(vkCreateDescriptorPool)          \
    X(vkDestroyDescriptorPool)         \
    X(vkAllocateDescriptorSets)        \
    X(vkUpdateDescriptorSets)          \
    X(vkCmdBindPipeline)               \
    X(vkCmdBindDescriptorSets)         \
    X(vkCmdPushConstants)              \
    X(vkCmdDispatch)                   \
    X(vkCmdDispatchIndirect)           \
    X(vkCmdPipelineBarrier)            \
    X(vkCmdFillBuffer)                 \
    X(vkCmdCopyBuffer)                 \
    X(vkMapMemory)                     \
    X(vkCmdResetQueryPool)             \
    X(vkCmdWriteTimestamp)

struct Functions {
#define FFX_DOF_VK_DECLARE(name) PFN_##name name = nullptr;
    FFX_DOF_VK_INSTANCE_FUNCTIONS(FFX_DOF_VK_DECLARE)
    FFX_DOF_VK_OPTIONAL_INSTANCE_FUNCTIONS(FFX_DOF_VK_DECLARE)
    FFX_DOF_VK_DEVICE_FUNCTIONS(FFX_DOF_VK_DECLARE)
#undef FFX_DOF_VK_DECLARE
};

// Loads every function; on failure returns the name of the first missing required one, else null.
const char* loadFunctions(PFN_vkGetInstanceProcAddr getInstanceProcAddr, PFN_vkGetDeviceProcAddr getDeviceProcAddr,
                          VkInstance instance, VkDevice device, Functions* functions);

}  // namespace ffxdof::vk
