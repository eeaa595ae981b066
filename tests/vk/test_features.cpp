// The device features the engine enabled (FfxDofBackendDescriptionVK::pEnabledFeatures): the chain
// parser on the CPU, and on validated devices that leave features out, that a context whose shaders
// need a feature the device lacks is refused naming it, while every accepted one runs without a
// validation message.
#include "ffx_dof_vk_features.h"
#include "vk_test_support.h"

#include <cstring>
#include <string>
#include <vector>

using namespace ffxdof;
using namespace ffxdof::vktest;
using shaders::Feature;
using shaders::featureBit;

namespace {

template <typename T>
T structure(VkStructureType type, void* next = nullptr) {
    T info{};
    info.sType = type;
    info.pNext = next;
    return info;
}

// A context of a small size on `backend`; the result of ffxDofContextCreate (the context is destroyed).
FfxDofErrorCode createContext(FfxDofBackend backend, std::string* message) {
    FfxDofContextDescription info{};
    info.quality = 4;
    info.resolution = {32, 24};
    info.cocLimitFactor = 0.05f;
    info.backendInterface = backend;
    FfxDofContext context = nullptr;
    const FfxDofErrorCode result = ffxDofContextCreate(&context, &info);
    *message = ffxDofGetLastErrorMessage();
    if (context) ffxDofContextDestroy(&context);
    return result;
}

// A validated device with these features left out (where the device supports them).
std::unique_ptr<vkrun::Device> deviceWithout(std::vector<std::string> features) {
    vkrun::DeviceOptions options;
    options.validation = true;
    options.withoutFeatures = std::move(features);
    return std::make_unique<vkrun::Device>(options);
}

// Records whether any shader module the backend creates declares the Float16 capability.
bool sawFloat16 = false;
PFN_vkCreateShaderModule realCreateShaderModule = nullptr;

VKAPI_ATTR VkResult VKAPI_CALL watchingCreateShaderModule(VkDevice device, const VkShaderModuleCreateInfo* info,
                                                          const VkAllocationCallbacks* allocator,
                                                          VkShaderModule* module) {
    const uint32_t* words = info->pCode;
    const size_t count = info->codeSize / sizeof(uint32_t);
    for (size_t w = 5; w + 1 < count;) {
        const uint32_t length = words[w] >> 16, opcode = words[w] & 0xffffu;
        if (opcode == 17 /* OpCapability */ && words[w + 1] == 9 /* Float16 */) sawFloat16 = true;
        w += length ? length : 1;
    }
    return realCreateShaderModule(device, info, allocator, module);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL watchingGetDeviceProcAddr(VkDevice device, const char* name) {
    if (std::strcmp(name, "vkCreateShaderModule") == 0) {
        realCreateShaderModule = reinterpret_cast<PFN_vkCreateShaderModule>(vkGetDeviceProcAddr(device, name));
        return reinterpret_cast<PFN_vkVoidFunction>(&watchingCreateShaderModule);
    }
    return vkGetDeviceProcAddr(device, name);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The chain parser (no device).

TEST_CASE("the feature chain: VkPhysicalDeviceFeatures2 with the Vulkan 1.1, 1.2 and 1.3 structures",
          "[vulkan][features]") {
    auto v13 = structure<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    auto v12 = structure<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &v13);
    auto v11 = structure<VkPhysicalDeviceVulkan11Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &v12);
    auto features2 = structure<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v11);

    vk::EnabledFeatures none = vk::enabledFeaturesOf(&features2);
    CHECK(none.shader == 0);
    CHECK_FALSE(none.subgroupSizeControl);
    CHECK_FALSE(none.computeFullSubgroups);

    features2.features.shaderStorageImageWriteWithoutFormat = VK_TRUE;
    features2.features.shaderInt16 = VK_TRUE;
    v11.storageBuffer16BitAccess = VK_TRUE;
    v11.storagePushConstant16 = VK_TRUE;
    v12.shaderFloat16 = VK_TRUE;
    v12.vulkanMemoryModel = VK_TRUE;
    v13.subgroupSizeControl = VK_TRUE;
    v13.computeFullSubgroups = VK_TRUE;
    const vk::EnabledFeatures enabled = vk::enabledFeaturesOf(&features2);
    CHECK(enabled.shader ==
          (featureBit(Feature::StorageImageWriteWithoutFormat) | featureBit(Feature::Int16) |
           featureBit(Feature::StorageBuffer16BitAccess) | featureBit(Feature::StoragePushConstant16) |
           featureBit(Feature::Float16) | featureBit(Feature::VulkanMemoryModel)));
    CHECK(enabled.subgroupSizeControl);
    CHECK(enabled.computeFullSubgroups);
    CHECK(vk::missingFeature(enabled, enabled.shader) == nullptr);
}

TEST_CASE("the feature chain: the individual structures the Vulkan 1.x ones absorbed", "[vulkan][features]") {
    auto sizeControl = structure<VkPhysicalDeviceSubgroupSizeControlFeatures>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_SIZE_CONTROL_FEATURES);
    auto memoryModel = structure<VkPhysicalDeviceVulkanMemoryModelFeatures>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_MEMORY_MODEL_FEATURES, &sizeControl);
    auto storage8 = structure<VkPhysicalDevice8BitStorageFeatures>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_8BIT_STORAGE_FEATURES, &memoryModel);
    auto float16 = structure<VkPhysicalDeviceShaderFloat16Int8Features>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES, &storage8);
    auto storage16 = structure<VkPhysicalDevice16BitStorageFeatures>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_16BIT_STORAGE_FEATURES, &float16);
    auto features2 = structure<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &storage16);
    storage16.uniformAndStorageBuffer16BitAccess = VK_TRUE;
    float16.shaderFloat16 = VK_TRUE;
    float16.shaderInt8 = VK_TRUE;
    storage8.storageBuffer8BitAccess = VK_TRUE;
    storage8.storagePushConstant8 = VK_TRUE;
    memoryModel.vulkanMemoryModelDeviceScope = VK_TRUE;
    sizeControl.subgroupSizeControl = VK_TRUE;
    const vk::EnabledFeatures enabled = vk::enabledFeaturesOf(&features2);
    CHECK(enabled.shader ==
          (featureBit(Feature::UniformAndStorageBuffer16BitAccess) | featureBit(Feature::Float16) |
           featureBit(Feature::Int8) | featureBit(Feature::StorageBuffer8BitAccess) |
           featureBit(Feature::StoragePushConstant8) | featureBit(Feature::VulkanMemoryModelDeviceScope)));
    CHECK(enabled.subgroupSizeControl);
    CHECK_FALSE(enabled.computeFullSubgroups);  // only subgroupSizeControl was enabled
}

TEST_CASE("the feature chain: unknown structures are skipped, and any structure may enable a feature",
          "[vulkan][features]") {
    // An extension structure the backend does not know, in the middle of the chain.
    auto float16 = structure<VkPhysicalDeviceShaderFloat16Int8Features>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES);
    auto robustness = structure<VkPhysicalDeviceImageRobustnessFeatures>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_IMAGE_ROBUSTNESS_FEATURES, &float16);
    robustness.robustImageAccess = VK_TRUE;
    auto v12 =
        structure<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &robustness);
    auto features2 = structure<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12);
    // Vulkan12Features says no, the individual structure after the unknown one says yes.
    float16.shaderFloat16 = VK_TRUE;
    CHECK(vk::enabledFeaturesOf(&features2).shader == featureBit(Feature::Float16));
    // The reverse order of the same answer.
    float16.shaderFloat16 = VK_FALSE;
    v12.shaderFloat16 = VK_TRUE;
    CHECK(vk::enabledFeaturesOf(&features2).shader == featureBit(Feature::Float16));

    CHECK(vk::enabledFeaturesOf(nullptr).shader == 0);
    // A (broken) cyclic chain ends after kMaxFeatureChainLength structures instead of hanging.
    auto a = structure<VkPhysicalDeviceVulkan11Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
    auto cyclic = structure<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &a);
    a.pNext = &cyclic;
    a.storageBuffer16BitAccess = VK_TRUE;
    CHECK(vk::enabledFeaturesOf(&cyclic).shader == featureBit(Feature::StorageBuffer16BitAccess));
}

TEST_CASE("subgroup operations count only where compute shaders have them", "[vulkan][features]") {
    auto properties =
        structure<VkPhysicalDeviceSubgroupProperties>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES);
    properties.supportedOperations = VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
    properties.supportedStages = VK_SHADER_STAGE_FRAGMENT_BIT;
    CHECK(vk::subgroupFeaturesOf(properties) == 0);
    properties.supportedStages |= VK_SHADER_STAGE_COMPUTE_BIT;
    CHECK(vk::subgroupFeaturesOf(properties) ==
          (featureBit(Feature::GroupNonUniform) | featureBit(Feature::GroupNonUniformArithmetic)));
}

TEST_CASE("a missing feature is named with its structures and the remedy", "[vulkan][features]") {
    vk::EnabledFeatures enabled;
    enabled.shader = featureBit(Feature::Float16);
    const uint32_t float16 = featureBit(Feature::Float16);
    const uint32_t storage16 = featureBit(Feature::StorageBuffer16BitAccess);
    const uint32_t writeWithoutFormat = featureBit(Feature::StorageImageWriteWithoutFormat);
    CHECK(vk::missingFeature(enabled, float16) == nullptr);
    CHECK(std::string(vk::missingFeature(enabled, float16 | storage16)) ==
          "storageBuffer16BitAccess (VkPhysicalDevice16BitStorageFeatures / VkPhysicalDeviceVulkan11Features)");
    CHECK(std::string(vk::missingFeature(enabled, writeWithoutFormat)) ==
          "shaderStorageImageWriteWithoutFormat (VkPhysicalDeviceFeatures)");

    // A 16-bit shader that needs 16-bit storage: FFX_DOF_VK_DISABLE_FLOAT16 is a way out.
    const uint32_t words[1] = {0};
    const shaders::Blob halfBlob{words, 1, {8, 8, 1}, float16 | storage16};
    CHECK(vk::checkShaderFeatures(enabled, halfBlob, "blur", true, false) == FFX_DOF_ERROR_UNSUPPORTED);
    CHECK(std::string(ffxDofGetLastErrorMessage()) ==
          "the 16-bit blur shader needs storageBuffer16BitAccess (VkPhysicalDevice16BitStorageFeatures / "
          "VkPhysicalDeviceVulkan11Features), which pEnabledFeatures does not enable; enable it at vkCreateDevice "
          "and in pEnabledFeatures, or set FFX_DOF_VK_DISABLE_FLOAT16");
    // A feature every permutation needs: no such hint.
    const shaders::Blob writingBlob{words, 1, {8, 8, 1}, writeWithoutFormat};
    CHECK(vk::checkShaderFeatures(enabled, writingBlob, "composite", false, false) == FFX_DOF_ERROR_UNSUPPORTED);
    const std::string message = ffxDofGetLastErrorMessage();
    CHECK(message.find("the composite shader needs shaderStorageImageWriteWithoutFormat") == 0);
    CHECK(message.find("FFX_DOF_VK_DISABLE_FLOAT16") == std::string::npos);
    // A subgroup operation is the device's, not the engine's to enable.
    const shaders::Blob subgroupBlob{words, 1, {8, 8, 1}, featureBit(Feature::GroupNonUniformArithmetic)};
    CHECK(vk::checkShaderFeatures(enabled, subgroupBlob, "downsample_depth", false, true) == FFX_DOF_ERROR_UNSUPPORTED);
    CHECK(std::string(ffxDofGetLastErrorMessage())
              .find("the wave64 downsample_depth shader needs "
                    "VK_SUBGROUP_FEATURE_ARITHMETIC_BIT in compute shaders") == 0);
    enabled.shader |= featureBit(Feature::GroupNonUniformArithmetic);
    CHECK(vk::checkShaderFeatures(enabled, subgroupBlob, "downsample_depth", false, true) == FFX_DOF_OK);
}

// ---------------------------------------------------------------------------------------------
// On devices.

TEST_CASE("a backend description without pEnabledFeatures is refused, saying what to pass", "[vulkan][features]") {
    vkrun::Device& device = validatedDevice();
    FfxDofBackendDescriptionVK description = device.backendDescription();
    REQUIRE(description.pEnabledFeatures == &device.enabledFeatures());
    description.pEnabledFeatures = nullptr;
    FfxDofBackend backend = reinterpret_cast<FfxDofBackend>(uintptr_t(1));
    CHECK(ffxDofBackendCreateVK(&description, &backend) == FFX_DOF_ERROR_INVALID_POINTER);
    CHECK(backend == nullptr);
    const std::string message = ffxDofGetLastErrorMessage();
    CHECK(message.find("pEnabledFeatures is null") != std::string::npos);
    CHECK(message.find("VkPhysicalDeviceFeatures2 chain given to vkCreateDevice") != std::string::npos);
    requireNoValidationMessages(device);
}

TEST_CASE("without shaderStorageImageWriteWithoutFormat a context is refused naming it", "[vulkan][features]") {
    std::unique_ptr<vkrun::Device> device = deviceWithout({"shaderStorageImageWriteWithoutFormat"});
    REQUIRE_FALSE(device->features().shaderStorageImageWriteWithoutFormat);
    for (uint32_t flags : {0u, uint32_t(FFX_DOF_VK_DISABLE_FLOAT16), uint32_t(FFX_DOF_VK_USE_HLSL_SHADERS)}) {
        CAPTURE(flags);
        FfxDofBackendDescriptionVK description = device->backendDescription(flags);
        FfxDofBackend backend = nullptr;
        REQUIRE(ffxDofBackendCreateVK(&description, &backend) == FFX_DOF_OK);
        std::string message;
        CHECK(createContext(backend, &message) == FFX_DOF_ERROR_UNSUPPORTED);
        INFO(message);
        CHECK(message.find("needs shaderStorageImageWriteWithoutFormat (VkPhysicalDeviceFeatures), which "
                           "pEnabledFeatures does not enable") != std::string::npos);
        CHECK(message.find("FFX_DOF_VK_DISABLE_FLOAT16") == std::string::npos);  // no help for this one
        REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    }
    // Refused before any pipeline needs it: the validation layer has nothing to say.
    requireNoValidationMessages(*device, "without shaderStorageImageWriteWithoutFormat");
}

TEST_CASE("shaderFloat16 without 16-bit storage: the 16-bit shaders run, as they need none", "[vulkan][features]") {
    std::unique_ptr<vkrun::Device> device = deviceWithout({"storageBuffer16BitAccess"});
    REQUIRE_FALSE(device->features().storageBuffer16BitAccess);
    REQUIRE(device->features().shaderFloat16);  // as tests/hlsl/test_selection.cpp: lavapipe has it
    for (uint32_t flags : {0u, uint32_t(FFX_DOF_VK_DISABLE_FLOAT16)}) {
        CAPTURE(flags);
        FfxDofBackendDescriptionVK description = device->backendDescription(flags);
        description.vkGetDeviceProcAddr = &watchingGetDeviceProcAddr;
        FfxDofBackend backend = nullptr;
        REQUIRE(ffxDofBackendCreateVK(&description, &backend) == FFX_DOF_OK);
        sawFloat16 = false;
        std::string message;
        CHECK(createContext(backend, &message) == FFX_DOF_OK);
        INFO(message);
        CHECK(sawFloat16 == (flags == 0));  // the 16-bit shaders were the ones chosen
        REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    }
    // And they run clean end to end.
    const Scene scene = makeScene(48, 32, 6.0f);
    const vkrun::RunResult result = vkrun::runEffect(*device, scene.color, scene.depth, settingsFor(scene));
    CHECK(allFinite(result.output));
    requireNoValidationMessages(*device, "16-bit shaders without storageBuffer16BitAccess");
}

TEST_CASE("without shaderFloat16 the 32-bit shaders are chosen and run", "[vulkan][features]") {
    std::unique_ptr<vkrun::Device> device = deviceWithout({"shaderFloat16", "storageBuffer16BitAccess"});
    FfxDofBackendDescriptionVK description = device->backendDescription();
    description.vkGetDeviceProcAddr = &watchingGetDeviceProcAddr;
    FfxDofBackend backend = nullptr;
    REQUIRE(ffxDofBackendCreateVK(&description, &backend) == FFX_DOF_OK);
    sawFloat16 = false;
    std::string message;
    CHECK(createContext(backend, &message) == FFX_DOF_OK);
    INFO(message);
    CHECK_FALSE(sawFloat16);
    REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    const Scene scene = makeScene(48, 32, 6.0f);
    const vkrun::RunResult result = vkrun::runEffect(*device, scene.color, scene.depth, settingsFor(scene));
    CHECK(allFinite(result.output));
    requireNoValidationMessages(*device, "without shaderFloat16");
}

TEST_CASE("shaderStorageImageExtendedFormats is not needed: the capability is core", "[vulkan][features]") {
    std::unique_ptr<vkrun::Device> device = deviceWithout({"shaderStorageImageExtendedFormats"});
    const Scene scene = makeScene(48, 32, 6.0f);
    vkrun::RunSettings settings = settingsFor(scene);
    const vkrun::RunResult result = vkrun::runEffect(*device, scene.color, scene.depth, settings);
    CHECK(allFinite(result.output));
    settings.useHlsl = true;
    CHECK(allFinite(vkrun::runEffect(*device, scene.color, scene.depth, settings).output));
    requireNoValidationMessages(*device, "without shaderStorageImageExtendedFormats");
}
