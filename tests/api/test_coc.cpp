// ffxDofCalculateCocScale/Bias against the thin-lens formula for random cameras, depth conventions
// (standard, reversed, reversed-infinite, -Z and +Z cameras, D3D [0,1] and GL [-1,1] clip depth).
#include "ffx_dof.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace {

// Projection terms (row 3 and row 4 of the 4x4 matrix, 1-based) mapping view z to clip z and w.
struct ProjectionTerms {
    double p33, p34, p43;
    double deviceDepth(double z) const { return (p33 * z + p34) / (p43 * z); }
};

// Right-handed view space, camera looking down -Z, D3D clip depth in [0, 1].
ProjectionTerms d3dStandard(double n, double f) { return {f / (n - f), n * f / (n - f), -1.0}; }
ProjectionTerms d3dReversed(double n, double f) { return {n / (f - n), n * f / (f - n), -1.0}; }
ProjectionTerms d3dReversedInfinite(double n) { return {0.0, n, -1.0}; }
// Left-handed, camera looking down +Z.
ProjectionTerms d3dStandardLeftHanded(double n, double f) { return {f / (f - n), -n * f / (f - n), 1.0}; }
// OpenGL: NDC depth in [-1, 1]; the depth buffer stores window depth 0.5 * ndc + 0.5 (glDepthRange 0..1).
ProjectionTerms glStandard(double n, double f) { return {-(f + n) / (f - n), -2.0 * f * n / (f - n), -1.0}; }
// The terms to pass for GL: window depth = ((p33 + p43) / 2 * z + p34 / 2) / (p43 * z).
ProjectionTerms glWindowTerms(const ProjectionTerms& gl) { return {0.5 * (gl.p33 + gl.p43), 0.5 * gl.p34, gl.p43}; }

// Thin lens, all distances positive, result in half-resolution pixels, near field positive.
double thinLensRadius(double aperture, double focusDistance, double focalLength, double conversion, double distance) {
    return conversion * aperture * focalLength * (focusDistance - distance) /
           (distance * (focusDistance - focalLength));
}

struct Camera {
    double aperture, focusDistance, focalLength, conversion, nearPlane, farPlane;
};

Camera randomCamera(std::mt19937& rng) {
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    Camera c;
    c.focalLength = uniform(0.018, 0.2);  // 18..200 mm
    const double fstop = uniform(1.2, 16.0);
    c.aperture = c.focalLength / (2.0 * fstop);
    const double sensorWidth = uniform(0.012, 0.036);
    c.conversion = 0.5 * uniform(320.0, 3840.0) / sensorWidth;  // sensor metres -> half-res px
    c.nearPlane = uniform(0.05, 0.5);
    c.focusDistance = std::max(c.nearPlane * uniform(1.5, 40.0), c.focalLength * 1.5);
    c.farPlane = c.focusDistance * uniform(2.0, 100.0);
    return c;
}

// Checks radius(d) = d * scale + bias against the thin lens for distances across the frustum. The error is
// measured relative to max(|r|, |r at infinity|): near the focus plane r is a difference of two terms as
// large as the background CoC, which float scale/bias carry to ~1e-7 of their size.
void checkCamera(const Camera& c, const ProjectionTerms& terms, double focusSign, std::mt19937& rng) {
    const float focus = static_cast<float>(focusSign * c.focusDistance);
    const float scale = ffxDofCalculateCocScale(float(c.aperture), focus, float(c.focalLength), float(c.conversion),
                                                float(terms.p33), float(terms.p34), float(terms.p43));
    const float bias = ffxDofCalculateCocBias(float(c.aperture), focus, float(c.focalLength), float(c.conversion),
                                              float(terms.p33), float(terms.p34), float(terms.p43));
    REQUIRE(std::isfinite(scale));
    REQUIRE(std::isfinite(bias));
    const double infinityRadius =
        std::fabs(c.conversion * c.aperture * c.focalLength / (c.focusDistance - c.focalLength));
    std::uniform_real_distribution<double> logDistance(std::log(c.nearPlane), std::log(c.farPlane));
    for (int i = 0; i < 64; ++i) {
        const double distance = std::exp(logDistance(rng));
        const double z = focusSign * distance;  // view-space coordinate along the optical axis
        const double d = terms.deviceDepth(z);
        const double expected = thinLensRadius(c.aperture, c.focusDistance, c.focalLength, c.conversion, distance);
        const double actual = d * double(scale) + double(bias);
        INFO("distance " << distance << " focus " << c.focusDistance << " expected " << expected << " got " << actual);
        CHECK(std::fabs(actual - expected) / std::max(std::fabs(expected), infinityRadius) < 1e-5);
    }
}

}  // namespace

TEST_CASE("CoC scale and bias match the thin lens for random cameras") {
    std::mt19937 rng(20261121);
    for (int cameraIndex = 0; cameraIndex < 200; ++cameraIndex) {
        const Camera c = randomCamera(rng);
        // Cameras looking down -Z take a negative focus distance.
        checkCamera(c, d3dStandard(c.nearPlane, c.farPlane), -1.0, rng);
        checkCamera(c, d3dReversed(c.nearPlane, c.farPlane), -1.0, rng);
        checkCamera(c, d3dReversedInfinite(c.nearPlane), -1.0, rng);
        checkCamera(c, d3dStandardLeftHanded(c.nearPlane, c.farPlane), +1.0, rng);
        checkCamera(c, glWindowTerms(glStandard(c.nearPlane, c.farPlane)), -1.0, rng);
    }
}

TEST_CASE("worked example of docs/coc.md: 50 mm f/2 focused at 2 m, 1920 px over 36 mm") {
    // D3D standard depth, near 0.1 m, far 100 m, camera looking down -Z.
    const ProjectionTerms terms = d3dStandard(0.1, 100.0);
    const float aperture = 0.05f / (2.0f * 2.0f), focus = -2.0f, focalLength = 0.05f;
    const float conversion = 0.5f * 1920.0f / 0.036f;
    const float scale = ffxDofCalculateCocScale(aperture, focus, focalLength, conversion, float(terms.p33),
                                                float(terms.p34), float(terms.p43));
    const float bias = ffxDofCalculateCocBias(aperture, focus, focalLength, conversion, float(terms.p33),
                                              float(terms.p34), float(terms.p43));
    // In focus at 2 m, +radius in front, -radius behind; at 1 m: 0.0125*0.05*(2-1)/(1*1.95)*26666.7 = 8.547 px.
    CHECK(terms.deviceDepth(-2.0) * scale + bias == Approx(0.0).margin(1e-4));
    CHECK(terms.deviceDepth(-1.0) * scale + bias == Approx(8.547).epsilon(1e-4));
    CHECK(terms.deviceDepth(-10.0) * scale + bias == Approx(-6.838).epsilon(1e-3));
    CHECK(scale == Approx(-170.7692).epsilon(1e-5));
    CHECK(bias == Approx(162.3932).epsilon(1e-5));
    // The same camera with reversed depth: only the line changes, the radii do not.
    const ProjectionTerms reversed = d3dReversed(0.1, 100.0);
    const float reversedScale = ffxDofCalculateCocScale(aperture, focus, focalLength, conversion, float(reversed.p33),
                                                        float(reversed.p34), float(reversed.p43));
    const float reversedBias = ffxDofCalculateCocBias(aperture, focus, focalLength, conversion, float(reversed.p33),
                                                      float(reversed.p34), float(reversed.p43));
    CHECK(reversedScale == Approx(170.7692).epsilon(1e-5));
    CHECK(reversedBias == Approx(-8.3761).epsilon(1e-4));
    CHECK(reversed.deviceDepth(-1.0) * reversedScale + reversedBias == Approx(8.547).epsilon(1e-4));
    // OpenGL [-1, 1] clip depth: the window-depth terms reproduce the D3D line exactly.
    const ProjectionTerms gl = glWindowTerms(glStandard(0.1, 100.0));
    CHECK(gl.p33 == Approx(terms.p33));
    CHECK(gl.p34 == Approx(terms.p34));
}

TEST_CASE("impossible lenses give NaN, which dispatch rejects") {
    const ProjectionTerms terms = d3dStandard(0.1, 100.0);
    // Focus closer than the focal length.
    CHECK(std::isnan(
        ffxDofCalculateCocScale(0.01f, -0.04f, 0.05f, 1000.0f, float(terms.p33), float(terms.p34), float(terms.p43))));
    // Not a perspective projection (p34 = 0).
    CHECK(std::isnan(ffxDofCalculateCocBias(0.01f, -2.0f, 0.05f, 1000.0f, 1.0f, 0.0f, -1.0f)));
    // Negative aperture.
    CHECK(std::isnan(
        ffxDofCalculateCocBias(-0.01f, -2.0f, 0.05f, 1000.0f, float(terms.p33), float(terms.p34), float(terms.p43))));
}

TEST_CASE("a zero aperture gives zero CoC everywhere") {
    const ProjectionTerms terms = d3dReversed(0.1, 100.0);
    CHECK(ffxDofCalculateCocScale(0.0f, -3.0f, 0.05f, 1000.0f, float(terms.p33), float(terms.p34), float(terms.p43)) ==
          0.0f);
    CHECK(ffxDofCalculateCocBias(0.0f, -3.0f, 0.05f, 1000.0f, float(terms.p33), float(terms.p34), float(terms.p43)) ==
          0.0f);
}
