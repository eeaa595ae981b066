// Thin-lens circle of confusion as an affine function of device depth.
//
// Thin lens (A aperture radius, f focal length, F focus distance, Z object distance, all one unit):
//   r = A f (F - Z) / (Z (F - f))                      [sensor units, positive in front of focus]
// Written with the signed view-space coordinate z (and F signed the same way, negative for cameras
// that look down -Z) so that F / z is the positive ratio of distances:
//   r = A f / (|F| - f) * (F / z - 1)
// The projection maps z to device depth d = clipZ / clipW = (p33 z + p34) / (p43 z), hence
//   1 / z = (d p43 - p33) / p34
// and r is affine in d ("it's just a madd"):
//   r = d * [A f F p43 / ((|F| - f) p34)]  +  A f / (|F| - f) * (-F p33 / p34 - 1)
// Both terms are multiplied by `conversion` (sensor units -> half-resolution pixels).
// Computed in double: near the focus plane r is a small difference of large terms.
#include "ffx_dof.h"

#include <cmath>
#include <limits>

namespace {

struct CocLine {
    double scale;
    double bias;
};

CocLine cocLine(double aperture, double focus, double focalLength, double conversion, double proj33, double proj34,
                double proj43) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double lensToFocus = std::fabs(focus) - focalLength;
    // A lens cannot focus closer than its focal length, and p34 = 0 is not a perspective projection:
    // NaN makes ffxDofContextDispatch reject the result with FFX_DOF_ERROR_INVALID_ARGUMENT.
    if (!(lensToFocus > 0.0) || proj34 == 0.0 || !(aperture >= 0.0) || !(focalLength > 0.0)) return {nan, nan};
    const double k = conversion * aperture * focalLength / lensToFocus;
    return {k * focus * proj43 / proj34, k * (-focus * proj33 / proj34 - 1.0)};
}

}  // namespace

extern "C" float ffxDofCalculateCocScale(float aperture, float focus, float focalLength, float conversion, float proj33,
                                         float proj34, float proj43) {
    return static_cast<float>(cocLine(aperture, focus, focalLength, conversion, proj33, proj34, proj43).scale);
}

extern "C" float ffxDofCalculateCocBias(float aperture, float focus, float focalLength, float conversion, float proj33,
                                        float proj34, float proj43) {
    return static_cast<float>(cocLine(aperture, focus, focalLength, conversion, proj33, proj34, proj43).bias);
}
