// Unit tests of the pure functions of shaders_common (ffx_dof_common.h and each pass's own math in its
// pass header) through the C++ mapping.
// Every expectation is computed independently of the function under test (formula, brute force,
// numerical integration or a standard-library algorithm).
#include <catch2/catch.hpp>

#include "ffx_dof_common.h"
#include "ffx_dof_downsample_depth.h"
#include "ffx_dof_downsample_color.h"
#include "ffx_dof_dilate.h"
#include "ffx_dof_blur.h"
#include "ffx_dof_composite.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <set>
#include <utility>
#include <vector>

namespace {
constexpr float kPi = 3.14159265358979f;
}

TEST_CASE("CoC from depth is the affine map, clamped to the limit", "[coc]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> any(-50.0f, 50.0f);
    std::uniform_real_distribution<float> depth(0.0f, 1.0f);
    for (int i = 0; i < 1000; ++i) {
        float scale = any(rng), bias = any(rng), limit = std::fabs(any(rng)), d = depth(rng);
        float expected = std::min(std::max(d * scale + bias, -limit), limit);
        REQUIRE(ffxDofCocFromDepth(d, scale, bias, limit) == Approx(expected).margin(1e-5));
    }
    CHECK(ffxDofCocFromDepth(0.5f, 10.0f, 0.0f, 2.0f) == 2.0f);
    CHECK(ffxDofCocFromDepth(0.5f, -10.0f, 0.0f, 2.0f) == -2.0f);
}

TEST_CASE("Nearer and farther depth follow the depth convention", "[coc]") {
    // Standard depth (FFX_DOF_OPTION_REVERSE_DEPTH 0 in this translation unit): smaller is nearer.
    CHECK(ffxDofNearerDepth(0.2f, 0.7f) == 0.2f);
    CHECK(ffxDofFartherDepth(0.2f, 0.7f) == 0.7f);
}

TEST_CASE("Bilateral weight: 1 for equal radii, 0 beyond one pixel of difference", "[downsample]") {
    CHECK(ffxDofBilateralWeight(3.0f, 3.0f) == 1.0f);
    CHECK(ffxDofBilateralWeight(3.0f, 3.25f) == Approx(0.75f));
    CHECK(ffxDofBilateralWeight(3.0f, 2.5f) == Approx(0.5f));
    CHECK(ffxDofBilateralWeight(3.0f, 4.0f) == 0.0f);
    CHECK(ffxDofBilateralWeight(-3.0f, 5.0f) == 0.0f);
}

TEST_CASE("Bilateral reduce averages equal radii and drops outliers", "[downsample]") {
    FfxFloat32x3 color;
    float coc;
    ffxDofBilateralReduce(FfxFloat32x3(1, 0, 0), FfxFloat32x3(0, 1, 0), FfxFloat32x3(0, 0, 1), FfxFloat32x3(1, 1, 1),
                          2.0f, 2.0f, 2.0f, 2.0f, color, coc);
    CHECK(color.x == Approx(0.5f));
    CHECK(color.y == Approx(0.5f));
    CHECK(color.z == Approx(0.5f));
    CHECK(coc == Approx(2.0f));
    // The bottom-right pixel differs by 5 px of radius from the top-left: weight 0.
    ffxDofBilateralReduce(FfxFloat32x3(1, 1, 1), FfxFloat32x3(1, 1, 1), FfxFloat32x3(1, 1, 1), FfxFloat32x3(9, 9, 9),
                          -3.0f, -3.0f, -3.0f, 2.0f, color, coc);
    CHECK(color.x == Approx(1.0f));
    CHECK(coc == Approx(-3.0f));
}

TEST_CASE("A near radius carries its coverage in quarters and stays a half", "[downsample]") {
    for (const float radius : {0.5f, 1.0f, 2.75f, 7.3f, 24.0f, 40.1f, 130.0f}) {
        for (const float coverage : {0.25f, 0.5f, 0.75f, 1.0f}) {
            INFO("radius " << radius << ", coverage " << coverage);
            const float rounded = ffxDofRoundForHalfCoc(radius);
            const float packed = ffxDofPackNearCoverage(rounded, coverage);
            CHECK(ffxDofNearCoverage(packed) == coverage);
            // Still exactly a half (its R16 float store keeps the bits), within 3 of its last units.
            CHECK(ffxDofRoundForHalfCoc(packed) == packed);
            CHECK(std::abs(packed - rounded) <= 3.0f * rounded / 1024.0f);
        }
    }
    // Far and in-focus radii are left as they are.
    for (const float radius : {-40.0f, -3.2f, 0.0f, 0.25f}) CHECK(ffxDofPackNearCoverage(radius, 0.5f) == radius);
}

TEST_CASE("A quad the near field covers in part keeps its near pixels and their share", "[downsample]") {
    const FfxFloat32x3 bar(1.0f, 0.8f, 0.6f), wall(0.2f, 0.2f, 0.2f);
    // A bar of 1 px at radius 12 over an in-focus wall, in either column: half the quad, the bar's colour,
    // its radius less the inset.
    for (int column = 0; column < 2; ++column) {
        INFO("column " << column);
        const float left = column == 0 ? 12.0f : 0.0f, right = column == 0 ? 0.0f : 12.0f;
        const FfxDofNearQuad quad =
            ffxDofReduceNearQuad(column == 0 ? bar : wall, column == 0 ? wall : bar, column == 0 ? bar : wall,
                                 column == 0 ? wall : bar, left, right, left, right);
        CHECK(quad.partial);
        CHECK(quad.texel.coverage == 0.5f);
        CHECK(quad.texel.coc == 12.0f - FFX_DOF_NEAR_COVERAGE_INSET);
        CHECK(quad.texel.color.x == Approx(bar.x));
        CHECK(quad.texel.color.z == Approx(bar.z));
    }
    // One near pixel of four: a quarter.
    CHECK(ffxDofReduceNearQuad(bar, wall, wall, wall, 6.0f, -3.0f, -3.0f, -3.0f).texel.coverage == 0.25f);
    // All near, none near, or a near radius too small to keep apart: the bilateral reduction stands.
    CHECK_FALSE(ffxDofReduceNearQuad(bar, bar, bar, bar, 6.0f, 7.5f, 6.0f, 9.0f).partial);
    CHECK_FALSE(ffxDofReduceNearQuad(wall, wall, wall, wall, 0.0f, -3.0f, 0.2f, -9.0f).partial);
    CHECK_FALSE(
        ffxDofReduceNearQuad(bar, wall, wall, wall, FFX_DOF_NEAR_COVERAGE_MIN_RADIUS - 0.1f, 0.0f, 0.0f, 0.0f).partial);
}

TEST_CASE("A coarse near radius carries its coverage in sixteenths and stays a half", "[downsample]") {
    for (const float radius : {1.5f, 2.75f, 7.3f, 24.0f, 40.1f, 130.0f}) {
        for (int sixteenths = 1; sixteenths <= 16; ++sixteenths) {
            const float coverage = float(sixteenths) / 16.0f;
            INFO("radius " << radius << ", coverage " << coverage);
            const float packed = ffxDofPackCoarseNearCoverage(radius, coverage);
            CHECK(ffxDofCoarseNearCoverage(packed) == coverage);
            // Exactly a half (ffxDofPackCoarseTexel stores it as one), within 1/32 of the radius.
            CHECK(ffxDofRoundForHalfCoc(packed) == packed);
            CHECK(std::abs(packed - radius) <= radius / 32.0f);
        }
    }
    // Below a sixteenth rounds up to one: a near texel never vanishes.
    CHECK(ffxDofCoarseNearCoverage(ffxDofPackCoarseNearCoverage(12.0f, 0.01f)) == 1.0f / 16.0f);
    for (const float radius : {-40.0f, -3.2f, 0.0f, 0.25f}) CHECK(ffxDofPackCoarseNearCoverage(radius, 0.5f) == radius);
}

namespace {

// A 16 x 16 pixel block reduced to its MIP-3 texel as ffxDofDownsampleColor does it.
FfxDofMipTexel reduceBlockToMip3(const std::vector<FfxFloat32x3>& colors, const std::vector<float>& cocs) {
    std::vector<FfxDofMipTexel> level;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            auto at = [&](int dx, int dy) { return size_t((2 * y + dy) * 16 + 2 * x + dx); };
            level.push_back(ffxDofReduceQuadTexel(colors[at(0, 0)], colors[at(1, 0)], colors[at(0, 1)],
                                                  colors[at(1, 1)], cocs[at(0, 0)], cocs[at(1, 0)], cocs[at(0, 1)],
                                                  cocs[at(1, 1)]));
        }
    for (int side = 4; side >= 1; side /= 2) {
        std::vector<FfxDofMipTexel> next;
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                auto child = [&](int dx, int dy) { return level[size_t((2 * y + dy) * 2 * side + 2 * x + dx)]; };
                next.push_back(ffxDofReduceMipTexel(child(0, 0), child(1, 0), child(0, 1), child(1, 1)));
            }
        level = next;
    }
    return level[0];
}

}  // namespace

TEST_CASE("A MIP texel in group-shared memory keeps its coverage in 256ths and its radius", "[downsample]") {
    for (const float radius : {-40.0f, -3.2f, 0.0f, 0.75f, 2.5f, 19.5f, 130.0f}) {
        for (const int parts : {1, 3, 16, 64, 255, 256}) {
            const float coverage = float(parts) / 256.0f;
            INFO("radius " << radius << ", coverage " << coverage);
            const FfxDofMipTexel stored =
                ffxDofMakeMipTexel(FfxFloat32x3(1.0f, 2.0f, 3.0f), radius, coverage, FfxFloat32x2(0.25f, -0.125f));
            ffxDofStoreSharedMipTexel(5u, stored);
            const FfxDofMipTexel texel = ffxDofSharedMipTexel(5u);
            // What the storing invocation keeps in registers is what its slot holds, to the bit.
            const FfxDofMipTexel kept = ffxDofAsSharedMipTexel(stored);
            CHECK(ffxDofAsUInt(kept.coc) == ffxDofAsUInt(texel.coc));
            CHECK(kept.coverage == texel.coverage);
            CHECK(kept.color.x == texel.color.x);
            CHECK(kept.lightOffset.x == texel.lightOffset.x);
            CHECK(texel.coverage == coverage);
            CHECK(std::abs(texel.coc - radius) <= std::abs(radius) / 32768.0f);
            CHECK(texel.color.y == 2.0f);
            CHECK(texel.lightOffset.y == -0.125f);
        }
    }
}

TEST_CASE("The coarse levels keep a thin near bar's share of their texel and where it lies", "[downsample]") {
    const FfxFloat32x3 bar(1.0f, 0.8f, 0.6f), wall(0.2f, 0.2f, 0.2f);
    for (const int width : {1, 2, 4}) {
        for (int left = 0; left + width <= 16; left += 3) {
            INFO("bar of " << width << " px from column " << left);
            std::vector<FfxFloat32x3> colors(256, wall);
            std::vector<float> cocs(256, 0.0f);
            for (int y = 0; y < 16; ++y)
                for (int x = left; x < left + width; ++x) {
                    colors[size_t(y * 16 + x)] = bar;
                    cocs[size_t(y * 16 + x)] = 20.0f;
                }
            const FfxDofMipTexel mip3 = reduceBlockToMip3(colors, cocs);
            CHECK(mip3.coverage == Approx(width / 16.0f));
            CHECK(mip3.color.x == Approx(bar.x));
            // The radius of the bar's quads: the bar's where it covers them whole (an even width from an even
            // column), the inset less where only in part, their mean where both.
            const bool wholeQuads = left % 2 == 0 && width % 2 == 0;
            CHECK(mip3.coc <= 20.0f);
            CHECK(mip3.coc >= 20.0f - (wholeQuads ? 0.0f : FFX_DOF_NEAR_COVERAGE_INSET));
            if (!wholeQuads && width <= 2) CHECK(mip3.coc == 20.0f - FFX_DOF_NEAR_COVERAGE_INSET);
            // The light offset (MIP-3 texels from the centre) points at the bar's pixels, whose quads lie
            // within one pixel of them.
            const float barCentre = (float(left) + 0.5f * float(width)) / 16.0f - 0.5f;
            CHECK(std::abs(mip3.lightOffset.x - barCentre) <= 1.0f / 16.0f);
            CHECK(std::abs(mip3.lightOffset.y) <= 1e-3f);
            // Stored and read back, the coverage is the bar's share in sixteenths.
            CHECK(ffxDofCoarseNearCoverage(ffxDofPackCoarseNearCoverage(mip3.coc, mip3.coverage)) ==
                  float(width) / 16.0f);
        }
    }
}

TEST_CASE("Bilateral reduce keeps a bright pixel's energy and radius wherever it lies in the quad", "[downsample]") {
    // A bright pixel of radius -4.8 among black ones of -5.65 (a point in front of a far background).
    for (int position = 0; position < 4; ++position) {
        FfxFloat32x3 colors[4] = {FfxFloat32x3(0), FfxFloat32x3(0), FfxFloat32x3(0), FfxFloat32x3(0)};
        float cocs[4] = {-5.65f, -5.65f, -5.65f, -5.65f};
        colors[position] = FfxFloat32x3(8.0f);
        cocs[position] = -4.8f;
        FfxFloat32x3 color;
        float coc;
        ffxDofBilateralReduce(colors[0], colors[1], colors[2], colors[3], cocs[0], cocs[1], cocs[2], cocs[3], color,
                              coc);
        INFO("bright pixel at " << position);
        CHECK(color.x == Approx(2.0f));  // the plain average: energy kept
        CHECK(coc == Approx(-4.8f).margin(0.01f));
    }
    // Beyond the flat range the outlier gets weight 0 wherever it is (it used to depend on the
    // top-left pixel being the outlier or not).
    for (int position = 0; position < 4; ++position) {
        float cocs[4] = {-3.0f, -3.0f, -3.0f, -3.0f};
        cocs[position] = 2.0f;
        FfxFloat32x3 colors[4] = {FfxFloat32x3(1), FfxFloat32x3(1), FfxFloat32x3(1), FfxFloat32x3(1)};
        colors[position] = FfxFloat32x3(9.0f);
        FfxFloat32x3 color;
        float coc;
        ffxDofBilateralReduce(colors[0], colors[1], colors[2], colors[3], cocs[0], cocs[1], cocs[2], cocs[3], color,
                              coc);
        INFO("outlier at " << position);
        CHECK(color.x == Approx(1.0f));
        CHECK(coc == Approx(-3.0f));
    }
}

namespace {

// The light-rim radius of a centre pixel among 8 neighbours, through the shader's three functions.
float lightRimCoc(float luminance, float coc, const std::vector<std::pair<float, float>>& neighbours) {
    FfxDofLightRim rim = ffxDofLightRimBegin(luminance, coc);
    for (const auto& [neighbourLuminance, neighbourCoc] : neighbours)
        rim = ffxDofLightRimAdd(rim, luminance, coc, neighbourLuminance, neighbourCoc);
    return ffxDofLightRimCoc(rim, luminance, coc);
}

}  // namespace

TEST_CASE("Light offsets: the luminance-weighted centre of a quad's sources, their own offsets carried up",
          "[downsample]") {
    const FfxFloat32x2 none(0.0f, 0.0f);
    // Equal light everywhere: the texel's centre.
    FfxFloat32x2 offset = ffxDofReduceLightOffset(1.0f, 1.0f, 1.0f, 1.0f, none, none, none, none);
    CHECK(offset.x == Approx(0.0f).margin(1e-6));
    CHECK(offset.y == Approx(0.0f).margin(1e-6));
    // All the light in one source: that source's centre, a quarter of the texel from its centre.
    offset = ffxDofReduceLightOffset(0.0f, 5.0f, 0.0f, 0.0f, none, none, none, none);
    CHECK(offset.x == Approx(0.25f));
    CHECK(offset.y == Approx(-0.25f));
    // A source's own offset (in its texels) counts half in the reduced texel's.
    offset = ffxDofReduceLightOffset(0.0f, 0.0f, 2.0f, 0.0f, none, none, FfxFloat32x2(0.5f, -0.5f), none);
    CHECK(offset.x == Approx(0.0f).margin(1e-6));
    CHECK(offset.y == Approx(0.0f).margin(1e-6));
}

TEST_CASE("Light offsets: two levels of reduction place a lone bright pixel exactly", "[downsample]") {
    // A 4 x 4 px block (one MIP-1 texel) of black pixels with one bright pixel, all at one far radius:
    // MIP 0 from the four quads, then MIP 1 from MIP 0 with their offsets. The MIP-1 offset is the
    // pixel's centre relative to the block's, in MIP-1 texels (4 px), whichever pixel it is.
    for (int bright = 0; bright < 16; ++bright) {
        const int bx = bright % 4, by = bright / 4;
        FfxFloat32x3 mip0Color[4];
        float mip0Coc[4];
        FfxFloat32x2 mip0Offset[4];
        for (int q = 0; q < 4; ++q) {
            const int qx = (q % 2) * 2, qy = (q / 2) * 2;
            FfxFloat32x3 colors[4];
            for (int p = 0; p < 4; ++p) {
                const bool lit = qx + p % 2 == bx && qy + p / 2 == by;
                colors[p] = FfxFloat32x3(lit ? 1000.0f : 0.0f);
            }
            const FfxFloat32x2 none(0.0f, 0.0f);
            ffxDofBilateralReduceLight(colors[0], colors[1], colors[2], colors[3], -6.0f, -6.0f, -6.0f, -6.0f, none,
                                       none, none, none, mip0Color[q], mip0Coc[q], mip0Offset[q]);
        }
        FfxFloat32x3 color;
        float coc;
        FfxFloat32x2 offset;
        ffxDofBilateralReduceLight(mip0Color[0], mip0Color[1], mip0Color[2], mip0Color[3], mip0Coc[0], mip0Coc[1],
                                   mip0Coc[2], mip0Coc[3], mip0Offset[0], mip0Offset[1], mip0Offset[2], mip0Offset[3],
                                   color, coc, offset);
        INFO("bright pixel (" << bx << ", " << by << ")");
        CHECK(color.x == Approx(1000.0f / 16.0f));
        CHECK(offset.x == Approx((bx + 0.5f) / 4.0f - 0.5f).margin(1e-4));
        CHECK(offset.y == Approx((by + 0.5f) / 4.0f - 0.5f).margin(1e-4));
    }
}

TEST_CASE("Light rims: a bright rim pixel at the background's depth takes the light's radius", "[downsample]") {
    // A rim pixel (250) at the background's radius -14, beside the light (1000 at -9) and the
    // background (0.05 at -14): the brightness the light gives it must spread with the light's disc.
    const std::vector<std::pair<float, float>> rimOfLight = {{1000.0f, -9.0f}, {500.0f, -9.0f}, {0.05f, -14.0f},
                                                             {0.05f, -14.0f},  {0.05f, -14.0f}, {0.05f, -14.0f},
                                                             {0.05f, -14.0f},  {250.0f, -14.0f}};
    CHECK(lightRimCoc(250.0f, -14.0f, rimOfLight) == -9.0f);
    // The nearest of two brighter far neighbours, never a dimmer one.
    std::vector<std::pair<float, float>> twoLights = rimOfLight;
    twoLights[2] = {300.0f, -6.0f};
    twoLights[3] = {100.0f, -2.0f};  // nearer but dimmer than the pixel: not its light
    CHECK(lightRimCoc(250.0f, -14.0f, twoLights) == -6.0f);
}

TEST_CASE("Light rims: every other pixel keeps its own radius", "[downsample]") {
    const std::vector<std::pair<float, float>> flat(8, {0.05f, -14.0f});
    // The background itself, and a pixel of it not 4 times brighter than its dimmest neighbour.
    CHECK(lightRimCoc(0.05f, -14.0f, flat) == -14.0f);
    std::vector<std::pair<float, float>> beside = flat;
    beside[0] = {1000.0f, -9.0f};
    CHECK(lightRimCoc(0.19f, -14.0f, beside) == -14.0f);
    CHECK(lightRimCoc(0.21f, -14.0f, beside) == -9.0f);  // just above 4 times the dimmest (0.05)
    // In focus or in the near field: the composite draws those pixels from the input, and a far radius
    // would spread them into the background (or the reverse).
    CHECK(lightRimCoc(250.0f, -0.5f, beside) == -0.5f);
    CHECK(lightRimCoc(250.0f, 3.0f, beside) == 3.0f);
    // The light must be in the far field too: an in-focus or near neighbour never lends its radius.
    std::vector<std::pair<float, float>> inFocusLight = flat;
    inFocusLight[0] = {1000.0f, -0.5f};
    inFocusLight[1] = {1000.0f, 4.0f};
    CHECK(lightRimCoc(250.0f, -14.0f, inFocusLight) == -14.0f);
    // A light farther than the pixel does not pull it back.
    std::vector<std::pair<float, float>> fartherLight = flat;
    fartherLight[0] = {1000.0f, -20.0f};
    CHECK(lightRimCoc(250.0f, -14.0f, fartherLight) == -14.0f);
    // Black stays black whatever surrounds it.
    const std::vector<std::pair<float, float>> black(8, {0.0f, -14.0f});
    std::vector<std::pair<float, float>> blackBeside = black;
    blackBeside[0] = {0.0f, -9.0f};
    CHECK(lightRimCoc(0.0f, -14.0f, blackBeside) == -14.0f);
}

TEST_CASE("Light rims: a pixel the tile's dimmest pixel rules out keeps its radius whatever its neighbours",
          "[downsample]") {
    // Pass 2 reads no neighbour for a quad none of whose pixels ffxDofIsLightRim admits against the dimmest
    // pixel of the whole rim grid. Sound only if the full test never gives such a pixel another radius: random
    // neighbourhoods of lights, rims and dim surfaces at mixed depths.
    std::mt19937 random(29);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto luminanceOf = [&]() {
        const float kind = unit(random);
        return kind < 0.1f ? 0.0f : kind < 0.3f ? 1000.0f * unit(random) : 2.0f * unit(random);
    };
    auto cocOf = [&]() { return unit(random) < 0.2f ? 6.0f * unit(random) - 3.0f : -20.0f * unit(random); };
    int ruledOut = 0;
    int admitted = 0;
    int rimsAmongAdmitted = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const float luminance = luminanceOf();
        const float coc = cocOf();
        std::vector<std::pair<float, float>> neighbours(8);
        float dimmest = luminance;  // over the pixel and its neighbours: no more than the grid's
        for (auto& [neighbourLuminance, neighbourCoc] : neighbours) {
            neighbourLuminance = luminanceOf();
            neighbourCoc = unit(random) < 0.5f ? coc + 2.0f * unit(random) - 1.0f : cocOf();
            dimmest = std::min(dimmest, neighbourLuminance);
        }
        // The grid's dimmest pixel may lie outside the 3 x 3: anywhere from 0 to the neighbourhood's dimmest.
        const float gridDimmest = dimmest * (trial % 3 == 0 ? 1.0f : unit(random));
        const float rimCoc = lightRimCoc(luminance, coc, neighbours);
        if (!ffxDofIsLightRim(luminance, coc, gridDimmest)) {
            ++ruledOut;
            INFO("luminance " << luminance << ", radius " << coc << ", grid's dimmest " << gridDimmest);
            CHECK(rimCoc == coc);
        } else {
            ++admitted;
            rimsAmongAdmitted += rimCoc != coc;
        }
    }
    // Both sides were exercised, and the bound is not so loose that it admits nothing but rims.
    CHECK(ruledOut > 2000);
    CHECK(rimsAmongAdmitted > 100);
    CHECK(rimsAmongAdmitted < admitted);
}

TEST_CASE("The border ring of a grid names each border cell once (the rim grid, the composite's filtered texels)",
          "[downsample][composite]") {
    for (const uint32_t side : {uint32_t(FFX_DOF_RIM_SIDE), uint32_t(FFX_DOF_FILTERED_SIDE), 3u}) {
        std::set<std::pair<uint32_t, uint32_t>> cells;
        for (uint32_t index = 0; index < 4 * (side - 1); ++index) {
            const FfxUInt32x2 cell = ffxDofBorderCell(index, side);
            INFO("side " << side << ", index " << index << ": (" << cell.x << ", " << cell.y << ")");
            CHECK((cell.x == 0 || cell.x == side - 1 || cell.y == 0 || cell.y == side - 1));
            CHECK(cell.x < side);
            CHECK(cell.y < side);
            cells.insert({cell.x, cell.y});
        }
        CHECK(cells.size() == size_t(4 * (side - 1)));
    }
}

TEST_CASE("The composite's packed texels keep what they claim to keep exactly", "[composite]") {
    // Raw summaries: every LAYER_ALPHA code's opacity and validity come back bit for bit; the luminances as halves.
    for (int code = 0; code < 256; ++code) {
        const glm::vec2 alpha = ffxDofUnpackLayerAlpha((float(code) + 0.25f) / 255.0f);
        const glm::vec4 summary = ffxDofUnpackRawSummary(ffxDofPackRawSummary(3.0f, 0.1f, alpha));
        INFO("code " << code);
        CHECK(ffxDofAsUInt(summary.z) == ffxDofAsUInt(alpha.x));
        CHECK(summary.w == alpha.y);
        CHECK(summary.x == 3.0f);
        CHECK(summary.y == Approx(0.1f).epsilon(1.0 / 2048.0));
    }
    // Filtered texels: validity, radius (a HALF_COC value) and opacity exact; colours rounded to halves, and the
    // texel returned to the invocation that stored it is the one the others load.
    for (const float radius : {-27.0f, -3.3984375f, 0.0f, 0.49975586f, 12.5f}) {
        for (const float validity : {0.0f, 1.0f}) {
            FfxDofFilteredTexel texel;
            texel.nearColor = FfxDofFloat3(0.1f, 2.0f, 4000.0f);
            texel.farColor = FfxDofFloat3(1.0f / 3.0f, 0.0f, 65.5f);
            texel.alpha = glm::vec2(0.123456789f, validity);
            texel.coc = radius;
            const FfxDofFilteredTexel stored = ffxDofStoreFilteredTexel(7, texel);
            const FfxDofFilteredTexel loaded = ffxDofLoadFilteredTexel(7);
            INFO("radius " << radius << ", validity " << validity);
            CHECK(loaded.coc == radius);
            CHECK(loaded.alpha.y == validity);
            CHECK(loaded.alpha.x == texel.alpha.x);
            CHECK(glm::vec3(loaded.nearColor) == glm::vec3(stored.nearColor));
            CHECK(glm::vec3(loaded.farColor) == glm::vec3(stored.farColor));
            CHECK(float(loaded.farColor.x) == Approx(1.0f / 3.0f).epsilon(1.0 / 2048.0));
            CHECK(float(loaded.nearColor.z) == 4000.0f);
        }
    }
}

TEST_CASE("The composite's raw grid is its invocations' block centres and two rings, each cell once", "[composite]") {
    std::set<std::pair<uint32_t, uint32_t>> cells;
    for (uint32_t local = 0; local < uint32_t(FFX_DOF_GROUP_THREADS); ++local) {
        const FfxUInt32x2 cell = ffxDofLocalCoord(local) + FfxUInt32x2(2u, 2u);
        cells.insert({cell.x, cell.y});
    }
    const uint32_t ringCells = uint32_t(FFX_DOF_RAW_SIDE * FFX_DOF_RAW_SIDE - FFX_DOF_GROUP_THREADS);
    for (uint32_t index = 0; index < ringCells; ++index) {
        const FfxUInt32x2 cell = ffxDofRawRingCell(index);
        INFO("ring index " << index << ": (" << cell.x << ", " << cell.y << ")");
        CHECK(cell.x < uint32_t(FFX_DOF_RAW_SIDE));
        CHECK(cell.y < uint32_t(FFX_DOF_RAW_SIDE));
        // Outside the interior, which the block centres cover.
        CHECK((cell.x < 2u || cell.x >= uint32_t(FFX_DOF_RAW_SIDE) - 2u || cell.y < 2u ||
               cell.y >= uint32_t(FFX_DOF_RAW_SIDE) - 2u));
        cells.insert({cell.x, cell.y});
    }
    CHECK(cells.size() == size_t(FFX_DOF_RAW_SIDE * FFX_DOF_RAW_SIDE));
}

TEST_CASE("Bilateral reduce keeps the energy of a small far light in front of a farther background", "[downsample]") {
    // A light of radius -10.4 among background pixels of -16 (1, 2 or 3 of the quad's pixels), 1000x
    // brighter: the texel holds the quad's plain average (energy kept) with the light's radius.
    for (int lights = 1; lights <= 3; ++lights) {
        for (int first = 0; first < 4; ++first) {
            FfxFloat32x3 colors[4];
            float cocs[4];
            for (int i = 0; i < 4; ++i) {
                const bool light = (i - first + 4) % 4 < lights;
                colors[i] = FfxFloat32x3(light ? 50.0f : 0.05f);
                cocs[i] = light ? -10.4f : -16.0f;
            }
            FfxFloat32x3 color;
            float coc;
            ffxDofBilateralReduce(colors[0], colors[1], colors[2], colors[3], cocs[0], cocs[1], cocs[2], cocs[3], color,
                                  coc);
            INFO(lights << " light pixels from " << first);
            CHECK(color.x == Approx((50.0f * lights + 0.05f * (4 - lights)) / 4.0f).epsilon(1e-4));
            CHECK(coc == Approx(-10.4f).margin(0.02f));
        }
    }
    // A dark pixel in front of a bright background is still dropped (no dark halo in the background).
    FfxFloat32x3 color;
    float coc;
    ffxDofBilateralReduce(FfxFloat32x3(0.01f), FfxFloat32x3(2.0f), FfxFloat32x3(2.0f), FfxFloat32x3(2.0f), -3.0f,
                          -16.0f, -16.0f, -16.0f, color, coc);
    CHECK(color.x == Approx(2.0f));
    CHECK(coc == Approx(-16.0f));
}

TEST_CASE("Ring merge amount: merged when flat, full when not, continuous in between", "[kernel]") {
    CHECK(ffxDofRingMergeAmount(0.0f) == 1.0f);
    CHECK(ffxDofRingMergeAmount(0.5f) == 1.0f);
    CHECK(ffxDofRingMergeAmount(0.75f) == Approx(0.5f));
    CHECK(ffxDofRingMergeAmount(1.0f) == 0.0f);
    CHECK(ffxDofRingMergeAmount(7.0f) == 0.0f);
    // No jump anywhere: a small change of spread moves the amount by at most spread change / 0.5.
    for (float spread = 0.0f; spread < 1.5f; spread += 0.01f)
        CHECK(std::abs(ffxDofRingMergeAmount(spread + 0.01f) - ffxDofRingMergeAmount(spread)) <= 0.0201f);
}

namespace {

// The texels a walk of the annulus visits, in order; fails on a runaway walk.
std::vector<std::pair<int, int>> walkAnnulus(const FfxDofAnnulus& annulus) {
    std::vector<std::pair<int, int>> texels;
    int steps = 0;
    for (FfxDofAnnulusWalk walk = ffxDofAnnulusBegin(annulus); ffxDofAnnulusRowsLeft(annulus, walk);
         walk = ffxDofAnnulusNext(annulus, walk)) {
        if (ffxDofAnnulusValid(walk)) texels.emplace_back(int(walk.texel.x), int(walk.texel.y));
        REQUIRE(++steps < 100000);
    }
    return texels;
}

std::vector<std::pair<int, int>> walkAnnulus(FfxFloat32x2 origin, float innerRadius, float outerRadius,
                                             float innerBlock = 1.0f, float outerBlock = 1.0f) {
    return walkAnnulus(ffxDofMakeAnnulus(origin, innerRadius, outerRadius, innerBlock, outerBlock, 1.0f));
}

// Distance from `origin` to the centre of texel (x, y), in double precision.
double centreDistance(FfxFloat32x2 origin, int x, int y) {
    return std::hypot(x + 0.5 - double(origin.x), y + 0.5 - double(origin.y));
}

}  // namespace

TEST_CASE("Walks at two MIPs sharing a border judged by the coarse texels read every fine texel once", "[kernel]") {
    // The blur's schedule in small: an outer ring at MIP m, a merged group at MIP m + 1 (block 2)
    // inside it, a centre ring at MIP m inside that. The fine walks judge their borders with the
    // coarse walk by the coarse texels; every fine texel of the whole kernel must be read exactly once,
    // directly or as a quarter of the coarse texel holding it.
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 400; ++trial) {
        const FfxFloat32x2 origin(20.0f + 4.0f * unit(rng), 20.0f + 4.0f * unit(rng));
        const float spacing = 0.7f + 0.8f * unit(rng);
        const uint32_t rings = 2u + uint32_t(unit(rng) * 9.0f);
        const float kernelOuter = ffxDofRingInnerRadius(rings + 1u, spacing);
        // The rim border moved in as the blur moves it where merged rings meet the outermost ring.
        const float rimInset = trial % 2 == 0 ? FFX_DOF_RING_MERGE_RIM_INSET : 0.0f;
        const float groupOuter = ffxDofWalkBorderRadius(rings, spacing, rings, true, rimInset);
        const float groupInner = ffxDofRingInnerRadius(1u, spacing);
        std::map<std::pair<int, int>, int> reads;
        for (const auto& t : walkAnnulus(origin, groupOuter, kernelOuter, 2.0f, 1.0f)) ++reads[t];
        for (const auto& t : walkAnnulus(origin, 0.0f, groupInner, 1.0f, 2.0f)) ++reads[t];
        for (const auto& t : walkAnnulus(origin * 0.5f, groupInner * 0.5f, groupOuter * 0.5f))
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) ++reads[{2 * t.first + dx, 2 * t.second + dy}];
        INFO("trial " << trial << ": origin " << origin.x << ", " << origin.y << ", spacing " << spacing << ", rings "
                      << rings << ", rim inset " << rimInset);
        for (const auto& [texel, count] : reads) REQUIRE(count == 1);
        // Nothing of the kernel is missed: every texel whose centre lies well inside is read.
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x)
                if (centreDistance(origin, x, y) < kernelOuter - 1e-3) REQUIRE(reads.count({x, y}) == 1);
    }
}

TEST_CASE("The blur's walks read every fine texel of a kernel once in all, at every merge amount", "[kernel]") {
    // The real schedule: the outermost ring as ffxDofGatherKernel walks it, then the inner rings'
    // plan (ffxDofPlanInnerRings), each walk's annulus as ffxDofGatherRing builds it. A texel of a
    // coarser MIP stands for the fine texels it holds, at its walk's presence; in all, every fine texel of
    // the kernel must count once. Rings walked one by one counted some twice where a part-merged group
    // met the rings below it: its inner border is judged by the coarse texels, its rings' borders by the
    // fine ones, and a block's corner texels lay beyond the next fine border.
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 1500; ++trial) {
        FfxDofKernel kernel{};
        kernel.aperture = ffxDofRoundAperture();
        kernel.rings = 1u + uint32_t(unit(rng) * 10.0f);
        kernel.baseMip = uint32_t(trial % 2);
        const float texel = float(1u << kernel.baseMip);
        kernel.spacing = (0.71f + 0.7f * unit(rng)) * texel;
        kernel.origin = FfxFloat32x2(40.0f + 4.0f * unit(rng), 40.0f + 4.0f * unit(rng)) * texel;
        // As ffxDofGatherKernel, and rings merge only where the smallest radius spans two coarse texels
        // (ffxDofMergedRingsResolve): at least 4 texels of the kernel's MIP.
        const bool mergeEligible = FFX_DOF_RING_MERGE_LOG > 0 && kernel.rings >= 2u && trial % 5 != 0 &&
                                   float(kernel.rings) * kernel.spacing >= 4.0f * texel;
        kernel.rimInset = mergeEligible && trial % 3 != 0 ? FFX_DOF_RING_MERGE_RIM_INSET * texel : 0.0f;
        // A shaped disc's rim rings are never merged: fewer mergeable rings. ffxDofGatherInnerRings has rim
        // rings only where the rim border, moved in, lies above them (else the rim lies in the band).
        uint32_t mergeableRings = kernel.rings - 1u;
        if (trial % 4 == 0) {
            const uint32_t candidate = uint32_t(unit(rng) * float(kernel.rings));
            if ((float(candidate) + 0.5f) * kernel.spacing <
                (float(kernel.rings) - 0.5f) * kernel.spacing - kernel.rimInset)
                mergeableRings = candidate;
        }
        const float mergeAmount = !mergeEligible ? 0.0f : trial % 7 == 0 ? 1.0f : trial % 7 == 1 ? 0.0f : unit(rng);
        const uint32_t coarseMip = ffxDofCoarseMip(kernel.baseMip);

        std::map<std::pair<int, int>, float> reads;
        const auto addWalk = [&](uint32_t first, uint32_t last, uint32_t mip, uint32_t innerMip, uint32_t outerMip,
                                 float presence) {
            const int block = 1 << (mip - kernel.baseMip);
            for (const auto& [x, y] :
                 walkAnnulus(ffxDofRingsAnnulus(kernel, first, last, mip, innerMip, outerMip, false)))
                for (int dy = 0; dy < block; ++dy)
                    for (int dx = 0; dx < block; ++dx) reads[{x * block + dx, y * block + dy}] += presence;
        };
        // Where no ring can merge, ffxDofGatherKernel walks the whole kernel at once.
        addWalk(mergeEligible ? kernel.rings : 0u, kernel.rings, kernel.baseMip,
                mergeEligible ? coarseMip : kernel.baseMip, kernel.baseMip, 1.0f);
        FfxDofInnerRingPlan plan = ffxDofPlanInnerRings(kernel.rings, mergeableRings, kernel.baseMip, mergeAmount);
        int walks = 0;
        while (mergeEligible && plan.pending != 0u) {
            const FfxDofInnerWalk walk = ffxDofNextInnerWalk(plan);
            REQUIRE(walk.firstRing <= walk.lastRing);
            REQUIRE(walk.lastRing < kernel.rings);
            addWalk(walk.firstRing, walk.lastRing, walk.mip, coarseMip, coarseMip, walk.presence);
            REQUIRE(++walks <= 5);
        }
        INFO("trial " << trial << ": rings " << kernel.rings << ", mergeable " << mergeableRings << ", base MIP "
                      << kernel.baseMip << ", spacing " << kernel.spacing << ", merge amount " << mergeAmount
                      << ", rim inset " << kernel.rimInset);
        for (const auto& [fine, count] : reads) {
            INFO("fine texel " << fine.first << ", " << fine.second);
            REQUIRE(std::abs(count - 1.0f) < 1e-5f);
        }
        // Nothing of the kernel is missed.
        const float kernelRadius = (float(kernel.rings) + 0.5f) * kernel.spacing / texel;
        for (int y = 0; y < 100; ++y)
            for (int x = 0; x < 100; ++x)
                if (centreDistance(kernel.origin / texel, x, y) < kernelRadius - 1e-3)
                    REQUIRE(reads.count({x, y}) == 1);
    }
}

TEST_CASE("Kernel row half-width is the circle's or the anamorphic ellipse's", "[kernel]") {
    CHECK(ffxDofKernelRowHalfWidth(5.0f, 0.0f, 1.0f) == 5.0f);
    CHECK(ffxDofKernelRowHalfWidth(5.0f, 3.0f, 1.0f) == Approx(4.0f));
    CHECK(ffxDofKernelRowHalfWidth(5.0f, -4.0f, 1.0f) == Approx(3.0f));
    CHECK(ffxDofKernelRowHalfWidth(5.0f, 5.0f, 1.0f) == 0.0f);
    CHECK(ffxDofKernelRowHalfWidth(5.0f, 7.0f, 1.0f) == 0.0f);  // outside: no row, not NaN
    CHECK(ffxDofKernelRowHalfWidth(0.0f, 0.0f, 1.0f) == 0.0f);
    CHECK(ffxDofKernelRowHalfWidth(5.0f, 3.0f, 0.5f) == Approx(2.0f));  // ratio 2: half as wide
}

TEST_CASE("Texel span: the texels whose centres lie strictly within the half-width", "[kernel]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> center(-20.0f, 20.0f), width(0.0f, 6.0f);
    for (int trial = 0; trial < 5000; ++trial) {
        // Centres on and off texel centres and edges, widths of exact half-integers too.
        const float c = trial % 4 == 0 ? std::round(center(rng)) + 0.5f * float(trial % 8 == 0) : center(rng);
        const float w = trial % 3 == 0 ? 0.5f * float(trial % 11) : width(rng);
        const FfxFloat32x2 span = ffxDofTexelSpan(c, w);
        int first = 1000, last = -1000;
        for (int i = -40; i <= 40; ++i) {
            if (std::abs(i + 0.5 - double(c)) < double(w)) {
                first = std::min(first, i);
                last = std::max(last, i);
            }
        }
        INFO("centre " << c << " half-width " << w);
        if (first > last) {
            REQUIRE(span.x > span.y);
        } else {
            REQUIRE(span.x == float(first));
            REQUIRE(span.y == float(last));
        }
    }
}

TEST_CASE("Ring radii: ring k spans (k - 1/2) s to (k + 1/2) s, ring 0 the centre", "[kernel]") {
    CHECK(ffxDofRingInnerRadius(0, 1.3f) == 0.0f);
    CHECK(ffxDofRingInnerRadius(1, 1.3f) == Approx(0.65f));
    CHECK(ffxDofRingInnerRadius(4, 0.8f) == Approx(2.8f));
}

TEST_CASE("Merged rings stand for a tile's radii where they are flat or span two coarse texels", "[kernel]") {
    // (far, near, footprint min, footprint max) as DILATED_TILES holds them; base MIP 1: coarse texels of
    // 4 half-res px.
    CHECK(ffxDofMergedRingsResolve(FfxFloat32x4(-16.0f, 0.0f, -16.0f, -15.2f), 1u));       // flat
    CHECK(ffxDofMergedRingsResolve(FfxFloat32x4(-16.0f, 0.0f, -16.0f, -9.2f), 1u));        // smallest 9.2 >= 8
    CHECK(ffxDofMergedRingsResolve(FfxFloat32x4(-16.0f, 0.0f, -16.0f, -8.0f), 1u));        // exactly two texels
    CHECK_FALSE(ffxDofMergedRingsResolve(FfxFloat32x4(-16.0f, 0.0f, -16.0f, -7.5f), 1u));  // a light of 7.5
    CHECK_FALSE(ffxDofMergedRingsResolve(FfxFloat32x4(-16.0f, 0.0f, -16.0f, -3.0f), 1u));  // a light of 3
    CHECK_FALSE(ffxDofMergedRingsResolve(FfxFloat32x4(-16.0f, 0.0f, -16.0f, 0.2f), 1u));   // in focus
    CHECK_FALSE(ffxDofMergedRingsResolve(FfxFloat32x4(-16.0f, 6.0f, -16.0f, 6.0f), 1u));   // near field
    CHECK(ffxDofMergedRingsResolve(FfxFloat32x4(-16.0f, 0.0f, -16.0f, -4.0f), 0u));        // coarse texels of 2
    CHECK_FALSE(ffxDofMergedRingsResolve(FfxFloat32x4(-16.0f, 0.0f, -16.0f, -3.0f), 0u));
}

TEST_CASE("Walk borders: only the rim border judged by coarse texels moves in, never below 0", "[kernel]") {
    // Ring 5 of 5 is the outermost ring: its inner edge is the rim border.
    CHECK(ffxDofWalkBorderRadius(5, 1.2f, 5, true, 0.5f) == Approx(4.9f));
    CHECK(ffxDofWalkBorderRadius(5, 1.2f, 5, false, 0.5f) == Approx(5.4f));
    CHECK(ffxDofWalkBorderRadius(4, 1.2f, 5, true, 0.5f) == Approx(4.2f));
    CHECK(ffxDofWalkBorderRadius(1, 0.2f, 1, true, 0.5f) == 0.0f);
    // Computed in the units of two MIPs a power of two apart, the border agrees to the bit.
    CHECK(ffxDofWalkBorderRadius(7, 1.37f, 7, true, 0.5f) * 0.5f == ffxDofWalkBorderRadius(7, 0.685f, 7, true, 0.25f));
}

TEST_CASE("Annulus walk: exactly the texels whose centres lie from inner (included) to outer radius, each once",
          "[kernel]") {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 3000; ++trial) {
        // Origins anywhere, and exactly on texel centres and edges (the jitter can be 0).
        FfxFloat32x2 origin(30.0f + 4.0f * unit(rng), 30.0f + 4.0f * unit(rng));
        if (trial % 5 == 0) origin = glm::floor(origin) + FfxFloat32x2(0.5f * float(trial % 2), 0.5f);
        const float outer = 12.0f * unit(rng);
        const float inner = trial % 7 == 0 ? 0.0f : outer * unit(rng);
        const std::vector<std::pair<int, int>> texels = walkAnnulus(origin, inner, outer);
        std::set<std::pair<int, int>> unique(texels.begin(), texels.end());
        INFO("origin " << origin.x << ", " << origin.y << ", radii " << inner << " .. " << outer);
        REQUIRE(unique.size() == texels.size());
        // Row by row, left to right.
        REQUIRE(std::is_sorted(texels.begin(), texels.end(), [](auto a, auto b) {
            return std::make_pair(a.second, a.first) < std::make_pair(b.second, b.first);
        }));
        size_t expected = 0;
        for (int y = 10; y < 55; ++y) {
            for (int x = 10; x < 55; ++x) {
                const double d = centreDistance(origin, x, y);
                // Away from the borders by float rounding; on them either side is right.
                if (std::abs(d - inner) < 1e-4 || std::abs(d - outer) < 1e-4) {
                    expected += unique.count({x, y});
                    continue;
                }
                const bool inside = d >= inner && d < outer;
                REQUIRE(unique.count({x, y}) == size_t(inside));
                expected += inside;
            }
        }
        REQUIRE(texels.size() == expected);
    }
}

TEST_CASE("The rings of a kernel read every texel inside it exactly once", "[kernel]") {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 500; ++trial) {
        const float radius = 0.5f + 20.0f * unit(rng);
        const uint32_t rings = ffxDofRingCount(radius, 1 + trial % 12);
        const float spacing = radius / float(rings);
        const FfxFloat32x2 origin = FfxFloat32x2(40.5f, 40.5f) + ffxDofKernelJitter(FfxUInt32x2(trial, 3), 0);
        std::map<std::pair<int, int>, int> reads;
        for (uint32_t ring = 0; ring <= rings; ++ring) {
            for (const auto& texel :
                 walkAnnulus(origin, ffxDofRingInnerRadius(ring, spacing), ffxDofRingInnerRadius(ring + 1, spacing)))
                ++reads[texel];
        }
        const double edge = (double(rings) + 0.5) * double(spacing);
        size_t inside = 0;
        for (int y = 0; y < 81; ++y)
            for (int x = 0; x < 81; ++x) inside += centreDistance(origin, x, y) < edge - 1e-4;
        INFO("radius " << radius << ", rings " << rings);
        for (const auto& [texel, count] : reads) {
            REQUIRE(count == 1);
            REQUIRE(centreDistance(origin, texel.first, texel.second) < edge + 1e-4);
        }
        REQUIRE(reads.size() >= inside);
        REQUIRE(reads.size() <= inside + size_t(8.0 * edge));  // texels on the edge, within rounding
    }
}

TEST_CASE("A one-texel source is read once by every kernel that covers it", "[kernel]") {
    // The issue-6 defect: ring points read the nearest texel, so a source texel was read 0 to 2 times
    // depending on where the output texel lay; every output texel's kernel must now read it once.
    const FfxFloat32x2 source(50.5f, 50.5f);
    const float radius = 4.8f;
    const uint32_t rings = ffxDofRingCount(radius, 10);
    const float spacing = radius / float(rings);
    for (int y = 44; y <= 57; ++y) {
        for (int x = 44; x <= 57; ++x) {
            const FfxFloat32x2 origin = FfxFloat32x2(float(x) + 0.5f, float(y) + 0.5f) +
                                        ffxDofKernelJitter(FfxUInt32x2(uint32_t(x), uint32_t(y)), 7);
            const double distance = std::hypot(double(origin.x - source.x), double(origin.y - source.y));
            int reads = 0;
            for (uint32_t ring = 0; ring <= rings; ++ring) {
                for (const auto& texel : walkAnnulus(origin, ffxDofRingInnerRadius(ring, spacing),
                                                     ffxDofRingInnerRadius(ring + 1, spacing)))
                    reads += texel == std::make_pair(50, 50);
            }
            INFO("output texel " << x << ", " << y << ", distance " << distance);
            CHECK(reads == (distance < (double(rings) + 0.5) * spacing ? 1 : 0));
        }
    }
}

TEST_CASE("Ring count follows the radius, capped by quality and the compile-time bound", "[kernel]") {
    CHECK(ffxDofRingCount(0.0f, 10) == 0u);
    CHECK(ffxDofRingCount(0.49f, 10) == 0u);
    CHECK(ffxDofRingCount(0.5f, 10) == 1u);
    CHECK(ffxDofRingCount(3.2f, 10) == 4u);
    CHECK(ffxDofRingCount(30.0f, 10) == 10u);
    CHECK(ffxDofRingCount(30.0f, 0) == 1u);
    CHECK(ffxDofRingCount(1000.0f, 1000) == uint32_t(FFX_DOF_OPTION_MAX_RINGS));
}

TEST_CASE("MIP level for a ring spacing: the texel size nearest the spacing in log2", "[kernel]") {
    CHECK(ffxDofMipForSpacing(0.6f) == 0.0f);
    CHECK(ffxDofMipForSpacing(1.0f) == 0.0f);
    CHECK(ffxDofMipForSpacing(1.41f) == 0.0f);
    CHECK(ffxDofMipForSpacing(1.42f) == 1.0f);
    CHECK(ffxDofMipForSpacing(2.82f) == 1.0f);
    CHECK(ffxDofMipForSpacing(2.84f) == 2.0f);
    CHECK(ffxDofMipForSpacing(100.0f) == float(FFX_DOF_OPTION_MAX_MIP - 1));
    // Spacing in texels of the chosen level: 1/sqrt(2) to sqrt(2) (from 0.5 at level 0, where a
    // kernel of radius 0.5 to 1 has one ring), so a walk reads about as many texels as 6k ring points.
    for (float spacing = 0.5f; spacing < 8.0f; spacing *= 1.01f) {
        const float texels = spacing / std::exp2(ffxDofMipForSpacing(spacing));
        CHECK(texels >= (spacing < 1.0f ? 0.5f : 0.7071f));
        CHECK(texels < 1.4143f);
    }
}

TEST_CASE("The coarser MIP of far kernels: texels no smaller than the ring spacing", "[kernel]") {
    CHECK(ffxDofCoarserMipForSpacing(0.6f) == 0.0f);
    CHECK(ffxDofCoarserMipForSpacing(1.0f) == 0.0f);
    CHECK(ffxDofCoarserMipForSpacing(1.01f) == 1.0f);
    CHECK(ffxDofCoarserMipForSpacing(2.0f) == 1.0f);
    CHECK(ffxDofCoarserMipForSpacing(2.01f) == 2.0f);
    CHECK(ffxDofCoarserMipForSpacing(100.0f) == float(FFX_DOF_OPTION_MAX_MIP - 1));
    for (float spacing = 0.5f; spacing < 8.0f; spacing *= 1.01f) {
        const float texels = spacing / std::exp2(ffxDofCoarserMipForSpacing(spacing));
        CHECK(texels <= 1.0f);
        CHECK(texels > (spacing < 1.0f ? 0.49f : 0.5f));
        // Never finer than the nearest level, at most one coarser.
        CHECK(ffxDofCoarserMipForSpacing(spacing) >= ffxDofMipForSpacing(spacing));
        CHECK(ffxDofCoarserMipForSpacing(spacing) <= ffxDofMipForSpacing(spacing) + 1.0f);
    }
}

TEST_CASE("Which kernels read the coarser MIP: far, nothing near and no light around, inside the image", "[kernel]") {
    FfxDofConstants constants{};
    constants.halfSize = FfxUInt32x2(480, 270);
    constants.anamorphicRatio = 1.0f;
    // (far reach, near reach, footprint min, max) of a far tile that no near radius reaches.
    const FfxFloat32x4 farTile(-12.0f, -11.0f, -12.0f, -11.0f);
    const FfxFloat32x2 middle(240.5f, 135.5f);
    const float radius = 11.5f;
    const float coarser = ffxDofCoarserMipForSpacing(radius / 10.0f);
    CHECK(ffxDofKernelTakesCoarserMip(middle, -radius, radius, farTile, false, coarser, constants));
    // A near or in-focus texel, a near radius reaching the tile, a light in the tiles around (FFX_DOF_LISTED_TILE_*):
    // the nearest MIP.
    CHECK_FALSE(ffxDofKernelTakesCoarserMip(middle, radius, radius, farTile, false, coarser, constants));
    CHECK_FALSE(ffxDofKernelTakesCoarserMip(middle, -0.4f, radius, farTile, false, coarser, constants));
    CHECK_FALSE(ffxDofKernelTakesCoarserMip(middle, -radius, radius, FfxFloat32x4(-12.0f, 8.0f, -12.0f, 8.0f), false,
                                            coarser, constants));
    CHECK_FALSE(ffxDofKernelTakesCoarserMip(middle, -radius, radius, farTile, true, coarser, constants));
    // Everything it reads inside the image, the walk beyond the kernel (the tile's far reach) and a texel
    // of the coarser MIP and of its merged rings' MIP included: not within that of any border.
    const float reach = 12.0f + std::exp2(coarser) * (1.0f + std::exp2(float(FFX_DOF_RING_MERGE_LOG)));
    for (const FfxFloat32x2 nearBorder :
         {FfxFloat32x2(reach - 0.5f, 135.5f), FfxFloat32x2(240.5f, reach - 0.5f),
          FfxFloat32x2(480.0f - reach + 0.5f, 135.5f), FfxFloat32x2(240.5f, 270.0f - reach + 0.5f)})
        CHECK_FALSE(ffxDofKernelTakesCoarserMip(nearBorder, -radius, radius, farTile, false, coarser, constants));
    for (const FfxFloat32x2 inside : {FfxFloat32x2(reach, 135.5f), FfxFloat32x2(240.5f, reach),
                                      FfxFloat32x2(480.0f - reach, 135.5f), FfxFloat32x2(240.5f, 270.0f - reach)})
        CHECK(ffxDofKernelTakesCoarserMip(inside, -radius, radius, farTile, false, coarser, constants));
}

TEST_CASE("A coarse outermost ring reads every texel whose light the kernel reaches, the walk beyond it the rest",
          "[kernel]") {
    // A texel of MIP 1 or coarser holds its light up to sqrt(1/2) texel from its centre (its light
    // offset); the kernel's reach takes a light up to its radius + half a pixel away. The outermost
    // ring's outer border lies far enough out for the centre of any such texel, and the walk beyond
    // the kernel (ffxDofBehindAnnulus) starts at that border: the two share no texel and miss none.
    // Behind a kernel at MIP 0 the walk beyond is at MIP 1 (ffxDofBehindMip) and leaves out the lights
    // the kernel's border holds: a light in any texel of MIP 0 is read once.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 400; ++trial) {
        FfxDofKernel kernel{};
        kernel.aperture = ffxDofRoundAperture();
        kernel.rings = 2u + uint32_t(unit(rng) * 9.0f);
        kernel.baseMip = uint32_t(trial % 3);
        const float texel = float(1u << kernel.baseMip);
        kernel.spacing = (0.5f + 0.5f * unit(rng)) * texel;  // the coarser MIP: 0.5 to 1 texel per ring
        kernel.origin = FfxFloat32x2(60.0f + 4.0f * unit(rng), 60.0f + 4.0f * unit(rng)) * texel;
        const float radius = float(kernel.rings) * kernel.spacing;
        kernel.behindRadius = radius * (1.2f + unit(rng));
        INFO("trial " << trial << ": rings " << kernel.rings << ", MIP " << kernel.baseMip << ", spacing "
                      << kernel.spacing);
        const float outer = ffxDofKernelOuterRadius(kernel.rings, kernel.spacing / texel, kernel.baseMip);
        if (kernel.baseMip > 0u && kernel.spacing >= 1.0f)
            CHECK(outer * texel >= radius + 0.5f + std::sqrt(0.5f) * texel);
        std::set<std::pair<int, int>> ring;
        for (const auto& t : walkAnnulus(ffxDofRingsAnnulus(kernel, kernel.rings, kernel.rings, kernel.baseMip,
                                                            kernel.baseMip, kernel.baseMip, false)))
            ring.insert(t);
        const uint32_t behindMip = ffxDofBehindMip(kernel.baseMip);
        std::set<std::pair<int, int>> behind;
        for (const auto& t : walkAnnulus(ffxDofBehindAnnulus(kernel, behindMip, false))) {
            if (behindMip == kernel.baseMip) REQUIRE(ring.count(t) == 0);
            behind.insert(t);
        }
        const FfxFloat32x2 origin = kernel.origin / texel;
        const float innerOfRing = ffxDofRingInnerRadius(kernel.rings, kernel.spacing / texel);
        const float outerOfBehind = (kernel.behindRadius + 0.5f * kernel.spacing) / texel;
        const FfxDofAnnulusBorder kernelBorder = ffxDofRingsAnnulus(kernel, kernel.rings, kernel.rings, kernel.baseMip,
                                                                    kernel.baseMip, kernel.baseMip, false)
                                                     .outer;
        const int shift = int(behindMip - kernel.baseMip);
        for (int y = 0; y < 140; ++y)
            for (int x = 0; x < 140; ++x) {
                // A light in texel (x, y) of the kernel's MIP: at a coarser walk, its texel holds it there
                // (its light offset), and the walk leaves it out where the kernel's border holds it.
                const bool behindReads = behind.count({x >> shift, y >> shift}) == 1 &&
                                         (shift == 0 || !ffxDofBorderHolds(kernelBorder, FfxFloat32x2(x, y)));
                const double d = centreDistance(origin, x, y);
                if (d <= innerOfRing + 1e-3)
                    REQUIRE_FALSE(behindReads);  // the inner rings read it
                else if (d < outerOfBehind - (1 << shift) - 1e-3)
                    REQUIRE(ring.count({x, y}) + (behindReads ? 1 : 0) == 1);
            }
    }
}

TEST_CASE("MIP sizes follow the Vulkan rule", "[tiles]") {
    CHECK(ffxDofMipSize(FfxUInt32x2(961, 540), 0) == FfxUInt32x2(961, 540));
    CHECK(ffxDofMipSize(FfxUInt32x2(961, 540), 1) == FfxUInt32x2(480, 270));
    CHECK(ffxDofMipSize(FfxUInt32x2(5, 1), 3) == FfxUInt32x2(1, 1));
}

TEST_CASE("Local coordinates cover the 8 x 8 group once", "[tiles]") {
    std::vector<int> seen(64, 0);
    for (uint32_t i = 0; i < 64; ++i) {
        FfxUInt32x2 c = ffxDofLocalCoord(i);
        REQUIRE(c.x < 8u);
        REQUIRE(c.y < 8u);
        seen[c.y * 8 + c.x]++;
    }
    CHECK(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

TEST_CASE("Tile gap distance is the shortest pixel-centre distance between tiles", "[tiles]") {
    const int t = FFX_DOF_TILE_SIZE;
    for (int dy = -4; dy <= 4; ++dy) {
        for (int dx = -4; dx <= 4; ++dx) {
            float best = 1e30f;
            for (int ay = 0; ay < t; ++ay)
                for (int ax = 0; ax < t; ++ax)
                    for (int by = 0; by < t; ++by)
                        for (int bx = 0; bx < t; ++bx)
                            best = std::min(best, std::hypot(float(dx * t + bx - ax), float(dy * t + by - ay)));
            REQUIRE(ffxDofTileGapDistance(FfxInt32x2(dx, dy)) == Approx(best));
        }
    }
}

TEST_CASE("Dilation range covers the global radius and margin", "[tiles]") {
    for (float r = 0.0f; r < 200.0f; r += 0.37f) {
        int range = ffxDofDilateTileRange(r);
        // The first tile beyond the range is out of reach of every radius up to r.
        CHECK_FALSE(ffxDofTileReaches(r, ffxDofTileGapDistance(FfxInt32x2(range + 1, 0))));
    }
}

TEST_CASE("Reach and area weight", "[gather]") {
    CHECK(ffxDofReach(5.0f, 3.0f) == 1.0f);
    CHECK(ffxDofReach(5.0f, 5.0f) == 0.5f);
    CHECK(ffxDofReach(5.0f, 5.5f) == 0.0f);
    FfxDofPixelAperture round{};
    round.areaScale = 1.0f;
    CHECK(ffxDofApertureAreaWeight(round, 2.0f) == Approx(0.25f));
    CHECK(ffxDofApertureAreaWeight(round, 0.1f) == Approx(4.0f));
}

TEST_CASE("Far layers: a texel's own surface and nearer samples in front, farther ones behind", "[gather]") {
    // Own radius 10: up to 10.5 fully front, 11.5 and beyond fully back, linear between.
    CHECK(ffxDofFarFrontShare(4.0f, 10.0f) == 1.0f);
    CHECK(ffxDofFarFrontShare(10.5f, 10.0f) == 1.0f);
    CHECK(ffxDofFarFrontShare(11.0f, 10.0f) == Approx(0.5f));
    CHECK(ffxDofFarFrontShare(11.5f, 10.0f) == 0.0f);
    CHECK(ffxDofFarFrontShare(30.0f, 10.0f) == 0.0f);
}

TEST_CASE("Far layers compose front to back by the front layer's coverage", "[gather]") {
    const float pi = 3.14159265f;
    FfxFloat32x3 color;
    FfxDofBucket front = ffxDofEmptyBucket(), back = ffxDofEmptyBucket();
    CHECK_FALSE(ffxDofComposeFarLayers(front, back, color));
    // Only a back layer (a near texel's background): its average.
    back.color = FfxFloat32x3(2, 0, 0);
    back.weight = 4.0f;
    REQUIRE(ffxDofComposeFarLayers(front, back, color));
    CHECK(color.x == Approx(0.5f));
    // A solid front surface (weights summing to pi) hides the background entirely.
    front.color = FfxFloat32x3(0, pi, 0);
    front.weight = pi;
    REQUIRE(ffxDofComposeFarLayers(front, back, color));
    CHECK(color.x == Approx(0.0f).margin(1e-6));
    CHECK(color.y == Approx(1.0f));
    // A small light in front (weight 0.1 of pi): 10% of it over 90% of the background, whatever the
    // light's brightness (its centre must not keep the input's brightness).
    front.color = FfxFloat32x3(0, 50.0f * 0.1f * pi, 0);
    front.weight = 0.1f * pi;
    REQUIRE(ffxDofComposeFarLayers(front, back, color));
    CHECK(color.x == Approx(0.45f));
    CHECK(color.y == Approx(5.0f));
    // Only a front layer: its average, even where its coverage is partial (nothing behind it).
    REQUIRE(ffxDofComposeFarLayers(front, ffxDofEmptyBucket(), color));
    CHECK(color.y == Approx(50.0f));
}

TEST_CASE("Near opacity of a uniform near field of the kernel radius is 1", "[gather]") {
    // The blur's geometry and weights: every texel of the kernel read once from the kernel's MIP, each
    // weighing reach * area weight * texel area; a near region of exactly the kernel radius R covers
    // the kernel, its samples reaching fully up to R - 1/2 and by half at R.
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 200; ++trial) {
        const float radius = 1.0f + 30.0f * unit(rng);
        const uint32_t rings = ffxDofRingCount(radius, 10);
        const float spacing = radius / float(rings);
        const uint32_t mip = uint32_t(ffxDofMipForSpacing(spacing));
        const float texel = std::exp2(float(mip));
        const FfxFloat32x2 center(64.5f, 64.5f);
        const FfxFloat32x2 origin = center + ffxDofKernelJitter(FfxUInt32x2(trial, 1), 0);
        float weight = 0.0f;
        for (uint32_t ring = 0; ring <= rings; ++ring) {
            for (const auto& [x, y] : walkAnnulus(origin / texel, ffxDofRingInnerRadius(ring, spacing) / texel,
                                                  ffxDofRingInnerRadius(ring + 1, spacing) / texel)) {
                const float distance = float(centreDistance(center / texel, x, y)) * texel;
                weight += ffxDofReach(radius, distance) / (radius * radius) * texel * texel;
            }
        }
        INFO("radius " << radius << ", MIP " << mip << ", weight / pi " << weight / kPi);
        // The sum is the covered area over pi R^2; the kernel ends half a ring beyond R (0.25 to 0.7
        // texels), the reach at R + 0.5: the area it leaves out is a few texels of the rim.
        CHECK(weight / kPi == Approx(1.0f).margin(1.5f * texel / radius));
        CHECK(ffxDofNearOpacity(0.5f * kPi) == Approx(0.5f));
        CHECK(ffxDofNearOpacity(weight) >= 1.0f - 1.5f * texel / radius);
    }
}

TEST_CASE("Median of nine matches nth_element", "[postfilter]") {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> small(0, 4);  // many ties
    std::uniform_real_distribution<float> any(-10.0f, 10.0f);
    for (int trial = 0; trial < 20000; ++trial) {
        float v[9];
        for (float& x : v) x = trial % 2 ? any(rng) : float(small(rng));
        std::vector<float> sorted(v, v + 9);
        std::nth_element(sorted.begin(), sorted.begin() + 4, sorted.end());
        REQUIRE(ffxDofMedian9(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]) == sorted[4]);
    }
}

TEST_CASE("Outlier gain moves only a texel outside its neighbours' range", "[postfilter]") {
    // Hot and cold spots are pulled to the nearest neighbour's luminance.
    CHECK(ffxDofOutlierGain(2.0f, 0.5f, 1.0f) == Approx(0.5f));
    CHECK(ffxDofOutlierGain(1.0f, 1.5f, 3.0f) == Approx(1.5f));
    // Within the range (an edge, a disc's rim): unchanged, so no energy is taken.
    CHECK(ffxDofOutlierGain(1.0f, 0.0f, 10.0f) == 1.0f);
    CHECK(ffxDofOutlierGain(1.0f, 1.0f, 1.0f) == 1.0f);
    // Bounded brightening; a black texel stays black.
    CHECK(ffxDofOutlierGain(1.0f, 100.0f, 200.0f) == Approx(FFX_DOF_OUTLIER_MAX_GAIN));
    CHECK(ffxDofOutlierGain(0.0f, 1.0f, 2.0f) == 1.0f);
    // A lone bright texel among black ones goes black.
    CHECK(ffxDofOutlierGain(5.0f, 0.0f, 0.0f) == 0.0f);
}

TEST_CASE("Near layer weight: the opacity itself, clamped", "[postfilter]") {
    CHECK(ffxDofNearLayerWeight(0.0f) == 0.0f);
    CHECK(ffxDofNearLayerWeight(-1.0f) == 0.0f);
    CHECK(ffxDofNearLayerWeight(1.0f) == 1.0f);
    CHECK(ffxDofNearLayerWeight(2.0f) == 1.0f);
    // A thin bar's faint veil keeps its opacity (the technique's cubic made 0.2 about 0.1, and a toe
    // below 0.1 halved the veils of 1 to 4 px bars at near radii of 24 to 40 px).
    CHECK(ffxDofNearLayerWeight(0.2f) == 0.2f);
    CHECK(ffxDofNearLayerWeight(0.03f) == 0.03f);
}

TEST_CASE("Fixed blur weights are the coverage of a 3 px disc", "[postfilter]") {
    auto coverage = [](int cx, int cy) {
        const int n = 400;
        int inside = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                float x = float(cx) - 0.5f + (float(i) + 0.5f) / n;
                float y = float(cy) - 0.5f + (float(j) + 0.5f) / n;
                inside += x * x + y * y <= 2.25f;
            }
        return float(inside) / float(n * n);
    };
    CHECK(ffxDofFixedBlurWeight(0, 0) == Approx(coverage(0, 0)).margin(0.005));
    CHECK(ffxDofFixedBlurWeight(1, 0) == Approx(coverage(1, 0)).margin(0.005));
    CHECK(ffxDofFixedBlurWeight(0, -1) == Approx(coverage(0, -1)).margin(0.005));
    CHECK(ffxDofFixedBlurWeight(-1, 1) == Approx(coverage(-1, 1)).margin(0.005));
}

TEST_CASE("Upsample position maps full-res pixel centres into half-res texel space", "[upsample]") {
    FfxInt32x2 topLeft;
    FfxFloat32x2 f = ffxDofUpsamplePosition(FfxUInt32x2(0, 1), topLeft);
    CHECK(topLeft == FfxInt32x2(-1, 0));
    CHECK(f.x == Approx(0.75f));
    CHECK(f.y == Approx(0.25f));
    f = ffxDofUpsamplePosition(FfxUInt32x2(17, 30), topLeft);
    CHECK(topLeft == FfxInt32x2(8, 14));
    CHECK(f.x == Approx(0.25f));
    CHECK(f.y == Approx(0.75f));
}

TEST_CASE("Upsample: a quad's four pixels read the 3 x 3 texels from its texel's top-left neighbour", "[upsample]") {
    // ffxDofComposite reads each pixel's 2 x 2 taps from the quad's 3 x 3 block at offset (dx, dy), the
    // pixel's place in the quad, with fraction 0.75 (even) or 0.25 (odd) per axis.
    for (uint32_t qy = 0; qy < 40; qy += 2) {
        for (uint32_t qx = 0; qx < 40; qx += 2) {
            for (uint32_t k = 0; k < 4; ++k) {
                const FfxUInt32x2 inQuad(k & 1u, k >> 1u);
                FfxInt32x2 topLeft;
                const FfxFloat32x2 f = ffxDofUpsamplePosition(FfxUInt32x2(qx, qy) + inQuad, topLeft);
                CHECK(topLeft == FfxInt32x2(int32_t(qx / 2) - 1, int32_t(qy / 2) - 1) + FfxInt32x2(inQuad));
                CHECK(f.x == (inQuad.x ? 0.25f : 0.75f));
                CHECK(f.y == (inQuad.y ? 0.25f : 0.75f));
            }
        }
    }
}

TEST_CASE("Raw layer colours keep every B10G11R11 value through the composite's 16-bit group-shared copy",
          "[composite]") {
    // Every 11-bit float (5-bit exponent, 6-bit mantissa; the 10-bit blue has 5): a half holds each exactly.
    for (uint32_t bits = 0; bits < (1u << 11); ++bits) {
        const uint32_t exponent = bits >> 6, mantissa = bits & 63u;
        if (exponent == 31u) continue;  // inf and NaN: the layers are finite
        const float value = exponent == 0 ? std::ldexp(float(mantissa), -14 - 6)
                                          : std::ldexp(1.0f + float(mantissa) / 64.0f, int(exponent) - 15);
        const FfxDofFloat3 color(value, value * 0.5f, 0.0f);
        const FfxDofFloat3 back = ffxDofUnpackRawColor(ffxDofPackRawColor(color));
        INFO("value " << value);
        CHECK(back.x == value);
        CHECK(back.y == value * 0.5f);
    }
}

TEST_CASE("Upsample CoC weight favours matching radii", "[upsample]") {
    CHECK(ffxDofUpsampleCocWeight(-30.0f, -30.0f) == 1.0f);
    CHECK(ffxDofUpsampleCocWeight(0.0f, -30.0f) == Approx(1e-3f));
    CHECK(ffxDofUpsampleCocWeight(-30.0f, 0.0f) == Approx(1e-3f));
    CHECK(ffxDofUpsampleCocWeight(0.5f, 0.0f) == Approx(0.5f));
    // Near and in-focus pixels judge a tap against half their own radius.
    CHECK(ffxDofUpsampleCocWeight(27.0f, 30.0f) == Approx(0.8f));
    CHECK(ffxDofUpsampleCocWeight(15.0f, 30.0f) == Approx(1e-3f));
    // A far tap whose layer holds its own surface, for a far pixel: the smaller radius over the larger,
    // whichever is the pixel's.
    CHECK(ffxDofUpsampleCocWeight(-27.0f, -30.0f) == Approx(0.9f));
    CHECK(ffxDofUpsampleCocWeight(-6.5f, -16.0f) == Approx(6.5f / 16.0f));
    CHECK(ffxDofUpsampleCocWeight(-16.0f, -6.5f) == Approx(6.5f / 16.0f));
    CHECK(ffxDofUpsampleCocWeight(-16.0f, -2.0f) == Approx(2.0f / 16.0f));
    CHECK(ffxDofUpsampleCocWeight(-3.0f, -3000.0f) == Approx(1e-3f));
    // A tap whose own surface the composite gathers at full resolution (its far layer leaves it out): as
    // before, ramped in from FFX_DOF_FAR_LAYER_ONLY_RADIUS - FFX_DOF_OWN_SURFACE_FADE.
    CHECK(ffxDofUpsampleCocWeight(-0.8f, -16.0f) == Approx(1e-3f));
    CHECK(ffxDofUpsampleCocWeight(-2.0f, -16.0f) == Approx(1e-3f));
    CHECK(ffxDofUpsampleCocWeight(-2.5f, -16.0f) == Approx(0.5f * 2.5f / 16.0f));
    CHECK(ffxDofUpsampleCocWeight(-3.0f, -16.0f) == Approx(3.0f / 16.0f));
    // A far tap for a near pixel, and the reverse, are still rejected.
    CHECK(ffxDofUpsampleCocWeight(-16.0f, 16.0f) == Approx(1e-3f));
    CHECK(ffxDofUpsampleCocWeight(16.0f, -16.0f) == Approx(1e-3f));
}

TEST_CASE("Layer blend weights match the variance of the pixel's disc", "[composite]") {
    // Per-axis variance of the fixed 3x3 kernel, from its weights, in half-res px^2.
    double weightSum = 0.0, moment = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            weightSum += ffxDofFixedBlurWeight(dx, dy);
            moment += ffxDofFixedBlurWeight(dx, dy) * dx * dx;
        }
    }
    const double fixedVariance = moment / weightSum / 4.0;
    CHECK(FFX_DOF_FIXED_BLUR_VARIANCE == Approx(fixedVariance).epsilon(1e-3));
    // A disc of radius r (half-res px = 2r full-res px) has a per-axis variance of (2r)^2 / 4 full-res
    // px^2, r^2 / 4 half-res px^2.
    for (float r : {0.5f, 0.6f, 0.7f}) {
        CHECK(ffxDofFixedBlurBlend(r, 0.0f) * fixedVariance == Approx(r * r / 4.0).epsilon(1e-3));
        CHECK(ffxDofFarBlend(r, 1.0f) == 0.0f);
    }
    CHECK(ffxDofFixedBlurBlend(1.0f, 0.0f) == 1.0f);
    CHECK(ffxDofFixedBlurBlend(1.0f, 0.5f) == 0.0f);  // near opacity above 0.3 blocks the fixed blur
    for (float r : {1.0f, 1.5f, 1.9f}) {
        const double a = ffxDofFarBlend(r, 1.0f);
        const double mixed = a * (r * r / 4.0 + FFX_DOF_FAR_LAYER_EXTRA_VARIANCE) + (1.0 - a) * fixedVariance;
        CHECK(mixed == Approx(r * r / 4.0).epsilon(1e-3));
    }
    CHECK(ffxDofFarBlend(3.0f, 1.0f) == 1.0f);
    CHECK(ffxDofFarBlend(3.0f, 0.25f) == Approx(0.25f));
    CHECK(ffxDofFarBlend(2.5f, 1.0f) > ffxDofFarBlend(2.0f, 1.0f));
}

namespace {

// Taps of a near disc's rim over an in-focus surface of 0.3: the left two texels covered by the near layer
// (opacity `opacity`, colour 10), the right two not at all.
FfxDofUpsampleTaps nearRimTaps(float opacity) {
    FfxDofUpsampleTaps taps{};
    for (int k = 0; k < 4; ++k) {
        const bool covered = k == 0 || k == 2;
        taps.alpha[k] = glm::vec2(covered ? opacity : 0.0f, 1.0f);
        taps.nearColor[k] = FfxDofFloat3(covered ? 10.0f : 0.0f);
        taps.farColor[k] = FfxDofFloat3(0.3f);
        taps.coc[k] = 0.0f;
    }
    return taps;
}

// Composes one pixel of radius `coc` (input 0.3) from `taps` at the bilinear `fraction`; `composed` says
// whether it changed from its input.
glm::vec4 composeRimPixel(const FfxDofUpsampleTaps& taps, glm::vec2 fraction, float coc, bool* composed) {
    glm::vec4 color(0.3f, 0.3f, 0.3f, 1.0f);
    *composed = ffxDofComposePixel(taps, fraction, coc, glm::vec3(0.3f), false, glm::vec4(0.0f), false, glm::vec4(0.0f),
                                   glm::vec3(0.0f), glm::vec3(0.0f), color);
    return color;
}

}  // namespace

TEST_CASE("The near layer's rim keeps its light over in-focus pixels, and only the near layer changes them",
          "[composite]") {
    bool composed = false;
    // Half the footprint covered, at opacity 0.5: a near opacity of 0.25 with the covered taps' colour (10) over the
    // input, nothing else (no fixed blur, no far layer: the pixel is in focus). Before 7aea5e0 the colour was the
    // bilinear mean of all four taps (5), the uncovered ones' included.
    const glm::vec4 rim = composeRimPixel(nearRimTaps(0.5f), glm::vec2(0.5f), 0.0f, &composed);
    CHECK(composed);
    CHECK(rim.y == Approx(0.3f + 0.25f * (10.0f - 0.3f)));
    CHECK(rim.w == 1.0f);
    // Along a row across the rim, what the near layer adds is its bilinear share of each covered texel's light
    // (opacity times colour over the input): the left column's, at weights 1 - fx summing to 2.
    double added = 0.0;
    for (float fx : {0.125f, 0.375f, 0.625f, 0.875f})
        added += composeRimPixel(nearRimTaps(0.01f), glm::vec2(fx, 0.5f), 0.0f, &composed).y - 0.3;
    CHECK(added == Approx(2.0 * 0.01 * (10.0 - 0.3)).epsilon(1e-4));
    CHECK(added > 0.0);
    // No near coverage in the footprint: an in-focus pixel keeps its input.
    const glm::vec4 kept = composeRimPixel(nearRimTaps(0.0f), glm::vec2(0.5f), 0.0f, &composed);
    CHECK_FALSE(composed);
    CHECK(kept.y == 0.3f);
}

TEST_CASE("A near pixel whose own surface covers little of its disc shows mostly the layers", "[composite]") {
    // A near pixel of radius 1 half-res px that gathers its own surface at full resolution: the layers hold a near
    // opacity of 0.028 of colour 1 over a far layer of 0, its own gather a colour of 1 covering `coverage` of its disc.
    FfxDofUpsampleTaps taps{};
    for (int k = 0; k < 4; ++k) {
        taps.alpha[k] = glm::vec2(0.028f, 1.0f);
        taps.nearColor[k] = FfxDofFloat3(1.0f);
        taps.farColor[k] = FfxDofFloat3(0.0f);
        taps.coc[k] = 1.0f;
    }
    auto compose = [&](float coverage) {
        glm::vec4 color(1.0f, 1.0f, 1.0f, 1.0f);
        REQUIRE(ffxDofComposePixel(taps, glm::vec2(0.5f), 1.0f, glm::vec3(1.0f), true,
                                   glm::vec4(1.0f, 1.0f, 1.0f, coverage), false, glm::vec4(0.0f), glm::vec3(0.0f),
                                   glm::vec3(0.0f), color));
        return color.y;
    };
    // An isolated speck (its own pixel covers 0.08 of its disc): the own gather over the far layer (0.08) mixed
    // with the layers (0.028) by the square of what it leaves uncovered, 0.92^2.
    const float uncovered = 0.92f * 0.92f;
    CHECK(compose(0.08f) == Approx(0.08f * (1.0f - uncovered) + 0.028f * uncovered));
    // A surface that covers its whole disc is its own gather alone (the share below FFX_DOF_FAR_LAYER_ONLY_RADIUS
    // minus the fade is 0).
    CHECK(compose(1.0f) == Approx(1.0f));
    // Half covered (a surface's rim): a quarter of the layers, where the pixel's own blur shows its far layer too.
    CHECK(compose(0.5f) == Approx(0.5f * 0.75f + 0.028f * 0.25f));
}

namespace {

// Fills the composite's own-surface arrays (full-res |radius| and color per pixel of the 30 x 30
// neighbourhood) from a function of the pixel, and gathers at `pixel` for its own half-res |radius|.
template <typename Radius, typename Color>
glm::vec4 gatherOwnSurfaceAt(glm::ivec2 pixel, float halfResRadius, Radius radiusAt, Color colorAt) {
    const int side = FFX_DOF_OWN_SURFACE_SIDE;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            ffxDofStoreOwnSample(uint32_t(y * side + x), colorAt(glm::ivec2(x, y)), radiusAt(glm::ivec2(x, y)));
    return ffxDofGatherOwnSurface(pixel, halfResRadius);
}

}  // namespace

TEST_CASE("The own-surface gather blurs a pixel's own disc at full resolution", "[composite]") {
    const glm::ivec2 centre(FFX_DOF_OWN_SURFACE_SIDE / 2, FFX_DOF_OWN_SURFACE_SIDE / 2);
    const glm::vec3 background(0.25f, 0.5f, 0.75f);
    for (float halfResRadius : {0.5f, 1.0f, 2.0f, 2.9f}) {
        const float radius = 2.0f * halfResRadius;  // full-res px
        auto uniform = [&](glm::ivec2) { return radius; };
        auto flat = [&](glm::ivec2) { return background; };
        INFO("half-res radius " << halfResRadius);
        // A surface of one radius all around: its own color, fully covered.
        const glm::vec4 solid = gatherOwnSurfaceAt(centre, halfResRadius, uniform, flat);
        CHECK(solid.x == Approx(background.x).epsilon(1e-5));
        CHECK(solid.z == Approx(background.z).epsilon(1e-5));
        CHECK(solid.w == Approx(1.0f).margin(0.06));

        // One bright pixel on that surface spreads its energy over its disc: summed over every pixel
        // it reaches, what it adds is its own excess (scatter as gather), within 3%.
        const glm::ivec2 light = centre;
        auto withLight = [&](glm::ivec2 q) { return q == light ? background + glm::vec3(100.0f) : background; };
        double added = 0.0;
        const int reach = int(std::ceil(radius + 0.5f));
        for (int dy = -reach; dy <= reach; ++dy)
            for (int dx = -reach; dx <= reach; ++dx)
                added +=
                    gatherOwnSurfaceAt(light + glm::ivec2(dx, dy), halfResRadius, uniform, withLight).x - background.x;
        CHECK(added == Approx(100.0).epsilon(0.03));
    }

    // A sharp neighbour (in focus, radius 0) two pixels away spreads nothing into a blurred pixel; a
    // blurred one of the same radius does.
    auto sharpAt = [&](glm::ivec2 q) { return q == centre + glm::ivec2(2, 0) ? 0.0f : 4.0f; };
    auto brightAt = [&](glm::ivec2 q) { return q == centre + glm::ivec2(2, 0) ? glm::vec3(50.0f) : background; };
    CHECK(gatherOwnSurfaceAt(centre, 2.0f, sharpAt, brightAt).x == Approx(background.x).epsilon(1e-5));
    CHECK(gatherOwnSurfaceAt(
              centre, 2.0f, [](glm::ivec2) { return 4.0f; }, brightAt)
              .x > background.x + 0.5f);

    // At the edge of a surface (its right half sharp, in front): about half the disc covered, so the
    // half-res layers show through by the rest.
    auto halfPlane = [&](glm::ivec2 q) { return q.x > centre.x ? 0.0f : 4.0f; };
    const float edgeCoverage = gatherOwnSurfaceAt(centre, 2.0f, halfPlane, [&](glm::ivec2) { return background; }).w;
    CHECK(edgeCoverage > 0.4f);
    CHECK(edgeCoverage < 0.7f);
}

TEST_CASE("A quad's full-resolution gathers in one walk equal each pixel's own, to the bit", "[composite]") {
    std::mt19937 random(17);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const int side = FFX_DOF_OWN_SURFACE_SIDE;
    int smallSourcesSeen = 0;
    for (int trial = 0; trial < 40; ++trial) {
        // Radii of every kind around the quad: in focus, the gathers' own ranges, beyond them; some lights.
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const float radius = unit(random) < 0.2f ? 0.0f : 12.0f * unit(random);
                const float light = unit(random) < 0.05f ? 100.0f : 1.0f;
                ffxDofStoreOwnSample(uint32_t(y * side + x),
                                     glm::vec3(unit(random), unit(random), unit(random)) * light,
                                     unit(random) < 0.5f ? radius : -radius);
            }
        // Columns of both parities: the walks read the neighbourhood two samples at a time, from even columns.
        const glm::ivec2 topLeft(FFX_DOF_OWN_SURFACE_BORDER + trial % 8,
                                 FFX_DOF_OWN_SURFACE_BORDER + 2 * ((trial / 4) % 4));
        const uint32_t gathers = trial < 16 ? 15u : uint32_t(trial % 16);
        // Own surface: radii within the gather's range.
        glm::vec4 ownCocs;
        for (int k = 0; k < 4; ++k)
            ownCocs[k] = FFX_DOF_OWN_SURFACE_MIN_RADIUS +
                         (FFX_DOF_FAR_LAYER_ONLY_RADIUS - FFX_DOF_OWN_SURFACE_MIN_RADIUS) * unit(random);
        const FfxDofQuadGathers own = ffxDofGatherOwnSurfaceQuad(topLeft, ownCocs, gathers);
        // Small sources: far pixels from the last half-res px below the far-layer radius.
        glm::vec4 farCocs;
        for (int k = 0; k < 4; ++k) farCocs[k] = FFX_DOF_FAR_LAYER_ONLY_RADIUS - 1.0f + 8.0f * unit(random);
        const FfxDofQuadGathers small = ffxDofGatherSmallSourcesQuad(topLeft, farCocs, gathers);
        for (int k = 0; k < 4; ++k) {
            if ((gathers & (1u << k)) == 0u) {
                CHECK(small.gathered[k] == glm::vec4(0.0f));
                continue;
            }
            INFO("trial " << trial << ", pixel " << k << ", radii " << ownCocs[k] << " and " << farCocs[k]);
            const glm::ivec2 pixel = topLeft + glm::ivec2(k & 1, k >> 1);
            const glm::vec4 ownAlone = ffxDofGatherOwnSurface(pixel, ownCocs[k]);
            const glm::vec4 smallAlone = ffxDofGatherSmallSources(pixel, farCocs[k]);
            for (int c = 0; c < 4; ++c) {
                CHECK(own.gathered[k][c] == ownAlone[c]);
                CHECK(small.gathered[k][c] == smallAlone[c]);
            }
            if (smallAlone.w > 0.0f) ++smallSourcesSeen;
        }
    }
    CHECK(smallSourcesSeen > 20);  // the small-source sums were not all empty
}

TEST_CASE("The own-surface gather covers radii below the far-layer radius, and hands over to the layers",
          "[composite]") {
    // Tiles of (min, max) signed radii, half-res px.
    CHECK_FALSE(ffxDofTileGathersOwnSurface(glm::vec2(-0.4f, 0.4f)));   // in focus
    CHECK_FALSE(ffxDofTileGathersOwnSurface(glm::vec2(-0.9f, 0.9f)));   // the fixed 3x3 blur's radii
    CHECK_FALSE(ffxDofTileGathersOwnSurface(glm::vec2(-9.0f, -3.0f)));  // far layer alone
    CHECK_FALSE(ffxDofTileGathersOwnSurface(glm::vec2(3.0f, 9.0f)));    // near layer alone
    CHECK(ffxDofTileGathersOwnSurface(glm::vec2(-9.0f, -2.9f)));
    CHECK(ffxDofTileGathersOwnSurface(glm::vec2(-1.0f, 0.0f)));
    CHECK(ffxDofTileGathersOwnSurface(glm::vec2(0.0f, 1.0f)));
    CHECK(ffxDofTileGathersOwnSurface(glm::vec2(2.9f, 9.0f)));
    CHECK(ffxDofTileGathersOwnSurface(glm::vec2(-9.0f, 9.0f)));
    // The gather's neighbourhood holds the largest disc the composite gathers.
    CHECK(float(FFX_DOF_OWN_SURFACE_BORDER) >= 2.0f * FFX_DOF_FAR_LAYER_ONLY_RADIUS + 0.5f);
    CHECK(ffxDofOwnSurfaceLayerShare(FFX_DOF_FAR_LAYER_ONLY_RADIUS - FFX_DOF_OWN_SURFACE_FADE) == 0.0f);
    CHECK(ffxDofOwnSurfaceLayerShare(FFX_DOF_FAR_LAYER_ONLY_RADIUS - 0.5f * FFX_DOF_OWN_SURFACE_FADE) == Approx(0.5f));
    CHECK(ffxDofOwnSurfaceLayerShare(FFX_DOF_FAR_LAYER_ONLY_RADIUS) == 1.0f);
}

TEST_CASE(
    "Composite classes: a copy where every pixel keeps its input, full resolution only where it gathers there, "
    "the lights' pipeline only where lights are drawn",
    "[composite]") {
    const FfxUInt32 copy = FFX_DOF_COMPOSITE_CLASS_COPY;
    const FfxUInt32 layers = FFX_DOF_COMPOSITE_CLASS_LAYERS;
    const FfxUInt32 fullRes = FFX_DOF_COMPOSITE_CLASS_FULL_RES;
    const FfxUInt32 lights = FFX_DOF_COMPOSITE_CLASS_LIGHTS;
    // (min, max) signed radii, the dilated near radius, whether lights are drawn in it.
    const glm::vec2 inFocus(-0.4f, 0.4f);
    CHECK(ffxDofCompositeTileClass(inFocus, 0.4f, false) == copy);
    // A near field that reaches the tile, or a pixel just out of focus: the layers.
    CHECK(ffxDofCompositeTileClass(inFocus, FFX_DOF_NEAR_THRESHOLD, false) == layers);
    CHECK(ffxDofCompositeTileClass(glm::vec2(-FFX_DOF_IN_FOCUS_RADIUS, 0.0f), 0.0f, false) == layers);
    CHECK(ffxDofCompositeTileClass(glm::vec2(0.0f, FFX_DOF_IN_FOCUS_RADIUS), 0.0f, false) == layers);
    // An in-focus tile drawing small sources keeps its input: the sources are composed over far pixels only.
    CHECK(ffxDofCompositeTileClass(inFocus, 0.0f, true) == copy);
    // Far or near layers alone.
    CHECK(ffxDofCompositeTileClass(glm::vec2(-9.0f, -3.0f), 0.0f, false) == layers);
    CHECK(ffxDofCompositeTileClass(glm::vec2(3.0f, 9.0f), 9.0f, false) == layers);
    // Every tile whose own surface the composite gathers: without lights the own-surface pipeline, with lights drawn
    // in it the lights' pipeline.
    for (const glm::vec2 tile : {glm::vec2(-9.0f, -2.9f), glm::vec2(-1.0f, 0.0f), glm::vec2(0.0f, 1.0f),
                                 glm::vec2(2.9f, 9.0f), glm::vec2(-9.0f, 9.0f)}) {
        INFO("tile " << tile.x << ", " << tile.y);
        REQUIRE(ffxDofTileGathersOwnSurface(tile));
        CHECK(ffxDofCompositeTileClass(tile, tile.y, false) == fullRes);
        CHECK(ffxDofCompositeTileClass(tile, tile.y, true) == lights);
    }
    // Every tile drawing lights.
    CHECK(ffxDofCompositeTileClass(glm::vec2(-9.0f, -3.0f), 0.0f, true) == lights);
    CHECK(ffxDofCompositeTileClass(glm::vec2(3.0f, 9.0f), 9.0f, true) == lights);
    // FULL_RES leaves out the highlights' share of the pixels it gathers, so no tile beside one that gave light may
    // take it: such a tile's discs, of at least FFX_DOF_HIGHLIGHT_MIN_RADIUS, reach every tile of the 3 x 3 around it,
    // so dilate finds them drawing its light (reachedByHighlights).
    for (const FfxInt32x2 offset : {FfxInt32x2(0, 0), FfxInt32x2(1, 0), FfxInt32x2(0, 1), FfxInt32x2(1, 1)}) {
        INFO("offset " << offset.x << ", " << offset.y);
        CHECK(ffxDofTileReaches(FFX_DOF_HIGHLIGHT_MIN_RADIUS, ffxDofTileGapDistance(offset)));
    }
    // Every pixel a copy tile holds keeps its input in the full composition: in focus, no near opacity.
    CHECK(ffxDofTileKeepsInput(inFocus, 0.0f));
    CHECK_FALSE(ffxDofTileKeepsInput(inFocus, FFX_DOF_NEAR_THRESHOLD));
    // A listed tile and its flags come back as they went in, up to the largest tile coordinates of their fields
    // (x 16 bits, y 14; the SDK's static_assert keeps the largest image's tiles within them).
    const uint32_t lastRow = FFX_DOF_LISTED_TILE_Y_LIMIT - 1u;
    for (const FfxUInt32x2 tile : {FfxUInt32x2(0u, 0u), FfxUInt32x2(119u, 67u), FfxUInt32x2(65535u, 1u),
                                   FfxUInt32x2(3u, lastRow), FfxUInt32x2(65535u, lastRow)}) {
        for (uint32_t flags = 0; flags < 4u; ++flags) {
            INFO("tile " << tile.x << ", " << tile.y << ", flags " << flags);
            const FfxUInt32 word = ffxDofPackListedTile(tile, flags);
            CHECK(ffxDofUnpackListedTile(word) == tile);
            CHECK(ffxDofListedTileFlags(word) == flags);
        }
    }
    CHECK(ffxDofListedTileFlags(ffxDofPackListedTile(FfxUInt32x2(5u, 7u), FFX_DOF_LISTED_TILE_SMALL_SOURCES)) ==
          FFX_DOF_LISTED_TILE_SMALL_SOURCES);
}

TEST_CASE("sRGB encoding", "[composite]") {
    CHECK(ffxDofLinearToSrgb(0.0f) == 0.0f);
    CHECK(ffxDofLinearToSrgb(1.0f) == Approx(1.0f));
    CHECK(ffxDofLinearToSrgb(0.5f) == Approx(0.735357f).epsilon(1e-4));
    CHECK(ffxDofLinearToSrgb(0.002f) == Approx(0.02584f));
    // Round trip of every 8-bit code through the standard decode.
    for (int code = 0; code < 256; ++code) {
        float s = float(code) / 255.0f;
        float linear = s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
        REQUIRE(std::lround(ffxDofLinearToSrgb(linear) * 255.0f) == code);
    }
}

TEST_CASE("Kernel jitter stays sub-pixel and varies", "[kernel]") {
    FfxFloat32x2 first = ffxDofKernelJitter(FfxUInt32x2(0, 0), 0);
    bool varies = false;
    for (uint32_t i = 0; i < 1000; ++i) {
        FfxFloat32x2 j = ffxDofKernelJitter(FfxUInt32x2(i % 37, i / 37), i % 3);
        REQUIRE(std::fabs(j.x) <= 0.5f * FFX_DOF_JITTER_AMPLITUDE);
        REQUIRE(std::fabs(j.y) <= 0.5f * FFX_DOF_JITTER_AMPLITUDE);
        varies = varies || j != first;
    }
    CHECK(varies);
}

TEST_CASE("Two 16-bit floats pack into one word and back", "[storage]") {
    // Exact for values 16-bit floats hold; the color range limit and radii fit with 11 bits of mantissa.
    for (glm::vec2 v : {glm::vec2(0.0f, 1.0f), glm::vec2(0.5f, 4096.0f), glm::vec2(FFX_DOF_COLOR_RANGE_LIMIT, 6.25f),
                        glm::vec2(1.0f / 1024.0f, 65504.0f)})
        CHECK(ffxDofUnpackHalf2(ffxDofPackHalf2(v)) == v);
    // Others are rounded to 11 significant bits.
    const glm::vec2 rounded = ffxDofUnpackHalf2(ffxDofPackHalf2(glm::vec2(0.1f, 1234.567f)));
    CHECK(rounded.x == Approx(0.1f).epsilon(1.0 / 2048.0));
    CHECK(rounded.y == Approx(1234.567f).epsilon(1.0 / 2048.0));
    CHECK(ffxDofPackHalf2(glm::vec2(1.0f, 0.0f)) == 0x3c00u);
    CHECK(ffxDofPackHalf2(glm::vec2(0.0f, 1.0f)) == 0x3c000000u);
}

TEST_CASE("Near opacity and far validity share one 8-bit texel of LAYER_ALPHA", "[storage]") {
    bool previousValid = false;
    float previousPacked = -1.0f;
    for (int valid = 0; valid < 2; ++valid) {
        for (int i = 0; i <= 1000; ++i) {
            const float opacity = float(i) / 1000.0f;
            const float packed = ffxDofPackLayerAlpha(FfxFloat32x2(opacity, float(valid)));
            INFO("opacity " << opacity << ", validity " << valid << ": " << packed);
            // A quarter step above a multiple of 1/255: a unorm conversion that rounds to nearest and one
            // that truncates store the same byte; the device reads back that multiple.
            const float steps = packed * 255.0f;
            REQUIRE(std::round(steps) == std::floor(steps));
            REQUIRE(std::floor(steps) >= 0.0f);
            REQUIRE(std::floor(steps) <= 255.0f);
            const FfxFloat32x2 back = ffxDofUnpackLayerAlpha(std::floor(steps) / 255.0f);
            CHECK(back.y == float(valid));
            // The square root within half a step of 1/127, but an opacity from FFX_DOF_NEAR_OPACITY_KEPT keeps at
            // least one step (the blur makes up the difference in the near colour: below). So the opacity itself
            // comes back in fine steps near 0 and within 1/127 (half of a step of 2/127) near 1.
            const float smallest = 1.0f / (127.0f * 127.0f);
            if (opacity >= FFX_DOF_NEAR_OPACITY_KEPT)
                CHECK(back.x >= smallest);
            else
                CHECK(back.x == 0.0f);
            CHECK(std::fabs(std::sqrt(back.x) - std::sqrt(opacity)) <=
                  std::max(0.5f / 127.0f + 1e-6f, 1.0f / 127.0f - std::sqrt(opacity) + 1e-6f));
            CHECK(std::fabs(back.x - opacity) <= std::max(1.0f / 127.0f, smallest - opacity) + 1e-6f);
            if (opacity > 0.0f && opacity <= 0.01f) CHECK(std::fabs(back.x - opacity) <= 0.002f);
            // Monotonic in the opacity within each validity; every valid value above every invalid one.
            if (valid == int(previousValid)) CHECK(packed >= previousPacked);
            if (valid == 1 && i == 0) CHECK(packed > previousPacked);
            previousPacked = packed;
            previousValid = valid == 1;
        }
    }
    // Read back unquantized by the device (the CPU pipeline's accessors), the packed value unpacks the same.
    CHECK(ffxDofUnpackLayerAlpha(ffxDofPackLayerAlpha(FfxFloat32x2(1.0f, 1.0f))) == FfxFloat32x2(1.0f, 1.0f));
    CHECK(ffxDofUnpackLayerAlpha(ffxDofPackLayerAlpha(FfxFloat32x2(0.0f, 0.0f))) == FfxFloat32x2(0.0f, 0.0f));
    // Out-of-range opacities saturate.
    CHECK(ffxDofUnpackLayerAlpha(ffxDofPackLayerAlpha(FfxFloat32x2(1.5f, 0.0f))).x == 1.0f);
}

TEST_CASE("Colors are rounded to nearest before a packed-float store", "[storage]") {
    CHECK(ffxDofRoundMantissa(1.0f + 1.0f / 256.0f, 6u) == 1.0f);
    CHECK(ffxDofRoundMantissa(1.0f + 3.0f / 256.0f, 6u) == 1.0f + 1.0f / 64.0f);
    CHECK(ffxDofRoundMantissa(0.75f - 1e-4f, 6u) == 0.75f);
    CHECK(ffxDofRoundMantissa(0.0f, 5u) == 0.0f);
    CHECK(ffxDofRoundMantissa(-1.0f, 5u) == 0.0f);
    // Every result is representable with the given mantissa, and within half a unit in the last place.
    for (int i = 1; i < 5000; ++i) {
        const float x = float(i) * 0.00137f;
        const float r = ffxDofRoundMantissa(x, 5u);
        REQUIRE((ffxDofAsUInt(r) & ((1u << 18) - 1u)) == 0u);
        REQUIRE(std::fabs(r - x) <= std::ldexp(1.0f, std::ilogb(x) - 6) * 1.0001f);
    }
    const FfxDofFloat3 rounded = ffxDofRoundForPackedColor(FfxDofFloat3(1.0f + 3.0f / 256.0f));
    CHECK(float(rounded.x) == 1.0f + 1.0f / 64.0f);
    CHECK(float(rounded.z) == 1.0f);  // blue keeps 5 bits: 3/256 is below half of 1/32
}

TEST_CASE("Two tile lists sharing an array never meet, and each pass's lists have arrays of their own", "[tiles]") {
    for (const FfxUInt32 tiles : {1u, 2u, 7u, 8160u}) {
        INFO(tiles << " tiles");
        for (FfxUInt32 pair = 0; pair < FFX_DOF_TILE_LIST_ARRAYS; ++pair) {
            // Full between them, split anywhere: every word of the pair's array once, none outside it.
            for (const FfxUInt32 front : {0u, tiles / 3u, tiles}) {
                std::set<FfxUInt32> words;
                for (FfxUInt32 i = 0; i < front; ++i) words.insert(ffxDofTileListWord(2u * pair, i, tiles));
                for (FfxUInt32 i = 0; i < tiles - front; ++i)
                    words.insert(ffxDofTileListWord(2u * pair + 1u, i, tiles));
                REQUIRE(words.size() == tiles);
                CHECK(*words.begin() == pair * tiles);
                CHECK(*words.rbegin() == pair * tiles + tiles - 1u);
            }
        }
    }
    // The lists of a pair belong to one pass.
    for (FfxUInt32 list = 0; list < FFX_DOF_TILE_LIST_COUNT; ++list) {
        const bool blurList = list < FFX_DOF_BLUR_TILE_LIST_FIRST + FFX_DOF_BLUR_CLASS_COUNT;
        const bool pairedBlurList = (list ^ 1u) < FFX_DOF_BLUR_TILE_LIST_FIRST + FFX_DOF_BLUR_CLASS_COUNT;
        CHECK((blurList == pairedBlurList || (list ^ 1u) >= FFX_DOF_TILE_LIST_COUNT));
    }
}

TEST_CASE("Dilate's workgroups cover every block of tiles once, in transposed order", "[tiles]") {
    for (const FfxUInt32x2 tileCount : {FfxUInt32x2(1u, 1u), FfxUInt32x2(120u, 68u), FfxUInt32x2(9u, 17u),
                                        FfxUInt32x2(240u, 135u), FfxUInt32x2(3u, 40u)}) {
        INFO("tiles " << tileCount.x << " x " << tileCount.y);
        const FfxUInt32x2 blocks = (tileCount + FfxUInt32x2(7u, 7u)) / 8u;
        std::set<std::pair<FfxUInt32, FfxUInt32>> seen;
        for (FfxUInt32 y = 0; y < blocks.y; ++y)
            for (FfxUInt32 x = 0; x < blocks.x; ++x) {
                const FfxUInt32x2 block = ffxDofDilateBlock(FfxUInt32x2(x, y), tileCount);
                REQUIRE(block.x < blocks.x);
                REQUIRE(block.y < blocks.y);
                seen.insert({block.x, block.y});
            }
        CHECK(seen.size() == size_t(blocks.x) * blocks.y);
        // Workgroups of one row (one thread's share of a dispatch, in image order) reach down the image.
        if (blocks.y > 1 && blocks.x > 1) CHECK(ffxDofDilateBlock(FfxUInt32x2(blocks.x - 1u, 0u), tileCount).y > 0u);
    }
}

TEST_CASE("Blur tile classes from the dilated range and the kernel footprint", "[tiles]") {
    // (far, near, footprint min, footprint max) -> class, each case named by what decides it.
    struct Case {
        glm::vec4 dilated;
        FfxUInt32 expected;
    };
    const Case cases[] = {
        {{-0.4f, 0.3f, -0.4f, 0.3f}, FFX_DOF_BLUR_CLASS_COPY},           // every kernel below 0.5
        {{-0.4f, 0.3f, -9.0f, 9.0f}, FFX_DOF_BLUR_CLASS_COPY},           // non-reaching tiles do not matter
        {{-6.0f, -5.95f, -6.0f, -5.95f}, FFX_DOF_BLUR_CLASS_EQUAL_FAR},  // flat far field
        {{-6.0f, -5.9f, -6.0f, -5.9f}, FFX_DOF_BLUR_CLASS_EQUAL_FAR},    // exactly the spread
        {{4.0f, 4.05f, 4.0f, 4.05f}, FFX_DOF_BLUR_CLASS_EQUAL_NEAR},     // flat near field
        {{-6.0f, -5.95f, -6.0f, 0.0f}, FFX_DOF_BLUR_CLASS_FAR_ONLY},     // an in-focus tile in the footprint
        {{-6.0f, -3.0f, -6.0f, -3.0f}, FFX_DOF_BLUR_CLASS_FAR_ONLY},     // far gradient
        {{-6.0f, 0.4f, -6.0f, 8.0f}, FFX_DOF_BLUR_CLASS_FAR_ONLY},       // near tiles read but not reaching
        {{3.0f, 6.0f, 3.0f, 6.0f}, FFX_DOF_BLUR_CLASS_NEAR_ONLY},        // near gradient
        {{0.5f, 6.0f, 0.5f, 6.0f}, FFX_DOF_BLUR_CLASS_NEAR_ONLY},        // near threshold is near
        {{-6.0f, 6.0f, -6.0f, 6.0f}, FFX_DOF_BLUR_CLASS_MIXED},          // near over far
        {{0.0f, 4.0f, 0.0f, 4.0f}, FFX_DOF_BLUR_CLASS_MIXED},            // near over in focus
        {{0.45f, 0.5f, 0.45f, 0.5f}, FFX_DOF_BLUR_CLASS_MIXED},          // within the spread but on both sides
    };
    for (const Case& c : cases) {
        INFO("dilated (" << c.dilated.x << ", " << c.dilated.y << ", " << c.dilated.z << ", " << c.dilated.w << ")");
        CHECK(ffxDofBlurTileClass(c.dilated) == c.expected);
    }
}

TEST_CASE("The kernel footprint covers the radius, the texel rounding and the MIP texels read", "[tiles]") {
    for (FfxUInt32 quality : {1u, 4u, 10u, 32u, 100u}) {
        for (float radius : {0.0f, 0.5f, 3.0f, 12.0f, 40.0f, 100.0f}) {
            FfxUInt32 rings = std::max(ffxDofRingCount(radius, quality), 1u);
            float spacing = radius / float(rings);
            // The coarsest texels read (ffxDofCoarserMipForSpacing's): the outermost ring's, whose centres
            // lie up to half a spacing and FFX_DOF_LIGHT_OFFSET_REACH texels beyond the radius, and the
            // merged rings' inside it, each with half its diagonal, and the jittered origin.
            const float texel = std::exp2(ffxDofCoarserMipForSpacing(spacing));
            const float mergedTexel = texel * std::exp2(float(FFX_DOF_RING_MERGE_LOG));
            const float halfDiagonal = 0.5f * std::sqrt(2.0f);
            const float farthestRead =
                halfDiagonal * (FFX_DOF_JITTER_AMPLITUDE + 1.0f) +
                std::max(radius + 0.5f * spacing + (FFX_DOF_LIGHT_OFFSET_REACH + halfDiagonal) * texel,
                         radius - 0.5f * spacing + halfDiagonal * mergedTexel);
            INFO("quality " << quality << ", radius " << radius);
            CHECK(ffxDofKernelFootprintRadius(radius, quality) >= farthestRead);
        }
    }
    CHECK(ffxDofTileKernelRadius(FfxFloat32x2(-3.0f, 5.0f)) == 5.0f);
    CHECK(ffxDofTileKernelRadius(FfxFloat32x2(-7.0f, 5.0f)) == 7.0f);
    CHECK(ffxDofTileKernelRadius(FfxFloat32x2(0.2f, 0.3f)) == 0.3f);
}

TEST_CASE("Colour range scale: 1 up to the limit, else the power of two that brings the peak under it", "[hdr]") {
    CHECK(ffxDofColorRangeScale(0.0f) == 1.0f);
    CHECK(ffxDofColorRangeScale(1.0f) == 1.0f);
    CHECK(ffxDofColorRangeScale(FFX_DOF_COLOR_RANGE_LIMIT) == 1.0f);
    CHECK(ffxDofColorRangeScale(std::nextafter(FFX_DOF_COLOR_RANGE_LIMIT, 1e9f)) == 0.5f);
    CHECK(ffxDofColorRangeScale(8192.0f) == 0.5f);
    CHECK(ffxDofColorRangeScale(16400.0f) == 0.125f);
    CHECK(ffxDofColorRangeScale(std::numeric_limits<float>::quiet_NaN()) == 1.0f);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> exponent(-10.0f, 128.0f);
    std::vector<float> peaks = {4097.0f, 65504.0f, 70000.0f, 1e5f, 1e6f, 1e30f, std::numeric_limits<float>::max()};
    for (int i = 0; i < 2000; ++i) peaks.push_back(std::exp2(exponent(rng)));
    for (int e = 0; e < 128; ++e) peaks.push_back(std::ldexp(1.0f, e));
    for (float peak : peaks) {
        INFO("peak " << peak);
        const float scale = ffxDofColorRangeScale(peak);
        if (peak <= FFX_DOF_COLOR_RANGE_LIMIT) {
            REQUIRE(scale == 1.0f);
            continue;
        }
        int exp2 = 0;
        REQUIRE(std::frexp(scale, &exp2) == 0.5f);  // an exact power of two
        REQUIRE(std::isnormal(scale));
        // In the limit, and the largest such power of two (double math: no rounding).
        REQUIRE(double(peak) * double(scale) <= double(FFX_DOF_COLOR_RANGE_LIMIT));
        REQUIRE(double(peak) * double(scale) * 2.0 > double(FFX_DOF_COLOR_RANGE_LIMIT));
    }
    // The infinite peak cannot occur (pass 1 ignores non-finite channels) but still gives a finite scale.
    CHECK(std::isnormal(ffxDofColorRangeScale(std::numeric_limits<float>::infinity())));
}

TEST_CASE("Colour peak: the largest finite non-negative channel, alpha ignored", "[hdr]") {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK(ffxDofColorPeak(FfxFloat32x4(1.0f, 3.0f, 2.0f, 100.0f)) == 3.0f);
    CHECK(ffxDofColorPeak(FfxFloat32x4(inf, 5.0f, nan, 1.0f)) == 5.0f);
    CHECK(ffxDofColorPeak(FfxFloat32x4(-1e9f, -inf, nan, 1.0f)) == 0.0f);
    CHECK(ffxDofColorPeak(FfxFloat32x4(std::numeric_limits<float>::max(), 0.0f, 0.0f, 1.0f)) ==
          std::numeric_limits<float>::max());
}

TEST_CASE("Scaling into the range and back is exact for power-of-two scales", "[hdr]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> exponent(-20.0f, 127.0f);
    for (int i = 0; i < 2000; ++i) {
        const float value = std::exp2(exponent(rng));
        const float scale = ffxDofColorRangeScale(value);
        const FfxFloat32x4 color(value, value * 0.5f, value * 0.25f, 1.0f);
        const FfxFloat32x4 scaled = ffxDofScaleColor(color, scale);
        REQUIRE(scaled.x <= FFX_DOF_COLOR_RANGE_LIMIT);
        const FfxFloat32x4 back = ffxDofUnscaleColor(scaled, scale);
        if (std::isnormal(scaled.z)) REQUIRE(back == color);
    }
    // Clamps: nothing scaled exceeds a half, nothing unscaled is infinite.
    CHECK(ffxDofScaleChannel(std::numeric_limits<float>::infinity(), 1.0f) == FFX_DOF_FLOAT16_MAX);
    CHECK(std::isfinite(ffxDofUnscaleColor(FfxFloat32x4(4096.0f), std::ldexp(1.0f, -126)).x));
}

TEST_CASE("Coarse texels: the colour's B10G11R11 bits are the format's own", "[storage]") {
    // Every finite value of each channel's format (5 exponent bits, bias 15, 6 or 5 mantissa bits,
    // denormals below 2^-14): unpacked exactly, and packed back to the same bits.
    const auto unsignedFloat = [](uint32_t bits, uint32_t mantissaBits) {
        const uint32_t exponent = bits >> mantissaBits, mantissa = bits & ((1u << mantissaBits) - 1u);
        const float fraction = float(mantissa) / float(1u << mantissaBits);
        return exponent == 0 ? std::ldexp(fraction, -14) : std::ldexp(1.0f + fraction, int(exponent) - 15);
    };
    for (uint32_t bits = 0; bits < 0x7c0u; ++bits) {
        const glm::vec3 expected(unsignedFloat(bits, 6), unsignedFloat(bits, 6), unsignedFloat(bits >> 1u, 5));
        const uint32_t packed = bits | (bits << 11u) | ((bits >> 1u) << 22u);
        const FfxFloat32x3 color = ffxDofUnpackR11G11B10(packed);
        REQUIRE(color.x == expected.x);
        REQUIRE(color.y == expected.y);
        REQUIRE(color.z == expected.z);
        REQUIRE(ffxDofPackR11G11B10(color) == packed);
    }
    // Colours rounded for the packed formats (what pass 2 stores) pack exactly.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> exponent(-16.0f, 15.9f);
    for (int i = 0; i < 5000; ++i) {
        const FfxDofFloat3 color = ffxDofRoundForPackedColor(FfxDofFloat3(FfxDofFloat(std::exp2(exponent(rng))),
                                                                          FfxDofFloat(std::exp2(exponent(rng))),
                                                                          FfxDofFloat(std::exp2(exponent(rng)))));
        const FfxFloat32x3 back = ffxDofUnpackR11G11B10(ffxDofPackR11G11B10(ffxDofToFloat32x3(color)));
        REQUIRE(back.x == Approx(float(color.x)).epsilon(1.0 / 64).margin(1e-6));
        REQUIRE(back.y == Approx(float(color.y)).epsilon(1.0 / 64).margin(1e-6));
        REQUIRE(back.z == Approx(float(color.z)).epsilon(1.0 / 32).margin(1e-6));
        if (color.x >= 0.00006103515625f) REQUIRE(back.x == float(color.x));  // normal: exact
    }
    // Out of range: negative and -0 give 0 (no bit of a neighbouring channel), too large the largest finite.
    CHECK(ffxDofPackR11G11B10(FfxFloat32x3(-1.0f, -0.0f, -5.0f)) == 0u);
    const FfxFloat32x3 largest = ffxDofUnpackR11G11B10(ffxDofPackR11G11B10(FfxFloat32x3(1e9f, 70000.0f, 1e9f)));
    CHECK(largest.x == 65024.0f);
    CHECK(largest.y == 65024.0f);
    CHECK(largest.z == 64512.0f);
}

TEST_CASE("Coarse texels: radius as a half and light offset as two snorm8, independent of the colour", "[storage]") {
    // snorm8 as the APIs convert: round(clamp(v) * 127), and -128 reads as -1.
    for (int q = -128; q <= 127; ++q) {
        const float value = ffxDofUnpackSnorm8(uint32_t(q) & 0xffu, 0u);
        REQUIRE(value == Approx(std::max(float(q) / 127.0f, -1.0f)).epsilon(1e-6));
        if (q > -128) REQUIRE(ffxDofPackSnorm8(value) == (uint32_t(q) & 0xffu));
    }
    CHECK(ffxDofPackSnorm8(2.0f) == 127u);
    CHECK(ffxDofPackSnorm8(-2.0f) == 0x81u);
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> offset(-0.5f, 0.5f);
    std::uniform_real_distribution<float> coc(-64.0f, 64.0f);
    for (int i = 0; i < 2000; ++i) {
        const FfxFloat32x3 color(0.5f, 2.0f, 0.25f);
        const FfxFloat32x2 light(offset(rng), offset(rng));
        const float radius = coc(rng);
        const FfxUInt32x2 texel = ffxDofPackCoarseTexel(color, radius, light);
        REQUIRE(ffxDofCoarseTexelCoc(texel) == glm::unpackHalf2x16(glm::packHalf2x16(glm::vec2(radius, 0.0f))).x);
        const FfxFloat32x2 back = ffxDofCoarseTexelLightOffset(texel);
        // Twice the offset in 8 bits: within half a step of 1/127, halved.
        REQUIRE(std::fabs(back.x - light.x) <= 0.5f / 254.0f + 1e-6f);
        REQUIRE(std::fabs(back.y - light.y) <= 0.5f / 254.0f + 1e-6f);
        const FfxFloat32x3 backColor = ffxDofCoarseTexelColor(texel);
        REQUIRE((backColor.x == 0.5f && backColor.y == 2.0f && backColor.z == 0.25f));
    }
}

TEST_CASE("A radius rounded for its half store is a half, the nearest one, with its sign", "[storage]") {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> radius(-64.0f, 64.0f);
    for (int i = 0; i < 5000; ++i) {
        const float coc = radius(rng);
        if (std::fabs(coc) < 0.00006103515625f) continue;  // below the half's normal range: in focus anyway
        const float rounded = ffxDofRoundForHalfCoc(coc);
        // Representable: a half holds it exactly.
        REQUIRE(glm::unpackHalf2x16(glm::packHalf2x16(glm::vec2(rounded, 0.0f))).x == rounded);
        // Nearest: within half a unit in the last place (10 mantissa bits) of the radius, same sign.
        const float ulp = std::ldexp(1.0f, std::ilogb(coc) - 10);
        REQUIRE(std::fabs(rounded - coc) <= 0.5f * ulp);
        REQUIRE((rounded < 0.0f) == (coc < 0.0f));
    }
    CHECK(ffxDofRoundForHalfCoc(-18.2f) == -18.203125f);  // 0.2 of a unit (1/64) away; truncation gave -18.1875
    CHECK(ffxDofRoundForHalfCoc(0.0f) == 0.0f);
}

TEST_CASE("Hole fill proximity: the inverse square of the distance, bounded at half a texel", "[blur]") {
    CHECK(ffxDofFillProximity(1.0f) == Approx(1.0f));
    CHECK(ffxDofFillProximity(2.0f) == Approx(0.25f));
    CHECK(ffxDofFillProximity(4.0f) == Approx(1.0f / 16.0f));
    // A sample at the kernel centre (a background texel under a near one's jittered origin) stays finite.
    CHECK(ffxDofFillProximity(0.0f) == Approx(4.0f));
    CHECK(ffxDofFillProximity(0.25f) == Approx(4.0f));
    for (float d = 0.5f; d < 40.0f; d += 0.5f) CHECK(ffxDofFillProximity(d + 0.5f) < ffxDofFillProximity(d));
}

TEST_CASE("Veil share: a near sample hides a far texel's own surface from a near radius a pixel below its own",
          "[blur]") {
    // The far layer fills what near samples of at least the far radius hide of its disc; none below, so that the
    // front of an object at the focus (a near radius far below the background's) leaves the far layer as it was.
    CHECK(ffxDofVeilShare(24.0f, 4.8f) == 1.0f);
    CHECK(ffxDofVeilShare(4.8f, 4.8f) == 1.0f);
    CHECK(ffxDofVeilShare(4.3f, 4.8f) == Approx(0.5f));
    CHECK(ffxDofVeilShare(3.8f, 4.8f) == 0.0f);
    CHECK(ffxDofVeilShare(1.0f, 20.0f) == 0.0f);
    for (float r = 0.5f; r < 40.0f; r += 0.25f) CHECK(ffxDofVeilShare(r + 0.25f, 10.0f) >= ffxDofVeilShare(r, 10.0f));
}

TEST_CASE("Small sources: the composite's full-resolution share and the blur's complement meet", "[blur]") {
    // A source below radius 2 in front of a receiver of 3 or more: all drawn at full resolution.
    CHECK(ffxDofSmallSourceShare(1.0f, 16.0f) == 1.0f);
    CHECK(ffxDofSmallSourceShare(2.0f, 3.0f) == 1.0f);
    // Sources from FFX_DOF_FAR_LAYER_ONLY_RADIUS on stay in the half-res layers, and so do receivers
    // below 2 (their own pixels are gathered at full resolution, their layers keep the light).
    CHECK(ffxDofSmallSourceShare(FFX_DOF_FAR_LAYER_ONLY_RADIUS, 16.0f) == 0.0f);
    CHECK(ffxDofSmallSourceShare(1.0f, 2.0f) == 0.0f);
    CHECK(ffxDofSmallSourceShare(2.5f, 2.5f) == Approx(0.25f));
    // The own surface's share: none in focus, below the gather's start or in the near field, all from 1
    // to 2, handing over linearly to the layers by 3.
    CHECK(ffxDofOwnGatherShare(-0.9f) == 0.0f);
    CHECK(ffxDofOwnGatherShare(2.0f) == 0.0f);
    CHECK(ffxDofOwnGatherShare(-1.0f) == 1.0f);
    CHECK(ffxDofOwnGatherShare(-2.0f) == 1.0f);
    CHECK(ffxDofOwnGatherShare(-2.5f) == Approx(0.5f));
    CHECK(ffxDofOwnGatherShare(-3.0f) == 0.0f);
    CHECK(ffxDofOwnGatherShare(-20.0f) == 0.0f);
}

TEST_CASE("Small sources: a tile may hold bright ones where a channel is above white and a far radius below 3",
          "[blur][composite]") {
    // (min, max) signed radius, colour peak.
    CHECK(ffxDofTileMayHoldBrightSmallSources(FfxFloat32x3(-2.0f, -2.0f, 1.5f)));
    CHECK(ffxDofTileMayHoldBrightSmallSources(FfxFloat32x3(-20.0f, 4.0f, 1000.0f)));  // spans the range
    // At or below white: the half-res path.
    CHECK_FALSE(ffxDofTileMayHoldBrightSmallSources(FfxFloat32x3(-2.0f, -2.0f, FFX_DOF_SMALL_SOURCE_MIN_PEAK)));
    // Every far radius from FFX_DOF_FAR_LAYER_ONLY_RADIUS on: the layers alone draw them.
    CHECK_FALSE(ffxDofTileMayHoldBrightSmallSources(FfxFloat32x3(-20.0f, -FFX_DOF_FAR_LAYER_ONLY_RADIUS, 50.0f)));
    // In focus or near only: no far source.
    CHECK_FALSE(ffxDofTileMayHoldBrightSmallSources(FfxFloat32x3(-0.4f, 6.0f, 50.0f)));
    CHECK(ffxDofTileMayHoldBrightSmallSources(FfxFloat32x3(-FFX_DOF_IN_FOCUS_RADIUS, 6.0f, 50.0f)));
}

TEST_CASE("Small sources: the 3 x 3 tiles around a tile, clamped to the image", "[blur][composite]") {
    const FfxUInt32x2 tileCount(5u, 4u);
    for (FfxUInt32 k = 0u; k < 9u; ++k) {
        const FfxUInt32x2 inside = ffxDofTileAround(FfxUInt32x2(2u, 2u), k, tileCount);
        CHECK(inside.x == 1u + k % 3u);
        CHECK(inside.y == 1u + k / 3u);
        const FfxUInt32x2 corner = ffxDofTileAround(FfxUInt32x2(4u, 0u), k, tileCount);
        CHECK(corner.x == std::min(3u + k % 3u, 4u));
        CHECK(corner.y == (k / 3u == 0u ? 0u : k / 3u - 1u));
    }
}

TEST_CASE("Own samples keep |radius| as a half within one ulp and say which are far", "[composite]") {
    for (const float radius : {-11.0f, -4.0f, -2.0f, -1.0f, -0.3f, 0.0f, 0.3f, 1.0f, 2.5f, 4.0f, 11.0f}) {
        ffxDofStoreOwnSample(7u, FfxFloat32x3(0.25f, 2.0f, 9.0f), radius);
        const FfxFloat32x4 sample = ffxDofLoadOwnSample(7u);
        INFO("radius " << radius << ": stored " << sample.w);
        CHECK(sample.x == 0.25f);
        CHECK(sample.y == 2.0f);
        CHECK(sample.z == 9.0f);
        // |radius| rounded to a half, then its lowest mantissa bit set or cleared: one unit in the last place.
        const float rounded = ffxDofUnpackHalf2(ffxDofPackHalf2(FfxFloat32x2(std::abs(radius), 0.0f))).x;
        const float ulp = std::ldexp(1.0f, std::ilogb(std::max(rounded, 1.0f / 1024.0f)) - 10);
        CHECK(std::abs(sample.w - rounded) <= ulp);
        CHECK(ffxDofOwnSampleIsFar(7u) == (radius < 0.0f));
    }
}

TEST_CASE("A reduced radius is its brightest pixels' radius, through every MIP level", "[downsample]") {
    // One light pixel (50 at radius -2) among dim background pixels (0.05 at -16), reduced like MIPs
    // 0 to 3 (the light in one quad, that texel among three background texels, twice more). Weighted by
    // light alone the radius drifted toward the background's: 2.04, 2.21, 2.85 and 4.89 px, so the blur
    // judged such a light by a larger radius than its pixels have (ffx_dof_small_sources.h: the
    // composite draws it by its pixels' radius): a 1 px light at 4 px added 1.21 times its energy. With
    // the light squared: 2.00, 2.00, 2.01, 2.17 (at MIP 3 the light is 16 times its neighbours' level).
    const float bound[4] = {0.002f, 0.002f, 0.02f, 0.2f};
    FfxFloat32x3 color = FfxFloat32x3(50.0f);
    float coc = -2.0f;
    const FfxFloat32x3 background(0.05f);
    const FfxFloat32x2 none(0.0f, 0.0f);
    for (int level = 0; level < 4; ++level) {
        FfxFloat32x3 reduced;
        float reducedCoc;
        FfxFloat32x2 offset;
        ffxDofBilateralReduceLight(color, background, background, background, coc, -16.0f, -16.0f, -16.0f, none, none,
                                   none, none, reduced, reducedCoc, offset);
        INFO("level " << level << ": radius " << reducedCoc);
        CHECK(reducedCoc == Approx(-2.0f).margin(bound[level]));
        color = reduced;
        coc = reducedCoc;
    }
    // Pixels of equal light still average their radii.
    FfxFloat32x3 reduced;
    float reducedCoc;
    ffxDofBilateralReduce(FfxFloat32x3(1.0f), FfxFloat32x3(1.0f), FfxFloat32x3(1.0f), FfxFloat32x3(1.0f), -4.0f, -4.5f,
                          -4.0f, -4.5f, reduced, reducedCoc);
    CHECK(reducedCoc == Approx(-4.25f));
}

TEST_CASE("The pixel grid's disc area is the reach summed over the pixel centres", "[composite]") {
    // Brute force over a square that holds every disc, in double; and the continuous area it corrects.
    for (float radius = 0.5f; radius <= 13.0f; radius += 0.125f) {
        double area = 0.0;
        for (int y = -16; y <= 16; ++y)
            for (int x = -16; x <= 16; ++x)
                area += std::clamp(double(radius) - std::sqrt(double(x * x + y * y)) + 0.5, 0.0, 1.0);
        INFO("radius " << radius);
        CHECK(ffxDofPixelDiscArea(radius) == Approx(area).epsilon(1e-5));
    }
    CHECK(ffxDofPixelDiscArea(2.0f) / (3.14159265f * 4.0f) == Approx(1.0434).epsilon(1e-3));
    CHECK(ffxDofPixelDiscArea(1.0f) == Approx(1.0 + 4.0 * 0.5 + 4.0 * std::clamp(1.5 - std::sqrt(2.0), 0.0, 1.0)));
}

TEST_CASE("A small near disc's weights, scaled by the grid's disc area, sum to pi over the texel grid", "[blur]") {
    // One near sample of |radius| r reaches the texels around it with reach * 1 / r^2 (ffxDofRoundAreaWeight); the
    // blur scales a texel's near weights by ffxDofNearGridAreaScale of their mean radius, so that the disc's
    // weights, summed over the texels it reaches, are pi (opacity 1 for the whole disc), as over the plane.
    auto gridSum = [](float radius) {
        double sum = 0.0;
        for (int y = -8; y <= 8; ++y)
            for (int x = -8; x <= 8; ++x)
                sum += ffxDofReach(radius, std::sqrt(float(x * x + y * y))) * ffxDofRoundAreaWeight(radius);
        return sum;
    };
    for (float radius = 0.5f; radius < FFX_DOF_NEAR_GRID_AREA_RADIUS; radius += 0.0625f) {
        INFO("radius " << radius);
        CHECK(gridSum(radius) * ffxDofNearGridAreaScale(radius) == Approx(kPi).epsilon(1e-5));
    }
    // From FFX_DOF_NEAR_GRID_AREA_RADIUS the grid's disc is within 1.8% of pi r^2, unscaled.
    for (float radius = FFX_DOF_NEAR_GRID_AREA_RADIUS; radius <= 7.0f; radius += 0.0625f) {
        INFO("radius " << radius);
        CHECK(ffxDofNearGridAreaScale(radius) == 1.0f);
        CHECK(std::abs(gridSum(radius) / kPi - 1.0) < 0.018);
    }
    // Half a pixel and below weigh as half a pixel: the disc is the texel itself.
    CHECK(ffxDofNearGridAreaScale(0.5f) == Approx(kPi / 4.0f));
}

namespace {
// Fills the composite's raw near texels (group-shared, FFX_DOF_RAW_SIDE per side) with `opacity` and `color` per
// texel, no far layer, and post-filters every filtered texel; returns the light of the near layer before and after
// (opacity times green, summed over the filtered texels, whose 3 x 3 windows hold every raw texel that is not 0).
void postFilterNearTexels(const std::function<float(int, int)>& opacity, const std::function<float(int, int)>& color,
                          double* rawLight, double* filteredLight) {
    *rawLight = *filteredLight = 0.0;
    for (int y = 0; y < FFX_DOF_RAW_SIDE; ++y)
        for (int x = 0; x < FFX_DOF_RAW_SIDE; ++x) {
            const FfxDofFloat3 near(color(x, y));
            const size_t index = size_t(y) * FFX_DOF_RAW_SIDE + size_t(x);
            ffxDofSharedRawNear[index] = ffxDofPackRawColor(near);
            ffxDofSharedRawFar[index] = ffxDofPackRawColor(FfxDofFloat3(0.0f));
            ffxDofSharedRawSummary[index] =
                ffxDofPackRawSummary(ffxDofLuminance(near), 0.0f, glm::vec2(opacity(x, y), 0.0f));
            *rawLight += double(opacity(x, y)) * double(ffxDofUnpackRawColor(ffxDofSharedRawNear[index]).y);
        }
    for (uint32_t index = 0; index < uint32_t(FFX_DOF_FILTERED_SIDE * FFX_DOF_FILTERED_SIDE); ++index) {
        ffxDofStoreFilteredTexel(index, ffxDofPostFilterTexel(index, ffxDofRawCentreOf(index)));
        const FfxDofFilteredTexel filtered = ffxDofLoadFilteredTexel(index);
        *filteredLight += double(filtered.alpha.x) * double(filtered.nearColor.y);
    }
}
}  // namespace

TEST_CASE("The near post-filter keeps a small disc's light and a near surface's own colours", "[composite]") {
    // A small near disc as the blur stores it: a core, and a rim of tiny opacities whose colour the blur made up for
    // their whole LAYER_ALPHA step (1.45 times the core's). The 3 x 3 mean opacity under each texel's own colour drew
    // the rim's made-up colour at the disc's opacity (1.08 times the light); what the mean adds comes from the
    // neighbours, with their colour.
    auto discOpacity = [](int x, int y) {
        const int d = std::abs(x - 6) + std::abs(y - 6);
        return d == 0 ? 0.025f : d == 1 ? 0.022f : d == 2 ? 0.006f : d == 3 ? 0.00006f : 0.0f;
    };
    auto discColor = [&](int x, int y) { return discOpacity(x, y) == 0.00006f ? 1.45f : 1.0f; };
    double raw = 0.0, filtered = 0.0;
    postFilterNearTexels(discOpacity, discColor, &raw, &filtered);
    CHECK(filtered == Approx(raw).epsilon(0.01));
    // A near surface of one opacity keeps each texel's own colour (its texture), untouched by the mean.
    auto textured = [](int x, int y) { return 0.25f + 0.5f * float((x * 7 + y * 3) % 5) / 4.0f; };
    postFilterNearTexels([](int, int) { return 0.75f; }, textured, &raw, &filtered);
    for (int y = 0; y < FFX_DOF_FILTERED_SIDE; ++y)
        for (int x = 0; x < FFX_DOF_FILTERED_SIDE; ++x) {
            INFO("filtered texel (" << x << ", " << y << ")");
            const glm::vec3 kept =
                glm::vec3(ffxDofLoadFilteredTexel(uint32_t(y) * FFX_DOF_FILTERED_SIDE + uint32_t(x)).nearColor);
            CHECK(kept.y == Approx(ffxDofUnpackRawColor(ffxDofPackRawColor(FfxDofFloat3(textured(x + 1, y + 1)))).y));
        }
}
