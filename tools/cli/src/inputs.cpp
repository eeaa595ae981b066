#include "inputs.h"

#include "cli_error.h"
#include "commands.h"
#include "ffx_dof.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>

namespace ffxdof::cli {
namespace {

// Counts the values that fail a check and remembers the first, to report both in one line.
struct BadValues {
    size_t count = 0;
    size_t firstIndex = 0;
    float firstValue = 0.0f;
};

template <typename IsBad>
BadValues findBad(const std::vector<float>& values, size_t valuesPerPixel, IsBad isBad) {
    BadValues bad;
    for (size_t i = 0; i < values.size(); ++i) {
        if (isBad(values[i])) {
            if (bad.count == 0) {
                bad.firstIndex = i / valuesPerPixel;
                bad.firstValue = values[i];
            }
            ++bad.count;
        }
    }
    return bad;
}

void throwIfBad(const BadValues& bad, uint32_t width, const std::string& path, const std::string& what,
                const std::string& hint = "") {
    if (bad.count == 0) {
        return;
    }
    std::ostringstream message;
    message << path << ": " << bad.count << (bad.count == 1 ? " value is " : " values are ") << what
            << " (first at x=" << bad.firstIndex % width << ", y=" << bad.firstIndex / width << ": " << bad.firstValue
            << ")" << (hint.empty() ? "" : "; ") << hint;
    throw CliError(ExitCode::InvalidValue, message.str());
}

}  // namespace

void checkResolutions(const io::ImageRGBA& color, const std::string& colorPath, const io::ImageR& depth,
                      const std::string& depthPath) {
    std::ostringstream message;
    if (color.width != depth.width || color.height != depth.height) {
        message << "color and depth differ in size: " << colorPath << " is " << color.width << "x" << color.height
                << ", " << depthPath << " is " << depth.width << "x" << depth.height;
    } else if (color.width == 0 || color.height == 0 || color.width > FFX_DOF_MAX_RESOLUTION ||
               color.height > FFX_DOF_MAX_RESOLUTION) {
        message << colorPath << " is " << color.width << "x" << color.height << "; width and height must be 1 to "
                << FFX_DOF_MAX_RESOLUTION;
    } else {
        return;
    }
    throw CliError(ExitCode::InvalidValue, message.str());
}

void checkColorFinite(const io::ImageRGBA& color, const std::string& path) {
    throwIfBad(findBad(color.pixels, 4, [](float v) { return !std::isfinite(v); }), color.width, path,
               "not finite in the color");
}

double checkLinearDepth(const io::ImageR& depth, const std::string& path) {
    throwIfBad(findBad(depth.pixels, 1, [](float v) { return !std::isfinite(v); }), depth.width, path,
               "not finite in the depth");
    throwIfBad(findBad(depth.pixels, 1, [](float v) { return v <= 0.0f; }), depth.width, path,
               "0 or negative in the linear depth",
               "linear depth is the view distance in metres; use --depth-kind device for z-buffers");
    double nearest = INFINITY;
    for (float z : depth.pixels) {
        nearest = std::fmin(nearest, double(z));
    }
    return nearest;
}

void checkDeviceDepth(const io::ImageR& depth, const std::string& path) {
    throwIfBad(findBad(depth.pixels, 1, [](float v) { return !std::isfinite(v); }), depth.width, path,
               "not finite in the depth");
    throwIfBad(findBad(depth.pixels, 1, [](float v) { return v < 0.0f || v > 1.0f; }), depth.width, path,
               "outside [0, 1] in the device depth", "use --depth-kind linear for distances in metres");
}

EffectDepth linearToEffectDepth(const io::ImageR& depth, const std::string& path) {
    EffectDepth result;
    const double nearest = checkLinearDepth(depth, path);
    result.projection = projectionForLinearDepth(nearest);
    const size_t nearestIndex =
        size_t(std::find(depth.pixels.begin(), depth.pixels.end(), float(nearest)) - depth.pixels.begin());
    std::ostringstream origin;
    origin << "the nearest depth of " << path << " (" << nearest << " m at x=" << nearestIndex % depth.width
           << ", y=" << nearestIndex / depth.width << ")";
    result.projectionOrigin = origin.str();
    result.deviceDepth.resize(depth.pixels.size());
    for (size_t i = 0; i < depth.pixels.size(); ++i) {
        result.deviceDepth[i] = float(result.projection.deviceDepth(depth.pixels[i]));
    }
    return result;
}

io::ExrPixelType chooseExrPixelType(const std::string& outType, const io::ImageRGBA& image, const std::string& path) {
    constexpr float kLargestHalf = 65504.0f;
    float largest = 0.0f;
    size_t nonFinite = 0;
    for (float value : image.pixels) {
        if (!std::isfinite(value)) {
            ++nonFinite;
        } else {
            largest = std::max(largest, std::fabs(value));
        }
    }
    if (nonFinite > 0) {
        throw CliError(ExitCode::Device, "the effect produced " + std::to_string(nonFinite) +
                                             " non-finite values; nothing was written to " + path);
    }
    if (outType == "float") return io::ExrPixelType::Float;
    if (largest <= kLargestHalf) return io::ExrPixelType::Half;
    if (outType == "half") {
        std::ostringstream message;
        message << "--out-type half cannot hold the largest value of " << path << ", " << largest
                << " (half's largest is 65504); use --out-type float or auto";
        throw CliError(ExitCode::InvalidValue, message.str());
    }
    return io::ExrPixelType::Float;
}

double effectiveCocLimit(const EffectOptions& options, double largestRadius, uint32_t height) {
    if (!options.cocLimitFollowsImage || height == 0) return options.cocLimit;
    // Just above the largest radius, so the SDK's clamp never bites; float rounding of the factor and of
    // the SDK's limit (factor * height * 0.5) is far below the margin.
    const double factor = largestRadius / (0.5 * double(height)) * 1.001 + 1e-6;
    return std::min(factor, kLargestAutoCocLimit);
}

void checkEffectOptions(const EffectOptions& options) {
    if (options.quality < 1 || options.quality > FFX_DOF_MAX_QUALITY) {
        throw CliError(ExitCode::InvalidValue, "--quality must be 1 to " + std::to_string(FFX_DOF_MAX_QUALITY) +
                                                   ", got " + std::to_string(options.quality));
    }
    // The SDK takes a float: a double beyond its range would arrive as infinity.
    if (!std::isfinite(options.cocLimit) || options.cocLimit < 0.0 || options.cocLimit > double(FLT_MAX)) {
        std::ostringstream message;
        message << "--coc-limit must be a finite number, 0 or more (at most 3.4e38), got " << options.cocLimit;
        throw CliError(ExitCode::InvalidValue, message.str());
    }
    const ApertureOptions& a = options.aperture;
    if (a.blades != 0 && (a.blades < 3 || a.blades > FFX_DOF_MAX_APERTURE_BLADES)) {
        throw CliError(ExitCode::InvalidValue, "--blades must be 0 (round) or 3 to " +
                                                   std::to_string(FFX_DOF_MAX_APERTURE_BLADES) + ", got " +
                                                   std::to_string(a.blades));
    }
    const struct {
        const char* option;
        double value, lowest, highest;
    } ranges[] = {{"--blade-rotation", a.bladeRotationDegrees, -1e6, 1e6},
                  {"--roundness", a.roundness, 0.0, 1.0},
                  {"--anamorphic", a.anamorphicRatio, FFX_DOF_MIN_ANAMORPHIC_RATIO, FFX_DOF_MAX_ANAMORPHIC_RATIO},
                  {"--cat-eye", a.catEye, 0.0, 1.0}};
    for (const auto& range : ranges) {
        if (!std::isfinite(range.value) || range.value < range.lowest || range.value > range.highest) {
            std::ostringstream message;
            message << range.option << " must be " << range.lowest << " to " << range.highest << ", got "
                    << range.value;
            throw CliError(ExitCode::InvalidValue, message.str());
        }
    }
    if (options.device < -1) {
        throw CliError(ExitCode::InvalidValue,
                       "--device must be a device index, 0 or more, got " + std::to_string(options.device));
    }
}

FfxDofAperture toDofAperture(const ApertureOptions& aperture) {
    FfxDofAperture result{};
    result.bladeCount = aperture.blades;
    result.bladeRotation = float(aperture.bladeRotationDegrees * (3.14159265358979323846 / 180.0));
    result.roundness = float(aperture.roundness);
    result.anamorphicRatio = float(aperture.anamorphicRatio);
    result.catEye = float(aperture.catEye);
    return result;
}

}  // namespace ffxdof::cli
