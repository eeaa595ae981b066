// EffectSession: the effect over a sequence of frames with the device's backend and reused engine images.
#include "vkrun_internal.h"

#include <memory>

namespace ffxdof::vkrun {
namespace {

struct Context {
    FfxDofContext handle = nullptr;
    ~Context() { ffxDofContextDestroy(&handle); }
};

}  // namespace

struct EffectSession::Impl {
    Device& device;
    std::unique_ptr<GpuImage> color, depth, output;

    explicit Impl(Device& d) : device(d) {}

    static bool matches(const std::unique_ptr<GpuImage>& image, uint32_t width, uint32_t height, VkFormat format) {
        return image && image->width() == width && image->height() == height && image->format() == format;
    }
};

EffectSession::EffectSession(Device& device) : impl_(std::make_unique<Impl>(device)) {}
EffectSession::~EffectSession() = default;

HostImage EffectSession::run(const HostImage& color, const HostImage& depth, const RunSettings& settings,
                             float* autofocusDistance) {
    if (color.channels != 4 || color.pixels.size() != size_t(color.width) * color.height * 4) {
        throw Error("the color image must be RGBA with width * height * 4 floats");
    }
    if (depth.channels != 1 || depth.width != color.width || depth.height != color.height ||
        depth.pixels.size() != size_t(depth.width) * depth.height) {
        throw Error("the depth image must have one channel and the color's size");
    }
    if (!isSupportedColorFormat(settings.colorFormat) || !isSupportedColorFormat(settings.outputFormat) ||
        !isSupportedDepthFormat(settings.depthFormat) || settings.outputFormat == VK_FORMAT_R8G8B8A8_SRGB) {
        throw Error("EffectSession: unsupported color, output or depth format");
    }
    Impl& s = *impl_;
    const uint32_t width = color.width, height = color.height;
    const VkImageUsageFlags transfers = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (!Impl::matches(s.color, width, height, settings.colorFormat)) {
        s.color = std::make_unique<GpuImage>(s.device, width, height, settings.colorFormat,
                                             VK_IMAGE_USAGE_SAMPLED_BIT | transfers);
    }
    if (!Impl::matches(s.depth, width, height, settings.depthFormat)) {
        s.depth = std::make_unique<GpuImage>(
            s.device, width, height, settings.depthFormat,
            VK_IMAGE_USAGE_SAMPLED_BIT | transfers |
                (isDepthAspectFormat(settings.depthFormat) ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : 0));
    }
    if (!Impl::matches(s.output, width, height, settings.outputFormat)) {
        s.output = std::make_unique<GpuImage>(s.device, width, height, settings.outputFormat,
                                              VK_IMAGE_USAGE_STORAGE_BIT | transfers);
    }
    const VkImageLayout colorLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const VkImageLayout depthLayout = isDepthAspectFormat(settings.depthFormat)
                                          ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                                          : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const VkImageLayout outputLayout = VK_IMAGE_LAYOUT_GENERAL;
    s.color->upload(color, colorLayout);
    s.depth->upload(depth, depthLayout);
    const uint32_t contextFlags = contextFlagsFor(settings);
    if (contextFlags & FFX_DOF_OUTPUT_PRE_INIT) {
        s.output->upload(color, outputLayout);
    } else {
        // Only its layout matters: every pixel is written.
        s.device.submitAndWait([&](VkCommandBuffer commandBuffer) {
            auto barrier = makeInfo<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
            barrier.srcAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
            barrier.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
            barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
            barrier.newLayout = outputLayout;
            barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.image = s.output->image();
            barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0, nullptr, 1, &barrier);
        });
    }

    // A fresh context per frame: its first dispatch uses frame index 0 (see the class comment).
    Context context;
    const FfxDofContextDescription description = contextDescriptionFor(s.device, settings, width, height);
    checkDof(ffxDofContextCreate(&context.handle, &description), "ffxDofContextCreate");

    FfxDofDispatchDescription dispatch{};
    dispatch.color = ffxDofGetResourceVK(s.color->image(), settings.colorFormat, width, height, colorLayout, 0);
    dispatch.depth = ffxDofGetResourceVK(s.depth->image(), settings.depthFormat, width, height, depthLayout, 0);
    dispatch.output = ffxDofGetResourceVK(s.output->image(), settings.outputFormat, width, height, outputLayout, 0);
    dispatch.cocScale = settings.cocScale;
    dispatch.cocBias = settings.cocBias;
    dispatch.pAutofocus = settings.useAutofocus ? &settings.autofocus : nullptr;
    dispatch.pAperture = apertureOrNull(settings);
    VkCommandBuffer commandBuffer = s.device.beginCommands();
    dispatch.commandList = ffxDofGetCommandListVK(commandBuffer);
    const FfxDofErrorCode dispatched = ffxDofContextDispatch(&context.handle, &dispatch);
    s.device.endSubmitAndWait(commandBuffer);  // also after a failed dispatch, to free the command buffer
    checkDof(dispatched, "ffxDofContextDispatch");
    if (settings.useAutofocus && autofocusDistance != nullptr) {
        checkDof(ffxDofContextGetAutofocusDistance(&context.handle, 0, autofocusDistance),
                 "ffxDofContextGetAutofocusDistance");
    }
    return s.output->download(outputLayout);
}

}  // namespace ffxdof::vkrun
