// Internals of ffx_dof_vkrun shared by its source files and its tests.
#pragma once

#include "ffx_dof_vk_util.h"  // makeInfo, formatName, isDepthAspectFormat: shared with the backend
#include "ffx_dof_vkrun.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ffxdof::vkrun {

using vk::isDepthAspectFormat;
using vk::makeInfo;

// Throws Error("<what> failed: VK_ERROR_...") unless result is VK_SUCCESS.
void check(VkResult result, const char* what);
// Throws Error("<call>: <error string> (<last error message>)", code) unless code is FFX_DOF_OK.
void checkDof(FfxDofErrorCode code, const char* call);

// Bytes of one texel as copied between a buffer and the image (D24_UNORM_S8_UINT: X8_D24, 4 bytes).
uint32_t bytesPerTexel(VkFormat format);
// Host floats to texels (color: 4 channels; depth: 1) and color texels back to RGBA floats.
std::vector<uint8_t> encodeTexels(const HostImage& image, VkFormat format);
HostImage decodeColorTexels(const uint8_t* bytes, uint32_t width, uint32_t height, VkFormat format);

// An image with its own memory, destroyed with the device it was made on.
class GpuImage {
public:
    GpuImage(Device& device, uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
             VkImageCreateFlags flags = 0);
    ~GpuImage();
    GpuImage(const GpuImage&) = delete;
    GpuImage& operator=(const GpuImage&) = delete;

    VkImage image() const { return image_; }
    VkFormat format() const { return format_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    VkImageAspectFlags aspects() const;  // all aspects of the format (depth and stencil for D24S8)

    // Uploads host pixels (converted to the format) and leaves the image in `layout`.
    void upload(const HostImage& pixels, VkImageLayout layout);
    // Reads a color image that is in `layout` back as RGBA floats; the image stays in `layout`.
    HostImage download(VkImageLayout layout);

private:
    Device& device_;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkFormat format_;
    uint32_t width_, height_;
};

// The dispatch's pAperture: NULL for the round aperture, so that the default runs the path engines
// that never heard of apertures take.
inline const FfxDofAperture* apertureOrNull(const RunSettings& settings) {
    const FfxDofAperture& a = settings.aperture;
    const bool round = (a.bladeCount == 0 || a.roundness >= 1.0f) && a.anamorphicRatio == 1.0f && a.catEye == 0.0f;
    return round ? nullptr : &settings.aperture;
}

// The context's flags: RunSettings::contextFlags, with FFX_DOF_ENABLE_APERTURE_SHAPES when the aperture
// is shaped (a harness run is one context and one aperture).
inline uint32_t contextFlagsFor(const RunSettings& settings) {
    return settings.contextFlags | (apertureOrNull(settings) ? uint32_t(FFX_DOF_ENABLE_APERTURE_SHAPES) : 0u) |
           (settings.inPlace ? uint32_t(FFX_DOF_OUTPUT_PRE_INIT) : 0u);
}

// The FfxDofBackendFlagBitsVK of the settings' switches.
inline uint32_t backendFlagsFor(const RunSettings& settings) {
    return (settings.forceFloat32 ? uint32_t(FFX_DOF_VK_DISABLE_FLOAT16) : 0u) |
           (settings.useHlsl ? uint32_t(FFX_DOF_VK_USE_HLSL_SHADERS) : 0u) |
           (settings.disableWave64 ? uint32_t(FFX_DOF_VK_DISABLE_WAVE64) : 0u);
}

// The context description of a harness run at width x height, on the device's shared backend for the settings.
inline FfxDofContextDescription contextDescriptionFor(Device& device, const RunSettings& settings, uint32_t width,
                                                      uint32_t height) {
    FfxDofContextDescription description{};
    description.flags = contextFlagsFor(settings);
    description.quality = settings.quality;
    description.resolution = {width, height};
    description.backendInterface = device.sharedBackend(backendFlagsFor(settings), settings.maxFramesInFlight);
    description.cocLimitFactor = settings.cocLimitFactor;
    return description;
}

}  // namespace ffxdof::vkrun
