// The autofocus pass's pure functions on the CPU: the robust centre, the surface test, the clamp,
// the smoothing, the sample grid, and the CoC line against the SDK's double-precision helpers.
#include <catch2/catch.hpp>

#include "ffx_dof.h"
#include "ffx_dof_autofocus.h"

#include <cmath>

namespace {

// A camera looking down -Z, near 0.1, far 100, depth 0 at the near plane; f = 50 mm at f/2.
FfxDofConstants cameraConstants() {
    FfxDofConstants c{};
    const float p33 = 100.0f / (0.1f - 100.0f), p34 = 0.1f * 100.0f / (0.1f - 100.0f), p43 = -1.0f;
    c.fullSize = {640, 480};
    c.focusRegionCenter = {0.5f, 0.5f};
    c.focusRegionSize = {0.2f, 0.2f};
    c.focusInvZScale = p43 / p34;
    c.focusInvZBias = p33 / p34;
    c.focusLensFactor = 0.0125f * 0.05f * (0.5f * 640.0f / 0.036f);
    c.focusFocalLength = 0.05f;
    c.focusMinDistance = -0.2f;  // signed like view z in front of the camera (negative here)
    c.focusMaxDistance = -50.0f;
    c.focusBlend = 1.0f;
    return c;
}

float depthAt(float distance) {
    const float p33 = 100.0f / (0.1f - 100.0f), p34 = 0.1f * 100.0f / (0.1f - 100.0f);
    return -p33 + p34 / distance;
}

}  // namespace

TEST_CASE("the median of nine ignores up to four outliers", "[autofocus]") {
    CHECK(ffxDofMedian9(5, 1, 9, 3, 7, 2, 8, 4, 6) == 5.0f);
    CHECK(ffxDofMedian9(2, 2, 2, 2, 2, 1000, -1000, 1e9f, 0) == 2.0f);
}

TEST_CASE("a depth converts to its signed inverse view distance", "[autofocus]") {
    const FfxDofConstants c = cameraConstants();
    for (const float distance : {0.2f, 1.0f, 2.5f, 40.0f}) {
        CHECK(1.0f / ffxDofInverseViewZ(depthAt(distance), c) == Approx(-distance).epsilon(1e-4));
    }
}

TEST_CASE("the surface test accepts 5 percent and refuses more", "[autofocus]") {
    CHECK(ffxDofOnFocusSurface(-1.0f / 2.0f, -1.0f / 2.0f));
    CHECK(ffxDofOnFocusSurface(-1.0f / 2.09f, -1.0f / 2.0f));
    CHECK_FALSE(ffxDofOnFocusSurface(-1.0f / 2.2f, -1.0f / 2.0f));
    CHECK_FALSE(ffxDofOnFocusSurface(-1.0f / 10.0f, -1.0f / 2.0f));
}

TEST_CASE("the focus is clamped to the range and infinity becomes the farthest focus", "[autofocus]") {
    const FfxDofConstants c = cameraConstants();
    CHECK(ffxDofClampFocus(-1.0f / 3.0f, c) == Approx(-3.0f));
    CHECK(ffxDofClampFocus(-1.0f / 0.05f, c) == Approx(-0.2f));
    CHECK(ffxDofClampFocus(-1.0f / 80.0f, c) == Approx(-50.0f));
    CHECK(ffxDofClampFocus(0.0f, c) == Approx(-50.0f));
}

TEST_CASE("the smoothing moves a share of the gap in dioptres and starts without history", "[autofocus]") {
    CHECK(ffxDofSmoothFocus(0.0f, -4.0f, 0.3f) == -4.0f);  // no history
    CHECK(ffxDofSmoothFocus(-2.0f, -4.0f, 1.0f) == -4.0f);
    const float halfway = ffxDofSmoothFocus(-2.0f, -4.0f, 0.5f);
    CHECK(1.0f / halfway == Approx(0.5f * (-0.5f - 0.25f)));
    // Repeated steps close the gap as (1 - blend)^n.
    float focus = -2.0f;
    for (int i = 0; i < 10; ++i) focus = ffxDofSmoothFocus(focus, -8.0f, 0.2f);
    CHECK(1.0f / focus == Approx(-0.125f + (-0.5f + 0.125f) * std::pow(0.8f, 10.0f)).epsilon(1e-4));
}

TEST_CASE("the CoC line of a focus is the SDK's", "[autofocus]") {
    const FfxDofConstants c = cameraConstants();
    const float p33 = 100.0f / (0.1f - 100.0f), p34 = 0.1f * 100.0f / (0.1f - 100.0f), p43 = -1.0f;
    const float conversion = 0.5f * 640.0f / 0.036f;
    for (const float distance : {0.3f, 1.5f, 7.0f, 30.0f}) {
        CAPTURE(distance);
        const FfxFloat32x2 line = ffxDofFocusCocLine(-distance, c);
        const float scale = ffxDofCalculateCocScale(0.0125f, -distance, 0.05f, conversion, p33, p34, p43);
        const float bias = ffxDofCalculateCocBias(0.0125f, -distance, 0.05f, conversion, p33, p34, p43);
        CHECK(line.x == Approx(scale).epsilon(1e-4));
        CHECK(line.y == Approx(bias).epsilon(1e-4).margin(1e-3));
        // In focus at the focus distance, whichever line.
        CHECK(std::abs(depthAt(distance) * line.x + line.y) < 1e-2f);
    }
}

TEST_CASE("the sample grid covers the region and stays in the image", "[autofocus]") {
    FfxDofConstants c = cameraConstants();
    uint32_t minX = 1u << 30, maxX = 0, minY = 1u << 30, maxY = 0;
    for (uint32_t i = 0; i < FFX_DOF_AUTOFOCUS_GRID * FFX_DOF_AUTOFOCUS_GRID; ++i) {
        const FfxUInt32x2 p = ffxDofFocusSamplePixel(i, c);
        minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
    }
    // A 20% region at the centre of 640x480: x 256..383, y 192..287.
    CHECK(minX >= 256u);
    CHECK(maxX <= 383u);
    CHECK(minY >= 192u);
    CHECK(maxY <= 287u);
    CHECK(maxX - minX >= 115u);
    // A region over the corner is clamped into the image.
    c.focusRegionCenter = {1.0f, 0.0f};
    for (uint32_t i = 0; i < FFX_DOF_AUTOFOCUS_GRID * FFX_DOF_AUTOFOCUS_GRID; ++i) {
        const FfxUInt32x2 p = ffxDofFocusSamplePixel(i, c);
        CHECK(p.x < 640u);
        CHECK(p.y < 480u);
    }
    for (uint32_t i = 0; i < 9; ++i) CHECK(ffxDofFocusCentrePixel(i, c).x <= 639u);
}
