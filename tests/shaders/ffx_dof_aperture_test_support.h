// Helpers of the aperture's CPU tests, built with either gauge (FFX_DOF_OPTION_APERTURE_SHAPES 1 or 2).
#pragma once

#include "ffx_dof_aperture.h"
#include "ffx_dof_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ffxdof::testing {

constexpr double kPi = 3.14159265358979323846;

inline FfxDofAperture makeAperture(uint32_t blades, float rotationDegrees = 0.0f, float roundness = 0.0f,
                                   float anamorphic = 1.0f, float catEye = 0.0f) {
    return FfxDofAperture{blades, float(rotationDegrees * kPi / 180.0), roundness, anamorphic, catEye};
}

// The aperture a pixel at `pixel` of a `frame`-sized half-res image sees.
inline FfxDofPixelAperture pixelAperture(const FfxDofAperture& aperture,
                                         FfxFloat32x2 pixel = FfxFloat32x2(50.0f, 50.0f),
                                         FfxFloat32x2 frame = FfxFloat32x2(100.0f, 100.0f)) {
    FfxDofConstants constants{};
    ffxdof::setApertureConstants(aperture, &constants);
    return ffxDofMakeAperture(constants, pixel, frame);
}

// The largest relative error of this build's gauge (ffxDofApertureDistance) against the largest
// n_k . u / inradius over every side of the polygon and the circle, over offsets on a spiral through
// every direction and a range of lengths, near and far. The aperture has no cat's eye.
inline double largestBladeGaugeError(const FfxDofAperture& aperture) {
    FfxDofConstants constants{};
    ffxdof::setApertureConstants(aperture, &constants);
    const FfxDofPixelAperture a = pixelAperture(aperture);
    const double inverseInradius = std::hypot(constants.bladeNormal.x, constants.bladeNormal.y);
    const uint32_t blades = constants.bladeCount;
    double largestError = 0.0;
    for (int i = 0; i < 400; ++i) {
        const double angle = i * 2.399963, length = 0.05 + 0.01 * i;
        const double x = length * std::cos(angle), y = length * std::sin(angle);
        for (const bool nearSample : {false, true}) {
            const double side = nearSample ? 1.0 : -1.0;
            const double ux = x * side * aperture.anamorphicRatio, uy = -y * side;
            double expected = std::hypot(ux, uy);
            for (uint32_t k = 0; k < blades; ++k) {
                const double normalAngle = aperture.bladeRotation + 2.0 * kPi * k / blades;
                expected =
                    std::max(expected, (std::cos(normalAngle) * ux + std::sin(normalAngle) * uy) * inverseInradius);
            }
            const double gauge = ffxDofApertureDistance(a, FfxFloat32x2(float(x), float(y)), nearSample);
            largestError = std::max(largestError, std::abs(gauge - expected) / expected);
        }
    }
    return largestError;
}

}  // namespace ffxdof::testing
