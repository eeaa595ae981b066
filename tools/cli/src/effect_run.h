// What apply, demo and bench share to run the effect through the Vulkan harness (tools/vkrun):
// settings from the command line, device creation, and harness errors turned into CliError(Device).
#pragma once

#include "commands.h"
#include "ffx_dof_imageio.h"
#include "ffx_dof_vkrun.h"

#include <memory>

namespace ffxdof::cli {

// Opens the Vulkan device chosen with --device (with the validation layer for --validate); throws
// CliError(Device) naming the devices there are.
std::unique_ptr<vkrun::Device> openDevice(const EffectOptions& effect);

// The harness settings for one run: 32-bit float color and output (EXR values are kept as they are),
// D32_SFLOAT depth, and the effect options. With autofocus (not null) the effect chooses the focus and
// coc is ignored.
vkrun::RunSettings makeRunSettings(const EffectOptions& effect, const CocParameters& coc, bool reversedDepth,
                                   const FfxDofAutofocus* autofocus = nullptr);

// Runs the effect; harness failures, and with --validate any validation message, become CliError(Device).
vkrun::RunResult runEffectOrThrow(vkrun::Device& device, const vkrun::HostImage& color, const vkrun::HostImage& depth,
                                  const vkrun::RunSettings& settings);

// The same through a session (apply: one backend and one set of images for every frame, a fresh
// context per frame, so a frame's output does not depend on the frames before it). With autofocus,
// *autofocusDistance (when not null) receives the distance it chose.
vkrun::HostImage runEffectOrThrow(vkrun::Device& device, vkrun::EffectSession& session, const vkrun::HostImage& color,
                                  const vkrun::HostImage& depth, const vkrun::RunSettings& settings,
                                  float* autofocusDistance = nullptr);

// Conversions between the image library's and the harness's host images.
vkrun::HostImage toHostImage(const io::ImageRGBA& image);
vkrun::HostImage toHostImage(uint32_t width, uint32_t height, const std::vector<float>& singleChannel);
io::ImageRGBA toImageRGBA(const vkrun::HostImage& image);

// Writes an image chosen by extension (EXR pixels of exrType); io errors become CliError(OutputWrite).
void writeOutput(const std::string& path, const io::ImageRGBA& image,
                 io::ExrPixelType exrType = io::ExrPixelType::Half);

}  // namespace ffxdof::cli
