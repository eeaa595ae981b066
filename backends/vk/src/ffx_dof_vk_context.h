// A Vulkan context: the internal images and buffers of its plan, descriptor sets per frame in flight,
// the cache of engine-image views, and the recording of a dispatch. Its pipelines and their layouts
// are the backend's (BackendVK::passPipeline), kept for the contexts made after it.
#pragma once

#include "ffx_dof_readback_ring.h"
#include "ffx_dof_vk_backend.h"
#include "ffx_dof_vk_engine_images.h"

#include <array>
#include <vector>

namespace ffxdof::vk {

class ContextVK final : public BackendContext {
public:
    ContextVK(BackendVK& backend, const ContextPlan& plan)
        : backend_(backend), plan_(plan), readbackRing_(backend.framesInFlight), formats_(backend), views_(backend) {}
    ~ContextVK() override;

    FfxDofErrorCode create();
    FfxDofErrorCode dispatch(const DispatchPlan& dispatch) override;
    FfxDofMemoryUsage memoryUsage() const override { return memoryUsage_; }
    FfxDofErrorCode autofocusDistance(uint32_t dispatchesAgo, float* distance) const override;

    void setTimestampQueries(VkQueryPool pool, uint32_t firstQuery) {
        queryPool_ = pool;
        firstQuery_ = firstQuery;
    }
    // The engine is about to destroy `image`: forget its views (ffxDofContextReleaseImageVK).
    void releaseImage(VkImage image);
    size_t cachedViewCount() const { return views_.size(); }

private:
    struct InternalImage {
        VkImage image = VK_NULL_HANDLE;
        VkImageView allLevels = VK_NULL_HANDLE;
        std::array<VkImageView, kMipCount> level{};
    };
    // The engine views a ring slot's descriptor sets hold (VK_NULL_HANDLE: not written yet).
    struct EngineDescriptors {
        VkImageView color = VK_NULL_HANDLE, depth = VK_NULL_HANDLE, output = VK_NULL_HANDLE;
        VkImageLayout colorLayout = VK_IMAGE_LAYOUT_UNDEFINED, depthLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    };

    // Creation (ffx_dof_vk_context.cpp).
    FfxDofErrorCode createImages();
    // GLOBALS, TILE_LIST_ARGS, TILE_LISTS and HIGHLIGHTS, by storage buffer slot.
    FfxDofErrorCode createBuffers();
    FfxDofErrorCode createReadback();
    // Finds (or has the backend make) the layouts and pipelines of the plan's passes.
    FfxDofErrorCode createPipelines();
    FfxDofErrorCode createDescriptors();
    void writeInternalDescriptors();
    VkImageView internalView(const SlotTarget& target, bool storage) const;

    // Recording (ffx_dof_vk_record.cpp).
    FfxDofErrorCode updateEngineDescriptors(uint32_t ringSlot, const EngineImages& images, uint64_t dispatchIndex);
    void forgetViews(const std::vector<VkImageView>& destroyed);
    void recordInternalBarrier(VkCommandBuffer commandBuffer) const;
    void recordEngineBarriers(VkCommandBuffer commandBuffer, const EngineImages& images, bool toEffect,
                              bool outputIsColor) const;
    void recordFocusReadback(VkCommandBuffer commandBuffer, uint32_t slot) const;

    BackendVK& backend_;
    const ContextPlan& plan_;
    std::array<InternalImage, kInternalImageCount> images_{};
    VkDeviceMemory imageMemory_ = VK_NULL_HANDLE;
    struct InternalBuffer {
        VkBuffer buffer = VK_NULL_HANDLE;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        VkDeviceSize bytes = 0;
    };
    std::array<InternalBuffer, kStorageBufferSlotCount> buffers_{};  // [FFX_DOF_UAV_BUFFER_*]
    VkBuffer globals() const { return buffers_[FFX_DOF_UAV_BUFFER_GLOBALS].buffer; }
    VkBuffer tileListArgs() const { return buffers_[FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS].buffer; }
    FfxDofMemoryUsage memoryUsage_{};
    // The focus distances of the last autofocus dispatches, copied from GLOBALS for
    // ffxDofContextGetAutofocusDistance: host-visible, mapped, one float per slot of the ring.
    AutofocusReadbackRing readbackRing_;
    VkBuffer readback_ = VK_NULL_HANDLE;
    VkDeviceMemory readbackMemory_ = VK_NULL_HANDLE;
    const float* readbackValues_ = nullptr;

    // The backend's, not destroyed with the context.
    std::array<VkDescriptorSetLayout, kPassCount> setLayouts_{};
    std::array<VkPipelineLayout, kPassCount> pipelineLayouts_{};
    std::array<std::array<VkPipeline, kMaxPassVariants>, kPassCount> pipelines_{};  // [pass][variant]

    VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
    std::vector<std::array<VkDescriptorSet, kPassCount>> sets_;  // [ring slot][pass]
    std::vector<EngineDescriptors> engineDescriptors_;           // [ring slot]
    FormatSupport formats_;
    EngineViewCache views_;
    uint64_t dispatchCount_ = 0;

    VkQueryPool queryPool_ = VK_NULL_HANDLE;
    uint32_t firstQuery_ = 0;
};

}  // namespace ffxdof::vk
