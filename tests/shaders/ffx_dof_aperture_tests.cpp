// The aperture's pure functions (shaders_common/ffx_dof_aperture.h) with the constants the SDK sets
// for them (setApertureConstants), and single shaped points through the five passes on the CPU.
#include <catch2/catch.hpp>

#include "ffx_dof_aperture.h"
#include "ffx_dof_aperture_test_support.h"
#include "ffx_dof_cpu_pipeline.h"
#include "ffx_dof_plan.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace ffxdof::testing;

namespace {

// The screen position (y up) relative to a far point at which a pixel is reached by it: the gauge takes
// the offset from the pixel to the sample, y down.
float farGaugeAt(const FfxDofPixelAperture& a, double xUp, double yUp) {
    return ffxDofApertureDistance(a, FfxFloat32x2(float(-xUp), float(yUp)), false);
}

// Area of {gauge < 1} on a fine grid (pixel space, far field), and the sum of the area weights of a
// disc of radius `radius` (pi when the shape keeps energy).
struct ShapeMeasure {
    double area = 0.0;
    double weightSum = 0.0;
    double width = 0.0, height = 0.0;  // extent of the unit shape
};
ShapeMeasure measureShape(const FfxDofPixelAperture& a) {
    ShapeMeasure m;
    const double step = 0.005, radius = 1.0;
    double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
    for (double y = -2.2; y <= 2.2; y += step) {
        for (double x = -2.2; x <= 2.2; x += step) {
            if (farGaugeAt(a, x, y) >= 1.0f) continue;
            m.area += step * step;
            minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y), maxY = std::max(maxY, y);
        }
    }
    m.weightSum = m.area * ffxDofApertureAreaWeight(a, float(radius)) / (radius * radius) * 1.0;
    m.width = maxX - minX;
    m.height = maxY - minY;
    return m;
}

}  // namespace

TEST_CASE("The round aperture's gauge is the offset's length, computed as before", "[aperture]") {
    const FfxDofPixelAperture round = pixelAperture(makeAperture(0));
    for (const auto& [x, y] : {std::pair{3.0f, 4.0f}, std::pair{-1.25f, 0.5f}, std::pair{0.1f, -7.3f}}) {
        CHECK(ffxDofApertureDistance(round, FfxFloat32x2(x, y), false) == std::sqrt(x * x + y * y));
        CHECK(ffxDofApertureDistance(round, FfxFloat32x2(x, y), true) == std::sqrt(x * x + y * y));
    }
    CHECK(ffxDofApertureAreaWeight(round, 2.0f) == 0.25f);
    CHECK(ffxDofApertureAreaWeight(round, 0.1f) == 4.0f);
}

TEST_CASE("Fully round blades are the round aperture", "[aperture]") {
    FfxDofConstants constants{};
    ffxdof::setApertureConstants(makeAperture(6, 20.0f, 1.0f), &constants);
    CHECK(constants.bladeCount == 0u);
    CHECK(constants.apertureAreaScale == 1.0f);
}

TEST_CASE("Blades: flat sides left and right at rotation 0, counter-clockwise rotation", "[aperture]") {
    const double inradius = std::cos(kPi / 6.0);
    const FfxDofPixelAperture hexagon = pixelAperture(makeAperture(6));
    CHECK(farGaugeAt(hexagon, inradius, 0.0) == Approx(1.0f).epsilon(1e-5));   // a flat side at the right
    CHECK(farGaugeAt(hexagon, -inradius, 0.0) == Approx(1.0f).epsilon(1e-5));  // and at the left
    CHECK(farGaugeAt(hexagon, 0.0, 1.0) == Approx(1.0f).epsilon(1e-5));        // a corner at the top
    const FfxDofPixelAperture turned = pixelAperture(makeAperture(6, 30.0f));
    CHECK(farGaugeAt(turned, 1.0, 0.0) == Approx(1.0f).epsilon(1e-5));  // a corner at the right
    CHECK(farGaugeAt(turned, 0.0, inradius) == Approx(1.0f).epsilon(1e-5));

    // A triangle at rotation 0 has a flat side at the right and a corner at the left; turned by 90
    // degrees counter-clockwise (y up), the flat side is at the top.
    const FfxDofPixelAperture triangle = pixelAperture(makeAperture(3));
    CHECK(farGaugeAt(triangle, 0.5, 0.0) == Approx(1.0f).epsilon(1e-5));
    CHECK(farGaugeAt(triangle, -1.0, 0.0) == Approx(1.0f).epsilon(1e-5));
    const FfxDofPixelAperture up = pixelAperture(makeAperture(3, 90.0f));
    CHECK(farGaugeAt(up, 0.0, 0.5) == Approx(1.0f).epsilon(1e-5));
    CHECK(farGaugeAt(up, 0.0, -1.0) == Approx(1.0f).epsilon(1e-5));
}

// The folded gauge (ffxDofApertureDistance compares at most FFX_DOF_FOLDED_BLADE_SIDES sides) against the
// largest n_k . u / inradius over every side of the polygon and the circle, for every blade count.
TEST_CASE("The folded blade gauge is the largest over every side, for 3 to 16 blades", "[aperture]") {
    for (uint32_t blades = 3; blades <= 16; ++blades) {
        for (const float rotation : {0.0f, 17.0f, 45.0f, -100.0f}) {
            for (const float roundness : {0.0f, 0.4f}) {
                for (const float anamorphic : {1.0f, 1.5f}) {
                    const double largestError =
                        largestBladeGaugeError(makeAperture(blades, rotation, roundness, anamorphic));
                    INFO(blades << " blades, rotation " << rotation << ", roundness " << roundness << ", anamorphic "
                                << anamorphic << ": largest relative error " << largestError);
                    CHECK(largestError < 1e-5);
                }
            }
        }
    }
}

TEST_CASE("A near-field disc is the far-field disc turned 180 degrees", "[aperture]") {
    for (const FfxDofAperture& aperture :
         {makeAperture(5, 17.0f), makeAperture(3, 0.0f, 0.3f, 1.4f), makeAperture(0, 0.0f, 0.0f, 1.0f, 0.8f)}) {
        const FfxDofPixelAperture a = pixelAperture(aperture, FfxFloat32x2(90.0f, 10.0f));
        for (const auto& [x, y] : {std::pair{0.7f, 0.2f}, std::pair{-0.4f, 0.55f}, std::pair{0.1f, -0.9f}}) {
            CHECK(ffxDofApertureDistance(a, FfxFloat32x2(x, y), true) ==
                  Approx(ffxDofApertureDistance(a, FfxFloat32x2(-x, -y), false)).epsilon(1e-6));
        }
    }
}

TEST_CASE("Every shape's disc weighs pi: energy is kept", "[aperture]") {
    struct Case {
        FfxDofAperture aperture;
        FfxFloat32x2 pixel;
        double area;       // the unit shape's area on screen, where known exactly
        double tolerance;  // of the weight sum
    };
    const double hexagonArea = 1.5 * std::sqrt(3.0);
    const double lensArea = 2.0 * std::acos(0.5) - 0.5 * std::sqrt(3.0);  // discs one radius apart
    const FfxFloat32x2 centre(50.0f, 50.0f), corner(0.0f, 0.0f);
    const Case cases[] = {
        {makeAperture(0), centre, kPi, 0.01},
        {makeAperture(6), centre, hexagonArea, 0.01},
        {makeAperture(4, 45.0f), centre, 2.0, 0.01},
        {makeAperture(3), centre, 3.0 * std::sqrt(3.0) / 4.0, 0.01},
        {makeAperture(7, 10.0f, 0.5f), centre, -1.0, 0.01},
        {makeAperture(0, 0.0f, 0.0f, 1.5f), centre, kPi / 1.5, 0.01},
        {makeAperture(0, 0.0f, 0.0f, 0.5f), centre, kPi / 0.5, 0.01},
        {makeAperture(0, 0.0f, 0.0f, 1.0f, 1.0f), corner, lensArea, 0.01},
        {makeAperture(6, 0.0f, 0.0f, 1.5f, 0.7f), corner, -1.0, 0.01},
        {makeAperture(5, 10.0f, 0.2f, 1.0f, 0.4f), corner, -1.0, 0.01},
        {makeAperture(3, 0.0f, 0.0f, 1.0f, 1.0f), corner, -1.0, 0.01},
    };
    for (const Case& c : cases) {
        const ShapeMeasure m = measureShape(pixelAperture(c.aperture, c.pixel));
        INFO("blades " << c.aperture.bladeCount << ", roundness " << c.aperture.roundness << ", anamorphic "
                       << c.aperture.anamorphicRatio << ", cat's eye " << c.aperture.catEye << ": area " << m.area
                       << ", weight sum / pi " << m.weightSum / kPi);
        if (c.area > 0.0) CHECK(m.area == Approx(c.area).epsilon(0.01));
        CHECK(m.weightSum / kPi == Approx(1.0).epsilon(c.tolerance));
    }
}

TEST_CASE("The anamorphic ratio keeps the height and narrows the width", "[aperture]") {
    const ShapeMeasure tall = measureShape(pixelAperture(makeAperture(0, 0.0f, 0.0f, 1.5f)));
    CHECK(tall.height == Approx(2.0).margin(0.02));
    CHECK(tall.width == Approx(2.0 / 1.5).margin(0.02));
    const ShapeMeasure wide = measureShape(pixelAperture(makeAperture(0, 0.0f, 0.0f, 0.5f)));
    CHECK(wide.width == Approx(4.0).margin(0.02));
    CHECK(FfxFloat32(ffxDofKernelRowHalfWidth(1.0f, 0.0f, 1.0f / 0.5f)) == 2.0f);  // the walk covers it
}

TEST_CASE("Cat's eye: round at the centre, narrowed toward the edge along the radius", "[aperture]") {
    const FfxDofAperture catEye = makeAperture(0, 0.0f, 0.0f, 1.0f, 1.0f);
    const ShapeMeasure centre = measureShape(pixelAperture(catEye, FfxFloat32x2(50.0f, 50.0f)));
    CHECK(centre.area == Approx(kPi).epsilon(0.01));
    // At the right edge the clipping disc is offset along x: the disc keeps its height, loses width.
    const ShapeMeasure edge = measureShape(pixelAperture(catEye, FfxFloat32x2(100.0f, 50.0f)));
    CHECK(edge.height > 1.8);
    CHECK(edge.width < 1.35);
}

TEST_CASE("The tile passes reach the shape's largest extent", "[aperture]") {
    FfxDofConstants constants{};
    ffxdof::setApertureConstants(makeAperture(0, 0.0f, 0.0f, 0.5f), &constants);
    CHECK(ffxDofApertureExtent(constants) == 2.0f);
    CHECK(ffxDofApertureRingSpacingScale(constants) == 1.0f);
    ffxdof::setApertureConstants(makeAperture(0, 0.0f, 0.0f, 2.0f), &constants);
    CHECK(ffxDofApertureExtent(constants) == 1.0f);
    CHECK(ffxDofApertureRingSpacingScale(constants) == 0.5f);
}

namespace {

// A single bright far point through the five passes (ring merging on): its half-res far layer.
struct ShapedDisc {
    double energy = 0.0;
    double area = 0.0;  // texels above a tenth of the disc's level
    double width = 0.0, height = 0.0;
    double rightArea = 0.0, leftArea = 0.0;  // thresholded texels right / left of the point
    double innerFlatness = 0.0;              // std / mean within `flatRadius` of the point
};
// `radiusSlope`: how much the radius grows per px to the right of the point (0: a flat far field).
ShapedDisc measureShapedPoint(const FfxDofAperture& aperture, float radius, float flatRadius = 0.0f,
                              float radiusSlope = 0.0f) {
    const uint32_t width = 128, height = 128;
    const int px = 64, py = 64;
    ffxdoftest::Scene scene;
    scene.width = width;
    scene.height = height;
    scene.color.assign(size_t(width) * height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    scene.depth.assign(size_t(width) * height, radius);  // radius = -depth: far field
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) scene.depth[size_t(y) * width + x] += radiusSlope * (float(x) - float(px));
    // At white: a point above it leaves the half-res layers this measures for the composite's full-resolution
    // disc (ffx_dof_highlights.h; the Vulkan aperture tests measure that one, in the output).
    scene.color[size_t(py) * width + size_t(px)] = glm::vec4(1.0f, 1.0f, 1.0f, 1.0f);
    ffxdoftest::Settings settings;
    settings.aperture = aperture;
    settings.cocLimit = 40.0f;
    ffxdoftest::Layers layers;
    ffxdoftest::runPipeline(scene, settings, &layers);
    std::vector<double> values(layers.farColor.size());
    double peak = 0.0;
    ShapedDisc disc;
    for (size_t i = 0; i < values.size(); ++i) {
        values[i] = layers.farColor[i].x * layers.layerAlpha[i].y;
        disc.energy += values[i];
        peak = std::max(peak, values[i]);
    }
    // The disc's level: the median of the texels above a hundredth of the peak.
    std::vector<double> lit;
    for (double v : values)
        if (v > 0.01 * peak) lit.push_back(v);
    std::nth_element(lit.begin(), lit.begin() + lit.size() / 2, lit.end());
    const double level = lit[lit.size() / 2];
    int minX = 1 << 30, maxX = -1, minY = 1 << 30, maxY = -1;
    const double centreX = (px + 0.5) / 2.0;
    for (uint32_t y = 0; y < layers.halfHeight; ++y) {
        for (uint32_t x = 0; x < layers.halfWidth; ++x) {
            if (values[size_t(y) * layers.halfWidth + x] < 0.5 * level) continue;
            disc.area += 1.0;
            (x + 0.5 > centreX ? disc.rightArea : disc.leftArea) += 1.0;
            minX = std::min(minX, int(x)), maxX = std::max(maxX, int(x));
            minY = std::min(minY, int(y)), maxY = std::max(maxY, int(y));
        }
    }
    double sum = 0.0, sum2 = 0.0, count = 0.0;
    for (uint32_t y = 0; y < layers.halfHeight; ++y) {
        for (uint32_t x = 0; x < layers.halfWidth; ++x) {
            const double dx = x + 0.5 - centreX, dy = y + 0.5 - (py + 0.5) / 2.0;
            if (dx * dx + dy * dy > double(flatRadius) * flatRadius) continue;
            const double v = values[size_t(y) * layers.halfWidth + x];
            sum += v, sum2 += v * v, count += 1.0;
        }
    }
    if (count > 0.0) {
        const double mean = sum / count;
        disc.innerFlatness = std::sqrt(std::max(0.0, sum2 / count - mean * mean)) / mean;
    }
    disc.width = maxX - minX + 1;
    disc.height = maxY - minY + 1;
    return disc;
}

}  // namespace

TEST_CASE("A shaped far point through the passes: its shape, size, orientation and energy", "[aperture][pipeline]") {
    const float radius = 12.0f;
    const ShapedDisc round = measureShapedPoint(makeAperture(0), radius);
    INFO("round: area " << round.area << ", energy " << round.energy);
    CHECK(round.area == Approx(kPi * radius * radius).epsilon(0.05));

    const ShapedDisc hexagon = measureShapedPoint(makeAperture(6), radius);
    INFO("hexagon: area " << hexagon.area << ", " << hexagon.width << " x " << hexagon.height << ", energy "
                          << hexagon.energy);
    CHECK(hexagon.area == Approx(1.5 * std::sqrt(3.0) * radius * radius).epsilon(0.05));
    CHECK(hexagon.width == Approx(2.0 * std::cos(kPi / 6.0) * radius).margin(1.5));  // flat sides left and right
    CHECK(hexagon.height == Approx(2.0 * radius).margin(1.5));
    CHECK(hexagon.energy == Approx(round.energy).epsilon(0.03));

    // The triangle's rim lies well inside the walk's circle, where inner rings are merged: its rim groups
    // stay at full resolution (a coarse texel's centre moved the tip apart from the body).
    const ShapedDisc triangle = measureShapedPoint(makeAperture(3), radius, 0.4f * radius);
    INFO("triangle: left " << triangle.leftArea << ", right " << triangle.rightArea << ", area " << triangle.area
                           << ", inner flatness " << triangle.innerFlatness);
    CHECK(triangle.area == Approx(0.75 * std::sqrt(3.0) * radius * radius).epsilon(0.08));
    CHECK(triangle.innerFlatness < 0.05);
    // A far point's triangle has its flat side at the right and a corner at the left, around its centre:
    // 5/9 of its area lies right of the centre, 4/9 left.
    CHECK(triangle.rightArea > 1.1 * triangle.leftArea);
    CHECK(triangle.energy == Approx(round.energy).epsilon(0.03));

    // Over a sloped far field (radii changing by 0.01 to 0.08 px per px) the tiles are not flat but the
    // point's surroundings may still merge: its rim rings stay at full resolution there too (merged, the
    // triangle kept 0.96 of its energy and was 0.056 from flat inside).
    for (const float slope : {0.01f, 0.02f, 0.04f, 0.08f}) {
        const ShapedDisc sloped = measureShapedPoint(makeAperture(3), radius, 0.4f * radius, slope);
        INFO("over a slope of " << slope << ": energy " << sloped.energy << ", inner flatness "
                                << sloped.innerFlatness);
        CHECK(sloped.energy == Approx(round.energy).epsilon(0.03));
        CHECK(sloped.innerFlatness < 0.03);
    }

    const ShapedDisc tall = measureShapedPoint(makeAperture(0, 0.0f, 0.0f, 1.5f), radius);
    INFO("anamorphic 1.5: " << tall.width << " x " << tall.height << ", energy " << tall.energy);
    CHECK(tall.height / tall.width == Approx(1.5).epsilon(0.1));
    CHECK(tall.area == Approx(kPi * radius * radius / 1.5).epsilon(0.06));
    CHECK(tall.energy == Approx(round.energy).epsilon(0.03));
}
