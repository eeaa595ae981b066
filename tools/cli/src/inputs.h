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
};

// Linear depth (metres) -> device z of projectionForLinearDepth(nearest depth). Checks the values first.
EffectDepth linearToEffectDepth(const io::ImageR& depth, const std::string& path);

}  // namespace ffxdof::cli
