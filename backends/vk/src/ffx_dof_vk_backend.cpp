// The Vulkan backend object and ffxDofBackendCreateVK.
#include "ffx_dof_vk_backend.h"

#include "ffx_dof_vk_context.h"

#include <new>
#include <string>
#include <vector>

namespace ffxdof::vk {
namespace {

constexpr uint32_t kDefaultFramesInFlight = 3;
// Enough for any realistic engine; bounds the descriptor pool.
constexpr uint32_t kMaxFramesInFlight = 16;
constexpr uint32_t kWave64 = 64;

}  // namespace

FfxDofErrorCode failVk(VkResult result, const char* what) {
    const FfxDofErrorCode code = (result == VK_ERROR_OUT_OF_HOST_MEMORY || result == VK_ERROR_OUT_OF_DEVICE_MEMORY)
                                     ? FFX_DOF_ERROR_OUT_OF_MEMORY
                                     : FFX_DOF_ERROR_BACKEND;
    return fail(code, "%s failed: %s", what, resultName(result));
}

BackendVK::~BackendVK() {
    // After a failed init the caches are empty (and even the functions may be missing).
    pipelines_.clear([&](VkPipeline pipeline) { fn.vkDestroyPipeline(device, pipeline, allocator); });
    layouts_.clear([&](const PassLayout& layout) {
        fn.vkDestroyPipelineLayout(device, layout.pipeline, allocator);
        fn.vkDestroyDescriptorSetLayout(device, layout.set, allocator);
    });
    if (ownsPipelineCache_) fn.vkDestroyPipelineCache(device, pipelineCache, allocator);
}

FfxDofErrorCode BackendVK::init(const FfxDofBackendDescriptionVK& description) {
    physicalDevice = description.physicalDevice;
    device = description.device;
    allocator = description.allocationCallbacks;
    framesInFlight = description.maxFramesInFlight ? description.maxFramesInFlight : kDefaultFramesInFlight;
    if (framesInFlight > kMaxFramesInFlight) {
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "maxFramesInFlight is %u; at most %u is supported",
                    description.maxFramesInFlight, kMaxFramesInFlight);
    }
    constexpr uint32_t kKnownFlags =
        FFX_DOF_VK_DISABLE_FLOAT16 | FFX_DOF_VK_DISABLE_WAVE64 | FFX_DOF_VK_USE_HLSL_SHADERS;
    if (description.flags & ~kKnownFlags) {
        return fail(FFX_DOF_ERROR_INVALID_FLAGS, "backend flags 0x%x include bits that are not FfxDofBackendFlagBitsVK",
                    description.flags);
    }
    if (const char* missing = loadFunctions(description.vkGetInstanceProcAddr, description.vkGetDeviceProcAddr,
                                            description.instance, device, &fn)) {
        return fail(FFX_DOF_ERROR_BACKEND, "the Vulkan entry point %s could not be loaded", missing);
    }
    fn.vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties_);

    language_ = (description.flags & FFX_DOF_VK_USE_HLSL_SHADERS) ? ShaderLanguage::Hlsl : ShaderLanguage::Glsl;
    features = enabledFeaturesOf(description.pEnabledFeatures);
    features.shader |= queriedSubgroupFeatures(fn, physicalDevice);
    useHalf_ = features.has(shaders::Feature::Float16) && !(description.flags & FFX_DOF_VK_DISABLE_FLOAT16);
    useWave64 = features.subgroupSizeControl && features.computeFullSubgroups &&
                !(description.flags & FFX_DOF_VK_DISABLE_WAVE64) && deviceSupportsWave64();

    if (description.pipelineCache != VK_NULL_HANDLE) {
        pipelineCache = description.pipelineCache;
    } else {
        auto cacheInfo = makeInfo<VkPipelineCacheCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO);
        FFX_DOF_VK_CHECK(fn.vkCreatePipelineCache(device, &cacheInfo, allocator, &pipelineCache),
                         "vkCreatePipelineCache");
        ownsPipelineCache_ = true;
    }
    return FFX_DOF_OK;
}

BackendCapabilities BackendVK::capabilities() const {
    BackendCapabilities capabilities;
    for (uint32_t pass = 0; pass < kPassCount; ++pass) capabilities.tables[pass] = passTable(language_, Pass(pass));
    capabilities.half = useHalf_;
    capabilities.wave64 = useWave64;
    return capabilities;
}

FfxDofErrorCode BackendVK::createContext(const ContextPlan& plan, std::unique_ptr<BackendContext>* out) {
    std::unique_ptr<ContextVK> context(new (std::nothrow) ContextVK(*this, plan));
    if (!context) return fail(FFX_DOF_ERROR_OUT_OF_MEMORY, "allocating the Vulkan context failed");
    const FfxDofErrorCode result = context->create();
    if (result != FFX_DOF_OK) return result;  // the partly built context is destroyed here
    *out = std::move(context);
    return FFX_DOF_OK;
}

FfxDofErrorCode BackendVK::passLayout(const PlannedPass& pass, PassLayout* out) {
    const LayoutKey key{pass.sampledSlots, pass.storageSlots, pass.bufferSlots};
    return layouts_.findOrCreate(key, out, [&](PassLayout* made) {
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        for (const SlotClass& slotClass : kSlotClasses) {
            const uint32_t slots = pass.*slotClass.slots;
            for (uint32_t slot = 0; slot < 32; ++slot) {
                if (!(slots & (1u << slot))) continue;
                VkDescriptorSetLayoutBinding binding{};
                binding.binding = slotClass.base + slot;
                binding.descriptorType = slotClass.type;
                binding.descriptorCount = 1;
                binding.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
                bindings.push_back(binding);
            }
        }
        auto setLayoutInfo =
            makeInfo<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
        setLayoutInfo.bindingCount = uint32_t(bindings.size());
        setLayoutInfo.pBindings = bindings.data();
        FFX_DOF_VK_CHECK(fn.vkCreateDescriptorSetLayout(device, &setLayoutInfo, allocator, &made->set),
                         "vkCreateDescriptorSetLayout");

        const VkPushConstantRange pushRange{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(FfxDofConstants)};
        auto layoutInfo = makeInfo<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
        layoutInfo.setLayoutCount = 1;
        layoutInfo.pSetLayouts = &made->set;
        layoutInfo.pushConstantRangeCount = 1;
        layoutInfo.pPushConstantRanges = &pushRange;
        const VkResult created = fn.vkCreatePipelineLayout(device, &layoutInfo, allocator, &made->pipeline);
        if (created != VK_SUCCESS) {
            fn.vkDestroyDescriptorSetLayout(device, made->set, allocator);
            return failVk(created, "vkCreatePipelineLayout");
        }
        return FFX_DOF_OK;
    });
}

FfxDofErrorCode BackendVK::passPipeline(const char* passName, const shaders::Blob& blob, VkPipelineLayout layout,
                                        bool wave64, VkPipeline* out) {
    return pipelines_.findOrCreate(PipelineKey{&blob, layout, wave64}, out, [&](VkPipeline* made) {
        auto moduleInfo = makeInfo<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
        moduleInfo.codeSize = blob.wordCount * sizeof(uint32_t);
        moduleInfo.pCode = blob.words;
        VkShaderModule module = VK_NULL_HANDLE;
        FFX_DOF_VK_CHECK(fn.vkCreateShaderModule(device, &moduleInfo, allocator, &module), "vkCreateShaderModule");

        auto subgroupSize = makeInfo<VkPipelineShaderStageRequiredSubgroupSizeCreateInfo>(
            VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_REQUIRED_SUBGROUP_SIZE_CREATE_INFO);
        subgroupSize.requiredSubgroupSize = kWave64;
        auto pipelineInfo = makeInfo<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
        pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        pipelineInfo.stage.module = module;
        pipelineInfo.stage.pName = "main";
        if (wave64) {
            // The wave64 shaders assume every subgroup is 64 lanes wide and full.
            pipelineInfo.stage.pNext = &subgroupSize;
            pipelineInfo.stage.flags = VK_PIPELINE_SHADER_STAGE_CREATE_REQUIRE_FULL_SUBGROUPS_BIT;
        }
        pipelineInfo.layout = layout;
        const VkResult created = fn.vkCreateComputePipelines(device, pipelineCache, 1, &pipelineInfo, allocator, made);
        fn.vkDestroyShaderModule(device, module, allocator);
        if (created != VK_SUCCESS) {
            const std::string what = std::string("vkCreateComputePipelines (") + passName + ")";
            return failVk(created, what.c_str());
        }
        return FFX_DOF_OK;
    });
}

bool BackendVK::findMemoryType(uint32_t typeBits, uint32_t* index, VkMemoryPropertyFlags required) const {
    *index = chooseMemoryType(memoryProperties_, typeBits, required);
    return *index != UINT32_MAX;
}

VkFormatFeatureFlags BackendVK::optimalFeatures(VkFormat format) const {
    VkFormatProperties properties{};
    fn.vkGetPhysicalDeviceFormatProperties(physicalDevice, format, &properties);
    return properties.optimalTilingFeatures;
}

bool BackendVK::deviceSupportsWave64() const {
    if (!fn.vkGetPhysicalDeviceProperties2) return false;
    auto sizeControl = makeInfo<VkPhysicalDeviceSubgroupSizeControlProperties>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_SIZE_CONTROL_PROPERTIES);
    auto properties = makeInfo<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
    properties.pNext = &sizeControl;
    fn.vkGetPhysicalDeviceProperties2(physicalDevice, &properties);
    return sizeControl.minSubgroupSize <= kWave64 && kWave64 <= sizeControl.maxSubgroupSize &&
           (sizeControl.requiredSubgroupSizeStages & VK_SHADER_STAGE_COMPUTE_BIT);
}

}  // namespace ffxdof::vk

using namespace ffxdof;

extern "C" FfxDofErrorCode ffxDofBackendCreateVK(const FfxDofBackendDescriptionVK* pDescription,
                                                 FfxDofBackend* pBackend) {
    clearLastError();
    if (!pBackend) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pBackend is null");
    *pBackend = nullptr;
    if (!pDescription) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pDescription is null");
    const FfxDofBackendDescriptionVK& d = *pDescription;
    if (d.instance == VK_NULL_HANDLE) return fail(FFX_DOF_ERROR_INVALID_POINTER, "instance is VK_NULL_HANDLE");
    if (d.physicalDevice == VK_NULL_HANDLE) {
        return fail(FFX_DOF_ERROR_INVALID_POINTER, "physicalDevice is VK_NULL_HANDLE");
    }
    if (d.device == VK_NULL_HANDLE) return fail(FFX_DOF_ERROR_INVALID_POINTER, "device is VK_NULL_HANDLE");
    if (!d.pEnabledFeatures) {
        return fail(FFX_DOF_ERROR_INVALID_POINTER,
                    "pEnabledFeatures is null; pass the VkPhysicalDeviceFeatures2 chain given to vkCreateDevice "
                    "(VkDeviceCreateInfo::pNext) so the backend knows which features the device has enabled");
    }
    if (!d.vkGetInstanceProcAddr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "vkGetInstanceProcAddr is null");
    if (!d.vkGetDeviceProcAddr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "vkGetDeviceProcAddr is null");

    std::unique_ptr<vk::BackendVK> backend(new (std::nothrow) vk::BackendVK);
    if (!backend) return fail(FFX_DOF_ERROR_OUT_OF_MEMORY, "allocating the Vulkan backend failed");
    const FfxDofErrorCode result = backend->init(d);
    if (result != FFX_DOF_OK) return result;
    *pBackend = backend.release();
    return FFX_DOF_OK;
}
