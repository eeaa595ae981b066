// The Vulkan backend: pipelines from the embedded SPIR-V, internal images, descriptor rings and
// the recording of the five passes into the engine's command buffer.
#include "ffx_dof_vk.h"

#include "ffx_dof_backend.h"
#include "ffx_dof_context.h"
#include "ffx_dof_vk_features.h"
#include "ffx_dof_vk_functions.h"
#include "ffx_dof_vk_internal_images.h"
#include "ffx_dof_vk_shaders.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <new>
#include <string>
#include <type_traits>
#include <vector>

namespace ffxdof::vk {
namespace {

constexpr uint32_t kDefaultFramesInFlight = 3;
// Enough for any realistic engine; bounds the descriptor pool.
constexpr uint32_t kMaxFramesInFlight = 16;
constexpr uint32_t kWave64 = 64;

FfxDofErrorCode failVk(VkResult result, const char* what) {
    const FfxDofErrorCode code = (result == VK_ERROR_OUT_OF_HOST_MEMORY || result == VK_ERROR_OUT_OF_DEVICE_MEMORY)
                                     ? FFX_DOF_ERROR_OUT_OF_MEMORY
                                     : FFX_DOF_ERROR_BACKEND;
    return fail(code, "%s failed: %s", what, resultName(result));
}

#define FFX_DOF_VK_CHECK(call, what)                                         \
    do {                                                                     \
        const VkResult checkedResult = (call);                               \
        if (checkedResult != VK_SUCCESS) return failVk(checkedResult, what); \
    } while (0)

// FfxDofResource::handle <-> VkImage: a pointer on 64-bit platforms, a uint64_t on 32-bit ones.
VkImage imageOf(const FfxDofResource& resource) {
    if constexpr (std::is_pointer_v<VkImage>) {
        return reinterpret_cast<VkImage>(static_cast<uintptr_t>(resource.handle));
    } else {
        return VkImage(resource.handle);
    }
}

// The layouts an engine image may be declared in: valid for an image of its aspect and holding its
// contents, so the barriers into and out of the effect's layouts are valid. Anything else (UNDEFINED,
// PREINITIALIZED, an attachment layout of the other aspect, a value that is no VkImageLayout at all)
// is refused before any barrier is recorded.
bool isAcceptedLayout(VkImageLayout layout, bool depthAspect) {
    switch (layout) {
        case VK_IMAGE_LAYOUT_GENERAL:
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
        case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
            return true;
        case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
            return !depthAspect;
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL:
            return depthAspect;
        default:
            return false;
    }
}

VkDescriptorType descriptorTypeOf(shaders::BindingKind kind) {
    switch (kind) {
        case shaders::BindingKind::SampledImage:
            return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
        case shaders::BindingKind::StorageImage:
            return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        case shaders::BindingKind::StorageBuffer:
            return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        case shaders::BindingKind::Sampler:
            return VK_DESCRIPTOR_TYPE_SAMPLER;
        default:
            return VK_DESCRIPTOR_TYPE_MAX_ENUM;
    }
}

// The slot class a binding number falls in (see ffx_dof_resources.h) and the kind it must have.
shaders::BindingKind expectedKindOf(uint32_t binding) {
    if (binding < FFX_DOF_UAV_IMAGE_BASE) return shaders::BindingKind::SampledImage;
    if (binding < FFX_DOF_UAV_BUFFER_BASE) return shaders::BindingKind::StorageImage;
    if (binding < FFX_DOF_SAMPLER_BASE) return shaders::BindingKind::StorageBuffer;
    return shaders::BindingKind::Sampler;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
class BackendVK;

class ContextVK final : public BackendContext {
public:
    ContextVK(BackendVK& backend, const ContextConfig& config) : backend_(backend), config_(config) {}
    ~ContextVK() override;

    FfxDofErrorCode create();
    FfxDofErrorCode dispatch(const DispatchPlan& plan) override;
    FfxDofMemoryUsage memoryUsage() const override { return memoryUsage_; }

    void setTimestampQueries(VkQueryPool pool, uint32_t firstQuery) {
        queryPool_ = pool;
        firstQuery_ = firstQuery;
    }

private:
    struct InternalImage {
        VkImage image = VK_NULL_HANDLE;
        uint32_t width = 0, height = 0, mipLevels = 1;
        VkImageView allLevels = VK_NULL_HANDLE;
        std::array<VkImageView, kMipCount> level{};
    };
    // The views of the engine's images made for one dispatch, kept until its ring slot comes round.
    struct EngineViews {
        VkImageView color = VK_NULL_HANDLE, depth = VK_NULL_HANDLE, output = VK_NULL_HANDLE;
    };
    // How one dispatch uses an engine image.
    struct EngineImageUse {
        VkImage image = VK_NULL_HANDLE;
        VkImageAspectFlags barrierAspects = VK_IMAGE_ASPECT_COLOR_BIT;
        VkImageLayout declared = VK_IMAGE_LAYOUT_UNDEFINED;
        VkImageLayout during = VK_IMAGE_LAYOUT_UNDEFINED;
        VkAccessFlags access = 0;
    };

    FfxDofErrorCode createImages();
    FfxDofErrorCode createPipelines();
    FfxDofErrorCode createDescriptors();
    FfxDofErrorCode validate(const DispatchPlan& plan, bool* encodeSrgb) const;
    FfxDofErrorCode makeEngineViews(const DispatchPlan& plan, EngineViews* views) const;
    void destroyEngineViews(EngineViews* views) const;
    void writeDescriptors(uint32_t slot, const EngineViews& views, VkImageLayout colorLayout,
                          VkImageLayout depthLayout);
    void recordEngineBarriers(VkCommandBuffer commandBuffer, const std::vector<EngineImageUse>& uses,
                              bool toShader) const;

    BackendVK& backend_;
    const ContextConfig config_;
    std::array<InternalImage, kInternalImageCount> images_{};
    VkDeviceMemory imageMemory_ = VK_NULL_HANDLE;
    VkBuffer globals_ = VK_NULL_HANDLE;
    VkDeviceMemory globalsMemory_ = VK_NULL_HANDLE;
    FfxDofMemoryUsage memoryUsage_{};

    std::array<const shaders::PassTable*, kPassCount> tables_{};
    std::array<VkDescriptorSetLayout, kPassCount> setLayouts_{};
    std::array<VkPipelineLayout, kPassCount> pipelineLayouts_{};
    std::array<VkPipeline, kPassCount> pipelines_{};
    PermutationOptions pipelineOptions_{};

    VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
    std::vector<std::array<VkDescriptorSet, kPassCount>> sets_;  // [ring slot][pass]
    std::vector<EngineViews> engineViews_;                       // [ring slot]
    uint64_t dispatchCount_ = 0;

    VkQueryPool queryPool_ = VK_NULL_HANDLE;
    uint32_t firstQuery_ = 0;
};

// ---------------------------------------------------------------------------------------------
class BackendVK final : public FfxDofBackend_T {
public:
    ~BackendVK() override {
        // After a failed init the objects (and even the functions) may be missing.
        if (sampler) fn.vkDestroySampler(device, sampler, allocator);
        if (ownsPipelineCache) fn.vkDestroyPipelineCache(device, pipelineCache, allocator);
    }

    FfxDofErrorCode init(const FfxDofBackendDescriptionVK& description) {
        instance = description.instance;
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
            return fail(FFX_DOF_ERROR_INVALID_FLAGS,
                        "backend flags 0x%x include bits that are not FfxDofBackendFlagBitsVK", description.flags);
        }
        if (const char* missing = loadFunctions(description.vkGetInstanceProcAddr, description.vkGetDeviceProcAddr,
                                                instance, device, &fn)) {
            return fail(FFX_DOF_ERROR_BACKEND, "the Vulkan entry point %s could not be loaded", missing);
        }
        fn.vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties);

        language = (description.flags & FFX_DOF_VK_USE_HLSL_SHADERS) ? ShaderLanguage::Hlsl : ShaderLanguage::Glsl;
        features = enabledFeaturesOf(description.pEnabledFeatures);
        features.shader |= queriedSubgroupFeatures(fn, physicalDevice);
        useHalf = features.has(shaders::Feature::Float16) && !(description.flags & FFX_DOF_VK_DISABLE_FLOAT16);
        useWave64 = features.subgroupSizeControl && features.computeFullSubgroups &&
                    !(description.flags & FFX_DOF_VK_DISABLE_WAVE64) && deviceSupportsWave64();

        if (description.pipelineCache != VK_NULL_HANDLE) {
            pipelineCache = description.pipelineCache;
        } else {
            auto cacheInfo = makeInfo<VkPipelineCacheCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO);
            FFX_DOF_VK_CHECK(fn.vkCreatePipelineCache(device, &cacheInfo, allocator, &pipelineCache),
                             "vkCreatePipelineCache");
            ownsPipelineCache = true;
        }

        auto samplerInfo = makeInfo<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
        samplerInfo.magFilter = VK_FILTER_LINEAR;
        samplerInfo.minFilter = VK_FILTER_LINEAR;
        samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        samplerInfo.maxLod = float(kMipCount - 1);  // FFX_DOF_SAMPLER_LINEAR_CLAMP in ffx_dof_resources.h
        FFX_DOF_VK_CHECK(fn.vkCreateSampler(device, &samplerInfo, allocator, &sampler), "vkCreateSampler");
        return FFX_DOF_OK;
    }

    FfxDofErrorCode createContext(const ContextConfig& config, std::unique_ptr<BackendContext>* out) override {
        std::unique_ptr<ContextVK> context(new (std::nothrow) ContextVK(*this, config));
        if (!context) return fail(FFX_DOF_ERROR_OUT_OF_MEMORY, "allocating the Vulkan context failed");
        const FfxDofErrorCode result = context->create();
        if (result != FFX_DOF_OK) return result;  // the partly built context is destroyed here
        *out = std::move(context);
        return FFX_DOF_OK;
    }

    // A memory type allowed by typeBits, device-local where possible.
    bool findMemoryType(uint32_t typeBits, uint32_t* index) const {
        for (VkMemoryPropertyFlags wanted :
             {VkMemoryPropertyFlags(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT), VkMemoryPropertyFlags(0)}) {
            for (uint32_t i = 0; i < memoryProperties.memoryTypeCount; ++i) {
                if ((typeBits & (1u << i)) && (memoryProperties.memoryTypes[i].propertyFlags & wanted) == wanted) {
                    *index = i;
                    return true;
                }
            }
        }
        return false;
    }

    VkFormatFeatureFlags optimalFeatures(VkFormat format) const {
        VkFormatProperties properties{};
        fn.vkGetPhysicalDeviceFormatProperties(physicalDevice, format, &properties);
        return properties.optimalTilingFeatures;
    }

    Functions fn;
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    const VkAllocationCallbacks* allocator = nullptr;
    VkPipelineCache pipelineCache = VK_NULL_HANDLE;
    bool ownsPipelineCache = false;
    VkSampler sampler = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    uint32_t framesInFlight = kDefaultFramesInFlight;
    ShaderLanguage language = ShaderLanguage::Glsl;
    EnabledFeatures features;
    bool useHalf = false;
    bool useWave64 = false;

private:
    bool deviceSupportsWave64() const {
        if (!fn.vkGetPhysicalDeviceProperties2) return false;
        auto sizeControl = makeInfo<VkPhysicalDeviceSubgroupSizeControlProperties>(
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_SIZE_CONTROL_PROPERTIES);
        auto properties = makeInfo<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
        properties.pNext = &sizeControl;
        fn.vkGetPhysicalDeviceProperties2(physicalDevice, &properties);
        return sizeControl.minSubgroupSize <= kWave64 && kWave64 <= sizeControl.maxSubgroupSize &&
               (sizeControl.requiredSubgroupSizeStages & VK_SHADER_STAGE_COMPUTE_BIT);
    }
};

// ---------------------------------------------------------------------------------------------
ContextVK::~ContextVK() {
    const Functions& fn = backend_.fn;
    const VkDevice device = backend_.device;
    const VkAllocationCallbacks* allocator = backend_.allocator;
    for (EngineViews& views : engineViews_) destroyEngineViews(&views);
    fn.vkDestroyDescriptorPool(device, descriptorPool_, allocator);
    for (uint32_t pass = 0; pass < kPassCount; ++pass) {
        fn.vkDestroyPipeline(device, pipelines_[pass], allocator);
        fn.vkDestroyPipelineLayout(device, pipelineLayouts_[pass], allocator);
        fn.vkDestroyDescriptorSetLayout(device, setLayouts_[pass], allocator);
    }
    for (InternalImage& image : images_) {
        for (VkImageView view : image.level) fn.vkDestroyImageView(device, view, allocator);
        fn.vkDestroyImageView(device, image.allLevels, allocator);
        fn.vkDestroyImage(device, image.image, allocator);
    }
    fn.vkFreeMemory(device, imageMemory_, allocator);
    fn.vkDestroyBuffer(device, globals_, allocator);
    fn.vkFreeMemory(device, globalsMemory_, allocator);
}

FfxDofErrorCode ContextVK::create() {
    FfxDofErrorCode result = createImages();
    if (result == FFX_DOF_OK) result = createPipelines();
    if (result == FFX_DOF_OK) result = createDescriptors();
    return result;
}

FfxDofErrorCode ContextVK::createImages() {
    const Functions& fn = backend_.fn;
    const VkDevice device = backend_.device;
    const VkAllocationCallbacks* allocator = backend_.allocator;
    const uint32_t halfWidth = (config_.resolution.width + 1) / 2;
    const uint32_t halfHeight = (config_.resolution.height + 1) / 2;
    const uint32_t tilesWidth = (halfWidth + FFX_DOF_TILE_SIZE - 1) / FFX_DOF_TILE_SIZE;
    const uint32_t tilesHeight = (halfHeight + FFX_DOF_TILE_SIZE - 1) / FFX_DOF_TILE_SIZE;

    // All images share one allocation: they live and die together with the context.
    std::array<VkMemoryRequirements, kInternalImageCount> requirements{};
    uint32_t typeBits = ~0u;
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        const InternalImageSpec& spec = kInternalImages[i];
        InternalImage& image = images_[i];
        constexpr VkFormatFeatureFlags kNeeded =
            VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT;
        if ((backend_.optimalFeatures(toVkFormat(spec.format)) & kNeeded) != kNeeded) {
            return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device cannot sample and store %s, the format of %s",
                        formatName(toVkFormat(spec.format)).c_str(), spec.name);
        }
        image.width = spec.extent == ImageExtent::Half ? halfWidth : tilesWidth;
        image.height = spec.extent == ImageExtent::Half ? halfHeight : tilesHeight;
        image.mipLevels = mipLevelsFor(spec, image.width, image.height);

        auto info = makeInfo<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = toVkFormat(spec.format);
        info.extent = {image.width, image.height, 1};
        info.mipLevels = image.mipLevels;
        info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.tiling = VK_IMAGE_TILING_OPTIMAL;
        info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        const std::string what = std::string("vkCreateImage (") + spec.name + ")";
        FFX_DOF_VK_CHECK(fn.vkCreateImage(device, &info, allocator, &image.image), what.c_str());
        fn.vkGetImageMemoryRequirements(device, image.image, &requirements[i]);
        typeBits &= requirements[i].memoryTypeBits;
    }

    std::array<VkDeviceSize, kInternalImageCount> offsets{};
    VkDeviceSize total = 0;
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        const VkDeviceSize alignment = requirements[i].alignment;
        offsets[i] = (total + alignment - 1) / alignment * alignment;
        total = offsets[i] + requirements[i].size;
        memoryUsage_.totalUsageInBytes += requirements[i].size;
    }
    // Every image is rewritten before it is read in each dispatch.
    memoryUsage_.aliasableUsageInBytes = memoryUsage_.totalUsageInBytes;

    auto allocation = makeInfo<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    allocation.allocationSize = total;
    if (!backend_.findMemoryType(typeBits, &allocation.memoryTypeIndex)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "no memory type can hold all internal images (type bits 0x%x)",
                    typeBits);
    }
    FFX_DOF_VK_CHECK(fn.vkAllocateMemory(device, &allocation, allocator, &imageMemory_),
                     "vkAllocateMemory (internal images)");

    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        InternalImage& image = images_[i];
        FFX_DOF_VK_CHECK(fn.vkBindImageMemory(device, image.image, imageMemory_, offsets[i]), "vkBindImageMemory");
        auto view = makeInfo<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        view.image = image.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = toVkFormat(kInternalImages[i].format);
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, image.mipLevels, 0, 1};
        FFX_DOF_VK_CHECK(fn.vkCreateImageView(device, &view, allocator, &image.allLevels), "vkCreateImageView");
        for (uint32_t level = 0; level < image.mipLevels; ++level) {
            view.subresourceRange.baseMipLevel = level;
            view.subresourceRange.levelCount = 1;
            FFX_DOF_VK_CHECK(fn.vkCreateImageView(device, &view, allocator, &image.level[level]), "vkCreateImageView");
        }
    }

    auto bufferInfo = makeInfo<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    bufferInfo.size = kGlobalsBufferBytes;
    bufferInfo.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    bufferInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    FFX_DOF_VK_CHECK(fn.vkCreateBuffer(device, &bufferInfo, allocator, &globals_), "vkCreateBuffer (GLOBALS)");
    VkMemoryRequirements bufferRequirements{};
    fn.vkGetBufferMemoryRequirements(device, globals_, &bufferRequirements);
    memoryUsage_.totalUsageInBytes += bufferRequirements.size;
    auto bufferAllocation = makeInfo<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    bufferAllocation.allocationSize = bufferRequirements.size;
    if (!backend_.findMemoryType(bufferRequirements.memoryTypeBits, &bufferAllocation.memoryTypeIndex)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "no memory type can hold the GLOBALS buffer");
    }
    FFX_DOF_VK_CHECK(fn.vkAllocateMemory(device, &bufferAllocation, allocator, &globalsMemory_),
                     "vkAllocateMemory (GLOBALS)");
    FFX_DOF_VK_CHECK(fn.vkBindBufferMemory(device, globals_, globalsMemory_, 0), "vkBindBufferMemory");
    return FFX_DOF_OK;
}

FfxDofErrorCode ContextVK::createPipelines() {
    const Functions& fn = backend_.fn;
    const VkDevice device = backend_.device;
    const VkAllocationCallbacks* allocator = backend_.allocator;

    // The option values are the core's (planDispatch); a context only ever dispatches with these.
    FfxDofDispatchDescription noDispatch{};
    pipelineOptions_ = planDispatch(config_, noDispatch, 0).options;

    for (uint32_t pass = 0; pass < kPassCount; ++pass) {
        const shaders::PassTable* table = passTable(backend_.language, Pass(pass));
        if (!table) {
            return fail(FFX_DOF_ERROR_UNSUPPORTED, "no %s shaders were built for the pass %s",
                        backend_.language == ShaderLanguage::Hlsl ? "HLSL" : "GLSL", kPassNames[pass]);
        }
        tables_[pass] = table;

        // Every axis the table has gets its value; an axis this backend does not know is an error.
        std::vector<shaders::Define> defines;
        for (uint32_t a = 0; a < table->axisCount; ++a) {
            const std::string macro = table->axes[a].macro;
            uint32_t value = 0;
            if (macro == "FFX_HALF") {
                value = backend_.useHalf ? 1 : 0;
            } else if (macro == "FFX_DOF_OPTION_WAVE64") {
                value = backend_.useWave64 ? 1 : 0;
            } else if (macro == "FFX_DOF_OPTION_REVERSE_DEPTH") {
                value = pipelineOptions_.reverseDepth;
            } else if (macro == "FFX_DOF_OPTION_DISABLE_RING_MERGE") {
                value = pipelineOptions_.ringMergeLog ? 0 : 1;
            } else if (macro == "FFX_DOF_OPTION_OUTPUT_PRE_INIT") {
                value = pipelineOptions_.combineInPlace;
            } else {
                return fail(FFX_DOF_ERROR_UNSUPPORTED, "the %s shaders have the axis %s, unknown to the Vulkan backend",
                            kPassNames[pass], macro.c_str());
            }
            defines.emplace_back(macro, value);
        }
        std::string error;
        const shaders::Blob* blob = shaders::findPermutation(*table, defines, &error);
        if (!blob) {
            return fail(FFX_DOF_ERROR_UNSUPPORTED, "no %s permutation: %s", kPassNames[pass], error.c_str());
        }
        const FfxDofErrorCode supported =
            checkShaderFeatures(backend_.features, *blob, kPassNames[pass], backend_.useHalf, backend_.useWave64);
        if (supported != FFX_DOF_OK) return supported;

        // Descriptor set layout from the reflected bindings (the union over the permutations).
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        for (uint32_t b = 0; b < table->bindingCount; ++b) {
            const shaders::Binding& binding = table->bindings[b];
            if (binding.kind == shaders::BindingKind::PushConstants) {
                if (binding.size > sizeof(FfxDofConstants)) {
                    return fail(FFX_DOF_ERROR_BACKEND, "the %s push constants are %u bytes; FfxDofConstants is %zu",
                                kPassNames[pass], binding.size, sizeof(FfxDofConstants));
                }
                continue;
            }
            if (binding.set != 0 || binding.arraySize != 1 || binding.kind != expectedKindOf(binding.binding)) {
                return fail(FFX_DOF_ERROR_BACKEND,
                            "the %s shader declares %s at set %u binding %u as %s x%u, which is not the resource "
                            "table's slot",
                            kPassNames[pass], binding.name, binding.set, binding.binding,
                            shaders::bindingKindName(binding.kind), binding.arraySize);
            }
            VkDescriptorSetLayoutBinding layoutBinding{};
            layoutBinding.binding = binding.binding;
            layoutBinding.descriptorType = descriptorTypeOf(binding.kind);
            layoutBinding.descriptorCount = 1;
            layoutBinding.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
            if (binding.kind == shaders::BindingKind::Sampler) layoutBinding.pImmutableSamplers = &backend_.sampler;
            bindings.push_back(layoutBinding);
        }
        auto setLayoutInfo =
            makeInfo<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
        setLayoutInfo.bindingCount = uint32_t(bindings.size());
        setLayoutInfo.pBindings = bindings.data();
        FFX_DOF_VK_CHECK(fn.vkCreateDescriptorSetLayout(device, &setLayoutInfo, allocator, &setLayouts_[pass]),
                         "vkCreateDescriptorSetLayout");

        const VkPushConstantRange pushRange{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(FfxDofConstants)};
        auto layoutInfo = makeInfo<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
        layoutInfo.setLayoutCount = 1;
        layoutInfo.pSetLayouts = &setLayouts_[pass];
        layoutInfo.pushConstantRangeCount = 1;
        layoutInfo.pPushConstantRanges = &pushRange;
        FFX_DOF_VK_CHECK(fn.vkCreatePipelineLayout(device, &layoutInfo, allocator, &pipelineLayouts_[pass]),
                         "vkCreatePipelineLayout");

        auto moduleInfo = makeInfo<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
        moduleInfo.codeSize = blob->wordCount * sizeof(uint32_t);
        moduleInfo.pCode = blob->words;
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
        if (backend_.useWave64) {
            // The wave64 shaders assume every subgroup is 64 lanes wide and full.
            pipelineInfo.stage.pNext = &subgroupSize;
            pipelineInfo.stage.flags = VK_PIPELINE_SHADER_STAGE_CREATE_REQUIRE_FULL_SUBGROUPS_BIT;
        }
        pipelineInfo.layout = pipelineLayouts_[pass];
        const VkResult created =
            fn.vkCreateComputePipelines(device, backend_.pipelineCache, 1, &pipelineInfo, allocator, &pipelines_[pass]);
        fn.vkDestroyShaderModule(device, module, allocator);
        if (created != VK_SUCCESS) {
            const std::string what = std::string("vkCreateComputePipelines (") + kPassNames[pass] + ")";
            return failVk(created, what.c_str());
        }
    }
    return FFX_DOF_OK;
}

FfxDofErrorCode ContextVK::createDescriptors() {
    const Functions& fn = backend_.fn;
    const uint32_t frames = backend_.framesInFlight;
    std::array<uint32_t, 4> counts{};  // sampled, storage image, storage buffer, sampler
    const VkDescriptorType types[4] = {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                       VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_SAMPLER};
    for (const shaders::PassTable* table : tables_) {
        for (uint32_t b = 0; b < table->bindingCount; ++b) {
            const VkDescriptorType type = descriptorTypeOf(table->bindings[b].kind);
            for (uint32_t t = 0; t < 4; ++t) counts[t] += (type == types[t]) ? frames : 0;
        }
    }
    std::vector<VkDescriptorPoolSize> sizes;
    for (uint32_t t = 0; t < 4; ++t) {
        if (counts[t]) sizes.push_back({types[t], counts[t]});
    }
    auto poolInfo = makeInfo<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    poolInfo.maxSets = frames * kPassCount;
    poolInfo.poolSizeCount = uint32_t(sizes.size());
    poolInfo.pPoolSizes = sizes.data();
    FFX_DOF_VK_CHECK(fn.vkCreateDescriptorPool(backend_.device, &poolInfo, backend_.allocator, &descriptorPool_),
                     "vkCreateDescriptorPool");
    sets_.resize(frames);
    engineViews_.resize(frames);
    for (uint32_t slot = 0; slot < frames; ++slot) {
        auto allocateInfo = makeInfo<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
        allocateInfo.descriptorPool = descriptorPool_;
        allocateInfo.descriptorSetCount = kPassCount;
        allocateInfo.pSetLayouts = setLayouts_.data();
        FFX_DOF_VK_CHECK(fn.vkAllocateDescriptorSets(backend_.device, &allocateInfo, sets_[slot].data()),
                         "vkAllocateDescriptorSets");
    }
    return FFX_DOF_OK;
}

FfxDofErrorCode ContextVK::validate(const DispatchPlan& plan, bool* encodeSrgb) const {
    if (!plan.commandList) return fail(FFX_DOF_ERROR_INVALID_POINTER, "commandList is null");
    const struct {
        const char* name;
        const FfxDofResource& resource;
    } resources[] = {{"color", plan.color}, {"depth", plan.depth}, {"output", plan.output}};
    for (const auto& r : resources) {
        if (r.resource.handle == 0) return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s: the VkImage is null", r.name);
        if (r.resource.width != config_.resolution.width || r.resource.height != config_.resolution.height) {
            return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s is %ux%u but the context was created for %ux%u", r.name,
                        r.resource.width, r.resource.height, config_.resolution.width, config_.resolution.height);
        }
        if (r.resource.flags & ~uint32_t(FFX_DOF_VK_RESOURCE_MUTABLE_FORMAT)) {
            return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s has flags 0x%x that are not FfxDofResourceFlagBitsVK",
                        r.name, r.resource.flags);
        }
    }
    const VkFormat colorFormat = VkFormat(plan.color.format);
    const VkFormat depthFormat = VkFormat(plan.depth.format);
    const VkFormat outputFormat = VkFormat(plan.output.format);
    if (!isColorFormat(colorFormat)) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "color format %s is not supported (R16G16B16A16_SFLOAT, R32G32B32A32_SFLOAT, "
                    "B10G11R11_UFLOAT_PACK32, R8G8B8A8_UNORM or R8G8B8A8_SRGB)",
                    formatName(colorFormat).c_str());
    }
    if (!isDepthFormat(depthFormat)) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "depth format %s is not supported (D32_SFLOAT, D24_UNORM_S8_UINT, D16_UNORM or R32_SFLOAT)",
                    formatName(depthFormat).c_str());
    }
    if (!isColorFormat(outputFormat)) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "output format %s is not supported (the color formats are)",
                    formatName(outputFormat).c_str());
    }
    for (const auto& r : resources) {
        const VkImageLayout layout = VkImageLayout(r.resource.state);
        const bool depthAspect = &r.resource == &plan.depth && isDepthAspectFormat(depthFormat);
        if (!isAcceptedLayout(layout, depthAspect)) {
            return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                        "%s is declared in %s, which is not accepted: use GENERAL, SHADER_READ_ONLY_OPTIMAL, "
                        "TRANSFER_SRC/DST_OPTIMAL or %s (the image must hold its contents before and after)",
                        r.name, layoutName(layout).c_str(),
                        depthAspect ? "DEPTH_STENCIL_ATTACHMENT/READ_ONLY_OPTIMAL, DEPTH_READ_ONLY_OPTIMAL"
                                    : "COLOR_ATTACHMENT_OPTIMAL");
        }
    }
    *encodeSrgb = outputFormat == VK_FORMAT_R8G8B8A8_SRGB;
    if (*encodeSrgb && !(plan.output.flags & FFX_DOF_VK_RESOURCE_MUTABLE_FORMAT)) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "output is VK_FORMAT_R8G8B8A8_SRGB, which cannot be a storage image: create it with "
                    "VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT and pass FFX_DOF_VK_RESOURCE_MUTABLE_FORMAT");
    }
    if (plan.outputIsColor && (plan.output.format != plan.color.format || plan.output.state != plan.color.state)) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "output is the color image (in place) but its format or layout differs from color's");
    }
    if (plan.depth.handle == plan.color.handle) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "depth and color are the same image");
    }
    if (!(backend_.optimalFeatures(colorFormat) & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device cannot sample color format %s",
                    formatName(colorFormat).c_str());
    }
    if (!(backend_.optimalFeatures(depthFormat) & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device cannot sample depth format %s",
                    formatName(depthFormat).c_str());
    }
    const VkFormat outputViewFormat = *encodeSrgb ? VK_FORMAT_R8G8B8A8_UNORM : outputFormat;
    if (!(backend_.optimalFeatures(outputViewFormat) & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device cannot write output format %s as a storage image",
                    formatName(outputViewFormat).c_str());
    }
    if (plan.options.reverseDepth != pipelineOptions_.reverseDepth ||
        plan.options.ringMergeLog != pipelineOptions_.ringMergeLog ||
        plan.options.combineInPlace != pipelineOptions_.combineInPlace) {
        return fail(FFX_DOF_ERROR_BACKEND, "the dispatch asks for permutation options the context was not built with");
    }
    return FFX_DOF_OK;
}

FfxDofErrorCode ContextVK::makeEngineViews(const DispatchPlan& plan, EngineViews* views) const {
    const Functions& fn = backend_.fn;
    // Each view is restricted to the usage it serves, so a view format that cannot be stored (an
    // _SRGB view of a mutable storage image) is still valid.
    const auto makeView = [&](const FfxDofResource& resource, VkFormat format, VkImageAspectFlags aspect,
                              VkImageUsageFlags usage, VkImageView* view) {
        auto usageInfo = makeInfo<VkImageViewUsageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_USAGE_CREATE_INFO);
        usageInfo.usage = usage;
        auto info = makeInfo<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        info.pNext = &usageInfo;
        info.image = imageOf(resource);
        info.viewType = VK_IMAGE_VIEW_TYPE_2D;
        info.format = format;
        info.subresourceRange = {aspect, 0, 1, 0, 1};
        return fn.vkCreateImageView(backend_.device, &info, backend_.allocator, view);
    };
    const VkFormat depthFormat = VkFormat(plan.depth.format);
    const VkImageAspectFlags depthAspect =
        isDepthAspectFormat(depthFormat) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    const VkFormat outputFormat = VkFormat(plan.output.format) == VK_FORMAT_R8G8B8A8_SRGB
                                      ? VK_FORMAT_R8G8B8A8_UNORM
                                      : VkFormat(plan.output.format);
    FFX_DOF_VK_CHECK(makeView(plan.color, VkFormat(plan.color.format), VK_IMAGE_ASPECT_COLOR_BIT,
                              VK_IMAGE_USAGE_SAMPLED_BIT, &views->color),
                     "vkCreateImageView (color)");
    FFX_DOF_VK_CHECK(makeView(plan.depth, depthFormat, depthAspect, VK_IMAGE_USAGE_SAMPLED_BIT, &views->depth),
                     "vkCreateImageView (depth, depth aspect)");
    FFX_DOF_VK_CHECK(
        makeView(plan.output, outputFormat, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_USAGE_STORAGE_BIT, &views->output),
        "vkCreateImageView (output)");
    return FFX_DOF_OK;
}

void ContextVK::destroyEngineViews(EngineViews* views) const {
    for (VkImageView* view : {&views->color, &views->depth, &views->output}) {
        backend_.fn.vkDestroyImageView(backend_.device, *view, backend_.allocator);
        *view = VK_NULL_HANDLE;
    }
}

void ContextVK::writeDescriptors(uint32_t slot, const EngineViews& views, VkImageLayout colorLayout,
                                 VkImageLayout depthLayout) {
    // Sized up front: the writes point into these arrays.
    std::vector<VkDescriptorImageInfo> imageInfos;
    std::vector<VkWriteDescriptorSet> writes;
    size_t total = 0;
    for (const shaders::PassTable* table : tables_) total += table->bindingCount;
    imageInfos.reserve(total);
    writes.reserve(total);
    const VkDescriptorBufferInfo globalsInfo{globals_, 0, kGlobalsBufferBytes};

    for (uint32_t pass = 0; pass < kPassCount; ++pass) {
        const shaders::PassTable& table = *tables_[pass];
        for (uint32_t b = 0; b < table.bindingCount; ++b) {
            const shaders::Binding& binding = table.bindings[b];
            auto write = makeInfo<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
            write.dstSet = sets_[slot][pass];
            write.dstBinding = binding.binding;
            write.descriptorCount = 1;
            write.descriptorType = descriptorTypeOf(binding.kind);
            VkDescriptorImageInfo image{VK_NULL_HANDLE, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL};
            switch (binding.kind) {
                case shaders::BindingKind::SampledImage: {
                    const uint32_t index = binding.binding - FFX_DOF_SRV_BASE;
                    if (index == FFX_DOF_SRV_INPUT_COLOR) {
                        image = {VK_NULL_HANDLE, views.color, colorLayout};
                    } else if (index == FFX_DOF_SRV_INPUT_DEPTH) {
                        image = {VK_NULL_HANDLE, views.depth, depthLayout};
                    } else {
                        for (uint32_t i = 0; i < kInternalImageCount; ++i) {
                            if (kInternalImages[i].sampledSlot == index) image.imageView = images_[i].allLevels;
                        }
                    }
                    break;
                }
                case shaders::BindingKind::StorageImage: {
                    const uint32_t index = binding.binding - FFX_DOF_UAV_IMAGE_BASE;
                    if (index == FFX_DOF_UAV_OUTPUT) image.imageView = views.output;
                    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
                        const InternalImageSpec& spec = kInternalImages[i];
                        const uint32_t slots = spec.mipChain ? kMipCount : 1;
                        if (index >= spec.storageSlot && index < spec.storageSlot + slots) {
                            // A level a small image lacks aliases its last level; the shader
                            // writes the same 1x1 value to both.
                            const uint32_t level = std::min(index - spec.storageSlot, images_[i].mipLevels - 1);
                            image.imageView = images_[i].level[level];
                        }
                    }
                    break;
                }
                case shaders::BindingKind::StorageBuffer:
                    write.pBufferInfo = &globalsInfo;
                    break;
                default:  // the sampler is immutable; push constants are not descriptors
                    continue;
            }
            if (write.descriptorType != VK_DESCRIPTOR_TYPE_STORAGE_BUFFER) {
                imageInfos.push_back(image);
                write.pImageInfo = &imageInfos.back();
            }
            writes.push_back(write);
        }
    }
    backend_.fn.vkUpdateDescriptorSets(backend_.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

void ContextVK::recordEngineBarriers(VkCommandBuffer commandBuffer, const std::vector<EngineImageUse>& uses,
                                     bool toShader) const {
    // The engine's accesses before and after are unknown, so the engine side of each barrier is
    // ALL_COMMANDS with all memory accesses; the effect side is exactly its compute accesses.
    std::vector<VkImageMemoryBarrier> barriers;
    for (const EngineImageUse& use : uses) {
        auto barrier = makeInfo<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
        barrier.srcAccessMask = toShader ? VkAccessFlags(VK_ACCESS_MEMORY_WRITE_BIT) : use.access;
        barrier.dstAccessMask =
            toShader ? use.access : VkAccessFlags(VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
        barrier.oldLayout = toShader ? use.declared : use.during;
        barrier.newLayout = toShader ? use.during : use.declared;
        barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = use.image;
        barrier.subresourceRange = {use.barrierAspects, 0, 1, 0, 1};
        barriers.push_back(barrier);
    }
    const VkPipelineStageFlags engineStages = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
    const VkPipelineStageFlags effectStages = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    backend_.fn.vkCmdPipelineBarrier(commandBuffer, toShader ? engineStages : effectStages,
                                     toShader ? effectStages : engineStages, 0, 0, nullptr, 0, nullptr,
                                     uint32_t(barriers.size()), barriers.data());
}

FfxDofErrorCode ContextVK::dispatch(const DispatchPlan& plan) {
    bool encodeSrgb = false;
    if (const FfxDofErrorCode invalid = validate(plan, &encodeSrgb); invalid != FFX_DOF_OK) return invalid;
    const Functions& fn = backend_.fn;
    const VkCommandBuffer commandBuffer = static_cast<VkCommandBuffer>(plan.commandList);

    // This slot's previous dispatch was maxFramesInFlight dispatches ago: the GPU is done with it.
    const uint32_t slot = uint32_t(dispatchCount_ % backend_.framesInFlight);
    destroyEngineViews(&engineViews_[slot]);
    if (const FfxDofErrorCode made = makeEngineViews(plan, &engineViews_[slot]); made != FFX_DOF_OK) {
        destroyEngineViews(&engineViews_[slot]);
        return made;
    }

    // Layouts during the dispatch. A read-only layout the engine already uses is kept.
    std::vector<EngineImageUse> uses;
    EngineImageUse color{imageOf(plan.color), VK_IMAGE_ASPECT_COLOR_BIT, VkImageLayout(plan.color.state)};
    if (plan.outputIsColor) {
        color.during = VK_IMAGE_LAYOUT_GENERAL;
        color.access = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    } else {
        color.during = (color.declared == VK_IMAGE_LAYOUT_GENERAL) ? VK_IMAGE_LAYOUT_GENERAL
                                                                   : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        color.access = VK_ACCESS_SHADER_READ_BIT;
    }
    uses.push_back(color);

    const VkFormat depthFormat = VkFormat(plan.depth.format);
    EngineImageUse depth{imageOf(plan.depth), VK_IMAGE_ASPECT_COLOR_BIT, VkImageLayout(plan.depth.state)};
    depth.access = VK_ACCESS_SHADER_READ_BIT;
    if (isDepthAspectFormat(depthFormat)) {
        const bool keep = depth.declared == VK_IMAGE_LAYOUT_GENERAL ||
                          depth.declared == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL ||
                          depth.declared == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
        depth.during = keep ? depth.declared : VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
        // Without separate depth/stencil layouts both aspects change layout together.
        depth.barrierAspects = VK_IMAGE_ASPECT_DEPTH_BIT;
        if (depthFormat == VK_FORMAT_D24_UNORM_S8_UINT && depth.declared != VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL) {
            depth.barrierAspects |= VK_IMAGE_ASPECT_STENCIL_BIT;
        }
    } else {
        depth.during = (depth.declared == VK_IMAGE_LAYOUT_GENERAL) ? VK_IMAGE_LAYOUT_GENERAL
                                                                   : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    }
    uses.push_back(depth);

    if (!plan.outputIsColor) {
        EngineImageUse output{imageOf(plan.output), VK_IMAGE_ASPECT_COLOR_BIT, VkImageLayout(plan.output.state),
                              VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_SHADER_WRITE_BIT};
        // Without PRE_INIT every pixel is written; with it, unchanged pixels are kept and read.
        if (plan.options.combineInPlace) output.access |= VK_ACCESS_SHADER_READ_BIT;
        uses.push_back(output);
    }

    writeDescriptors(slot, engineViews_[slot], color.during, depth.during);

    const bool timed = queryPool_ != VK_NULL_HANDLE;
    if (timed) fn.vkCmdResetQueryPool(commandBuffer, queryPool_, firstQuery_, FFX_DOF_VK_TIMESTAMP_COUNT);

    // Order this dispatch after the previous one's use of the internal resources, or (first
    // dispatch) bring them into GENERAL and zero GLOBALS.
    const VkAccessFlags shaderAccess = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    if (dispatchCount_ == 0) {
        std::vector<VkImageMemoryBarrier> toGeneral;
        for (const InternalImage& internal : images_) {
            auto barrier = makeInfo<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
            barrier.dstAccessMask = shaderAccess;
            barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
            barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
            barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.image = internal.image;
            barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, internal.mipLevels, 0, 1};
            toGeneral.push_back(barrier);
        }
        fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                0, 0, nullptr, 0, nullptr, uint32_t(toGeneral.size()), toGeneral.data());
        fn.vkCmdFillBuffer(commandBuffer, globals_, 0, kGlobalsBufferBytes, 0);
        auto zeroed = makeInfo<VkBufferMemoryBarrier>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER);
        zeroed.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        zeroed.dstAccessMask = shaderAccess;
        zeroed.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        zeroed.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        zeroed.buffer = globals_;
        zeroed.size = VK_WHOLE_SIZE;
        fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
                                0, nullptr, 1, &zeroed, 0, nullptr);
    } else {
        auto previous = makeInfo<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        previous.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        previous.dstAccessMask = shaderAccess;
        fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &previous, 0, nullptr, 0, nullptr);
    }
    recordEngineBarriers(commandBuffer, uses, true);

    FfxDofConstants constants = plan.constants;
    if (encodeSrgb) constants.outputFlags |= FFX_DOF_OUTPUT_FLAG_ENCODE_SRGB;
    if (timed) {
        fn.vkCmdWriteTimestamp(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, queryPool_, firstQuery_);
    }
    for (uint32_t pass = 0; pass < kPassCount; ++pass) {
        if (pass > 0) {
            auto between = makeInfo<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
            between.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
            between.dstAccessMask = shaderAccess;
            fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &between, 0, nullptr, 0, nullptr);
        }
        fn.vkCmdBindPipeline(commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[pass]);
        fn.vkCmdBindDescriptorSets(commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayouts_[pass], 0, 1,
                                   &sets_[slot][pass], 0, nullptr);
        fn.vkCmdPushConstants(commandBuffer, pipelineLayouts_[pass], VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                              &constants);
        fn.vkCmdDispatch(commandBuffer, plan.passes[pass].x, plan.passes[pass].y, plan.passes[pass].z);
        if (timed) {
            fn.vkCmdWriteTimestamp(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, queryPool_,
                                   firstQuery_ + 1 + pass);
        }
    }
    recordEngineBarriers(commandBuffer, uses, false);
    ++dispatchCount_;
    return FFX_DOF_OK;
}

}  // namespace ffxdof::vk

// ---------------------------------------------------------------------------------------------
using namespace ffxdof;

extern "C" {

FfxDofErrorCode ffxDofBackendCreateVK(const FfxDofBackendDescriptionVK* pDescription, FfxDofBackend* pBackend) {
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

FfxDofResource ffxDofGetResourceVK(VkImage image, VkFormat format, uint32_t width, uint32_t height,
                                   VkImageLayout layout, uint32_t resourceFlags) {
    FfxDofResource resource{};
    if constexpr (std::is_pointer_v<VkImage>) {
        resource.handle = static_cast<uint64_t>(reinterpret_cast<uintptr_t>(image));
    } else {
        resource.handle = uint64_t(image);
    }
    resource.format = uint32_t(format);
    resource.width = width;
    resource.height = height;
    resource.state = uint32_t(layout);
    resource.flags = resourceFlags;
    return resource;
}

FfxDofCommandList ffxDofGetCommandListVK(VkCommandBuffer commandBuffer) { return commandBuffer; }

FfxDofErrorCode ffxDofContextSetTimestampQueriesVK(FfxDofContext* pContext, VkQueryPool queryPool,
                                                   uint32_t firstQuery) {
    clearLastError();
    if (!pContext) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pContext is null");
    auto* context = dynamic_cast<vk::ContextVK*>(backendContextOf(*pContext));
    if (!context) return fail(FFX_DOF_ERROR_INVALID_CONTEXT, "the context is not a live Vulkan context");
    context->setTimestampQueries(queryPool, firstQuery);
    return FFX_DOF_OK;
}

}  // extern "C"
