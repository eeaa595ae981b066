#include "ffx_dof_vk_features.h"

#include "ffx_dof_backend.h"

#include <utility>

namespace ffxdof::vk {
namespace {

using shaders::Feature;
using shaders::featureBit;

void set(uint32_t* bits, VkBool32 enabled, Feature feature) {
    if (enabled) *bits |= featureBit(feature);
}

struct FeatureInfo {
    Feature feature;
    const char* description;
    bool deviceProperty;  // a subgroup operation the device reports, not a feature the engine enables
};

#define FFX_DOF_CORE "VkPhysicalDeviceFeatures"
#define FFX_DOF_SUBGROUP \
    " in compute shaders (VkPhysicalDeviceSubgroupProperties::supportedOperations and supportedStages)"
constexpr FeatureInfo kFeatures[] = {
    {Feature::Float16, "shaderFloat16 (VkPhysicalDeviceShaderFloat16Int8Features / VkPhysicalDeviceVulkan12Features)",
     false},
    {Feature::Float64, "shaderFloat64 (" FFX_DOF_CORE ")", false},
    {Feature::Int8, "shaderInt8 (VkPhysicalDeviceShaderFloat16Int8Features / VkPhysicalDeviceVulkan12Features)", false},
    {Feature::Int16, "shaderInt16 (" FFX_DOF_CORE ")", false},
    {Feature::Int64, "shaderInt64 (" FFX_DOF_CORE ")", false},
    {Feature::StorageBuffer16BitAccess,
     "storageBuffer16BitAccess (VkPhysicalDevice16BitStorageFeatures / VkPhysicalDeviceVulkan11Features)", false},
    {Feature::UniformAndStorageBuffer16BitAccess,
     "uniformAndStorageBuffer16BitAccess (VkPhysicalDevice16BitStorageFeatures / VkPhysicalDeviceVulkan11Features)",
     false},
    {Feature::StoragePushConstant16,
     "storagePushConstant16 (VkPhysicalDevice16BitStorageFeatures / VkPhysicalDeviceVulkan11Features)", false},
    {Feature::StorageBuffer8BitAccess,
     "storageBuffer8BitAccess (VkPhysicalDevice8BitStorageFeatures / VkPhysicalDeviceVulkan12Features)", false},
    {Feature::UniformAndStorageBuffer8BitAccess,
     "uniformAndStorageBuffer8BitAccess (VkPhysicalDevice8BitStorageFeatures / VkPhysicalDeviceVulkan12Features)",
     false},
    {Feature::StoragePushConstant8,
     "storagePushConstant8 (VkPhysicalDevice8BitStorageFeatures / VkPhysicalDeviceVulkan12Features)", false},
    {Feature::StorageImageReadWithoutFormat, "shaderStorageImageReadWithoutFormat (" FFX_DOF_CORE ")", false},
    {Feature::StorageImageWriteWithoutFormat, "shaderStorageImageWriteWithoutFormat (" FFX_DOF_CORE ")", false},
    {Feature::ImageGatherExtended, "shaderImageGatherExtended (" FFX_DOF_CORE ")", false},
    {Feature::VulkanMemoryModel,
     "vulkanMemoryModel (VkPhysicalDeviceVulkanMemoryModelFeatures / VkPhysicalDeviceVulkan12Features)", false},
    {Feature::VulkanMemoryModelDeviceScope,
     "vulkanMemoryModelDeviceScope (VkPhysicalDeviceVulkanMemoryModelFeatures / VkPhysicalDeviceVulkan12Features)",
     false},
    {Feature::GroupNonUniform, "VK_SUBGROUP_FEATURE_BASIC_BIT" FFX_DOF_SUBGROUP, true},
    {Feature::GroupNonUniformVote, "VK_SUBGROUP_FEATURE_VOTE_BIT" FFX_DOF_SUBGROUP, true},
    {Feature::GroupNonUniformArithmetic, "VK_SUBGROUP_FEATURE_ARITHMETIC_BIT" FFX_DOF_SUBGROUP, true},
    {Feature::GroupNonUniformBallot, "VK_SUBGROUP_FEATURE_BALLOT_BIT" FFX_DOF_SUBGROUP, true},
    {Feature::GroupNonUniformShuffle, "VK_SUBGROUP_FEATURE_SHUFFLE_BIT" FFX_DOF_SUBGROUP, true},
    {Feature::GroupNonUniformShuffleRelative, "VK_SUBGROUP_FEATURE_SHUFFLE_RELATIVE_BIT" FFX_DOF_SUBGROUP, true},
    {Feature::GroupNonUniformClustered, "VK_SUBGROUP_FEATURE_CLUSTERED_BIT" FFX_DOF_SUBGROUP, true},
    {Feature::GroupNonUniformQuad, "VK_SUBGROUP_FEATURE_QUAD_BIT" FFX_DOF_SUBGROUP, true},
};
#undef FFX_DOF_CORE
#undef FFX_DOF_SUBGROUP
static_assert(sizeof(kFeatures) / sizeof(kFeatures[0]) == shaders::kFeatureCount, "one entry per shaders::Feature");

// The features that only the 16-bit (FFX_HALF=1) shaders may declare: FFX_DOF_VK_DISABLE_FLOAT16
// avoids them (tests/shaderc/test_real_passes.cpp checks that no FFX_HALF=0 blob requires one).
constexpr uint32_t kHalfOnly =
    featureBit(Feature::Float16) | featureBit(Feature::Int16) | featureBit(Feature::StorageBuffer16BitAccess) |
    featureBit(Feature::UniformAndStorageBuffer16BitAccess) | featureBit(Feature::StoragePushConstant16);

const FeatureInfo* firstMissing(const EnabledFeatures& enabled, uint32_t requiredFeatures) {
    const uint32_t missing = requiredFeatures & ~enabled.shader;
    for (const FeatureInfo& info : kFeatures) {
        if (missing & featureBit(info.feature)) return &info;
    }
    return nullptr;
}

}  // namespace

EnabledFeatures enabledFeaturesOf(const VkPhysicalDeviceFeatures2* chain) {
    EnabledFeatures enabled;
    uint32_t* bits = &enabled.shader;
    const auto* node = reinterpret_cast<const VkBaseInStructure*>(chain);
    for (uint32_t count = 0; node && count < kMaxFeatureChainLength; node = node->pNext, ++count) {
        switch (node->sType) {
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2: {
                const VkPhysicalDeviceFeatures& f = reinterpret_cast<const VkPhysicalDeviceFeatures2*>(node)->features;
                set(bits, f.shaderFloat64, Feature::Float64);
                set(bits, f.shaderInt16, Feature::Int16);
                set(bits, f.shaderInt64, Feature::Int64);
                set(bits, f.shaderStorageImageReadWithoutFormat, Feature::StorageImageReadWithoutFormat);
                set(bits, f.shaderStorageImageWriteWithoutFormat, Feature::StorageImageWriteWithoutFormat);
                set(bits, f.shaderImageGatherExtended, Feature::ImageGatherExtended);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES: {
                const auto& f = *reinterpret_cast<const VkPhysicalDeviceVulkan11Features*>(node);
                set(bits, f.storageBuffer16BitAccess, Feature::StorageBuffer16BitAccess);
                set(bits, f.uniformAndStorageBuffer16BitAccess, Feature::UniformAndStorageBuffer16BitAccess);
                set(bits, f.storagePushConstant16, Feature::StoragePushConstant16);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_16BIT_STORAGE_FEATURES: {
                const auto& f = *reinterpret_cast<const VkPhysicalDevice16BitStorageFeatures*>(node);
                set(bits, f.storageBuffer16BitAccess, Feature::StorageBuffer16BitAccess);
                set(bits, f.uniformAndStorageBuffer16BitAccess, Feature::UniformAndStorageBuffer16BitAccess);
                set(bits, f.storagePushConstant16, Feature::StoragePushConstant16);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES: {
                const auto& f = *reinterpret_cast<const VkPhysicalDeviceVulkan12Features*>(node);
                set(bits, f.shaderFloat16, Feature::Float16);
                set(bits, f.shaderInt8, Feature::Int8);
                set(bits, f.storageBuffer8BitAccess, Feature::StorageBuffer8BitAccess);
                set(bits, f.uniformAndStorageBuffer8BitAccess, Feature::UniformAndStorageBuffer8BitAccess);
                set(bits, f.storagePushConstant8, Feature::StoragePushConstant8);
                set(bits, f.vulkanMemoryModel, Feature::VulkanMemoryModel);
                set(bits, f.vulkanMemoryModelDeviceScope, Feature::VulkanMemoryModelDeviceScope);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES: {
                const auto& f = *reinterpret_cast<const VkPhysicalDeviceShaderFloat16Int8Features*>(node);
                set(bits, f.shaderFloat16, Feature::Float16);
                set(bits, f.shaderInt8, Feature::Int8);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_8BIT_STORAGE_FEATURES: {
                const auto& f = *reinterpret_cast<const VkPhysicalDevice8BitStorageFeatures*>(node);
                set(bits, f.storageBuffer8BitAccess, Feature::StorageBuffer8BitAccess);
                set(bits, f.uniformAndStorageBuffer8BitAccess, Feature::UniformAndStorageBuffer8BitAccess);
                set(bits, f.storagePushConstant8, Feature::StoragePushConstant8);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_MEMORY_MODEL_FEATURES: {
                const auto& f = *reinterpret_cast<const VkPhysicalDeviceVulkanMemoryModelFeatures*>(node);
                set(bits, f.vulkanMemoryModel, Feature::VulkanMemoryModel);
                set(bits, f.vulkanMemoryModelDeviceScope, Feature::VulkanMemoryModelDeviceScope);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES: {
                const auto& f = *reinterpret_cast<const VkPhysicalDeviceVulkan13Features*>(node);
                enabled.subgroupSizeControl = enabled.subgroupSizeControl || f.subgroupSizeControl;
                enabled.computeFullSubgroups = enabled.computeFullSubgroups || f.computeFullSubgroups;
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_SIZE_CONTROL_FEATURES: {
                const auto& f = *reinterpret_cast<const VkPhysicalDeviceSubgroupSizeControlFeatures*>(node);
                enabled.subgroupSizeControl = enabled.subgroupSizeControl || f.subgroupSizeControl;
                enabled.computeFullSubgroups = enabled.computeFullSubgroups || f.computeFullSubgroups;
                break;
            }
            default:
                break;  // a structure that enables nothing ffx-dof uses
        }
    }
    return enabled;
}

uint32_t subgroupFeaturesOf(const VkPhysicalDeviceSubgroupProperties& properties) {
    if (!(properties.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT)) return 0;
    const std::pair<VkSubgroupFeatureFlagBits, Feature> operations[] = {
        {VK_SUBGROUP_FEATURE_BASIC_BIT, Feature::GroupNonUniform},
        {VK_SUBGROUP_FEATURE_VOTE_BIT, Feature::GroupNonUniformVote},
        {VK_SUBGROUP_FEATURE_ARITHMETIC_BIT, Feature::GroupNonUniformArithmetic},
        {VK_SUBGROUP_FEATURE_BALLOT_BIT, Feature::GroupNonUniformBallot},
        {VK_SUBGROUP_FEATURE_SHUFFLE_BIT, Feature::GroupNonUniformShuffle},
        {VK_SUBGROUP_FEATURE_SHUFFLE_RELATIVE_BIT, Feature::GroupNonUniformShuffleRelative},
        {VK_SUBGROUP_FEATURE_CLUSTERED_BIT, Feature::GroupNonUniformClustered},
        {VK_SUBGROUP_FEATURE_QUAD_BIT, Feature::GroupNonUniformQuad},
    };
    uint32_t bits = 0;
    for (const auto& [operation, feature] : operations) {
        if (properties.supportedOperations & operation) bits |= featureBit(feature);
    }
    return bits;
}

uint32_t queriedSubgroupFeatures(const Functions& fn, VkPhysicalDevice physicalDevice) {
    if (!fn.vkGetPhysicalDeviceProperties2) return 0;
    auto subgroup = makeInfo<VkPhysicalDeviceSubgroupProperties>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES);
    auto properties = makeInfo<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
    properties.pNext = &subgroup;
    fn.vkGetPhysicalDeviceProperties2(physicalDevice, &properties);
    return subgroupFeaturesOf(subgroup);
}

const char* missingFeature(const EnabledFeatures& enabled, uint32_t requiredFeatures) {
    const FeatureInfo* info = firstMissing(enabled, requiredFeatures);
    return info ? info->description : nullptr;
}

FfxDofErrorCode checkShaderFeatures(const EnabledFeatures& enabled, const shaders::Blob& blob, const char* pass,
                                    bool half, bool wave64) {
    const FeatureInfo* info = firstMissing(enabled, blob.requiredFeatures);
    if (!info) return FFX_DOF_OK;
    const char* kind = half ? (wave64 ? "16-bit wave64 " : "16-bit ") : (wave64 ? "wave64 " : "");
    if (info->deviceProperty) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "the %s%s shader needs %s, which the device does not support", kind,
                    pass, info->description);
    }
    const bool halfOnly = half && (featureBit(info->feature) & kHalfOnly);
    return fail(FFX_DOF_ERROR_UNSUPPORTED,
                "the %s%s shader needs %s, which pEnabledFeatures does not enable; enable it at vkCreateDevice and "
                "in pEnabledFeatures%s",
                kind, pass, info->description, halfOnly ? ", or set FFX_DOF_VK_DISABLE_FLOAT16" : "");
}

}  // namespace ffxdof::vk
