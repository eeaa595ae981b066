// The reference renderer's aperture shapes (issue 18): the unit shape S (blades, roundness, cat's eye),
// its area, its orientation on screen, the anamorphic squeeze, energy conservation, camera.json.
#include "emitter_scene.h"
#include "ffx_dof_reference.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace ffxdof;
using ffxdof::reftest::emitterScene;

namespace {

ref::ApertureShape blades(uint32_t count, double rotationDegrees = 0.0, double roundness = 0.0) {
    ref::ApertureShape shape;
    shape.bladeCount = count;
    shape.bladeRotationDegrees = rotationDegrees;
    shape.roundness = roundness;
    return shape;
}

// Two unit discs whose centres are d apart overlap in a lens of this area.
double lensArea(double d) { return 2.0 * std::acos(0.5 * d) - 0.5 * d * std::sqrt(4.0 - d * d); }

// The area of S counted on a fine grid with contains(): checks the inside test and the row integral
// against each other.
double gridArea(const ref::UnitAperture& aperture, glm::dvec2 catEyeCenter) {
    constexpr int kGrid = 1500;
    const double step = 2.0 / kGrid;
    long inside = 0;
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i) {
            inside += aperture.contains({-1.0 + (i + 0.5) * step, -1.0 + (j + 0.5) * step}, catEyeCenter);
        }
    }
    return inside * step * step;
}

// The pixels brighter than half the image's median lit level: the bokeh's outline.
struct Outline {
    int minX = std::numeric_limits<int>::max(), maxX = -1, minY = std::numeric_limits<int>::max(), maxY = -1;
    double centroidX = 0.0, centroidY = 0.0;  // of the lit pixels, pixel centres at +0.5
    int count = 0;
    double energy = 0.0;  // sum of the red channel over the whole image
    double width() const { return maxX - minX + 1; }
    double height() const { return maxY - minY + 1; }
    double boxCenterX() const { return 0.5 * (minX + maxX + 1); }
    double boxCenterY() const { return 0.5 * (minY + maxY + 1); }
};

Outline outline(const io::ImageRGBA& image) {
    Outline result;
    std::vector<float> lit;
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            const float value = image.at(x, y)[0];
            result.energy += value;
            if (value > 0.0f) lit.push_back(value);
        }
    }
    if (lit.empty()) return result;
    std::nth_element(lit.begin(), lit.begin() + lit.size() / 2, lit.end());
    const float threshold = 0.5f * lit[lit.size() / 2];
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            if (image.at(x, y)[0] <= threshold) continue;
            result.minX = std::min(result.minX, int(x)), result.maxX = std::max(result.maxX, int(x));
            result.minY = std::min(result.minY, int(y)), result.maxY = std::max(result.maxY, int(y));
            result.centroidX += x + 0.5, result.centroidY += y + 0.5;
            ++result.count;
        }
    }
    result.centroidX /= result.count, result.centroidY /= result.count;
    return result;
}

Outline renderOutline(ref::SceneSetup setup, const ref::ApertureShape& shape, uint32_t lensSamples = 64) {
    setup.camera.aperture = shape;
    ref::RenderSettings settings;
    settings.lensSamples = lensSamples;
    settings.threads = 2;
    return outline(ref::renderThinLens(setup.scene, setup.camera, settings).color);
}

}  // namespace

TEST_CASE("aperture area: polygons and roundness exactly and the row integral agrees", "[aperture]") {
    CHECK(ref::UnitAperture({}).area() == Approx(M_PI).epsilon(1e-12));
    CHECK(ref::UnitAperture(blades(6)).area() == Approx(3.0 * std::sqrt(3.0) / 2.0).epsilon(1e-4));
    CHECK(ref::UnitAperture(blades(4)).area() == Approx(2.0).epsilon(1e-4));
    CHECK(ref::UnitAperture(blades(3)).area() == Approx(3.0 * std::sqrt(3.0) / 4.0).epsilon(1e-4));
    CHECK(ref::UnitAperture(blades(6, 0.0, 1.0)).area() == Approx(M_PI).epsilon(1e-12));
    CHECK(ref::UnitAperture(blades(16, 0.0, 1.0)).isDisc());
    CHECK_FALSE(ref::UnitAperture(blades(16, 0.0, 0.99)).isDisc());
    // Half-way round lies between the polygon and the circle, and rotation changes nothing.
    const double half = ref::UnitAperture(blades(5, 0.0, 0.5)).area();
    CHECK(half > ref::UnitAperture(blades(5)).area());
    CHECK(half < M_PI);
    CHECK(ref::UnitAperture(blades(5, 33.0, 0.5)).area() == Approx(half).epsilon(1e-12));

    // The anamorphic ratio scales the lens, not S.
    ref::ApertureShape squeezed = blades(6);
    squeezed.anamorphicRatio = 1.5;
    CHECK(ref::UnitAperture(squeezed).area() == ref::UnitAperture(blades(6)).area());
    const glm::dvec2 lens = ref::UnitAperture(squeezed).lensPoint({0.6, 0.3}, 2.0);
    CHECK(lens.x == Approx(0.8));
    CHECK(lens.y == Approx(0.6));

    // A cat's-eye disc centred a hair off the axis is the unit disc again, through the row integral:
    // it agrees with the exact areas.
    for (uint32_t count : {3u, 4u, 6u, 9u, 16u}) {
        for (double roundness : {0.0, 0.4, 1.0}) {
            ref::ApertureShape shape = blades(count, 17.0, roundness);
            shape.catEye = 1.0;
            const ref::UnitAperture aperture(shape);
            INFO(count << " blades, roundness " << roundness);
            CHECK(aperture.area({1e-12, 0.0}) == Approx(aperture.area()).epsilon(1e-5));
        }
    }
}

TEST_CASE("aperture area: the cat's eye at a frame corner is the lens of two discs", "[aperture]") {
    ref::ApertureShape shape;
    shape.catEye = 1.0;
    const ref::UnitAperture aperture(shape);
    for (const glm::dvec2 corner : {glm::dvec2(0.0, 0.0), glm::dvec2(160.0, 0.0), glm::dvec2(160.0, 90.0)}) {
        const glm::dvec2 o = aperture.catEyeCenter(corner.x, corner.y, 160, 90);
        CHECK(glm::length(o) == Approx(1.0).epsilon(1e-12));
        CHECK(aperture.area(o) == Approx(2.0 * std::acos(0.5) - 0.5 * std::sqrt(3.0)).epsilon(1e-4));
    }
    CHECK(aperture.catEyeCenter(80.0, 45.0, 160, 90) == glm::dvec2(0.0));
    CHECK(aperture.area(aperture.catEyeCenter(80.0, 45.0, 160, 90)) == Approx(M_PI).epsilon(1e-12));
    // Halfway out at half strength: centre distance 0.25.
    shape.catEye = 0.5;
    const ref::UnitAperture weaker(shape);
    const glm::dvec2 o = weaker.catEyeCenter(120.0, 22.5, 160, 90);
    CHECK(glm::length(o) == Approx(0.25));
    CHECK(weaker.area(o) == Approx(lensArea(0.25)).epsilon(1e-4));

    // With blades too the row integral and the inside test agree (a grid count, good to about 1e-3).
    shape = blades(5, 10.0, 0.2);
    shape.catEye = 0.8;
    const ref::UnitAperture both(shape);
    for (const glm::dvec2 pixel : {glm::dvec2(3.0, 7.0), glm::dvec2(90.0, 80.0), glm::dvec2(150.0, 40.0)}) {
        const glm::dvec2 center = both.catEyeCenter(pixel.x, pixel.y, 160, 90);
        INFO("pixel " << pixel.x << ", " << pixel.y);
        CHECK(both.area(center) == Approx(gridArea(both, center)).epsilon(2e-3));
        CHECK(both.area(center) < both.area());
    }
}

TEST_CASE("aperture orientation: flat sides face +x at rotation 0 and turn counter-clockwise", "[aperture]") {
    // Hexagon: the normals at 0, 60, 120... degrees put vertices at 30, 90, 150... degrees.
    const ref::UnitAperture hexagon(blades(6));
    CHECK_FALSE(hexagon.contains({0.9, 0.0}));  // beyond the flat side at x = cos(30) = 0.866
    CHECK(hexagon.contains({0.85, 0.0}));
    CHECK(hexagon.contains({0.0, 0.95}));  // towards the vertex at 90 degrees
    const ref::UnitAperture turned(blades(6, 30.0));
    CHECK(turned.contains({0.9, 0.0}));
    CHECK_FALSE(turned.contains({0.0, 0.95}));

    // Triangle: flat side at x = 0.5, vertex at 180 degrees; 90 degrees turns the flat side to +y.
    const ref::UnitAperture triangle(blades(3));
    CHECK_FALSE(triangle.contains({0.55, 0.0}));
    CHECK(triangle.contains({0.45, 0.0}));
    CHECK(triangle.contains({-0.95, 0.0}));
    const ref::UnitAperture up(blades(3, 90.0));
    CHECK_FALSE(up.contains({0.0, 0.55}));
    CHECK(up.contains({0.0, -0.95}));
    CHECK_FALSE(up.contains({-0.95, 0.0}));

    // Row intervals: the hexagon's row through the centre ends at its flat sides; rows miss beyond
    // the vertices.
    double left = 0.0, right = 0.0;
    REQUIRE(hexagon.rowInterval(0.0, {}, left, right));
    CHECK(left == Approx(-std::cos(M_PI / 6.0)));
    CHECK(right == Approx(std::cos(M_PI / 6.0)));
    REQUIRE(triangle.rowInterval(0.0, {}, left, right));
    CHECK(left == Approx(-1.0));
    CHECK(right == Approx(0.5));
    CHECK_FALSE(hexagon.rowInterval(1.01, {}, left, right));

    // Cat's eye: the disc centred at o cuts the side away from o.
    ref::ApertureShape catEye;
    catEye.catEye = 1.0;
    const ref::UnitAperture eye(catEye);
    // Right edge of the frame, half height: o points right (+x); top edge: o points up (y up).
    const glm::dvec2 right0 = eye.catEyeCenter(100.0, 25.0, 100, 50);
    CHECK(right0.x > 0.0);
    CHECK(right0.y == Approx(0.0).margin(1e-15));
    CHECK(eye.catEyeCenter(50.0, 0.0, 100, 50).y > 0.0);
    CHECK(eye.contains({0.9, 0.0}, right0));
    CHECK_FALSE(eye.contains({-0.9, 0.0}, right0));
    CHECK(eye.contains({0.0, 0.0}, eye.catEyeCenter(0.0, 0.0, 100, 50)));  // the fallback point
}

TEST_CASE("aperture shape validation names the field", "[aperture]") {
    const auto rejects = [](ref::ApertureShape shape, const char* field) {
        INFO(field);
        CHECK_THROWS_WITH(shape.validate(), Catch::Contains(field));
        ref::Camera camera = ref::makeScene("point", 16, 16).camera;
        camera.aperture = shape;
        CHECK_THROWS_AS(camera.validate(), std::invalid_argument);
        CHECK_THROWS_WITH(ref::UnitAperture(shape), Catch::Contains(field));
    };
    for (uint32_t count : {1u, 2u, 17u, 100u}) rejects(blades(count), "aperture.bladeCount");
    for (uint32_t count : {0u, 3u, 16u}) CHECK_NOTHROW(blades(count).validate());
    rejects(blades(6, std::numeric_limits<double>::infinity()), "aperture.bladeRotationDegrees");
    rejects(blades(6, std::nan("")), "aperture.bladeRotationDegrees");
    rejects(blades(6, 0.0, -0.01), "aperture.roundness");
    rejects(blades(6, 0.0, 1.01), "aperture.roundness");
    ref::ApertureShape shape;
    shape.anamorphicRatio = 0.49;
    rejects(shape, "aperture.anamorphicRatio");
    shape.anamorphicRatio = 2.01;
    rejects(shape, "aperture.anamorphicRatio");
    shape = {};
    shape.catEye = 1.5;
    rejects(shape, "aperture.catEye");
    shape.catEye = -0.1;
    rejects(shape, "aperture.catEye");
}

TEST_CASE("camera JSON carries the aperture shape and rejects bad ones", "[aperture][camera]") {
    ref::Camera camera = ref::makeScene("point", 64, 48).camera;
    camera.aperture = blades(7, 12.5, 0.25);
    camera.aperture.anamorphicRatio = 1.33;
    camera.aperture.catEye = 0.6;
    const nlohmann::json json = ref::cameraToJson(camera);
    CHECK(json.at("aperture").at("bladeCount") == 7);
    const ref::Camera back = ref::cameraFromJson(json);
    CHECK(back.aperture.bladeCount == 7);
    CHECK(back.aperture.bladeRotationDegrees == 12.5);
    CHECK(back.aperture.roundness == 0.25);
    CHECK(back.aperture.anamorphicRatio == 1.33);
    CHECK(back.aperture.catEye == 0.6);

    // Files from before shapes, and partial objects, take the defaults.
    nlohmann::json old = json;
    old.erase("aperture");
    const ref::ApertureShape round = ref::cameraFromJson(old).aperture;
    CHECK(round.bladeCount == 0);
    CHECK(round.anamorphicRatio == 1.0);
    CHECK(round.catEye == 0.0);
    nlohmann::json partial = old;
    partial["aperture"] = {{"bladeCount", 5}};
    CHECK(ref::cameraFromJson(partial).aperture.bladeCount == 5);
    CHECK(ref::cameraFromJson(partial).aperture.roundness == 0.0);

    const auto rejects = [&](const nlohmann::json& aperture, const char* message) {
        nlohmann::json bad = old;
        bad["aperture"] = aperture;
        INFO(aperture.dump());
        CHECK_THROWS_WITH(ref::cameraFromJson(bad), Catch::Contains(message));
    };
    rejects(nlohmann::json::array({6}), "aperture must be an object");
    rejects({{"bladeCount", "six"}}, "aperture.bladeCount");
    rejects({{"bladeCount", 6.5}}, "aperture.bladeCount");
    rejects({{"bladeCount", -3}}, "aperture.bladeCount");
    rejects({{"bladeCount", 2}}, "aperture.bladeCount");
    rejects({{"bladeCount", 40}}, "aperture.bladeCount");
    rejects({{"roundness", "round"}}, "aperture.roundness must be a number");
    rejects({{"roundness", 2.0}}, "aperture.roundness");
    rejects({{"anamorphicRatio", 3.0}}, "aperture.anamorphicRatio");
    rejects({{"catEye", true}}, "aperture.catEye");
    rejects({{"bladeRotationDegrees", nullptr}}, "aperture.bladeRotationDegrees");
}

TEST_CASE("shaped bokeh: orientation far and near and the anamorphic squeeze", "[aperture][renderer]") {
    // About 20 px CoC radius at 96 x 96: far field (behind the focus) and near field (in front).
    const ref::SceneSetup far = emitterScene(96, 3.0, 20.0, 0.52, 48.0, 48.0);
    const ref::SceneSetup near = emitterScene(96, 5.0, 2.0, 0.5, 48.0, 48.0);
    REQUIRE(std::abs(far.camera.cocRadiusPixels(20.0)) == Approx(20.0).epsilon(0.05));
    REQUIRE(std::abs(near.camera.cocRadiusPixels(2.0)) == Approx(20.0).epsilon(0.05));

    // The triangle's flat side faces +x in S: its lit pixels lean towards it from the bounding box's
    // centre (by a quarter of the circumradius, 5 px). Far: the flat side is on the right of the
    // screen; near: turned 180 degrees, on the left. Turned 90 degrees (flat side up, y up): at the top
    // of the screen (smaller y) far, at the bottom near.
    const Outline farRight = renderOutline(far, blades(3));
    const Outline nearLeft = renderOutline(near, blades(3));
    const Outline farTop = renderOutline(far, blades(3, 90.0));
    const Outline nearBottom = renderOutline(near, blades(3, 90.0));
    CHECK(farRight.centroidX - farRight.boxCenterX() > 2.5);
    CHECK(std::abs(farRight.centroidY - farRight.boxCenterY()) < 1.0);
    CHECK(nearLeft.centroidX - nearLeft.boxCenterX() < -2.5);
    CHECK(farTop.centroidY - farTop.boxCenterY() < -2.5);
    CHECK(std::abs(farTop.centroidX - farTop.boxCenterX()) < 1.0);
    CHECK(nearBottom.centroidY - nearBottom.boxCenterY() > 2.5);

    // Six blades at rotation 0: flat sides left and right, so narrower (2 cos 30 = 1.73) than tall (2).
    const Outline hexagon = renderOutline(far, blades(6));
    INFO("hexagon " << hexagon.width() << " x " << hexagon.height());
    CHECK(hexagon.width() / hexagon.height() < 0.93);
    const Outline turned = renderOutline(far, blades(6, 30.0));
    CHECK(turned.width() / turned.height() > 1.07);

    // Anamorphic 1.5: 1.5 times taller than wide, far and near.
    ref::ApertureShape squeezed;
    squeezed.anamorphicRatio = 1.5;
    for (const ref::SceneSetup* setup : {&far, &near}) {
        const Outline disc = renderOutline(*setup, squeezed);
        INFO("anamorphic " << disc.width() << " x " << disc.height());
        CHECK(disc.width() / disc.height() == Approx(1.0 / 1.5).epsilon(0.1));
    }
}

TEST_CASE("shaped bokeh: a point gives the same energy as with the round aperture", "[aperture][renderer]") {
    // Every pixel averages over the same shape (lens area A^2 area(S) / s) and the bokeh is the image of
    // that shape, so its total does not depend on the shape.
    ref::ApertureShape hexagon = blades(6, 10.0, 0.3), squeezed = blades(5), tall;
    squeezed.anamorphicRatio = 0.7;
    tall.anamorphicRatio = 1.8;
    struct Case {
        const char* name;
        ref::SceneSetup setup;
    };
    // The footprint pass (points far behind and in front of the focus) and the whole-aperture pass (an
    // emitter larger than its blur).
    const Case cases[] = {
        {"far", emitterScene(96, 3.0, 20.0, 0.52, 48.0, 48.0)},
        {"far off-axis", emitterScene(96, 3.0, 20.0, 0.3, 76.0, 30.0)},
        {"near", emitterScene(96, 5.0, 2.0, 0.5, 40.0, 52.0)},
        {"whole aperture", emitterScene(96, 3.0, 3.3, 0.5, 52.0, 44.0, 6.0)},
    };
    for (const Case& c : cases) {
        const double round = renderOutline(c.setup, {}).energy;
        for (const ref::ApertureShape& shape : {hexagon, squeezed, tall}) {
            const Outline shaped = renderOutline(c.setup, shape);
            INFO(c.name << ": blades " << shape.bladeCount << ", anamorphic " << shape.anamorphicRatio);
            CHECK(shaped.energy == Approx(round).epsilon(0.02));
        }
    }
}

TEST_CASE("cat's eye: each pixel sees a point through its own trimmed aperture", "[aperture][renderer]") {
    // The cat's-eye disc follows the sensor position of each pixel, so a bokeh is not simply S at its
    // centre: pixel p sees the point through the lens point u(p) (the bokeh offset over the CoC radius, y
    // up; negated in front of the focus) if u(p) is in S(p), with the weight pi / area(S(p)) of the
    // average over that pixel's aperture. So the total energy is not the round aperture's; predict it
    // from the round image pixel by pixel.
    ref::ApertureShape catEye;
    catEye.catEye = 1.0;
    const ref::UnitAperture shape(catEye);
    struct Case {
        const char* name;
        ref::SceneSetup setup;
        double x, y, z;
    };
    const Case cases[] = {
        {"far, centre", emitterScene(96, 3.0, 20.0, 0.52, 48.0, 48.0), 48.0, 48.0, 20.0},
        {"far, right", emitterScene(96, 3.0, 20.0, 0.4, 80.0, 48.0), 80.0, 48.0, 20.0},
        {"far, top left", emitterScene(96, 3.0, 20.0, 0.3, 20.0, 22.0), 20.0, 22.0, 20.0},
        {"near, right", emitterScene(96, 5.0, 2.0, 0.35, 78.0, 48.0), 78.0, 48.0, 2.0},
    };
    ref::RenderSettings settings;
    settings.lensSamples = 64;
    settings.threads = 2;
    for (const Case& c : cases) {
        INFO(c.name);
        ref::SceneSetup setup = c.setup;
        const io::ImageRGBA round = ref::renderThinLens(setup.scene, setup.camera, settings).color;
        setup.camera.aperture = catEye;
        const io::ImageRGBA trimmed = ref::renderThinLens(setup.scene, setup.camera, settings).color;
        const double coc = setup.camera.cocRadiusPixels(c.z);  // > 0 in front of the focus
        const double sign = coc > 0.0 ? -1.0 : 1.0;
        double predicted = 0.0, rendered = 0.0, roundEnergy = 0.0;
        int predictedCount = 0;
        for (uint32_t y = 0; y < 96; ++y) {
            for (uint32_t x = 0; x < 96; ++x) {
                const glm::dvec2 u = sign * glm::dvec2(x + 0.5 - c.x, c.y - (y + 0.5)) / std::abs(coc);
                const glm::dvec2 o = shape.catEyeCenter(x + 0.5, y + 0.5, 96, 96);
                rendered += trimmed.at(x, y)[0];
                roundEnergy += round.at(x, y)[0];
                // The round image has the rim's partial pixels already; the cat's-eye disc trims it.
                if (glm::length(u - o) <= 1.0) predicted += round.at(x, y)[0] * M_PI / shape.area(o);
                predictedCount += shape.contains(u, o);
            }
        }
        INFO("rendered " << rendered << ", predicted " << predicted << ", round " << roundEnergy);
        CHECK(rendered == Approx(predicted).epsilon(0.02));
        CHECK(outline(trimmed).count == Approx(predictedCount).epsilon(0.05));
    }

    // Off-axis the bokeh is trimmed on the side of the frame centre: narrower radially than across.
    const Outline eye = outline([&] {
        ref::SceneSetup setup = emitterScene(96, 3.0, 20.0, 0.4, 80.0, 48.0);
        setup.camera.aperture = catEye;
        return ref::renderThinLens(setup.scene, setup.camera, settings).color;
    }());
    INFO("cat's eye " << eye.width() << " x " << eye.height());
    CHECK(eye.width() < 0.9 * eye.height());
    CHECK(eye.maxX - 80.0 > 80.0 - eye.minX);
}

TEST_CASE("shaped apertures keep a uniform or out-of-focus surface at its brightness", "[aperture][renderer]") {
    // A lens-sampled (not emitter) sphere far behind the focus, and a textured wall: the image averages
    // over the shaped aperture, so the totals do not change.
    ref::SceneSetup setup = emitterScene(64, 3.0, 20.0, 0.5, 32.0, 32.0);
    setup.scene.primitives.clear();
    const double metresPerPixel = 20.0 / (setup.camera.pixelsPerSensorUnit() * setup.camera.imageDistance());
    ref::Texture white;
    white.colorA = white.colorB = glm::vec3(1.0f);
    setup.scene.addSphere({0.0, 0.0, 20.0}, 6.0 * metresPerPixel, white);
    ref::RenderSettings settings;
    settings.lensSamples = 64;
    settings.threads = 2;
    const auto total = [&](const ref::ApertureShape& shape) {
        ref::SceneSetup shaped = setup;
        shaped.camera.aperture = shape;
        return outline(ref::renderThinLens(shaped.scene, shaped.camera, settings).color).energy;
    };
    ref::ApertureShape squeezed = blades(4, 20.0);
    squeezed.anamorphicRatio = 1.6;
    const double round = total({});
    CHECK(total(blades(6)) == Approx(round).epsilon(0.02));
    CHECK(total(squeezed) == Approx(round).epsilon(0.02));

    // A uniform wall stays exactly at its level: every pixel is an average of equal samples.
    ref::SceneSetup wall = setup;
    wall.scene.primitives.clear();
    ref::Texture grey;
    grey.colorA = grey.colorB = glm::vec3(0.25f);
    wall.scene.addQuad({0.0, 0.0, 10.0}, {50.0, 0.0, 0.0}, {0.0, 50.0, 0.0}, grey);
    wall.camera.aperture = blades(3);
    wall.camera.aperture.catEye = 1.0;
    const io::ImageRGBA flat = ref::renderThinLens(wall.scene, wall.camera, settings).color;
    for (size_t i = 0; i < flat.pixels.size(); ++i) {
        REQUIRE(flat.pixels[i] == Approx(i % 4 == 3 ? 1.0 : 0.25).epsilon(1e-6));
    }
}

TEST_CASE("with a shape the in-focus anti-aliasing and a zero aperture stay the pinhole image's",
          "[aperture][renderer]") {
    // Each sub-pixel position averages its own accepted lens samples, so the positions keep equal
    // shares whatever the shape rejects.
    ref::SceneSetup setup = ref::makeScene("near-object", 64, 40);
    setup.camera.apertureRadius = 0.0;
    setup.camera.aperture = blades(3, 40.0);
    setup.camera.aperture.anamorphicRatio = 0.6;
    setup.camera.aperture.catEye = 1.0;
    ref::RenderSettings settings;
    settings.lensSamples = 48;
    settings.threads = 2;
    const io::ImageRGBA pinhole = ref::renderPinhole(setup.scene, setup.camera, settings).color;
    const io::ImageRGBA truth = ref::renderThinLens(setup.scene, setup.camera, settings).color;
    float worst = 0.0f;
    for (size_t i = 0; i < pinhole.pixels.size(); ++i)
        worst = std::max(worst, std::abs(pinhole.pixels[i] - truth.pixels[i]));
    CHECK(worst < 1e-5f);
}

TEST_CASE("a shape that rejects every lens sample falls back to the lens centre", "[aperture][renderer]") {
    // One lens sample per pixel: where it falls outside the triangle the pixel has nothing to average;
    // it must still be the (sharp, here uniform) scene, not black.
    ref::SceneSetup setup = ref::makeScene("busy-background", 32, 18);
    setup.camera.aperture = blades(3);
    setup.camera.aperture.catEye = 1.0;
    ref::RenderSettings settings;
    settings.lensSamples = 1;
    settings.threads = 2;
    const ref::ThinLensImage one = ref::renderThinLens(setup.scene, setup.camera, settings);
    for (float value : one.color.pixels) REQUIRE(std::isfinite(value));
    setup.scene.primitives.clear();
    setup.scene.background = glm::vec3(0.5f);
    const ref::ThinLensImage uniform = ref::renderThinLens(setup.scene, setup.camera, settings);
    for (size_t i = 0; i < uniform.color.pixels.size(); ++i) {
        REQUIRE(uniform.color.pixels[i] == (i % 4 == 3 ? 1.0f : 0.5f));
    }
}
