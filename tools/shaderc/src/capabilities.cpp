// The SPIR-V capabilities a blob declares, classified for Vulkan: core (every device accepts them)
// or one shaders::Feature bit (an optional device feature, or a subgroup operation the device
// reports). A capability in neither list is an error: the runtime could not check it, so an engine
// without it would only hear from the validation layer. The classification follows the Vulkan
// specification's "SPIR-V Environment" capability table.
#include "shaderc.h"

#include <spirv_cross_c.h>

#include <string>

namespace ffxdof::shaderc {
namespace {

using shaders::Feature;

struct Optional {
    SpvCapability capability;
    Feature feature;
};

// Enabled by every Vulkan 1.1 device (the backends' minimum), no feature needed.
constexpr SpvCapability kCore[] = {
    SpvCapabilityMatrix,
    SpvCapabilityShader,
    SpvCapabilityInputAttachment,
    SpvCapabilitySampled1D,
    SpvCapabilityImage1D,
    SpvCapabilitySampledBuffer,
    SpvCapabilityImageBuffer,
    SpvCapabilityImageQuery,
    SpvCapabilityDerivativeControl,
    SpvCapabilityDeviceGroup,
    // Core since the specification decoupled it from shaderStorageImageExtendedFormats: a format
    // is usable as a storage image where its format features say so (the backends check those).
    SpvCapabilityStorageImageExtendedFormats,
};

constexpr Optional kOptional[] = {
    {SpvCapabilityFloat16, Feature::Float16},
    {SpvCapabilityFloat64, Feature::Float64},
    {SpvCapabilityInt8, Feature::Int8},
    {SpvCapabilityInt16, Feature::Int16},
    {SpvCapabilityInt64, Feature::Int64},
    {SpvCapabilityStorageBuffer16BitAccess, Feature::StorageBuffer16BitAccess},
    {SpvCapabilityUniformAndStorageBuffer16BitAccess, Feature::UniformAndStorageBuffer16BitAccess},
    {SpvCapabilityStoragePushConstant16, Feature::StoragePushConstant16},
    {SpvCapabilityStorageBuffer8BitAccess, Feature::StorageBuffer8BitAccess},
    {SpvCapabilityUniformAndStorageBuffer8BitAccess, Feature::UniformAndStorageBuffer8BitAccess},
    {SpvCapabilityStoragePushConstant8, Feature::StoragePushConstant8},
    {SpvCapabilityStorageImageReadWithoutFormat, Feature::StorageImageReadWithoutFormat},
    {SpvCapabilityStorageImageWriteWithoutFormat, Feature::StorageImageWriteWithoutFormat},
    {SpvCapabilityImageGatherExtended, Feature::ImageGatherExtended},
    {SpvCapabilityVulkanMemoryModel, Feature::VulkanMemoryModel},
    {SpvCapabilityVulkanMemoryModelDeviceScope, Feature::VulkanMemoryModelDeviceScope},
    {SpvCapabilityGroupNonUniform, Feature::GroupNonUniform},
    {SpvCapabilityGroupNonUniformVote, Feature::GroupNonUniformVote},
    {SpvCapabilityGroupNonUniformArithmetic, Feature::GroupNonUniformArithmetic},
    {SpvCapabilityGroupNonUniformBallot, Feature::GroupNonUniformBallot},
    {SpvCapabilityGroupNonUniformShuffle, Feature::GroupNonUniformShuffle},
    {SpvCapabilityGroupNonUniformShuffleRelative, Feature::GroupNonUniformShuffleRelative},
    {SpvCapabilityGroupNonUniformClustered, Feature::GroupNonUniformClustered},
    {SpvCapabilityGroupNonUniformQuad, Feature::GroupNonUniformQuad},
};

}  // namespace

uint32_t requiredFeatures(const std::vector<uint32_t>& capabilities) {
    uint32_t features = 0;
    for (uint32_t capability : capabilities) {
        bool known = false;
        for (SpvCapability core : kCore) known = known || capability == uint32_t(core);
        for (const Optional& optional : kOptional) {
            if (capability == uint32_t(optional.capability)) {
                features |= shaders::featureBit(optional.feature);
                known = true;
            }
        }
        if (!known) {
            throw Error("the SPIR-V declares capability " + std::to_string(capability) +
                        " (see spirv-dis), which ffx-dof-shaderc cannot map to a Vulkan feature; add it to "
                        "shaders::Feature and tools/shaderc/src/capabilities.cpp");
        }
    }
    return features;
}

}  // namespace ffxdof::shaderc
