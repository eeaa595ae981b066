// What the engine's device can run: the features it enabled at vkCreateDevice (read from the
// VkPhysicalDeviceFeatures2 chain in FfxDofBackendDescriptionVK::pEnabledFeatures) and the
// subgroup operations the device reports, against the shaders::Feature bits each blob requires
// (reflected from its SPIR-V by ffx-dof-shaderc).
#pragma once

#include "ffx_dof.h"
#include "ffx_dof_shader_table.h"
#include "ffx_dof_vk_functions.h"

#include <vulkan/vulkan.h>

namespace ffxdof::vk {

struct EnabledFeatures {
    // shaders::Feature bits: the features the chain enables and the subgroup operations the
    // device supports in compute shaders (subgroupFeaturesOf).
    uint32_t shader = 0;
    bool subgroupSizeControl = false;   // VkPhysicalDeviceSubgroupSizeControlFeatures / Vulkan13Features
    bool computeFullSubgroups = false;  // likewise
    bool has(shaders::Feature feature) const { return (shader & shaders::featureBit(feature)) != 0; }
};

// At most this many structures are read from a chain (a cycle cannot hang the backend).
constexpr uint32_t kMaxFeatureChainLength = 256;

// Walks the chain from `chain` on: VkPhysicalDeviceFeatures2, VkPhysicalDeviceVulkan11Features,
// Vulkan12Features, Vulkan13Features and the individual feature structures they absorbed
// (16BitStorage, 8BitStorage, ShaderFloat16Int8, VulkanMemoryModel, SubgroupSizeControl). Other
// sTypes are skipped. A feature counts as enabled when any structure in the chain enables it.
// nullptr gives no features.
EnabledFeatures enabledFeaturesOf(const VkPhysicalDeviceFeatures2* chain);

// The GroupNonUniform* bits the device supports in compute shaders (none when supportedStages
// lacks VK_SHADER_STAGE_COMPUTE_BIT).
uint32_t subgroupFeaturesOf(const VkPhysicalDeviceSubgroupProperties& properties);
// The same, queried from the device (0 without vkGetPhysicalDeviceProperties2).
uint32_t queriedSubgroupFeatures(const Functions& fn, VkPhysicalDevice physicalDevice);

// nullptr when `enabled` has every bit of requiredFeatures; otherwise the first one missing as
// the Vulkan feature and where it is enabled: "storageBuffer16BitAccess
// (VkPhysicalDevice16BitStorageFeatures / VkPhysicalDeviceVulkan11Features)", or for a subgroup
// operation the property that reports it.
const char* missingFeature(const EnabledFeatures& enabled, uint32_t requiredFeatures);

// FFX_DOF_OK when the device can run `blob`, the shader of `pass`; otherwise
// FFX_DOF_ERROR_UNSUPPORTED with a message naming the shader, the missing feature and the remedy
// ("... or set FFX_DOF_VK_DISABLE_FLOAT16" where the 32-bit shaders would not need it). half and
// wave64 say which permutation the backend chose.
FfxDofErrorCode checkShaderFeatures(const EnabledFeatures& enabled, const shaders::Blob& blob, const char* pass,
                                    bool half, bool wave64);

}  // namespace ffxdof::vk
