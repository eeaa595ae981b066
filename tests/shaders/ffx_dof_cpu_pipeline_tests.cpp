// Behaviour of the whole effect, run on the CPU over small procedural scenes. Depth is the negated
// CoC radius (cocScale -1, cocBias 0: standard depth, smaller is nearer, near radii positive) so the
// scenes state the blur they want.
#include <catch2/catch.hpp>

#include "ffx_dof_blur.h"
#include "ffx_dof_dilate.h"
#include "ffx_dof_downsample_color.h"
#include "ffx_dof_cpu_pipeline.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <cstring>
#include <random>

using ffxdoftest::Layers;
using ffxdoftest::Scene;
using ffxdoftest::Settings;

namespace {

const glm::vec4 kBackground(0.1f, 0.2f, 0.6f, 1.0f);
const glm::vec4 kObject(1.0f, 1.0f, 0.0f, 1.0f);

struct Rect {
    int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    // Distance from a pixel centre outside the rectangle to the rectangle's nearest pixel centre.
    float distance(int x, int y) const {
        float dx = float(std::max({x0 - x, 0, x - (x1 - 1)}));
        float dy = float(std::max({y0 - y, 0, y - (y1 - 1)}));
        return std::hypot(dx, dy);
    }
};

Scene makeScene(uint32_t w, uint32_t h, glm::vec4 background, float backgroundCoc) {
    Scene s;
    s.width = w;
    s.height = h;
    s.color.assign(size_t(w) * h, background);
    s.depth.assign(size_t(w) * h, -backgroundCoc);
    return s;
}

// `scene` with a square light of `size` px of `value` at radius `coc` (half-res px), its top-left pixel at `at`.
Scene withLight(Scene scene, glm::ivec2 at, float value, float coc, int size = 1) {
    for (int y = at.y; y < at.y + size; ++y)
        for (int x = at.x; x < at.x + size; ++x) {
            scene.color[size_t(y) * scene.width + size_t(x)] = glm::vec4(value, value, value, 1.0f);
            scene.depth[size_t(y) * scene.width + size_t(x)] = -coc;
        }
    return scene;
}

void paint(Scene& s, const Rect& r, float coc, bool checker) {
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            size_t i = size_t(y) * s.width + size_t(x);
            s.depth[i] = -coc;
            s.color[i] = checker && ((x / 2 + y / 2) % 2) ? glm::vec4(0.9f, 0.8f, 0.05f, 1.0f) : kObject;
        }
}

bool bitIdentical(const glm::vec4& a, const glm::vec4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("A sharp object in front of a strongly blurred background: untouched and no leak", "[pipeline]") {
    // Background blurred by 32 half-res px (64 full-res px), an in-focus checkered object.
    Scene scene = makeScene(192, 128, kBackground, -32.0f);
    // Odd edges: some half-res texels straddle the silhouette.
    const Rect object{73, 41, 119, 87};
    paint(scene, object, 0.0f, true);
    Settings settings;
    settings.cocLimit = 40.0f;
    Layers layers;
    std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, settings, &layers);

    size_t changedInside = 0;
    float worstLeak = 0.0f;
    for (int y = 0; y < int(scene.height); ++y)
        for (int x = 0; x < int(scene.width); ++x) {
            size_t i = size_t(y) * scene.width + size_t(x);
            if (object.contains(x, y)) {
                changedInside += !bitIdentical(out[i], scene.color[i]);
            } else {
                // Yellow leaking into the blue background raises red and green.
                worstLeak = std::max({worstLeak, std::fabs(out[i].x - kBackground.x),
                                      std::fabs(out[i].y - kBackground.y), std::fabs(out[i].z - kBackground.z)});
            }
        }
    CHECK(changedInside == 0);
    CHECK(worstLeak < 0.01f);
    CHECK(layers.globalMaxRadius == Approx(32.0f));
    CHECK(layers.globalsAfterComposite == 0u);
}

TEST_CASE("An in-focus scene comes out bit-identical", "[pipeline]") {
    Scene scene = makeScene(70, 50, kBackground, 0.3f);  // odd half size: partial tiles
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (size_t i = 0; i < scene.color.size(); ++i) {
        scene.color[i] = glm::vec4(unit(rng), unit(rng), unit(rng), unit(rng));
        scene.depth[i] = 0.49f - unit(rng) * 0.98f;
    }
    std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, Settings{});
    size_t changed = 0;
    for (size_t i = 0; i < out.size(); ++i) changed += !bitIdentical(out[i], scene.color[i]);
    CHECK(changed == 0);
}

TEST_CASE("Far-field blur spreads a bright square by about its radius and keeps its energy", "[pipeline]") {
    const float radius = 12.0f;  // half-res px = 24 full-res px
    Scene scene = makeScene(160, 128, glm::vec4(0, 0, 0, 1), -radius);
    const Rect square{76, 60, 84, 68};
    for (int y = square.y0; y < square.y1; ++y)
        for (int x = square.x0; x < square.x1; ++x) scene.color[size_t(y) * scene.width + size_t(x)] = glm::vec4(1);
    std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, Settings{});

    double energyIn = 0.0, energyOut = 0.0, litInside = 0.0, insideCount = 0.0, outsideMax = 0.0;
    for (int y = 0; y < int(scene.height); ++y)
        for (int x = 0; x < int(scene.width); ++x) {
            size_t i = size_t(y) * scene.width + size_t(x);
            energyIn += scene.color[i].x;
            energyOut += out[i].x;
            float d = square.distance(x, y);
            if (d > 2.0f && d < 2.0f * radius - 6.0f) {
                litInside += out[i].x > 1e-3f;
                insideCount += 1.0;
            }
            if (d > 2.0f * radius + 6.0f) outsideMax = std::max(outsideMax, double(out[i].x));
        }
    INFO("energy in " << energyIn << ", out " << energyOut);
    CHECK(energyOut == Approx(energyIn).epsilon(0.25));
    CHECK(litInside / insideCount > 0.95);
    CHECK(outsideMax < 1e-3);
}

TEST_CASE("A near-field object spreads over the in-focus background", "[pipeline]") {
    Scene scene = makeScene(160, 128, kBackground, 0.0f);
    const Rect object{60, 44, 100, 84};
    paint(scene, object, 10.0f, false);
    Layers layers;
    std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, Settings{}, &layers);

    double spreadNear = 0.0, nearCount = 0.0;
    size_t changedFar = 0;
    for (int y = 0; y < int(scene.height); ++y)
        for (int x = 0; x < int(scene.width); ++x) {
            if (object.contains(x, y)) continue;
            size_t i = size_t(y) * scene.width + size_t(x);
            float d = object.distance(x, y);
            if (d >= 1.0f && d <= 6.0f) {
                // Yellow over blue: red rises where the blurred foreground covers the background.
                spreadNear += out[i].x - kBackground.x;
                nearCount += 1.0;
            }
            if (d > 2.0f * 10.0f + 12.0f) changedFar += !bitIdentical(out[i], scene.color[i]);
        }
    CHECK(spreadNear / nearCount > 0.1);
    CHECK(changedFar == 0);
}

TEST_CASE("An isolated near pixel over an in-focus wall keeps its light at every near radius from 1 px", "[pipeline]") {
    // A speck in front of the focus (dust, a snowflake): one pixel of a near radius over a black in-focus wall, at a
    // quad's corner and inside one. Until 2026-11-30 the colour downsample's bilateral reduction dropped a near
    // pixel 1.25 half-res px or more from its quad's reference radius unless the pixel's radius was at least 2
    // (FFX_DOF_NEAR_COVERAGE_MIN_RADIUS), and no layer held it: from radius 1.25 to 1.75 it kept 0.026 to 0.051 of
    // its light. Each radius's figure is printed. Before 7aea5e0 the radii 1.25 and 2.25 added 1.09 and 1.06:
    // the blur weighed near samples by 1 / r^2 where the texel grid's disc is not pi r^2 (ffxDofNearGridAreaScale),
    // the composite's 3 x 3 opacity mean kept each texel's own colour (ffxDofPostFilterTexel) and the near layer's
    // rim mixed in the colour of texels it does not cover (ffxDofComposePixel); radius 1 then added 1.052, where
    // the speck's own pixel showed its own full-res gather (0.080 of its light) in place of the layers (0.028),
    // which keep that light in the pixels around (a near pixel covering little of its disc now shows mostly the
    // layers).
    const uint32_t w = 64, h = 64;
    const Scene wall = makeScene(w, h, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), 0.0f);
    Settings settings;
    settings.cocLimit = 16.4f;
    for (const glm::ivec2 at : {glm::ivec2(32, 32), glm::ivec2(33, 35)}) {
        for (float coc = 1.0f; coc <= 4.0f; coc += 0.25f) {
            Scene speck = wall;
            speck.color[size_t(at.y) * w + size_t(at.x)] = glm::vec4(1.0f, 1.0f, 1.0f, 1.0f);
            speck.depth[size_t(at.y) * w + size_t(at.x)] = -coc;
            double energy = 0.0;
            for (const glm::vec4& pixel : ffxdoftest::runPipeline(speck, settings)) energy += pixel.y;
            std::printf("isolated near pixel of radius %.2f half-res px at (%d, %d): adds %.3f of its light\n", coc,
                        at.x, at.y, energy);
            INFO("near radius " << coc << " half-res px at (" << at.x << ", " << at.y << "): adds " << energy);
            CHECK(energy >= 0.95);
            CHECK(energy <= 1.05);
        }
    }
}

TEST_CASE("Dilation never under-dilates (brute force over tile pairs)", "[pipeline]") {
    // Random blocks of radii, including large near and far ones.
    Scene scene = makeScene(256, 192, kBackground, 0.0f);
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> px(0, 255), py(0, 191), size(4, 40);
    std::uniform_real_distribution<float> coc(-30.0f, 30.0f);
    for (int block = 0; block < 40; ++block) {
        int x = px(rng), y = py(rng);
        Rect r{x, y, std::min(x + size(rng), 256), std::min(y + size(rng), 192)};
        paint(scene, r, coc(rng), false);
    }
    Settings settings;
    settings.maxRings = 4;
    Layers layers;
    ffxdoftest::runPipeline(scene, settings, &layers);

    const int t = FFX_DOF_TILE_SIZE;
    for (int cy = 0; cy < int(layers.tilesY); ++cy)
        for (int cx = 0; cx < int(layers.tilesX); ++cx) {
            glm::vec4 dilated = layers.dilatedTiles[size_t(cy) * layers.tilesX + size_t(cx)];
            for (int ty = 0; ty < int(layers.tilesY); ++ty)
                for (int tx = 0; tx < int(layers.tilesX); ++tx) {
                    glm::vec2 tile = layers.tiles[size_t(ty) * layers.tilesX + size_t(tx)];
                    // Shortest pixel-centre distance between the two tiles, by brute force.
                    int gapX = std::max(std::abs(tx - cx) * t - (t - 1), 0);
                    int gapY = std::max(std::abs(ty - cy) * t - (t - 1), 0);
                    float gap = std::hypot(float(gapX), float(gapY));
                    // A sample reaches up to radius + 0.5 (ffxDofReach).
                    if (tile.y > 0.0f && tile.y + 0.5f > gap) REQUIRE(dilated.y >= tile.y);
                    if (tile.x < 0.0f && -tile.x + 0.5f > gap) REQUIRE(dilated.x <= tile.x);
                    // The footprint range holds every tile the tile's kernels can read.
                    float kernelRadius = std::max({dilated.y, -dilated.x, 0.0f});
                    if (gap <= ffxDofKernelFootprintRadius(kernelRadius, settings.maxRings)) {
                        REQUIRE(dilated.z <= tile.x);
                        REQUIRE(dilated.w >= tile.y);
                    }
                }
        }
}

TEST_CASE("Every blur tile class occurs, and each path gives what the mixed path gives", "[pipeline]") {
    // Textured everywhere, so that a difference in weights shows in the colors.
    Scene scene = makeScene(448, 224, kBackground, -6.0f);  // flat far field: equal weights (far)
    for (size_t i = 0; i < scene.color.size(); ++i) {
        uint32_t h = uint32_t(i) * 2654435761u;
        scene.color[i] = glm::vec4(float(h >> 24) / 255.0f, float((h >> 16) & 255u) / 255.0f, 0.5f, 1.0f);
    }
    auto setCoc = [&](const Rect& r, auto cocAt) {
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) scene.depth[size_t(y) * scene.width + size_t(x)] = -cocAt(x, y);
    };
    setCoc(Rect{0, 0, 96, 224}, [](int x, int) { return -3.0f - 0.06f * float(x); });  // far gradient: far-only
    setCoc(Rect{224, 0, 320, 112}, [](int, int) { return 4.0f; });                     // flat near: equal (near)
    setCoc(Rect{224, 112, 320, 224}, [](int x, int) { return 3.0f + 0.03f * float(x - 224); });  // near-only
    setCoc(Rect{336, 0, 448, 224}, [](int, int) { return 0.0f; });  // in focus: copy inside
    Settings settings;
    Layers classified, mixed;
    std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, settings, &classified);
    settings.forceMixedBlurPath = true;
    ffxdoftest::runPipeline(scene, settings, &mixed);

    uint32_t tilesOfClass[FFX_DOF_BLUR_CLASS_COUNT] = {};
    for (uint32_t tileClass : classified.tileClasses) ++tilesOfClass[tileClass];
    INFO("tiles: copy " << tilesOfClass[FFX_DOF_BLUR_CLASS_COPY] << ", equal far "
                        << tilesOfClass[FFX_DOF_BLUR_CLASS_EQUAL_FAR] << ", equal near "
                        << tilesOfClass[FFX_DOF_BLUR_CLASS_EQUAL_NEAR] << ", far-only "
                        << tilesOfClass[FFX_DOF_BLUR_CLASS_FAR_ONLY] << ", near-only "
                        << tilesOfClass[FFX_DOF_BLUR_CLASS_NEAR_ONLY] << ", mixed "
                        << tilesOfClass[FFX_DOF_BLUR_CLASS_MIXED]);
    for (uint32_t count : tilesOfClass) CHECK(count >= 2u);

    // Far-only, near-only and copy leave out only sums that are zero on their tiles: bit-identical.
    // Equal weights on a region of one radius: the same weights, up to float rounding.
    float worstEqual = 0.0f;
    size_t differingExact = 0;
    for (uint32_t y = 0; y < classified.halfHeight; ++y)
        for (uint32_t x = 0; x < classified.halfWidth; ++x) {
            size_t i = size_t(y) * classified.halfWidth + x;
            uint32_t tileClass =
                classified.tileClasses[size_t(y / FFX_DOF_TILE_SIZE) * classified.tilesX + x / FFX_DOF_TILE_SIZE];
            glm::vec3 nearDiff = glm::abs(classified.nearColor[i] - mixed.nearColor[i]);
            glm::vec3 farDiff = glm::abs(classified.farColor[i] - mixed.farColor[i]);
            glm::vec2 alphaDiff = glm::abs(classified.layerAlpha[i] - mixed.layerAlpha[i]);
            float worst = std::max(
                {nearDiff.x, nearDiff.y, nearDiff.z, farDiff.x, farDiff.y, farDiff.z, alphaDiff.x, alphaDiff.y});
            if (tileClass == FFX_DOF_BLUR_CLASS_EQUAL_FAR || tileClass == FFX_DOF_BLUR_CLASS_EQUAL_NEAR)
                worstEqual = std::max(worstEqual, worst);
            else if (tileClass != FFX_DOF_BLUR_CLASS_MIXED)
                differingExact += worst != 0.0f;
        }
    CHECK(differingExact == 0u);
    CHECK(worstEqual <= 1e-4f);
    for (const glm::vec4& pixel : out) REQUIRE(std::isfinite(pixel.x + pixel.y + pixel.z));
}

TEST_CASE(
    "Own-surface tiles without lights take the class without the lights' code, and compose as the lights' class "
    "would",
    "[pipeline]") {
    // A slight blur over a textured field (radii 1 to 3 half-res px: every tile gathers its own surface at full
    // resolution), a near patch, and small lights above white in one corner: the tiles their light reaches, or that
    // lie beside a tile that gave light, take LIGHTS, the others FULL_RES (ffxDofCompositeTileClass). Composed by the
    // LIGHTS pipeline instead, the FULL_RES tiles must come out the same to the bit: what FULL_RES leaves out adds
    // nothing there.
    const uint32_t w = 256, h = 160;
    Scene scene = makeScene(w, h, kBackground, -2.0f);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            const uint32_t hash = uint32_t(i) * 2654435761u;
            scene.color[i] = glm::vec4(float(hash >> 24) / 255.0f, float((hash >> 16) & 255u) / 255.0f, 0.5f, 1.0f);
            scene.depth[i] = 1.2f + 1.4f * float(x) / float(w);  // radius -1.2 to -2.6: far, gathered at full res
        }
    paint(scene, Rect{150, 90, 190, 130}, 2.0f, true);  // near, gathered at full resolution too
    scene = withLight(scene, glm::ivec2(20, 20), 60.0f, -2.5f, 2);
    scene = withLight(scene, glm::ivec2(44, 30), 30.0f, -2.0f, 1);
    Settings settings;
    settings.cocLimit = 4.0f;
    Layers classified, lightsEverywhere;
    const std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, settings, &classified);
    settings.forceLightsCompositePath = true;
    const std::vector<glm::vec4> forced = ffxdoftest::runPipeline(scene, settings, &lightsEverywhere);

    uint32_t tilesOfClass[FFX_DOF_COMPOSITE_CLASS_COUNT] = {};
    for (const uint32_t compositeClass : classified.compositeClasses) ++tilesOfClass[compositeClass];
    INFO("tiles: copy " << tilesOfClass[FFX_DOF_COMPOSITE_CLASS_COPY] << ", layers "
                        << tilesOfClass[FFX_DOF_COMPOSITE_CLASS_LAYERS] << ", full resolution "
                        << tilesOfClass[FFX_DOF_COMPOSITE_CLASS_FULL_RES] << ", lights "
                        << tilesOfClass[FFX_DOF_COMPOSITE_CLASS_LIGHTS]);
    CHECK(tilesOfClass[FFX_DOF_COMPOSITE_CLASS_FULL_RES] >= 100u);
    CHECK(tilesOfClass[FFX_DOF_COMPOSITE_CLASS_LIGHTS] >= 4u);
    // The lights' tiles are the corner's; a tile beside one that gave light is one of them.
    for (size_t tile = 0; tile < classified.compositeClasses.size(); ++tile) {
        const uint32_t tx = uint32_t(tile % classified.tilesX), ty = uint32_t(tile / classified.tilesX);
        INFO("tile " << tx << ", " << ty);
        if ((classified.blurTileFlags[tile] & uint32_t(FFX_DOF_LISTED_TILE_LIGHTS)) != 0u)
            CHECK(classified.compositeClasses[tile] == uint32_t(FFX_DOF_COMPOSITE_CLASS_LIGHTS));
        if (tx >= 6u || ty >= 6u) CHECK(classified.compositeClasses[tile] != uint32_t(FFX_DOF_COMPOSITE_CLASS_LIGHTS));
    }
    // The lights are drawn: the corner holds more than the field's light.
    const glm::vec4 lightCentre = out[size_t(21) * w + 21];
    CHECK(lightCentre.x > 2.0f);
    size_t differing = 0;
    for (size_t i = 0; i < out.size(); ++i) differing += out[i] != forced[i];
    CHECK(differing == 0u);
}

TEST_CASE("Tiles hold the CoC range of their pixels", "[pipeline]") {
    Scene scene = makeScene(100, 60, kBackground, -3.0f);
    paint(scene, Rect{20, 10, 21, 11}, 7.5f, false);
    paint(scene, Rect{40, 40, 42, 41}, -20.0f, false);
    Layers layers;
    ffxdoftest::runPipeline(scene, Settings{}, &layers);
    REQUIRE(layers.tilesX == 7u);  // ceil(ceil(100 / 2) / 8)
    REQUIRE(layers.tilesY == 4u);
    CHECK(layers.tiles[0 * 7 + 1] == glm::vec2(-3.0f, 7.5f));    // pixel (20, 10) is in tile (1, 0)
    CHECK(layers.tiles[2 * 7 + 2] == glm::vec2(-20.0f, -3.0f));  // pixel (40, 40) is in tile (2, 2)
    CHECK(layers.tiles[3 * 7 + 6] == glm::vec2(-3.0f, -3.0f));
    CHECK(layers.globalMaxRadius == 20.0f);
}

TEST_CASE("Tiles hold the largest colour channel of their pixels, clamped to the half range", "[pipeline]") {
    Scene scene = makeScene(100, 60, glm::vec4(0.2f, 0.3f, 0.1f, 1.0f), -3.0f);
    scene.color[size_t(10) * 100 + 20] = glm::vec4(0.5f, 7.0f, 2.0f, 1.0f);              // tile (1, 0)
    scene.color[size_t(40) * 100 + 40] = glm::vec4(1.0e6f, 0.0f, 0.0f, 1.0f);            // tile (2, 2)
    scene.color[size_t(40) * 100 + 70] = glm::vec4(std::nanf(""), -50.0f, 0.25f, 1.0f);  // tile (4, 2)
    Layers layers;
    ffxdoftest::runPipeline(scene, Settings{}, &layers);
    REQUIRE(layers.tileColorPeaks.size() == 7u * 4u);
    CHECK(layers.tileColorPeaks[0 * 7 + 1] == 7.0f);
    CHECK(layers.tileColorPeaks[2 * 7 + 2] == 65504.0f);
    // NaN and negative channels never set a peak (ffxDofColorPeak): the background's 0.3 remains.
    CHECK(layers.tileColorPeaks[2 * 7 + 4] == 0.3f);
    CHECK(layers.tileColorPeaks[3 * 7 + 6] == 0.3f);
}

TEST_CASE("In-focus pixels behave the same whatever the sign of their tiny radius", "[pipeline]") {
    // A surface exactly at the focus has radius 0 up to rounding; whether that comes out as +1e-4 or
    // -1e-4 depends on the depth encoding and must not change the image (it once switched ring merging
    // off in the far-field tiles next to the band, through the dilated near radius).
    auto makeBandScene = [](float bandCoc) {
        Scene scene = makeScene(160, 96, kBackground, -8.0f);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        for (glm::vec4& c : scene.color) c = glm::vec4(unit(rng), unit(rng), unit(rng), 1.0f);
        for (int y = 0; y < int(scene.height); ++y)
            for (int x = 60; x < 84; ++x) scene.depth[size_t(y) * scene.width + size_t(x)] = -bandCoc;
        return scene;
    };
    std::vector<glm::vec4> positive = ffxdoftest::runPipeline(makeBandScene(1e-4f), Settings{});
    std::vector<glm::vec4> negative = ffxdoftest::runPipeline(makeBandScene(-1e-4f), Settings{});
    double worst = 0.0, sum = 0.0;
    for (size_t i = 0; i < positive.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = std::fabs(double(positive[i][c]) - double(negative[i][c]));
            worst = std::max(worst, d);
            sum += d;
        }
    INFO("max difference " << worst << ", mean " << sum / double(positive.size() * 3));
    // The blend weights of the composite and the bilateral weights see 2e-4 px of radius: far below
    // one step of an 8-bit output.
    CHECK(worst < 1e-3);
}

TEST_CASE("A small far light in front of a farther background keeps its energy and loses its core", "[pipeline]") {
    // With ring merging (this binary): inner rings read from a coarser MIP place a light's energy up to
    // a MIP texel from where it is, and the kernel's rim cuts some of it; 90 to 96% measured over light
    // sizes and positions. Without merging, tests/shaders/ffx_dof_cpu_bokeh_tests.cpp holds it to 5%.
    for (const ffxdoftest::LightCase& light : ffxdoftest::runSmallFarLightCases()) {
        INFO("light " << light.size << " px: energy added " << light.energyAdded << " of " << light.inputEnergy
                      << ", centre " << light.centre << " (disc level " << light.discLevel << ")");
        CHECK(light.energyAdded == Approx(light.inputEnergy).epsilon(0.12));
        CHECK(light.centre == Approx(light.discLevel).epsilon(0.20).margin(0.05));
    }
}

TEST_CASE("A single bright far pixel's disc with ring merging: flat and of its energy", "[pipeline]") {
    // Where the outermost ring (full resolution) meets the merged inner rings (a coarser MIP), and the
    // merged rings meet the centre ring, each side judged the border by its own texels' centres: the
    // point was read twice or not at all there, a notched rim and a dip near the centre (issue 17:
    // flatness 0.03 to 0.35 at radii 4.8 to 9). Both sides now judge by the coarse texels.
    for (const float radius : {4.8f, 9.0f, 13.35f}) {
        for (int position = 0; position < 2; ++position) {
            // At white: a light above it leaves this layer for the composite (ffx_dof_highlights.h).
            const ffxdoftest::PointDisc disc = ffxdoftest::measurePointDisc(radius, position, 0u, 1.0f);
            INFO("radius " << radius << ", position " << position << ": energy " << disc.energy << ", flatness "
                           << disc.flatness);
            CHECK(disc.energy == Approx(0.25).epsilon(0.04));
            CHECK(disc.flatness < 0.05);
        }
    }
}

TEST_CASE("A far light brighter than white gets a disc nearer the truth's size than a dim one", "[pipeline]") {
    // One half-res texel of light (2 x 2 px) on black, far field, radius 6 half-res px: the thin-lens
    // disc has a radius of 12 full-res px, so its light's mean squared distance from the centre is
    // 12^2 / 2. A dim light (disc level far below white) spreads over its full radius, rim ramp and
    // upsample included; a light above white is drawn at full resolution by the composite (ffx_dof_highlights.h),
    // so its outline comes nearer the truth's, and both keep their energy.
    // Glow: the brightest output beyond the disc's radius + 1.5 px (and the light's own half diagonal) over the
    // disc's level.
    const auto measure = [](float value, double& energyKept, double& radius, double& glow) {
        Scene scene = makeScene(96, 80, glm::vec4(0, 0, 0, 1), -6.0f);
        for (int y = 40; y < 42; ++y)
            for (int x = 48; x < 50; ++x)
                scene.color[size_t(y) * scene.width + size_t(x)] = glm::vec4(value, value, value, 1);
        const std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, Settings{});
        double energy = 0.0, moment = 0.0, beyond = 0.0;
        for (size_t i = 0; i < out.size(); ++i) {
            const double dx = double(i % scene.width) + 0.5 - 49.0, dy = double(i / scene.width) + 0.5 - 41.0;
            energy += out[i].y;
            moment += out[i].y * (dx * dx + dy * dy);
            if (std::hypot(dx, dy) > 12.0 + 1.5 + std::sqrt(0.5)) beyond = std::max(beyond, double(out[i].y));
        }
        energyKept = energy / (4.0 * value);
        radius = std::sqrt(2.0 * moment / energy);  // a flat disc's radius
        glow = beyond / (4.0 * value / (3.14159265358979 * 144.0));
    };
    double dimEnergy = 0.0, dimRadius = 0.0, dimGlow = 0.0, brightEnergy = 0.0, brightRadius = 0.0, brightGlow = 0.0;
    measure(0.5f, dimEnergy, dimRadius, dimGlow);             // disc level 0.5 * 4 / (pi 12^2): 0.004
    measure(500.0f, brightEnergy, brightRadius, brightGlow);  // 4.4
    INFO("dim: energy " << dimEnergy << ", radius " << dimRadius << ", glow " << dimGlow << "; bright: energy "
                        << brightEnergy << ", radius " << brightRadius << ", glow " << brightGlow << " (truth 12)");
    // The half-res layers' rim spreads 2 px beyond the disc (the dim light's); the full-resolution disc's does not.
    CHECK(dimGlow > 0.02);
    CHECK(brightGlow < 0.02);
    CHECK(dimEnergy == Approx(1.0).epsilon(0.015));  // measured 0.990 and 1.005
    CHECK(brightEnergy == Approx(1.0).epsilon(0.015));
    CHECK(dimRadius > 12.0);
    // Since 2026-11-30 a light above white leaves the layers and the composite draws it at full resolution
    // (ffx_dof_highlights.h): 12.07 (11.69 with the layers' inset, 0.5 full-res px, before).
    CHECK(std::abs(brightRadius - 12.0) < 0.15);
    CHECK(std::abs(brightRadius - 12.0) < std::abs(dimRadius - 12.0));
    // Both outlines within 0.35 px of the truth (measured 12.16 and 11.69). Before the rim border moved
    // in where merged rings meet the outermost ring (ffxDofWalkBorderRadius), the dim disc bulged
    // toward its coarse texel's centre and this held the bright one nearer the truth than the dim one.
    // Until merged rings drew a coarse texel's light where it lies in the texel (its light offset), they
    // drew this light half a half-res px off in x and y, which widened its spread about its own centre:
    // 12.18 and 11.75 then, within 0.3. The inset stays at 0.25 half-res px: 0.2 brings the bright disc
    // to 11.78 here but costs far-highlights 0.22 dB and mid-lights 0.16 against the truth.
    CHECK(std::abs(dimRadius - 12.0) < 0.35);
    CHECK(std::abs(brightRadius - 12.0) < 0.35);
}

TEST_CASE("HDR: colour far above the half range stays finite, is blurred and keeps its energy", "[pipeline][hdr]") {
    // Issue 13: a patch of 16,400 (or 1e5, or a sun of 1e6) used to come out black with inf/NaN
    // around it. The effect scales such frames into its range by a power of two (docs/technique.md).
    struct Case {
        const char* name;
        Rect rect;
        float value;
        float coc;  // of the patch (the black background is far, radius 6)
    };
    const Case cases[] = {
        {"sun of 1e6 (far)", {94, 78, 98, 82}, 1e6f, -6.0f},
        {"patch of 16400 (far)", {80, 64, 112, 96}, 16400.0f, -6.0f},
        {"patch of 1e5 (far)", {80, 64, 112, 96}, 1e5f, -6.0f},
        {"patch of 1e5 (near)", {80, 64, 112, 96}, 1e5f, 5.0f},
        {"patch of 1e30 (far)", {80, 64, 112, 96}, 1e30f, -6.0f},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        Scene scene = makeScene(192, 160, glm::vec4(0, 0, 0, 1), -6.0f);
        // The same scene at an intensity the effect handles without scaling, and as far above white as
        // the HDR one, so that both take the same highlight paths and differ only by the colour scale.
        Scene reference = scene;
        const float low = 1000.0f;
        for (int y = c.rect.y0; y < c.rect.y1; ++y)
            for (int x = c.rect.x0; x < c.rect.x1; ++x) {
                const size_t i = size_t(y) * scene.width + size_t(x);
                scene.color[i] = glm::vec4(c.value, c.value, c.value, 1.0f);
                scene.depth[i] = -c.coc;
                reference.color[i] = glm::vec4(low, low, low, 1.0f);
                reference.depth[i] = -c.coc;
            }
        Layers layers, lowLayers;
        const std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, Settings{}, &layers);
        const std::vector<glm::vec4> lowOut = ffxdoftest::runPipeline(reference, Settings{}, &lowLayers);
        // Pass 2 runs a second time, scaled, for the frame above the range only.
        CHECK(layers.colorRangeRerun);
        CHECK_FALSE(lowLayers.colorRangeRerun);
        CHECK(lowLayers.colorScale == 1.0f);
        CHECK(layers.colorPeak == c.value);
        CHECK(layers.colorScale == ffxDofColorRangeScale(c.value));
        CHECK(layers.colorScale < 1.0f);
        CHECK(layers.globalsAfterComposite == 0u);
        double energyIn = 0.0, energyOut = 0.0, lowIn = 0.0, lowEnergyOut = 0.0;
        size_t nonFinite = 0, spread = 0;
        for (size_t i = 0; i < out.size(); ++i) {
            for (int ch = 0; ch < 3; ++ch) nonFinite += !std::isfinite(out[i][ch]);
            energyIn += double(scene.color[i].x) + scene.color[i].y + scene.color[i].z;
            energyOut += double(out[i].x) + out[i].y + out[i].z;
            lowIn += double(reference.color[i].x) + reference.color[i].y + reference.color[i].z;
            lowEnergyOut += double(lowOut[i].x) + lowOut[i].y + lowOut[i].z;
            const int x = int(i % scene.width), y = int(i / scene.width);
            spread += !c.rect.contains(x, y) && out[i].x > 1e-3 * c.value;
        }
        CHECK(nonFinite == 0);
        CHECK(spread > 0);  // blurred, not copied
        // Energy: as well kept as at an ordinary intensity within 1% (the HDR path is the same blur,
        // scaled), and near the input's.
        INFO("energy in " << energyIn << ", out " << energyOut << "; at low intensity in " << lowIn << ", out "
                          << lowEnergyOut);
        CHECK(energyOut / energyIn == Approx(lowEnergyOut / lowIn).epsilon(0.01));
        // Issue 13: image sums within 1% (measured 0.1 to 0.5%; the near patch lost 4.7% through the
        // technique's cubic near-layer weight, now ffxDofNearLayerWeight).
        CHECK(std::abs(energyOut / energyIn - 1.0) <= 0.01);
    }
}

TEST_CASE("HDR: pass 2 runs again only for a channel above the range limit, wherever it lies", "[pipeline][hdr]") {
    // One pixel at, or just above, FFX_DOF_COLOR_RANGE_LIMIT, in the first, an inner and the last tile, on a border
    // row and column: the first run arms the second (and raises the frame's peak) from any tile's own pixels.
    const float above = std::nextafter(FFX_DOF_COLOR_RANGE_LIMIT, 1e30f);
    const int pixels[][2] = {{0, 0}, {37, 21}, {69, 49}};
    for (const auto& pixel : pixels) {
        for (const float value : {FFX_DOF_COLOR_RANGE_LIMIT, above}) {
            INFO("pixel " << pixel[0] << ", " << pixel[1] << ": " << value);
            Scene scene = makeScene(70, 50, kBackground, -4.0f);
            scene.color[size_t(pixel[1]) * scene.width + size_t(pixel[0])] = glm::vec4(value, 0.5f, 0.5f, 1.0f);
            Layers layers;
            ffxdoftest::runPipeline(scene, Settings{}, &layers);
            CHECK(layers.colorRangeRerun == (value > FFX_DOF_COLOR_RANGE_LIMIT));
            CHECK(layers.colorPeak == (value > FFX_DOF_COLOR_RANGE_LIMIT ? value : 0.0f));
            CHECK(layers.colorScale == ffxDofColorRangeScale(value));
        }
    }
}

TEST_CASE("HDR: an in-focus frame above the range is still copied bit for bit", "[pipeline][hdr]") {
    Scene scene = makeScene(70, 50, kBackground, 0.3f);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> exponent(-30.0f, 120.0f);
    for (size_t i = 0; i < scene.color.size(); ++i) {
        scene.color[i] = glm::vec4(std::exp2(exponent(rng)), std::exp2(exponent(rng)), std::exp2(exponent(rng)), 1.0f);
        scene.depth[i] = ((i * 7) % 10 - 4.5f) * 0.1f;  // |radius| < 0.5
    }
    std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, Settings{});
    size_t changed = 0;
    for (size_t i = 0; i < out.size(); ++i) changed += !bitIdentical(out[i], scene.color[i]);
    CHECK(changed == 0);
}

TEST_CASE("A small light far in front of its background keeps its energy at a radius below a coarse texel",
          "[pipeline]") {
    // Issue 17's minimal case at 3 half-res px in front of a background at 16, whose kernels read from
    // MIP 1 with merged rings at MIP 2 (4 half-res px texels). Merged, the light was drawn around the
    // coarse texels' centres while its own texels gathered it where it is: lights of 7 and 11 px gained
    // 20% and 18% (3 and 5 px: 4% and 12%; ffxDofMergedRingsResolve). Measured 0.981 and 1.040 now. Two
    // sizes only: the test is among the slowest under ASan.
    for (const ffxdoftest::LightCase& light : ffxdoftest::runSmallFarLightCases(3.0f, {7, 11})) {
        INFO(light.size << " px: energy added " << light.energyAdded / light.inputEnergy);
        CHECK(light.energyAdded / light.inputEnergy == Approx(1.0).epsilon(0.05));
    }
}

namespace {

// Issue 17's small far light (value 50 in front of a background of 0.05) with an anti-aliased rim: the
// ring of pixels around `light` that the light covers in part, at the background's depth (a depth
// buffer holds one surface per pixel).
constexpr float kRimBackgroundRadius = 16.0f, kRimLightRadius = 6.0f;  // far field, half-res px
constexpr float kRimBackgroundValue = 0.05f, kRimLightValue = 50.0f;

Scene makeRimBackground() {
    const glm::vec4 background(kRimBackgroundValue, kRimBackgroundValue, kRimBackgroundValue, 1.0f);
    return makeScene(128, 96, background, -kRimBackgroundRadius);
}

Scene makeRimmedLightScene(const Rect& light) {
    Scene scene = makeRimBackground();
    for (int y = light.y0 - 1; y < light.y1 + 1; ++y)
        for (int x = light.x0 - 1; x < light.x1 + 1; ++x) {
            const size_t i = size_t(y) * scene.width + size_t(x);
            // The light covers a quarter of a pixel beside its edges, a twentieth at its corners.
            const bool besideEdge = (x >= light.x0 && x < light.x1) || (y >= light.y0 && y < light.y1);
            const float coverage = light.contains(x, y) ? 1.0f : (besideEdge ? 0.25f : 0.05f);
            const float value = kRimBackgroundValue + coverage * (kRimLightValue - kRimBackgroundValue);
            scene.color[i] = glm::vec4(value, value, value, 1.0f);
            if (light.contains(x, y)) scene.depth[i] = kRimLightRadius;  // radius = -depth: far field
        }
    return scene;
}

// What the light adds to the output (RGB summed) over what it adds to the input, and the centre of
// what it adds to the output (full-res px, pixel centres at + 0.5). `outWithout`: the output of
// makeRimBackground.
struct AddedLight {
    double energyRatio = 0.0;
    glm::dvec2 centre{0.0};
};

AddedLight measureRimmedLight(const Rect& light, const std::vector<glm::vec4>& outWithout, Layers* layers) {
    const Scene with = makeRimmedLightScene(light), without = makeRimBackground();
    const std::vector<glm::vec4> outWith = ffxdoftest::runPipeline(with, Settings{}, layers);
    double inputAdded = 0.0, outputAdded = 0.0;
    glm::dvec2 moment(0.0);
    for (size_t i = 0; i < outWith.size(); ++i) {
        const glm::vec4 added = outWith[i] - outWithout[i], inputChange = with.color[i] - without.color[i];
        const double sum = double(added.x) + added.y + added.z;
        inputAdded += double(inputChange.x) + inputChange.y + inputChange.z;
        outputAdded += sum;
        moment += sum * glm::dvec2(double(i % with.width) + 0.5, double(i / with.width) + 0.5);
    }
    return {outputAdded / inputAdded, moment / outputAdded};
}

}  // namespace

TEST_CASE("A far light at a tile corner: its anti-aliased rim in the next tiles keeps the light's energy and place",
          "[pipeline]") {
    // Pass 2 gives a light's rim the light's radius (ffxDofLightRimCoc), reading the light across a tile
    // border through its one-pixel border. Pass 1 sees depth only, so a tile that holds the rim but no
    // pixel of the light holds the background's radius alone while its rim texels carry the light's: the
    // dilated footprint must still cover them (the blur's tile class and ring merging depend on it).
    const int tileSide = 2 * FFX_DOF_TILE_SIZE;  // full-res px
    // 2 x 2 px straddling the vertical tile border at x = 64 and resting on the horizontal one at y = 48:
    // the bottom rim row lies in tiles without a pixel of the light.
    const Rect light{4 * tileSide - 1, 3 * tileSide - 2, 4 * tileSide + 1, 3 * tileSide};
    const std::vector<glm::vec4> outWithout = ffxdoftest::runPipeline(makeRimBackground(), Settings{});
    Layers layers;
    const AddedLight atBorder = measureRimmedLight(light, outWithout, &layers);

    // The premise: the rim texels below the light, in tiles of the background's radius only, took the
    // light's nearer radius.
    const uint32_t rimY = uint32_t(light.y1 / 2);
    for (const uint32_t rimX : {uint32_t(light.x0 / 2), uint32_t(light.x1 / 2)}) {
        const size_t tile = size_t(rimY / FFX_DOF_TILE_SIZE) * layers.tilesX + rimX / FFX_DOF_TILE_SIZE;
        const float rimCoc = layers.coc0[size_t(rimY) * layers.halfWidth + rimX];
        const glm::vec4 dilated = layers.dilatedTiles[tile];
        INFO("rim texel (" << rimX << ", " << rimY << "): radius " << rimCoc << ", own tile " << layers.tiles[tile].x
                           << " to " << layers.tiles[tile].y << ", footprint " << dilated.z << " to " << dilated.w);
        CHECK(layers.tiles[tile] == glm::vec2(-kRimBackgroundRadius, -kRimBackgroundRadius));
        CHECK(rimCoc > -kRimBackgroundRadius + 1.0f);
    }
    // Every texel's radius lies within its tile's footprint range (up to the rounding of pass 2's
    // luminance-weighted mean of radii).
    size_t outsideFootprint = 0;
    for (uint32_t y = 0; y < layers.halfHeight; ++y)
        for (uint32_t x = 0; x < layers.halfWidth; ++x) {
            const glm::vec4 dilated =
                layers.dilatedTiles[size_t(y / FFX_DOF_TILE_SIZE) * layers.tilesX + x / FFX_DOF_TILE_SIZE];
            const float coc = layers.coc0[size_t(y) * layers.halfWidth + x];
            outsideFootprint += coc < dilated.z - 1e-4f || coc > dilated.w + 1e-4f;
        }
    CHECK(outsideFootprint == 0u);

    // Where the disc goes: across the vertical border, on the light (left and right of it are mirror
    // images, and so are the MIP texels read). Along y, the background's kernels read the light from merged
    // rings of coarse texels (4 half-res px) and draw its disc about their centre (ffx_dof_blur.h, before
    // ffxDofMergedRingsResolve), up to 4 full-res px from the light; so the reference is the same light one
    // such texel higher, its rim inside the tiles that hold the light: the tile border must not move the disc.
    const Rect inside{light.x0, light.y0 - 8, light.x1, light.y1 - 8};
    const AddedLight inTile = measureRimmedLight(inside, outWithout, nullptr);
    const glm::dvec2 lightCentre(0.5 * (light.x0 + light.x1), 0.5 * (light.y0 + light.y1));
    INFO("at the border: energy added " << atBorder.energyRatio << " of the input's, disc centre " << atBorder.centre.x
                                        << ", " << atBorder.centre.y << " (light " << lightCentre.x << ", "
                                        << lightCentre.y << "); 8 px higher: energy added " << inTile.energyRatio
                                        << ", disc centre moved down by 8 px " << inTile.centre.x << ", "
                                        << inTile.centre.y + 8.0);
    CHECK(atBorder.energyRatio == Approx(1.0).epsilon(0.05));  // issue 17's gate
    CHECK(inTile.energyRatio == Approx(1.0).epsilon(0.05));
    CHECK(std::abs(atBorder.centre.x - lightCentre.x) <= 1.0);
    // A tenth of a pixel: the bottom rim row alone drawn with the background's radius (pass 2 blind to
    // the tile above) moved the disc by 0.17 px.
    CHECK(glm::length(atBorder.centre - (inTile.centre + glm::dvec2(0.0, 8.0))) <= 0.1);
}

TEST_CASE("Behind a near bar, the far layer takes the background from the nearer side", "[pipeline]") {
    // An in-focus wall, white left of the bar and black right of it, behind a vertical near bar 16 px
    // wide at radius 8 (kernels 16 texels across, the bar 8): the far layer under the bar is the hole
    // fill, the background extrapolated from around it. Weighted by proximity, each column of the bar
    // takes it mostly from the side it is nearer. Two texels in from either edge the fill is 0.82 and
    // 0.18 (white and black); with equal weights over the kernel it was 0.72 and 0.28.
    Scene scene = makeScene(128, 64, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), 0.0f);
    const Rect bar{56, 0, 72, 64};
    for (uint32_t y = 0; y < scene.height; ++y)
        for (uint32_t x = 0; x < scene.width; ++x) {
            const size_t i = size_t(y) * scene.width + x;
            if (int(x) < bar.x0) scene.color[i] = glm::vec4(1.0f);
            if (bar.contains(int(x), int(y))) {
                scene.color[i] = glm::vec4(0.2f, 0.6f, 0.2f, 1.0f);
                scene.depth[i] = -8.0f;
            }
        }
    Layers layers;
    ffxdoftest::runPipeline(scene, Settings{}, &layers);
    std::vector<double> columnMean;
    const uint32_t firstColumn = uint32_t(bar.x0) / 2u, lastColumn = uint32_t(bar.x1) / 2u - 1u;
    for (uint32_t column = firstColumn; column <= lastColumn; ++column) {
        double sum = 0.0;
        for (uint32_t row = 0; row < layers.halfHeight; ++row) {
            const size_t i = size_t(row) * layers.halfWidth + column;
            REQUIRE(layers.layerAlpha[i].y > 0.0f);  // the fill makes the far layer valid under the bar
            sum += layers.farColor[i].y;
        }
        columnMean.push_back(sum / layers.halfHeight);
    }
    const double leftQuarter = columnMean[2], rightQuarter = columnMean[columnMean.size() - 3];
    INFO("far layer two texels inside the bar: left " << leftQuarter << ", right " << rightQuarter);
    CHECK(leftQuarter > 0.78);
    CHECK(rightQuarter < 0.22);
    CHECK(std::is_sorted(columnMean.rbegin(), columnMean.rend()));
}

TEST_CASE("A small near object over a blurred far field leaves no edge of its silhouette", "[pipeline]") {
    // A dark leaf 14 px wide at a near radius of 25 half-res px in front of a far wall at radius 4.8, bright
    // left of x = 77 and dark right of it (the step hidden behind the leaf). The thin lens sees behind the leaf:
    // its veil (0.06 opaque) lies over the far field blurred across the step, with no edge where the leaf's
    // pinhole silhouette is. Until the far layer beside such an object took its own surface behind the object
    // from the texels around (ffxDofVeilShare), it was the visible side's mean alone, unlike the hole fill of the
    // leaf's own texels: the output stepped by 0.13 and 0.09 across the silhouettes, a hard-edged ghost
    // (docs/quality.md, near-and-far); 0.071 and 0.065 with that alone, 0.057 and 0.044 since the leaf's hole fill
    // takes what the far samples reaching it leave uncovered (ffxDofFinishGather).
    const uint32_t w = 160, h = 96;
    Scene scene = makeScene(w, h, glm::vec4(0.0f), -4.8f);
    const Rect leaf{70, 30, 84, 66};
    const float bright = 0.8f, dark = 0.2f;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            const float wall = x < 77 ? bright : dark;
            scene.color[i] = glm::vec4(wall, wall, wall, 1.0f);
            if (leaf.contains(int(x), int(y))) {
                scene.color[i] = glm::vec4(0.1f, 0.1f, 0.1f, 1.0f);
                scene.depth[i] = -25.0f;
            }
        }
    Settings settings;
    settings.cocLimit = 30.0f;
    const std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, settings);
    for (const int edge : {leaf.x0, leaf.x1}) {
        double largestStep = 0.0;
        for (int x = edge - 3; x < edge + 3; ++x)
            largestStep = std::max(largestStep, double(std::abs(out[48 * w + x + 1].x - out[48 * w + x].x)));
        INFO("largest step between neighbouring pixels across the silhouette at x = " << edge << ": " << largestStep);
        CHECK(largestStep <= 0.11 * (bright - dark));
    }
}

TEST_CASE("Past the image border, a near object goes on as its edge, no more opaque there", "[pipeline]") {
    // A near rectangle against the left border (radius 8, so kernels reach 8 texels past the border)
    // over an in-focus background. Past the border the image is its edge texels repeated, so there the
    // rectangle goes on to the left: below its bottom edge, the border column's near opacity must be
    // what a column inside the rectangle's span, well away from both its ends, gets. (Judging reads past
    // the border at the clamped texel's own place counted each again at full reach: the border column
    // came out more opaque.)
    Scene scene = makeScene(160, 96, kBackground, 0.0f);
    paint(scene, Rect{0, 0, 56, 40}, 8.0f, false);
    Layers layers;
    ffxdoftest::runPipeline(scene, Settings{}, &layers);
    const uint32_t borderColumn = 0, insideColumn = 12;
    // The gathered opacity: LAYER_ALPHA keeps whole steps (ffxDofStoredNearOpacity) and the near colour makes up
    // the rest, between the object's colour and the far layer's: stored colour x stored opacity = object x gathered
    // opacity + far x (stored - gathered opacity). The stored colour's 6-bit mantissa makes each row's figure
    // noisy by a few thousandths; the defect this guards against was systematic (every row 0.008 to 0.04 more
    // opaque at the border), so each row is held to 0.01 and their mean to 0.004.
    const auto gatheredOpacity = [&](uint32_t row, uint32_t column) {
        const size_t i = size_t(row) * layers.halfWidth + column;
        const float stored = layers.layerAlpha[i].x, far = layers.farColor[i].x;
        return (layers.nearColor[i].x - far) * stored / (kObject.x - far);
    };
    double meanDifference = 0.0;
    for (uint32_t row = 20; row < 28; ++row) {
        const float border = gatheredOpacity(row, borderColumn);
        const float inside = gatheredOpacity(row, insideColumn);
        INFO("texel row " << row << ": near opacity at the border " << border << ", inside " << inside);
        CHECK(std::abs(border - inside) < 0.01f);
        meanDifference += (border - inside) / 8.0;
    }
    INFO("mean of border - inside over the rows: " << meanDifference);
    CHECK(std::abs(meanDifference) < 0.004);  // 0.008 to 0.04 more at the border before
}

TEST_CASE("A slightly blurred near object shows the background within its radius of its silhouette", "[pipeline]") {
    // A near square at radius 2 half-res px (4 full-res px: its own surface is gathered at full
    // resolution) over an in-focus background. One pixel inside its edge the truth's coverage is
    // about 0.66 (a disc of radius 4 px cut by a straight edge 1 px from its centre); kept opaque up
    // to the silhouette, that pixel came out as the object itself.
    Scene scene = makeScene(128, 96, kBackground, 0.0f);
    const Rect object{48, 32, 80, 64};
    paint(scene, object, 2.0f, false);
    std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, Settings{});
    double insideEdge = 0.0;
    for (int y = 44; y < 52; ++y) insideEdge += out[size_t(y) * scene.width + size_t(object.x0 + 1)].x;
    insideEdge /= 8.0;
    // Red: 1 on the object, 0.1 on the background.
    const double coverage = (insideEdge - kBackground.x) / (kObject.x - kBackground.x);
    INFO("coverage one pixel inside the left edge: " << coverage);
    CHECK(coverage > 0.55);
    CHECK(coverage < 0.8);
}

TEST_CASE("A small far light at a radius the composite blurs at full resolution keeps its energy", "[pipeline]") {
    // Radii of 0.8 to 1.4 half-res px in front of a background at 16: the light's own pixels are blurred
    // at full resolution, the background around it shows the half-res layers. Before the background drew
    // such lights at full resolution itself (ffxDofGatherSmallSources), a 1 px light at 0.8 kept 0.33 of
    // its energy and one at 1.0 0.51; with the light drawn both by its own pixels and by the far layer, up
    // to 1.26.
    for (float radius : {0.8f, 1.0f, 1.4f}) {
        for (const ffxdoftest::LightCase& light : ffxdoftest::runSmallFarLightCases(radius, {1, 2, 3})) {
            INFO("radius " << radius << ", " << light.size << " px: energy " << light.energyAdded / light.inputEnergy);
            CHECK(light.energyAdded / light.inputEnergy == Approx(1.0).margin(0.05));
        }
    }
}

TEST_CASE("A dim light on a bright light's rim leaves the bright disc there as it is", "[pipeline]") {
    // Issue 17's pair of lights at 16 px (docs/quality.md, a dim light beside a bright one) at half-res
    // radii: a bright light (3 x 3 px of 1000 at -9.1) and a dim one (2 x 2 px of 50 at -3) on the bright
    // disc's rim, over a background of 0.05 at -16. The dim light's two texels read the bright light beyond
    // their kernel (ffxDofGatherBehind). At MIP 0, where a texel's light is taken at its centre, the bright
    // light's far texels lay beyond the bright disc's rim there, while the background's texels around read
    // it from MIP 1 where its light lies: until 2026-11-29 the far layer at the dim light's texels kept 0.77
    // and 0.70 of the bright disc there, and the dim light added 0.91 of its energy beside the bright light.
    // Read from MIP 1 and up (ffxDofBehindMip): 0.95 and 0.92, and 0.95. What is left is the layering: at its
    // own texels the nearer dim light hides what lies behind by its coverage (two texels of light over its disc
    // of pi x 3^2 texels: about 7%), the bright disc included. The scene is that pair's divided by 1000, the
    // bright light at white, so that both lights stay in the layers: above white, each is a far highlight
    // (ffx_dof_highlights.h), which no texel holds (measured so: 0.94 and 0.91, and 0.96).
    const uint32_t w = 160, h = 128;
    const float background = 0.0001f;
    Scene none;
    none.width = w;
    none.height = h;
    none.color.assign(size_t(w) * h, glm::vec4(background, background, background, 1.0f));
    none.depth.assign(size_t(w) * h, 16.0f);
    const Scene bright = withLight(none, {80, 60}, FFX_DOF_HIGHLIGHT_MIN_LUMINANCE, -9.1f, 3);
    const float dimValue = 0.05f;
    const Scene dim = withLight(none, {64, 57}, dimValue, -3.0f, 2);
    const Scene both = withLight(bright, {64, 57}, dimValue, -3.0f, 2);
    Settings settings;
    settings.cocLimit = 16.4f;
    Layers noneLayers, brightLayers, dimLayers, bothLayers;
    const std::vector<glm::vec4> noneOut = ffxdoftest::runPipeline(none, settings, &noneLayers);
    const std::vector<glm::vec4> brightOut = ffxdoftest::runPipeline(bright, settings, &brightLayers);
    const std::vector<glm::vec4> dimOut = ffxdoftest::runPipeline(dim, settings, &dimLayers);
    const std::vector<glm::vec4> bothOut = ffxdoftest::runPipeline(both, settings, &bothLayers);
    // The dim light's texels: half-res (32, 28) and (32, 29).
    for (const size_t texel : {size_t(28) * brightLayers.halfWidth + 32, size_t(29) * brightLayers.halfWidth + 32}) {
        REQUIRE(bothLayers.coc0[texel] == Approx(-3.0f).margin(0.01));
        const double brightThere = brightLayers.farColor[texel].y;
        const double besideDim =
            bothLayers.farColor[texel].y - (dimLayers.farColor[texel].y - noneLayers.farColor[texel].y);
        INFO("texel " << texel << ": the bright disc's far layer " << brightThere << ", beside the dim light "
                      << besideDim);
        CHECK(besideDim / brightThere >= 0.9);
    }
    double dimAlone = 0.0, dimBeside = 0.0;
    for (size_t i = 0; i < noneOut.size(); ++i) {
        dimAlone += double(dimOut[i].y) - noneOut[i].y;
        dimBeside += double(bothOut[i].y) - brightOut[i].y;
    }
    const double dimInput = 4.0 * (dimValue - background);
    INFO("the dim light adds " << dimAlone / dimInput << " of its energy alone, " << dimBeside / dimInput
                               << " beside the bright light");
    CHECK(dimAlone / dimInput == Approx(1.0).margin(0.05));
    CHECK(dimBeside / dimInput == Approx(1.0).margin(0.05));
}

TEST_CASE("Two lights a few pixels apart in one quadrant are drawn as each alone", "[pipeline]") {
    // Far highlights keep one slot per quadrant of 8 x 8 px of a tile (ffx_dof_highlights.h): two 1 px lights of
    // 100 there are drawn as two discs at the ends of the light's principal axis, which are the two lights. Until
    // 2026-11-30 a slot was one disc about their middle with a rim as wide as their spread (at most 6 px), and the
    // L1 difference from the two drawn alone, over theirs, was 0.24 and 0.39 at radius 4.5 px for lights 3 and 5
    // px apart, 0.17 and 0.29 at 6 px, 0.13 and 0.22 at 8 px, 0.08 and 0.14 at 12 px; now 0.000 in every case.
    // Lights 7 px apart lie in two quadrants here.
    const uint32_t w = 64, h = 64;
    const Scene none = makeScene(w, h, glm::vec4(0.01f, 0.01f, 0.01f, 1.0f), -16.0f);
    Settings settings;
    settings.cocLimit = 16.4f;
    const std::vector<glm::vec4> noneOut = ffxdoftest::runPipeline(none, settings);
    for (const float coc : {-2.25f, -3.0f, -4.0f, -6.0f}) {
        // Both lights in the quadrant of pixels 32..39 each way, but for the gap of 7.
        const int x0 = 33, y0 = 34;
        const Scene first = withLight(none, {x0, y0}, 100.0f, coc);
        const std::vector<glm::vec4> firstOut = ffxdoftest::runPipeline(first, settings);
        for (const int gap : {3, 5, 7}) {
            const std::vector<glm::vec4> secondOut =
                ffxdoftest::runPipeline(withLight(none, {x0 + gap, y0}, 100.0f, coc), settings);
            const std::vector<glm::vec4> bothOut =
                ffxdoftest::runPipeline(withLight(first, {x0 + gap, y0}, 100.0f, coc), settings);
            double difference = 0.0, alone = 0.0;
            for (size_t i = 0; i < noneOut.size(); ++i) {
                const double apart = double(firstOut[i].y) + secondOut[i].y - 2.0 * noneOut[i].y;
                difference += std::abs(double(bothOut[i].y) - noneOut[i].y - apart);
                alone += std::abs(apart);
            }
            std::printf("two lights %d px apart at radius %.1f px: L1 difference from each alone %.3f\n", gap,
                        -2.0 * coc, difference / alone);
            INFO("radius " << -2.0f * coc << " px, " << gap << " px apart: " << difference / alone);
            CHECK(difference / alone <= 0.01);
        }
    }
}

TEST_CASE("A near and a far light in one quadrant keep their light, drawn as the brighter one's side", "[pipeline]") {
    // A quadrant's slot is near or far (ffx_dof_highlights.h): a near light and a far light a few px apart in one
    // quadrant are drawn with the radius and occlusion of the side that holds more of their light. Their light is
    // kept; the L1 difference from the two drawn alone, over theirs, is printed (the dimmer side's disc drawn at the
    // brighter side's radius).
    const uint32_t w = 64, h = 64;
    const Scene none = makeScene(w, h, glm::vec4(0.01f, 0.01f, 0.01f, 1.0f), -8.0f);
    Settings settings;
    settings.cocLimit = 16.4f;
    const std::vector<glm::vec4> noneOut = ffxdoftest::runPipeline(none, settings);
    for (const float nearValue : {50.0f, 200.0f}) {
        const Scene withNear = withLight(none, {33, 34}, nearValue, 4.0f);
        const Scene withFar = withLight(none, {37, 34}, 100.0f, -4.0f);
        const std::vector<glm::vec4> nearOut = ffxdoftest::runPipeline(withNear, settings);
        const std::vector<glm::vec4> farOut = ffxdoftest::runPipeline(withFar, settings);
        const std::vector<glm::vec4> bothOut =
            ffxdoftest::runPipeline(withLight(withNear, {37, 34}, 100.0f, -4.0f), settings);
        double added = 0.0, difference = 0.0, alone = 0.0;
        for (size_t i = 0; i < noneOut.size(); ++i) {
            const double apart = double(nearOut[i].y) + farOut[i].y - 2.0 * noneOut[i].y;
            added += double(bothOut[i].y) - noneOut[i].y;
            difference += std::abs(double(bothOut[i].y) - noneOut[i].y - apart);
            alone += std::abs(apart);
        }
        const double input = nearValue + 100.0 - 2.0 * 0.01;
        std::printf(
            "a near light of %.0f and a far light of 100 in one quadrant: %.4f of their light, L1 difference "
            "from each alone %.3f\n",
            nearValue, added / input, difference / alone);
        INFO("near light " << nearValue << ": light " << added / input << ", L1 difference " << difference / alone);
        CHECK(std::abs(added / input - 1.0) <= 0.02);
    }
}

TEST_CASE("Three lights in one quadrant keep their energy, drawn as two discs", "[pipeline]") {
    // A quadrant's slot holds two discs (ffx_dof_highlights.h), so three 1 px lights of 100 in one quadrant of 8 x 8
    // px are drawn as two at the ends of their principal axis, each with a rim as wide as the spread across it: the
    // light is kept, its place only roughly. The L1 difference from the three drawn alone, over theirs, measured
    // 2026-11-30 (the largest of the four patterns below; printed): 0.54 at radius 4.5 px, 0.31 at 8, 0.16 at 16.
    // Held as a ratchet: more slots per quadrant would cost HIGHLIGHTS memory (the 10 MB budget).
    const uint32_t w = 64, h = 64;
    const Scene none = makeScene(w, h, glm::vec4(0.01f, 0.01f, 0.01f, 1.0f), -16.0f);
    Settings settings;
    settings.cocLimit = 16.4f;
    const std::vector<glm::vec4> noneOut = ffxdoftest::runPipeline(none, settings);
    // Lights in the quadrant of pixels 32..39 each way: a small triangle, one spanning the quadrant, three in a row,
    // three corners.
    const glm::ivec2 patterns[][3] = {{{33, 34}, {36, 34}, {34, 37}},
                                      {{32, 32}, {39, 32}, {35, 39}},
                                      {{32, 33}, {35, 33}, {38, 33}},
                                      {{32, 32}, {39, 39}, {32, 39}}};
    const struct {
        float coc;
        double largestDifference;
    } radii[] = {{-2.25f, 0.56}, {-4.0f, 0.33}, {-8.0f, 0.18}};
    for (const auto& radius : radii) {
        for (const auto& lights : patterns) {
            std::vector<double> apart(noneOut.size(), 0.0);
            Scene all = none;
            for (const glm::ivec2 at : lights) {
                const std::vector<glm::vec4> alone =
                    ffxdoftest::runPipeline(withLight(none, at, 100.0f, radius.coc), settings);
                for (size_t i = 0; i < apart.size(); ++i) apart[i] += double(alone[i].y) - noneOut[i].y;
                all = withLight(all, at, 100.0f, radius.coc);
            }
            const std::vector<glm::vec4> allOut = ffxdoftest::runPipeline(all, settings);
            double difference = 0.0, aloneSum = 0.0, added = 0.0, addedApart = 0.0;
            for (size_t i = 0; i < apart.size(); ++i) {
                const double together = double(allOut[i].y) - noneOut[i].y;
                difference += std::abs(together - apart[i]);
                aloneSum += std::abs(apart[i]);
                added += together;
                addedApart += apart[i];
            }
            std::printf(
                "three lights at radius %.1f px, (%d, %d) (%d, %d) (%d, %d): L1 difference from each alone "
                "%.3f, energy %.3f\n",
                -2.0 * radius.coc, lights[0].x, lights[0].y, lights[1].x, lights[1].y, lights[2].x, lights[2].y,
                difference / aloneSum, added / addedApart);
            INFO("radius " << -2.0f * radius.coc << " px, lights (" << lights[0].x << ", " << lights[0].y << "), ("
                           << lights[1].x << ", " << lights[1].y << "), (" << lights[2].x << ", " << lights[2].y
                           << "): L1 difference " << difference / aloneSum << ", energy " << added / addedApart);
            CHECK(added / addedApart == Approx(1.0).margin(0.02));
            CHECK(difference / aloneSum <= radius.largestDifference);
        }
    }
}

TEST_CASE("A near point brighter than white is drawn as the far point of the same radius", "[pipeline]") {
    // Near highlights (ffx_dof_highlights.h): a bright near point over an in-focus black wall leaves the near layer
    // and is drawn at full resolution, as a far point on a far black background is. From the near layer its disc was
    // 1.3 to 1.9 px small, 8.7% too bright inside and with a glow beyond its rim (docs/quality.md, near point discs).
    const uint32_t w = 96, h = 96;
    Settings settings;
    settings.cocLimit = 24.0f;
    // At 20 the point's own input showed through its pixel (a dot of 1.6 times the level) before the composite left
    // what pass 2 took of it out of its input and fixed blur.
    for (const float halfRadius : {2.25f, 6.5f, 13.5f, 20.0f}) {
        const float energy = 0.25f * 3.14159265f * 4.0f * halfRadius * halfRadius;  // a disc level of 0.25
        std::vector<glm::vec4> images[2];
        for (int side = 0; side < 2; ++side) {
            // side 0: the point near over an in-focus wall; side 1: the point and its background far.
            Scene scene = makeScene(w, h, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), side == 0 ? 0.0f : -halfRadius);
            scene.color[48 * w + 48] = glm::vec4(energy, energy, energy, 1.0f);
            scene.depth[48 * w + 48] = side == 0 ? -halfRadius : halfRadius;
            images[side] = ffxdoftest::runPipeline(scene, settings);
        }
        double nearSum = 0.0, largestDifference = 0.0, glow = 0.0;
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                const float nearValue = images[0][y * w + x].y;
                nearSum += nearValue;
                largestDifference = std::max(largestDifference, double(std::fabs(nearValue - images[1][y * w + x].y)));
                if (std::hypot(x - 48.0, y - 48.0) > 2.0 * halfRadius + 1.5) glow = std::max(glow, double(nearValue));
            }
        std::printf(
            "near point of radius %.2f half-res px: %.4f of its light, largest difference from the far point "
            "%.5f, glow %.5f\n",
            halfRadius, nearSum / energy, largestDifference, glow);
        INFO("near radius " << halfRadius << ": energy " << nearSum / energy << ", difference " << largestDifference
                            << ", glow " << glow);
        CHECK(std::abs(nearSum / energy - 1.0) <= 0.02);
        CHECK(largestDifference <= 0.25 * 0.01);
        CHECK(glow <= 0.25 * 0.02);
    }
}

TEST_CASE("A bright near patch keeps its light, and its shape against the thin lens is held as measured",
          "[pipeline]") {
    // A 24 x 24 px patch of value 4 at a near radius over an in-focus wall of 0.02: the tiles at its edge take its
    // light out as near highlights (their floor is the wall's), one disc per quadrant of 8 x 8 px, and the tiles
    // inside keep it in the near layer. The thin lens, at full resolution: the wall less the patch's coverage plus
    // the patch's discs. Measured on 2026-11-30 (RMS difference over the image): 0.0356, 0.0262 and 0.0083 at radius
    // 2, 3 and 8 half-res px; from the near layer alone, before near highlights, 0.0363, 0.0326 and 0.0119; with
    // highlights' rims of at most 6 px instead of 9, 0.0665 at radius 2 (the quadrants' discs rippled by 10%).
    const uint32_t w = 128, h = 128;
    const int side = 24, first = 64 - side / 2;
    const float value = 4.0f, wall = 0.02f;
    Settings settings;
    settings.cocLimit = 20.0f;
    const float radii[] = {2.0f, 3.0f, 8.0f};
    const double measured[] = {0.0356, 0.0262, 0.0083};
    for (int r = 0; r < 3; ++r) {
        Scene scene = makeScene(w, h, glm::vec4(wall, wall, wall, 1.0f), 0.0f);
        for (int y = first; y < first + side; ++y)
            for (int x = first; x < first + side; ++x) {
                scene.color[size_t(y) * w + size_t(x)] = glm::vec4(value, value, value, 1.0f);
                scene.depth[size_t(y) * w + size_t(x)] = -radii[r];
            }
        const std::vector<glm::vec4> out = ffxdoftest::runPipeline(scene, settings);
        const double discRadius = 2.0 * radii[r], discArea = 3.14159265358979 * discRadius * discRadius;
        double squares = 0.0, outSum = 0.0, truthSum = 0.0;
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                double coverage = 0.0;
                for (int py = first; py < first + side; ++py)
                    for (int px = first; px < first + side; ++px)
                        coverage += std::clamp(discRadius + 0.5 - std::hypot(double(px) - x, double(py) - y), 0.0, 1.0);
                coverage = std::min(coverage / discArea, 1.0);
                const double truth = wall * (1.0 - coverage) + value * coverage;
                const double ours = out[size_t(y) * w + x].y;
                squares += (ours - truth) * (ours - truth);
                outSum += ours;
                truthSum += truth;
            }
        const double rms = std::sqrt(squares / double(w * h));
        std::printf(
            "bright near patch at radius %.0f half-res px: %.4f of the thin lens's light, RMS difference "
            "%.4f (measured %.4f)\n",
            radii[r], outSum / truthSum, rms, measured[r]);
        INFO("radius " << radii[r] << ": light " << outSum / truthSum << ", RMS " << rms);
        CHECK(std::abs(outSum / truthSum - 1.0) <= 0.01);
        CHECK(rms <= measured[r] * 1.1);
    }
}

TEST_CASE("A thin far object over a far field above white is blurred as over the same field below it", "[pipeline]") {
    // A dark branch 9 px wide at far radius 5.9 half-res px in front of a farther, uniform sky at radius 8; once with
    // the sky at 0.5, once with every value 4.6 times as bright (the sky at 2.3, above white). Nothing here is a
    // light, so the effect, linear in the colour, must give the same image scaled. Until a far pixel was judged a
    // light against its tile's mean far luminance (ffxDofHighlightShare) the bright sky gave its light to the
    // highlights wherever the branch darkened a tile, each quadrant's disc hidden by the branch whole or not at all:
    // the two differed by up to 0.33 of the dim case's value (0.013 since; the half-res images round the colour).
    const uint32_t w = 160, h = 96;
    const int branchFirst = 76, branchLast = 84;
    const float gain = 4.6f;
    std::vector<std::vector<glm::vec4>> outputs;
    for (const float scale : {1.0f, gain}) {
        Scene scene = makeScene(w, h, glm::vec4(0.5f * scale, 0.5f * scale, 0.5f * scale, 1.0f), -8.0f);
        for (uint32_t y = 0; y < h; ++y)
            for (int x = branchFirst; x <= branchLast; ++x) {
                const size_t i = size_t(y) * w + uint32_t(x);
                scene.color[i] = glm::vec4(glm::vec3(0.0109f * scale), 1.0f);
                scene.depth[i] = 5.9f;
            }
        Settings settings;
        settings.cocLimit = 10.0f;
        outputs.push_back(ffxdoftest::runPipeline(scene, settings));
    }
    double largestDifference = 0.0;
    for (uint32_t y = 16; y < h - 16; ++y)
        for (uint32_t x = 40; x < 120; ++x) {
            const size_t i = size_t(y) * w + x;
            const double dim = outputs[0][i].y, bright = outputs[1][i].y / gain;
            largestDifference = std::max(largestDifference, std::abs(bright - dim) / dim);
        }
    INFO("largest relative difference of the bright case (scaled back) from the dim one: " << largestDifference);
    CHECK(largestDifference <= 0.02);
}

TEST_CASE("A far field above white without lights takes the cheap paths, a light there only around itself",
          "[pipeline]") {
    // A sky from 1.8 to 2.8 (above white, no pixel twice its surround) at far radius 6 half-res px: nothing in it is
    // a light, and nothing in it is below FFX_DOF_FAR_LAYER_ONLY_RADIUS. Until dilate asked which tiles' pixels gave
    // light (FFX_DOF_HIGHLIGHT_GIVEN_BIT) instead of which have a channel above white, every tile took the
    // composite's full-resolution path and every far kernel the finer MIP (docs/performance.md, "A sky above white
    // takes the cheap paths").
    const uint32_t w = 256, h = 160;
    const float skyRadius = 6.0f;
    Scene sky = makeScene(w, h, glm::vec4(0.0f), -skyRadius);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) sky.color[size_t(y) * w + x] = glm::vec4(glm::vec3(1.8f + x / float(w)), 1.0f);
    Settings settings;
    settings.cocLimit = 10.0f;
    Layers layers;
    ffxdoftest::runPipeline(sky, settings, &layers);
    REQUIRE(layers.compositeClasses.size() == size_t(layers.tilesX) * layers.tilesY);
    for (size_t tile = 0; tile < layers.compositeClasses.size(); ++tile) {
        INFO("tile " << tile % layers.tilesX << ", " << tile / layers.tilesX);
        REQUIRE(layers.tileColorPeaks[tile] > 1.0f);
        CHECK(layers.compositeClasses[tile] == uint32_t(FFX_DOF_COMPOSITE_CLASS_LAYERS));
        CHECK(layers.blurTileFlags[tile] == 0u);
    }

    // A light of 3 x 3 px of 50 at the sky's radius, in tile (8, 5): the 3 x 3 tiles around it keep the finer MIP,
    // the composite draws it where its disc (12 full-res px and dilate's margin) reaches, and nowhere farther.
    const glm::ivec2 lightTile(8, 5);
    const Scene lit = withLight(sky, glm::ivec2(lightTile.x * 16 + 4, lightTile.y * 16 + 4), 50.0f, -skyRadius, 3);
    ffxdoftest::runPipeline(lit, settings, &layers);
    for (uint32_t ty = 0; ty < layers.tilesY; ++ty)
        for (uint32_t tx = 0; tx < layers.tilesX; ++tx) {
            INFO("tile " << tx << ", " << ty);
            const size_t tile = size_t(ty) * layers.tilesX + tx;
            const int away = std::max(std::abs(int(tx) - lightTile.x), std::abs(int(ty) - lightTile.y));
            CHECK(layers.blurTileFlags[tile] == (away <= 1 ? uint32_t(FFX_DOF_LISTED_TILE_LIGHTS) : 0u));
            if (away == 0) CHECK(layers.compositeClasses[tile] == uint32_t(FFX_DOF_COMPOSITE_CLASS_LIGHTS));
            if (away >= 3) CHECK(layers.compositeClasses[tile] == uint32_t(FFX_DOF_COMPOSITE_CLASS_LAYERS));
        }
}

TEST_CASE("A sky above white between nearer dark far branches is no light, bright bars in front of a dark field are",
          "[pipeline]") {
    // Dark bars of 12 px every 16 px at far radius 5 half-res px in front of a sky of 2.3 at radius 9: each tile is a
    // quarter sky, which is more than twice the tile's mean far luminance, and until a bright far field behind nearer
    // far content gave no light (ffxDofBrightFieldBehind) every tile gave light and every tile its discs reached took
    // the composite's full-resolution path (far-branches at 1080p: 3.4 times as long; docs/performance.md, "A bright
    // far field behind nearer far content"). The same with the limit at 4 half-res px, which gives both one radius:
    // the depth order is taken before the limit. With the depths swapped the bright bars lie in front of the dark
    // field, as lights do, and give light.
    const uint32_t w = 256, h = 160;
    auto barsScene = [&](float skyRadius, float barRadius) {
        Scene scene = makeScene(w, h, glm::vec4(2.3f, 2.3f, 2.3f, 1.0f), -skyRadius);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                if (x % 16u >= 2u && x % 16u < 14u) {
                    const size_t i = size_t(y) * w + x;
                    scene.color[i] = glm::vec4(glm::vec3(0.05f), 1.0f);
                    scene.depth[i] = barRadius;  // radius = -depth: far
                }
        return scene;
    };
    auto tilesGivingLight = [&](const Scene& scene, float cocLimit) {
        Settings settings;
        settings.cocLimit = cocLimit;
        Layers layers;
        ffxdoftest::runPipeline(scene, settings, &layers);
        size_t count = 0;
        for (const uint32_t flags : layers.blurTileFlags)
            if ((flags & uint32_t(FFX_DOF_LISTED_TILE_LIGHTS)) != 0u) ++count;
        size_t fullRes = 0;
        for (const uint32_t compositeClass : layers.compositeClasses)
            if (compositeClass == uint32_t(FFX_DOF_COMPOSITE_CLASS_FULL_RES) ||
                compositeClass == uint32_t(FFX_DOF_COMPOSITE_CLASS_LIGHTS))
                ++fullRes;
        INFO("tiles " << layers.blurTileFlags.size() << ", with lights around " << count << ", full resolution "
                      << fullRes);
        if (count == 0) CHECK(fullRes == 0);
        return count;
    };
    CHECK(tilesGivingLight(barsScene(9.0f, 5.0f), 10.0f) == 0);
    CHECK(tilesGivingLight(barsScene(9.0f, 5.0f), 4.0f) == 0);
    CHECK(tilesGivingLight(barsScene(5.0f, 9.0f), 10.0f) > 0);
}

TEST_CASE("A dark near object's anti-aliased rim over a sky above white is no near light", "[pipeline]") {
    // A dark bar at near radius 8 half-res px over a sky of 1.8 to 2.8 at far radius 6; its edge columns are half
    // sky, half bar, with the bar's depth, as a renderer's anti-aliasing leaves them. Against the near floor (the
    // bar's 0.05) such a pixel is 20 to 30 times as bright, and until a near pixel's surround took the far field's
    // mean as well (ffxDofHighlightFloor) every rim pixel above white was a near highlight, drawn at full resolution:
    // the composite of near-leaves-sky at 1080p took 1.14 to 1.19 times as long (docs/performance.md). Nothing here is
    // a light; with a near pixel's surround its floor alone, 40 of these 160 checks fail.
    const uint32_t w = 256, h = 160;
    Scene scene = makeScene(w, h, glm::vec4(0.0f), -6.0f);
    const int barFirst = 120, barLast = 131;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            const glm::vec3 sky(1.8f + x / float(w));
            const int column = int(x);
            if (column < barFirst || column > barLast) {
                scene.color[i] = glm::vec4(sky, 1.0f);
                continue;
            }
            const bool rim = column == barFirst || column == barLast;
            scene.color[i] = glm::vec4(rim ? 0.5f * (sky + glm::vec3(0.05f)) : glm::vec3(0.05f), 1.0f);
            scene.depth[i] = -8.0f;  // radius = -depth: near
        }
    Settings settings;
    settings.cocLimit = 10.0f;
    Layers layers;
    ffxdoftest::runPipeline(scene, settings, &layers);
    for (size_t tile = 0; tile < layers.blurTileFlags.size(); ++tile) {
        INFO("tile " << tile % layers.tilesX << ", " << tile / layers.tilesX);
        CHECK((layers.blurTileFlags[tile] & uint32_t(FFX_DOF_LISTED_TILE_LIGHTS)) == 0u);
    }
}

TEST_CASE("A far bar in front of a light casts a band across the light's whole disc", "[pipeline]") {
    // A light of 3 x 3 px at far radius 12 half-res px (a disc of 24 full-res px) over a dark field at 16, and a dark
    // vertical bar of 4 px at radius 4, 8 px right of the light. The thin lens's rays from a pixel p to the light
    // cross the bar's depth at light + (p - light)(1 - 4 / 12): the bar, x in [72, 76), hides the light from the
    // pixels whose x lies in [75.75, 81.75), a band across the disc beyond the bar. Until the composite walked the
    // segment from each pixel to the light (ffxDofHighlightVisibilityPast) it asked only the pixel's own surface,
    // so the band was lit as the rest of the disc. Behind the light (radius 14) or in focus the bar hides nothing
    // beyond itself.
    const uint32_t w = 128, h = 96;
    const glm::ivec2 light(63, 47);
    auto addedByLight = [&](float barCoc) {
        Scene scene = makeScene(w, h, glm::vec4(0.02f, 0.02f, 0.02f, 1.0f), -16.0f);
        paint(scene, Rect{72, 0, 76, int(h)}, barCoc, false);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 72; x < 76; ++x) scene.color[size_t(y) * w + x] = glm::vec4(0.02f, 0.02f, 0.02f, 1.0f);
        const std::vector<glm::vec4> without = ffxdoftest::runPipeline(scene, Settings{});
        const std::vector<glm::vec4> with =
            ffxdoftest::runPipeline(withLight(scene, light, 200.0f, -12.0f, 3), Settings{});
        // The light's mean added green over rows 42..54 in columns [x0, x1).
        return [with, without, w](int x0, int x1) {
            double sum = 0.0;
            for (int y = 42; y <= 54; ++y)
                for (int x = x0; x < x1; ++x)
                    sum += double(with[size_t(y) * w + size_t(x)].y - without[size_t(y) * w + size_t(x)].y);
            return sum / double(13 * (x1 - x0));
        };
    };
    const auto inFront = addedByLight(-4.0f);
    const double open = inFront(50, 58), band = inFront(77, 81), beyond = inFront(83, 86);
    INFO("bar in front: left of the light " << open << ", band " << band << ", beyond the band " << beyond);
    CHECK(open > 0.7);  // the disc's level: 1800 / (pi 24^2), 1.0
    CHECK(band < 0.1 * open);
    CHECK(beyond > 0.8 * open);
    for (const float barCoc : {-14.0f, 0.0f}) {
        const auto noBlocker = addedByLight(barCoc);
        INFO("bar at radius " << barCoc << ": left of the light " << noBlocker(50, 58) << ", band "
                              << noBlocker(77, 81));
        CHECK(noBlocker(77, 81) > 0.9 * noBlocker(50, 58));
    }
}

TEST_CASE("A small light in front of a bright one casts its shadow into the bright disc as the thin lens does",
          "[pipeline]") {
    // docs/quality.md's light pair at its nearest: a bright light of 3 x 3 px of 1000 at far radius 9.1 half-res px
    // over a field of 0.05 at 16, and a dim light of 2 x 2 px of 50 at radius 3, 8 px to its left and 3 px higher,
    // its rows straddling two half-res texels. In the thin lens the dim light hides the bright one from the pixels
    // whose rays to it cross its depth inside it: its square scaled by 1 / (1 - 3 / 9.1) about the bright light,
    // which lies wholly inside the bright disc and loses the disc's level there. Until the walk from the light read
    // the full-res depth, it read HALF_COC, where the texel holding one row of the dim light took the field's radius,
    // and the shadow lost that row (0.741 of the dim light's energy beside the bright one, against 0.615).
    const uint32_t w = 160, h = 120;
    const Scene none = makeScene(w, h, glm::vec4(0.05f, 0.05f, 0.05f, 1.0f), -16.0f);
    Settings settings;
    settings.cocLimit = 16.5f;
    const float brightRadius = 9.1f, dimRadius = 3.0f;
    const Scene bright = withLight(none, {80, 60}, 1000.0f, -brightRadius, 3);
    const Scene dim = withLight(none, {72, 57}, 50.0f, -dimRadius, 2);
    const Scene both = withLight(bright, {72, 57}, 50.0f, -dimRadius, 2);
    const auto sumGreen = [](const std::vector<glm::vec4>& image) {
        double sum = 0.0;
        for (const glm::vec4& p : image) sum += p.y;
        return sum;
    };
    const double noneSum = sumGreen(ffxdoftest::runPipeline(none, settings));
    const double brightSum = sumGreen(ffxdoftest::runPipeline(bright, settings));
    const double dimInput = 4.0 * (50.0 - 0.05);
    const double alone = (sumGreen(ffxdoftest::runPipeline(dim, settings)) - noneSum) / dimInput;
    const double beside = (sumGreen(ffxdoftest::runPipeline(both, settings)) - brightSum) / dimInput;
    // The bright disc's level (its energy over pi R^2, R in full-res px) over the dim square's shadow.
    const double scale = 1.0 / (1.0 - dimRadius / brightRadius);
    const double brightLevel = 9.0 * (1000.0 - 0.05) / (3.14159265358979 * 4.0 * brightRadius * brightRadius);
    const double thinLens = 1.0 - brightLevel * 4.0 * scale * scale / dimInput;
    INFO("dim light alone " << alone << ", beside the bright one " << beside << ", thin lens " << thinLens);
    CHECK(alone == Approx(1.0).margin(0.02));
    CHECK(beside == Approx(thinLens).margin(0.03));
}
