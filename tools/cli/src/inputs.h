// Checks of the images given to `ffx-dof apply` and the conversion of depth to what the effect reads.
// Every failed check throws CliError(InvalidValue) with one line naming the file, how many values are
// wrong and where the first one is.
#pragma once

#include "ffx_dof_imageio.h"
#include "lens.h"

#include <string>
#include <vector>

namespace ffxdof::cli {

enum class DepthKind { Linear, Device };

// Color and depth must have the same, non-zero size within the effect's limits.
void checkResolutions(const io::ImageRGBA& color, const std::string& colorPath, const io::ImageR& depth,
                      const std::string& depthPath);

// Every color value must be finite (NaN or infinity would spread over the whole kernel).
void checkColorFinite(const io::ImageRGBA& color, const std::string& path);

// Linear depth: every value finite and greater than 0. Returns the smallest value.
double checkLinearDepth(const io::ImageR& depth, const std::string& path);

// Device depth: every value finite and within [0, 1].
void checkDeviceDepth(const io::ImageR& depth, const std::string& path);

// Depth ready for the effect: device z values and the projection they follow.
struct EffectDepth {
    std::vector<float> deviceDepth;  // width * height, rows top to bottom
    DepthProjection projection;
    // Where the projection comes from, for messages: the nearest depth pixel for linear depth.
    std::string projectionOrigin;
};

// The EXR pixel type for an image, so the file holds what was computed: "half" and "float" as asked,
// "auto" half unless a value exceeds half's largest finite value (65504), then float. Throws
// CliError(InvalidValue) when "half" is asked for values half cannot hold, and CliError(Device) when
// the image holds a non-finite value (the effect must never produce one; nothing is written then).
io::ExrPixelType chooseExrPixelType(const std::string& outType, const io::ImageRGBA& image, const std::string& path);

// Linear depth (metres) -> device z of projectionForLinearDepth(nearest depth). Checks the values first.
EffectDepth linearToEffectDepth(const io::ImageR& depth, const std::string& path);

}  // namespace ffxdof::cli
