// Recording one dispatch: the engine images' descriptors (only when they changed), the barriers the
// plan's read and write sets call for, and the passes.
#include "ffx_dof_vk_context.h"

#include <algorithm>

namespace ffxdof::vk {
namespace {

constexpr VkAccessFlags kShaderAccess = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;

}  // namespace

void ContextVK::forgetViews(const std::vector<VkImageView>& destroyed) {
    for (EngineDescriptors& slot : engineDescriptors_) {
        for (VkImageView* view : {&slot.color, &slot.depth, &slot.output}) {
            if (std::find(destroyed.begin(), destroyed.end(), *view) != destroyed.end()) *view = VK_NULL_HANDLE;
        }
    }
}

void ContextVK::releaseImage(VkImage image) {
    std::vector<VkImageView> destroyed;
    views_.release(image, &destroyed);
    forgetViews(destroyed);
}

FfxDofErrorCode ContextVK::updateEngineDescriptors(uint32_t ringSlot, const EngineImages& images,
                                                   uint64_t dispatchIndex) {
    EngineDescriptors wanted;
    if (const FfxDofErrorCode status = views_.view(images.color, dispatchIndex, &wanted.color); status != FFX_DOF_OK)
        return status;
    if (const FfxDofErrorCode status = views_.view(images.depth, dispatchIndex, &wanted.depth); status != FFX_DOF_OK)
        return status;
    if (const FfxDofErrorCode status = views_.view(images.output, dispatchIndex, &wanted.output); status != FFX_DOF_OK)
        return status;
    wanted.colorLayout = images.color.during;
    wanted.depthLayout = images.depth.during;
    std::vector<VkImageView> destroyed;
    views_.trim(dispatchIndex, &destroyed);
    forgetViews(destroyed);

    EngineDescriptors& held = engineDescriptors_[ringSlot];
    const bool colorChanged = held.color != wanted.color || held.colorLayout != wanted.colorLayout;
    const bool depthChanged = held.depth != wanted.depth || held.depthLayout != wanted.depthLayout;
    const bool outputChanged = held.output != wanted.output;
    if (!colorChanged && !depthChanged && !outputChanged) return FFX_DOF_OK;

    std::array<VkDescriptorImageInfo, kPassCount * 3> imageInfos{};
    std::array<VkWriteDescriptorSet, kPassCount * 3> writes{};
    uint32_t writeCount = 0;
    const auto write = [&](uint32_t pass, uint32_t binding, VkDescriptorType type, VkImageView view,
                           VkImageLayout layout) {
        imageInfos[writeCount] = {VK_NULL_HANDLE, view, layout};
        VkWriteDescriptorSet& w = writes[writeCount];
        w = makeInfo<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        w.dstSet = sets_[ringSlot][pass];
        w.dstBinding = binding;
        w.descriptorCount = 1;
        w.descriptorType = type;
        w.pImageInfo = &imageInfos[writeCount];
        ++writeCount;
    };
    for (uint32_t pass = 0; pass < kPassCount; ++pass) {
        const PlannedPass& planned = plan_.passes[pass];
        if (colorChanged && (planned.sampledSlots & (1u << FFX_DOF_SRV_INPUT_COLOR))) {
            write(pass, FFX_DOF_SRV_BASE + FFX_DOF_SRV_INPUT_COLOR, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, wanted.color,
                  wanted.colorLayout);
        }
        if (depthChanged && (planned.sampledSlots & (1u << FFX_DOF_SRV_INPUT_DEPTH))) {
            write(pass, FFX_DOF_SRV_BASE + FFX_DOF_SRV_INPUT_DEPTH, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, wanted.depth,
                  wanted.depthLayout);
        }
        if (outputChanged && (planned.storageSlots & (1u << FFX_DOF_UAV_OUTPUT))) {
            write(pass, FFX_DOF_UAV_IMAGE_BASE + FFX_DOF_UAV_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, wanted.output,
                  VK_IMAGE_LAYOUT_GENERAL);
        }
    }
    backend_.fn.vkUpdateDescriptorSets(backend_.device, writeCount, writes.data(), 0, nullptr);
    held = wanted;
    return FFX_DOF_OK;
}

void ContextVK::recordInternalBarrier(VkCommandBuffer commandBuffer) const {
    const Functions& fn = backend_.fn;
    if (dispatchCount_ == 0) {
        // First use: the internal images from UNDEFINED into GENERAL, GLOBALS zeroed.
        std::array<VkImageMemoryBarrier, kInternalImageCount> toGeneral{};
        for (uint32_t i = 0; i < kInternalImageCount; ++i) {
            auto& barrier = toGeneral[i];
            barrier = makeInfo<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
            barrier.dstAccessMask = kShaderAccess;
            barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
            barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
            barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.image = images_[i].image;
            barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, plan_.images[i].mipLevels, 0, 1};
        }
        fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                0, 0, nullptr, 0, nullptr, uint32_t(toGeneral.size()), toGeneral.data());
        fn.vkCmdFillBuffer(commandBuffer, globals(), 0, kGlobalsBufferBytes, 0);
        auto zeroed = makeInfo<VkBufferMemoryBarrier>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER);
        zeroed.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        zeroed.dstAccessMask = kShaderAccess;
        zeroed.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        zeroed.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        zeroed.buffer = globals();
        zeroed.size = VK_WHOLE_SIZE;
        fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
                                0, nullptr, 1, &zeroed, 0, nullptr);
    } else {
        // The previous dispatch's writes of the internal resources (and its autofocus readback's read
        // of GLOBALS, and its composite's indirect read of TILE_LIST_ARGS) before this one's accesses.
        auto previous = makeInfo<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        previous.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        previous.dstAccessMask = kShaderAccess;
        fn.vkCmdPipelineBarrier(
            commandBuffer,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &previous, 0, nullptr, 0, nullptr);
    }
}

void ContextVK::recordEngineBarriers(VkCommandBuffer commandBuffer, const EngineImages& images, bool toEffect,
                                     bool outputIsColor) const {
    // The engine's accesses before and after are unknown, so the engine side of each barrier is
    // ALL_COMMANDS with all memory accesses; the effect side is exactly its compute accesses.
    std::array<VkImageMemoryBarrier, 3> barriers{};
    uint32_t count = 0;
    for (const EngineImageUse* use : {&images.color, &images.depth, &images.output}) {
        if (use == &images.output && outputIsColor) continue;  // the color barrier covers it
        VkImageMemoryBarrier& barrier = barriers[count++];
        barrier = makeInfo<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
        barrier.srcAccessMask = toEffect ? VkAccessFlags(VK_ACCESS_MEMORY_WRITE_BIT) : use->access;
        barrier.dstAccessMask =
            toEffect ? use->access : VkAccessFlags(VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
        barrier.oldLayout = toEffect ? use->declared : use->during;
        barrier.newLayout = toEffect ? use->during : use->declared;
        barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = use->image;
        barrier.subresourceRange = {use->barrierAspects, 0, 1, 0, 1};
    }
    const VkPipelineStageFlags engineStages = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
    const VkPipelineStageFlags effectStages = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    backend_.fn.vkCmdPipelineBarrier(commandBuffer, toEffect ? engineStages : effectStages,
                                     toEffect ? effectStages : engineStages, 0, 0, nullptr, 0, nullptr, count,
                                     barriers.data());
}

FfxDofErrorCode ContextVK::dispatch(const DispatchPlan& dispatch) {
    EngineImages images;
    if (const FfxDofErrorCode invalid = checkEngineImages(plan_, dispatch, &formats_, &images); invalid != FFX_DOF_OK)
        return invalid;
    const Functions& fn = backend_.fn;
    const VkCommandBuffer commandBuffer = static_cast<VkCommandBuffer>(dispatch.commandList);

    // This ring slot's previous dispatch was maxFramesInFlight dispatches ago: the GPU is done with it.
    const uint32_t ringSlot = uint32_t(dispatchCount_ % backend_.framesInFlight);
    if (const FfxDofErrorCode status = updateEngineDescriptors(ringSlot, images, dispatchCount_); status != FFX_DOF_OK)
        return status;

    const bool timed = queryPool_ != VK_NULL_HANDLE;
    if (timed) fn.vkCmdResetQueryPool(commandBuffer, queryPool_, firstQuery_, FFX_DOF_VK_TIMESTAMP_COUNT);
    recordInternalBarrier(commandBuffer);
    recordEngineBarriers(commandBuffer, images, true, dispatch.outputIsColor);

    FfxDofConstants constants = dispatch.constants;
    if (images.encodeSrgb) constants.outputFlags |= FFX_DOF_OUTPUT_FLAG_ENCODE_SRGB;
    if (timed) fn.vkCmdWriteTimestamp(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, queryPool_, firstQuery_);

    // A barrier before a pass that reads or writes what an earlier pass wrote, or writes what an
    // earlier pass read, since the last barrier (the plan's sets, from the shaders' reflection).
    ResourceSet writtenSinceBarrier = 0;
    ResourceSet readSinceBarrier = 0;
    // Every barrier also covers the indirect stage where a pass is dispatched indirectly: dilate writes
    // the composite's dispatch arguments, and the barrier before the blur is the one after dilate.
    const bool indirect = plan_.indirect != 0;
    for (uint32_t pass = 0; pass < kPassCount; ++pass) {
        if (!dispatch.runs[pass]) {
            // Not asked for (autofocus without pAutofocus): its timestamp still comes, so indices stay.
            if (timed) {
                fn.vkCmdWriteTimestamp(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, queryPool_,
                                       firstQuery_ + 1 + pass);
            }
            continue;
        }
        const PlannedPass& planned = plan_.passes[pass];
        const ResourceSet touched = planned.reads | planned.writes | planned.indirect;
        if ((touched & writtenSinceBarrier) || (planned.writes & readSinceBarrier)) {
            auto between = makeInfo<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
            between.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
            between.dstAccessMask =
                kShaderAccess | (indirect ? VkAccessFlags(VK_ACCESS_INDIRECT_COMMAND_READ_BIT) : 0u);
            const VkPipelineStageFlags dstStages =
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                (indirect ? VkPipelineStageFlags(VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT) : 0u);
            fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, dstStages, 0, 1, &between, 0,
                                    nullptr, 0, nullptr);
            writtenSinceBarrier = 0;
            readSinceBarrier = 0;
        }
        writtenSinceBarrier |= planned.writes;
        readSinceBarrier |= planned.reads | planned.indirect;

        fn.vkCmdBindDescriptorSets(commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayouts_[pass], 0, 1,
                                   &sets_[ringSlot][pass], 0, nullptr);
        fn.vkCmdPushConstants(commandBuffer, pipelineLayouts_[pass], VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                              &constants);
        if (planned.perTileList) {
            // Every variant of the dispatch's group, over the tiles dilate listed for it (ffx_dof_resources.h,
            // TILE_LISTS).
            for (uint32_t listed = 0; listed < planned.tileListVariants; ++listed) {
                const uint32_t v = dispatch.variants[pass] + listed;
                if (listed > 0 && dispatch.outputIsColor && (planned.writes & resourceBit(Resource::Output)) != 0) {
                    // In place a composite workgroup reads the input only within its own tile, which no other
                    // workgroup writes (ffx_dof_composite.h), but synchronization validation follows whole
                    // images: the earlier lists' writes before the next list's reads.
                    auto written = makeInfo<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
                    written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
                    written.dstAccessMask = kShaderAccess;
                    fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &written, 0, nullptr, 0,
                                            nullptr);
                }
                fn.vkCmdBindPipeline(commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[pass][v]);
                fn.vkCmdDispatchIndirect(commandBuffer, tileListArgs(),
                                         tileListArgsOffset(planned.variants[v].tileList));
            }
        } else {
            fn.vkCmdBindPipeline(commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE,
                                 pipelines_[pass][dispatch.variants[pass]]);
            fn.vkCmdDispatch(commandBuffer, planned.groups.x, planned.groups.y, planned.groups.z);
            if (pass == uint32_t(kColorRangeRerunPass)) {
                // Its second run, over no workgroup unless the first found a colour channel above the range limit
                // (ffx_dof_downsample_color.h): after the first's writes, its arguments among them, and with the
                // flag that has it read the frame's peak.
                auto armed = makeInfo<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
                armed.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
                armed.dstAccessMask = kShaderAccess | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
                fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0,
                                        1, &armed, 0, nullptr, 0, nullptr);
                FfxDofConstants rerun = constants;
                rerun.outputFlags |= FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN;
                fn.vkCmdPushConstants(commandBuffer, pipelineLayouts_[pass], VK_SHADER_STAGE_COMPUTE_BIT, 0,
                                      sizeof(rerun), &rerun);
                fn.vkCmdDispatchIndirect(commandBuffer, tileListArgs(), kColorRangeRerunArgsOffset);
                readSinceBarrier |= resourceBit(Resource::TileListArgs);
            }
        }
        if (timed) {
            fn.vkCmdWriteTimestamp(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, queryPool_,
                                   firstQuery_ + 1 + pass);
        }
    }
    recordEngineBarriers(commandBuffer, images, false, dispatch.outputIsColor);
    const bool ranAutofocus = dispatch.runs[uint32_t(Pass::Autofocus)];
    const uint32_t readbackSlot = readbackRing_.record(ranAutofocus);
    if (ranAutofocus) recordFocusReadback(commandBuffer, readbackSlot);
    ++dispatchCount_;
    return FFX_DOF_OK;
}

void ContextVK::recordFocusReadback(VkCommandBuffer commandBuffer, uint32_t slot) const {
    // After every pass: the focus word is final once the autofocus pass ran, and the copy then
    // needs no barrier against the later passes' GLOBALS atomics.
    const Functions& fn = backend_.fn;
    auto written = makeInfo<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    written.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                            &written, 0, nullptr, 0, nullptr);
    const VkBufferCopy region{FFX_DOF_GLOBALS_FOCUS_DISTANCE * sizeof(uint32_t), slot * sizeof(float), sizeof(float)};
    fn.vkCmdCopyBuffer(commandBuffer, globals(), readback_, 1, &region);
    auto toHost = makeInfo<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    fn.vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0,
                            nullptr, 0, nullptr);
}

FfxDofErrorCode ContextVK::autofocusDistance(uint32_t dispatchesAgo, float* distance) const {
    return readbackRing_.read(dispatchesAgo, readbackValues_, distance);
}

}  // namespace ffxdof::vk
