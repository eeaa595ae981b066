#include "lens.h"

#include "cli_error.h"
#include "ffx_dof.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace ffxdof::cli {
namespace {

constexpr double kMillimetre = 1e-3;

std::string formatNumber(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

[[noreturn]] void invalid(const std::string& message) { throw CliError(ExitCode::InvalidValue, message); }

void requirePositive(const char* option, double value, const char* unit) {
    if (!std::isfinite(value) || value <= 0.0) {
        invalid(std::string(option) + " must be a finite number" + (*unit ? std::string(" of ") + unit : "") +
                " greater than 0, got " + formatNumber(value));
    }
}

}  // namespace

ThinLens makeThinLens(const LensSettings& settings, bool autofocus) {
    if (!autofocus) requirePositive("--focus", settings.focusMetres, "metres");
    requirePositive("--focal-length", settings.focalLengthMm, "millimetres");
    requirePositive("--sensor-width", settings.sensorWidthMm, "millimetres");

    ThinLens lens;
    lens.focalLength = settings.focalLengthMm * kMillimetre;
    lens.focusDistance = autofocus ? 0.0 : settings.focusMetres;
    lens.sensorWidth = settings.sensorWidthMm * kMillimetre;
    // A lens cannot focus closer than its focal length: the image would form at infinity or behind it.
    if (!autofocus && lens.focusDistance <= lens.focalLength) {
        invalid("--focus (" + formatNumber(settings.focusMetres) + " m) must be greater than --focal-length (" +
                formatNumber(settings.focalLengthMm) + " mm = " + formatNumber(lens.focalLength) + " m)");
    }

    if (settings.fNumber && settings.apertureRadiusMetres) {
        throw CliError(ExitCode::Usage, "give either --fstop or --aperture-radius, not both");
    }
    if (settings.fNumber) {
        requirePositive("--fstop", *settings.fNumber, "");
        // The f-number is focal length over aperture diameter.
        lens.apertureRadius = lens.focalLength / (2.0 * *settings.fNumber);
        lens.apertureOption = "--fstop";
    } else if (settings.apertureRadiusMetres) {
        const double radius = *settings.apertureRadiusMetres;
        if (!std::isfinite(radius) || radius < 0.0) {
            invalid("--aperture-radius must be a finite number of metres, 0 or more, got " + formatNumber(radius));
        }
        lens.apertureRadius = radius;
    } else {
        throw CliError(ExitCode::Usage, "give --fstop or --aperture-radius");
    }
    return lens;
}

double halfResPixelsPerSensorMetre(const ThinLens& lens, uint32_t imageWidth) {
    return 0.5 * imageWidth / lens.sensorWidth;
}

double thinLensCocHalfResPixels(const ThinLens& lens, double z, uint32_t imageWidth) {
    const double sensorRadius = lens.apertureRadius * lens.focalLength * (lens.focusDistance - z) /
                                (z * (lens.focusDistance - lens.focalLength));
    return sensorRadius * halfResPixelsPerSensorMetre(lens, imageWidth);
}

double DepthProjection::deviceDepth(double distance) const {
    const double z = m43 < 0.0 ? -distance : distance;
    return (m33 * z + m34) / (m43 * z);
}

double DepthProjection::viewDistance(double deviceDepth) const {
    // From d = m33 / m43 + m34 / (m43 z):  z = m34 / (m43 d - m33).
    const double z = m34 / (m43 * deviceDepth - m33);
    return m43 < 0.0 ? -z : z;
}

DepthProjection projectionFromNearFar(double nearPlane, double farPlane, bool reversed) {
    if (!std::isfinite(nearPlane) || nearPlane <= 0.0) {
        invalid("--near must be a finite number of metres greater than 0, got " + formatNumber(nearPlane));
    }
    if (std::isnan(farPlane) || farPlane <= nearPlane) {
        invalid("--far (" + formatNumber(farPlane) + ") must be greater than --near (" + formatNumber(nearPlane) + ")");
    }
    // Left-handed, view z = distance, m43 = 1. Standard: d(near) = 0, d(far) = 1, so
    // m33 = far / (far - near), m34 = -near * far / (far - near). Reversed is d' = 1 - d:
    // m33' = 1 - m33 = -near / (far - near), m34' = -m34. With far -> infinity these become
    // (1, -near) and (0, near).
    DepthProjection projection;
    projection.m43 = 1.0;
    projection.reversed = reversed;
    if (std::isinf(farPlane)) {
        projection.m33 = reversed ? 0.0 : 1.0;
        projection.m34 = reversed ? nearPlane : -nearPlane;
    } else {
        const double range = farPlane - nearPlane;
        projection.m33 = reversed ? -nearPlane / range : farPlane / range;
        projection.m34 = (reversed ? 1.0 : -1.0) * nearPlane * farPlane / range;
    }
    return projection;
}

DepthProjection projectionFromMatrix(const std::array<double, 16>& rowMajor, bool reversedRequested) {
    for (double value : rowMajor) {
        if (!std::isfinite(value)) {
            invalid("--proj has a value that is not a finite number: " + formatNumber(value));
        }
    }
    const auto at = [&](int row, int column) { return rowMajor[size_t((row - 1) * 4 + (column - 1))]; };
    // Depth must be a function of view z alone: row 3 = (0, 0, m33, m34), row 4 = (0, 0, m43, 0).
    if (at(3, 1) != 0.0 || at(3, 2) != 0.0 || at(4, 1) != 0.0 || at(4, 2) != 0.0 || at(4, 4) != 0.0 ||
        at(4, 3) == 0.0 || at(3, 4) == 0.0) {
        invalid(
            "--proj is not a perspective projection for column vectors: expected row 3 = (0, 0, m33, m34) with "
            "m34 != 0 and row 4 = (0, 0, m43, 0) with m43 != 0 (transpose a row-vector matrix)");
    }
    DepthProjection projection;
    projection.m33 = at(3, 3);
    projection.m34 = at(3, 4);
    projection.m43 = at(4, 3);
    // d = m33 / m43 + m34 / (|m43| * distance): it grows with distance exactly when m34 < 0.
    projection.reversed = projection.m34 > 0.0;
    if (reversedRequested && !projection.reversed) {
        invalid("--reverse-depth was given but the --proj matrix maps farther points to larger depths (m34 < 0)");
    }
    return projection;
}

DepthProjection projectionForLinearDepth(double nearestDepth) {
    if (!std::isfinite(nearestDepth) || nearestDepth <= 0.0) {
        invalid("the nearest linear depth must be a finite number greater than 0, got " + formatNumber(nearestDepth));
    }
    return projectionFromNearFar(nearestDepth, INFINITY, /*reversed=*/true);
}

CocParameters computeCocParameters(const ThinLens& lens, const DepthProjection& projection, uint32_t imageWidth,
                                   const std::string& projectionOrigin) {
    const double conversion = halfResPixelsPerSensorMetre(lens, imageWidth);
    // The SDK computes in single precision: a value a float cannot hold (or only as a subnormal) gives
    // an infinite or NaN CoC. Each is named by the option it comes from.
    const auto requireSinglePrecision = [](double value, const std::string& what) {
        const double magnitude = std::fabs(value);
        if (!(magnitude <= double(FLT_MAX)) || (magnitude != 0.0 && magnitude < double(FLT_MIN))) {
            invalid(what + " = " + formatNumber(value) +
                    " is outside the single-precision range the effect computes in (1.2e-38 to 3.4e38)");
        }
    };
    requireSinglePrecision(lens.focusDistance, "--focus (metres)");
    requireSinglePrecision(lens.focalLength, "--focal-length (metres)");
    requireSinglePrecision(lens.apertureRadius, "the aperture radius from " + lens.apertureOption + " (metres)");
    requireSinglePrecision(conversion, "0.5 * image width / --sensor-width (pixels per metre)");
    requireSinglePrecision(projection.m33, "m33 of " + projectionOrigin);
    requireSinglePrecision(projection.m34, "m34 of " + projectionOrigin);
    requireSinglePrecision(projection.m43, "m43 of " + projectionOrigin);
    // The SDK follows the sign of view z: the focus distance is negative for a camera looking down -z.
    const double signedFocus = projection.m43 < 0.0 ? -lens.focusDistance : lens.focusDistance;
    CocParameters coc;
    coc.cocScale =
        ffxDofCalculateCocScale(float(lens.apertureRadius), float(signedFocus), float(lens.focalLength),
                                float(conversion), float(projection.m33), float(projection.m34), float(projection.m43));
    coc.cocBias =
        ffxDofCalculateCocBias(float(lens.apertureRadius), float(signedFocus), float(lens.focalLength),
                               float(conversion), float(projection.m33), float(projection.m34), float(projection.m43));
    if (!std::isfinite(coc.cocScale) || !std::isfinite(coc.cocBias)) {
        invalid("--focus " + formatNumber(lens.focusDistance) + " m, --focal-length " +
                formatNumber(lens.focalLength / kMillimetre) + " mm, " + lens.apertureOption + " (aperture radius " +
                formatNumber(lens.apertureRadius) + " m) and " + projectionOrigin +
                " give a non-finite circle of confusion (scale " + formatNumber(coc.cocScale) + ", bias " +
                formatNumber(coc.cocBias) + ")");
    }
    return coc;
}

float largestCocRadius(const std::vector<float>& deviceDepth, const CocParameters& coc) {
    float largest = 0.0f;
    for (float d : deviceDepth) largest = std::fmax(largest, std::fabs(d * coc.cocScale + coc.cocBias));
    return largest;
}

// ---- Autofocus --------------------------------------------------------------------------------------------

std::string autofocusPointSyntaxError(const std::string& text) {
    const std::string expected = "expected X,Y (two numbers 0 to 1, e.g. 0.5,0.4), got '" + text + "'";
    const size_t comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) return expected;
    for (const std::string& part : {text.substr(0, comma), text.substr(comma + 1)}) {
        if (part.empty() || std::isspace(static_cast<unsigned char>(part.front()))) return expected;
        char* end = nullptr;
        (void)std::strtod(part.c_str(), &end);
        if (*end != '\0') return expected;
    }
    return std::string();
}

AutofocusRegion parseAutofocusPoint(const std::string& text, double size) {
    const std::string error = autofocusPointSyntaxError(text);
    if (!error.empty()) throw CliError(ExitCode::Usage, "--autofocus: " + error);
    const size_t comma = text.find(',');
    AutofocusRegion region;
    region.x = std::strtod(text.substr(0, comma).c_str(), nullptr);
    region.y = std::strtod(text.substr(comma + 1).c_str(), nullptr);
    region.size = size;
    return region;
}

void checkAutofocusRegion(const AutofocusRegion& region) {
    const auto inUnitRange = [](double value) { return value >= 0.0 && value <= 1.0; };  // false for NaN
    if (!inUnitRange(region.x) || !inUnitRange(region.y)) {
        invalid("--autofocus X,Y must lie in 0 to 1 (normalized image coordinates, 0,0 the top-left corner), got " +
                formatNumber(region.x) + "," + formatNumber(region.y));
    }
    if (!(region.size > 0.0 && region.size <= 1.0)) {
        invalid(
            "--focus-region must be greater than 0 and at most 1 (a fraction of the image's width and height), "
            "got " +
            formatNumber(region.size));
    }
}

FocusRange autofocusRange(const ThinLens& lens, const DepthProjection& projection) {
    FocusRange range;
    range.nearest = 2.0 * lens.focalLength;
    // The far plane: where device depth reaches 1 (0 when reversed). Infinite, or on the wrong side of the
    // camera for an infinite projection: none.
    const double farPlane = projection.viewDistance(projection.reversed ? 0.0 : 1.0);
    range.farthest =
        std::isfinite(farPlane) && farPlane > 0.0 ? std::min(farPlane, kAutofocusFarthest) : kAutofocusFarthest;
    if (!(range.farthest >= range.nearest)) {
        invalid("--autofocus: the far plane (" + formatNumber(range.farthest) +
                " m) must lie beyond twice --focal-length (" + formatNumber(range.nearest) +
                " m), the nearest focus autofocus chooses");
    }
    return range;
}

FfxDofAutofocus makeAutofocus(const ThinLens& lens, const DepthProjection& projection, uint32_t imageWidth,
                              const AutofocusRegion& region, const FocusRange& range) {
    FfxDofAutofocus autofocus{};
    autofocus.regionCenter[0] = float(region.x);
    autofocus.regionCenter[1] = float(region.y);
    autofocus.regionSize[0] = autofocus.regionSize[1] = float(region.size);
    autofocus.aperture = float(lens.apertureRadius);
    autofocus.focalLength = float(lens.focalLength);
    autofocus.conversion = float(halfResPixelsPerSensorMetre(lens, imageWidth));
    autofocus.proj33 = float(projection.m33);
    autofocus.proj34 = float(projection.m34);
    autofocus.proj43 = float(projection.m43);
    autofocus.minFocusDistance = float(range.nearest);
    autofocus.maxFocusDistance = float(range.farthest);
    autofocus.timeConstant = 0.0f;
    autofocus.deltaTime = 0.0f;
    return autofocus;
}

FocusRange reachableAutofocus(const std::vector<float>& deviceDepth, uint32_t width, uint32_t height,
                              const DepthProjection& projection, const AutofocusRegion& region,
                              const FocusRange& range) {
    // The pixels the pass reads (the region's grid and the centre's 3x3 neighbours), with a pixel to spare
    // on every side against rounding.
    const auto span = [](double centre, double size, uint32_t extent, uint32_t& first, uint32_t& last) {
        const double low = std::min((centre - 0.5 * size) * extent, centre * extent - 1.0) - 1.0;
        const double high = std::max((centre + 0.5 * size) * extent, centre * extent + 1.0) + 1.0;
        first = uint32_t(std::clamp(std::floor(low), 0.0, double(extent - 1)));
        last = uint32_t(std::clamp(std::floor(high), 0.0, double(extent - 1)));
    };
    uint32_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    span(region.x, region.size, width, x0, x1);
    span(region.y, region.size, height, y0, y1);
    float lowest = INFINITY, highest = -INFINITY;
    for (uint32_t y = y0; y <= y1; ++y) {
        for (uint32_t x = x0; x <= x1; ++x) {
            const float d = deviceDepth[size_t(y) * width + x];
            lowest = std::fmin(lowest, d);
            highest = std::fmax(highest, d);
        }
    }
    // Distance is monotonic in device depth; an average of inverse distances stays between the extremes.
    const auto clampedDistance = [&](float d) {
        const double distance = std::fabs(projection.viewDistance(d));
        return std::isnan(distance) ? range.farthest : std::clamp(distance, range.nearest, range.farthest);
    };
    const double a = clampedDistance(lowest), b = clampedDistance(highest);
    return {std::min(a, b), std::max(a, b)};
}

std::string focusText(double metres) {
    // Three significant digits, never an exponent: 0.123, 2.48, 12.3, 10000.
    const int decimals =
        metres > 0.0 && std::isfinite(metres) ? std::clamp(2 - int(std::floor(std::log10(metres))), 0, 6) : 2;
    char text[64];
    std::snprintf(text, sizeof(text), "focus: %.*f m", decimals, metres);
    return text;
}

}  // namespace ffxdof::cli
