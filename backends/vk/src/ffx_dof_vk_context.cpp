// Creating a Vulkan context from its plan: images, pipelines (the backend's), descriptor sets (the internal
// resources written once, here).
#include "ffx_dof_vk_context.h"

#include "ffx_dof_vk_internal_images.h"

#include <string>

namespace ffxdof::vk {
namespace {

uint32_t bitCount(uint32_t bits) {
    uint32_t count = 0;
    for (; bits; bits &= bits - 1) ++count;
    return count;
}

}  // namespace

ContextVK::~ContextVK() {
    const Functions& fn = backend_.fn;
    const VkDevice device = backend_.device;
    const VkAllocationCallbacks* allocator = backend_.allocator;
    fn.vkDestroyDescriptorPool(device, descriptorPool_, allocator);
    for (InternalImage& image : images_) {
        for (VkImageView view : image.level) fn.vkDestroyImageView(device, view, allocator);
        fn.vkDestroyImageView(device, image.allLevels, allocator);
        fn.vkDestroyImage(device, image.image, allocator);
    }
    fn.vkFreeMemory(device, imageMemory_, allocator);
    for (InternalBuffer& buffer : buffers_) {
        fn.vkDestroyBuffer(device, buffer.buffer, allocator);
        fn.vkFreeMemory(device, buffer.memory, allocator);
    }
    fn.vkDestroyBuffer(device, readback_, allocator);
    fn.vkFreeMemory(device, readbackMemory_, allocator);  // unmaps it
}

FfxDofErrorCode ContextVK::create() {
    FfxDofErrorCode result = createImages();
    if (result == FFX_DOF_OK) result = createBuffers();
    if (result == FFX_DOF_OK) result = createReadback();
    if (result == FFX_DOF_OK) result = createPipelines();
    if (result == FFX_DOF_OK) result = createDescriptors();
    return result;
}

FfxDofErrorCode ContextVK::createImages() {
    const Functions& fn = backend_.fn;
    const VkDevice device = backend_.device;
    const VkAllocationCallbacks* allocator = backend_.allocator;

    // All images share one allocation: they live and die together with the context.
    std::array<VkMemoryRequirements, kInternalImageCount> requirements{};
    uint32_t typeBits = ~0u;
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        const PlannedImage& planned = plan_.images[i];
        const VkFormat format = toVkFormat(planned.spec->format);
        constexpr VkFormatFeatureFlags kNeeded =
            VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT;
        if ((formats_.optimalFeatures(format) & kNeeded) != kNeeded) {
            return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device cannot sample and store %s, the format of %s",
                        formatName(format).c_str(), planned.spec->name);
        }
        auto info = makeInfo<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {planned.width, planned.height, 1};
        info.mipLevels = planned.mipLevels;
        info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.tiling = VK_IMAGE_TILING_OPTIMAL;
        info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        const std::string what = std::string("vkCreateImage (") + planned.spec->name + ")";
        FFX_DOF_VK_CHECK(fn.vkCreateImage(device, &info, allocator, &images_[i].image), what.c_str());
        fn.vkGetImageMemoryRequirements(device, images_[i].image, &requirements[i]);
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
        const PlannedImage& planned = plan_.images[i];
        FFX_DOF_VK_CHECK(fn.vkBindImageMemory(device, image.image, imageMemory_, offsets[i]), "vkBindImageMemory");
        auto view = makeInfo<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        view.image = image.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = toVkFormat(planned.spec->format);
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, planned.mipLevels, 0, 1};
        FFX_DOF_VK_CHECK(fn.vkCreateImageView(device, &view, allocator, &image.allLevels), "vkCreateImageView");
        for (uint32_t level = 0; level < planned.mipLevels; ++level) {
            view.subresourceRange.baseMipLevel = level;
            view.subresourceRange.levelCount = 1;
            FFX_DOF_VK_CHECK(fn.vkCreateImageView(device, &view, allocator, &image.level[level]), "vkCreateImageView");
        }
    }
    return FFX_DOF_OK;
}

FfxDofErrorCode ContextVK::createBuffers() {
    const Functions& fn = backend_.fn;
    const VkDevice device = backend_.device;
    struct BufferSpec {
        const char* name;
        VkDeviceSize bytes;
        VkBufferUsageFlags usage;
    };
    const BufferSpec specs[kStorageBufferSlotCount] = {
        // Zeroed before the first dispatch; autofocus copies its distance out.
        {"GLOBALS", kGlobalsBufferBytes,
         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT},
        {"TILE_LIST_ARGS", kTileListArgsBytes,
         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT},
        {"TILE_LISTS", plan_.tileListsBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
        {"HIGHLIGHTS", plan_.highlightsBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
    };
    static_assert(FFX_DOF_UAV_BUFFER_GLOBALS == 0 && FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS == 1 &&
                      FFX_DOF_UAV_BUFFER_TILE_LISTS == 2 && FFX_DOF_UAV_BUFFER_HIGHLIGHTS == 3 &&
                      kStorageBufferSlotCount == 4,
                  "specs are listed by storage buffer slot");
    for (uint32_t slot = 0; slot < kStorageBufferSlotCount; ++slot) {
        const BufferSpec& spec = specs[slot];
        InternalBuffer& buffer = buffers_[slot];
        buffer.bytes = spec.bytes;
        auto bufferInfo = makeInfo<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
        bufferInfo.size = spec.bytes;
        bufferInfo.usage = spec.usage;
        bufferInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        const std::string create = std::string("vkCreateBuffer (") + spec.name + ")";
        FFX_DOF_VK_CHECK(fn.vkCreateBuffer(device, &bufferInfo, backend_.allocator, &buffer.buffer), create.c_str());
        VkMemoryRequirements requirements{};
        fn.vkGetBufferMemoryRequirements(device, buffer.buffer, &requirements);
        memoryUsage_.totalUsageInBytes += requirements.size;
        // Every dispatch rewrites the tile lists and the highlights before it reads them; GLOBALS carries
        // values across.
        if (slot != FFX_DOF_UAV_BUFFER_GLOBALS) memoryUsage_.aliasableUsageInBytes += requirements.size;
        auto allocation = makeInfo<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        allocation.allocationSize = requirements.size;
        if (!backend_.findMemoryType(requirements.memoryTypeBits, &allocation.memoryTypeIndex)) {
            return fail(FFX_DOF_ERROR_UNSUPPORTED, "no memory type can hold the %s buffer", spec.name);
        }
        const std::string allocate = std::string("vkAllocateMemory (") + spec.name + ")";
        FFX_DOF_VK_CHECK(fn.vkAllocateMemory(device, &allocation, backend_.allocator, &buffer.memory),
                         allocate.c_str());
        FFX_DOF_VK_CHECK(fn.vkBindBufferMemory(device, buffer.buffer, buffer.memory, 0), "vkBindBufferMemory");
    }
    return FFX_DOF_OK;
}

FfxDofErrorCode ContextVK::createReadback() {
    const Functions& fn = backend_.fn;
    const VkDevice device = backend_.device;
    const uint32_t slots = readbackRing_.slotCount();
    auto bufferInfo = makeInfo<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    bufferInfo.size = slots * sizeof(float);
    bufferInfo.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    bufferInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    FFX_DOF_VK_CHECK(fn.vkCreateBuffer(device, &bufferInfo, backend_.allocator, &readback_),
                     "vkCreateBuffer (autofocus readback)");
    VkMemoryRequirements requirements{};
    fn.vkGetBufferMemoryRequirements(device, readback_, &requirements);
    memoryUsage_.totalUsageInBytes += requirements.size;
    auto allocation = makeInfo<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    allocation.allocationSize = requirements.size;
    if (!backend_.findMemoryType(requirements.memoryTypeBits, &allocation.memoryTypeIndex,
                                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "no host-visible, coherent memory type can hold the autofocus readback");
    }
    FFX_DOF_VK_CHECK(fn.vkAllocateMemory(device, &allocation, backend_.allocator, &readbackMemory_),
                     "vkAllocateMemory (autofocus readback)");
    FFX_DOF_VK_CHECK(fn.vkBindBufferMemory(device, readback_, readbackMemory_, 0), "vkBindBufferMemory");
    void* mapped = nullptr;
    FFX_DOF_VK_CHECK(fn.vkMapMemory(device, readbackMemory_, 0, VK_WHOLE_SIZE, 0, &mapped),
                     "vkMapMemory (autofocus readback)");
    readbackValues_ = static_cast<const float*>(mapped);
    return FFX_DOF_OK;
}

FfxDofErrorCode ContextVK::createPipelines() {
    for (uint32_t pass = 0; pass < kPassCount; ++pass) {
        const PlannedPass& planned = plan_.passes[pass];
        for (uint32_t v = 0; v < planned.variantCount; ++v) {
            const FfxDofErrorCode supported =
                checkShaderFeatures(backend_.features, *planned.variants[v].blob, kPassNames[pass],
                                    plan_.axes.half != 0, plan_.axes.wave64 != 0);
            if (supported != FFX_DOF_OK) return supported;
        }
        BackendVK::PassLayout layout;
        if (const FfxDofErrorCode status = backend_.passLayout(planned, &layout); status != FFX_DOF_OK) return status;
        setLayouts_[pass] = layout.set;
        pipelineLayouts_[pass] = layout.pipeline;
        for (uint32_t v = 0; v < planned.variantCount; ++v) {
            if (const FfxDofErrorCode status =
                    backend_.passPipeline(kPassNames[pass], *planned.variants[v].blob, layout.pipeline,
                                          plan_.axes.wave64 != 0, &pipelines_[pass][v]);
                status != FFX_DOF_OK) {
                return status;
            }
        }
    }
    return FFX_DOF_OK;
}

FfxDofErrorCode ContextVK::createDescriptors() {
    const Functions& fn = backend_.fn;
    const uint32_t frames = backend_.framesInFlight;
    std::vector<VkDescriptorPoolSize> sizes;
    for (const SlotClass& slotClass : kSlotClasses) {
        uint32_t count = 0;
        for (const PlannedPass& pass : plan_.passes) count += bitCount(pass.*slotClass.slots);
        if (count) sizes.push_back({slotClass.type, count * frames});
    }
    auto poolInfo = makeInfo<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    poolInfo.maxSets = frames * kPassCount;
    poolInfo.poolSizeCount = uint32_t(sizes.size());
    poolInfo.pPoolSizes = sizes.data();
    FFX_DOF_VK_CHECK(fn.vkCreateDescriptorPool(backend_.device, &poolInfo, backend_.allocator, &descriptorPool_),
                     "vkCreateDescriptorPool");
    sets_.resize(frames);
    engineDescriptors_.resize(frames);
    for (uint32_t slot = 0; slot < frames; ++slot) {
        auto allocateInfo = makeInfo<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
        allocateInfo.descriptorPool = descriptorPool_;
        allocateInfo.descriptorSetCount = kPassCount;
        allocateInfo.pSetLayouts = setLayouts_.data();
        FFX_DOF_VK_CHECK(fn.vkAllocateDescriptorSets(backend_.device, &allocateInfo, sets_[slot].data()),
                         "vkAllocateDescriptorSets");
    }
    writeInternalDescriptors();
    return FFX_DOF_OK;
}

VkImageView ContextVK::internalView(const SlotTarget& target, bool storage) const {
    const InternalImage& image = images_[internalImageIndex(target.resource)];
    return storage ? image.level[target.firstMip] : image.allLevels;
}

void ContextVK::writeInternalDescriptors() {
    // Every binding of an internal resource, in every ring slot: they never change. The engine's
    // images are written by the dispatches that see them (updateEngineDescriptors).
    std::vector<VkDescriptorImageInfo> imageInfos;
    std::vector<VkWriteDescriptorSet> writes;
    imageInfos.reserve(sets_.size() * kPassCount * (kSampledSlotCount + kStorageImageSlotCount));
    std::array<VkDescriptorBufferInfo, kStorageBufferSlotCount> bufferInfos{};
    for (uint32_t slot = 0; slot < kStorageBufferSlotCount; ++slot)
        bufferInfos[slot] = {buffers_[slot].buffer, 0, buffers_[slot].bytes};
    for (const auto& ringSlot : sets_) {
        for (uint32_t pass = 0; pass < kPassCount; ++pass) {
            const PlannedPass& planned = plan_.passes[pass];
            for (const SlotClass& slotClass : kSlotClasses) {
                const uint32_t slots = planned.*slotClass.slots;
                for (uint32_t slot = 0; slot < 32; ++slot) {
                    if (!(slots & (1u << slot))) continue;
                    const bool storageImage = slotClass.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
                    const SlotTarget& target = slotClass.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE
                                                   ? plan_.sampledSlots[slot]
                                               : storageImage ? plan_.storageImageSlots[slot]
                                                              : plan_.storageBufferSlots[slot];
                    const bool buffer = slotClass.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                    if (!isInternalImage(target.resource) && !buffer) continue;
                    auto write = makeInfo<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
                    write.dstSet = ringSlot[pass];
                    write.dstBinding = slotClass.base + slot;
                    write.descriptorCount = 1;
                    write.descriptorType = slotClass.type;
                    if (buffer) {
                        write.pBufferInfo = &bufferInfos[slot];
                    } else {
                        imageInfos.push_back(
                            {VK_NULL_HANDLE, internalView(target, storageImage), VK_IMAGE_LAYOUT_GENERAL});
                        write.pImageInfo = &imageInfos.back();
                    }
                    writes.push_back(write);
                }
            }
        }
    }
    backend_.fn.vkUpdateDescriptorSets(backend_.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace ffxdof::vk
