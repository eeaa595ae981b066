// Unit tests of ffx_dof_highlights.h (near and far highlights drawn at full resolution) through the C++ mapping. Every
// expectation is computed independently of the function under test (formula, brute force over a pixel grid).
#include <catch2/catch.hpp>

#include "ffx_dof_highlights.h"

#include <cmath>
#include <random>

namespace {
FfxDofHighlight makeHighlight(glm::vec2 position, float radius, float spread, glm::vec3 energy) {
    FfxDofHighlight highlight;
    highlight.position = position;
    highlight.radius = radius;
    highlight.near = false;
    highlight.axis = glm::vec2(0.0f);
    highlight.spread = spread;
    highlight.energy = energy;
    return highlight;
}

// ffxDofHighlightShare over a floor that is its own surround (every near pixel's, and a far pixel's on a uniform far
// field).
float shareOverFloor(float luminance, float coc, float floor, float scale) {
    return ffxDofHighlightShare(luminance, coc, glm::vec2(floor, floor), scale);
}

}  // namespace

TEST_CASE("RGB9E5 keeps a colour within half a step of its largest channel", "[highlights]") {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> exponent(-12.0f, 15.9f);
    std::uniform_real_distribution<float> share(0.0f, 1.0f);
    for (int i = 0; i < 2000; ++i) {
        const float largest = std::exp2(exponent(rng));
        const glm::vec3 color(largest, largest * share(rng), largest * share(rng));
        const glm::vec3 back = ffxDofUnpackRgb9e5(ffxDofPackRgb9e5(color));
        // 9 mantissa bits below the largest channel's exponent + 1: a step of at most largest / 256.
        for (int c = 0; c < 3; ++c) REQUIRE(std::fabs(back[c] - color[c]) <= largest / 512.0f * 1.0001f);
    }
    CHECK(ffxDofPackRgb9e5(glm::vec3(0.0f)) == (15u - 15u) << 27u);  // zero mantissas, the smallest exponent
    CHECK(ffxDofUnpackRgb9e5(ffxDofPackRgb9e5(glm::vec3(1e9f, -1.0f, 2.0f))).x == FFX_DOF_RGB9E5_MAX);
    CHECK(ffxDofUnpackRgb9e5(ffxDofPackRgb9e5(glm::vec3(1e9f, -1.0f, 2.0f))).y == 0.0f);
    // A value that rounds up to the next power of two keeps it exactly.
    CHECK(ffxDofUnpackRgb9e5(ffxDofPackRgb9e5(glm::vec3(511.9f, 0.0f, 0.0f))).x == 512.0f);
}

TEST_CASE(
    "A packed highlight keeps its place, radius, axis, spread and energy within their steps, an empty slot is "
    "zero",
    "[highlights]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> place(0.0f, 15.75f), radius(3.0f, 120.0f), spread(0.0f, 15.0f),
        axis(-31.0f, 31.0f), energy(0.01f, 262144.0f);  // up to a quadrant of 64 px at the HDR range's 4096
    for (int i = 0; i < 1000; ++i) {
        FfxDofHighlight highlight = makeHighlight(glm::vec2(place(rng), place(rng)), radius(rng), spread(rng),
                                                  glm::vec3(energy(rng), energy(rng), energy(rng)));
        highlight.axis = glm::vec2(axis(rng), axis(rng));
        highlight.near = (i & 1) != 0;
        const glm::uvec3 words = ffxDofPackHighlight(highlight);
        REQUIRE(words.x != 0u);
        const FfxDofHighlight back = ffxDofUnpackHighlight(words);
        CHECK(back.near == highlight.near);
        CHECK(std::fabs(back.position.x - highlight.position.x) <= 0.125f + 1e-6f);
        CHECK(std::fabs(back.position.y - highlight.position.y) <= 0.125f + 1e-6f);
        CHECK(std::fabs(back.axis.x - highlight.axis.x) <= 0.125f + 1e-6f);
        CHECK(std::fabs(back.axis.y - highlight.axis.y) <= 0.125f + 1e-6f);
        CHECK(std::fabs(back.radius - highlight.radius) <= 1.0f / 64.0f + 1e-5f);
        CHECK(std::fabs(back.spread - highlight.spread) <= 1.0f / 32.0f + 1e-5f);
        const float largest = std::max(highlight.energy.x, std::max(highlight.energy.y, highlight.energy.z));
        for (int c = 0; c < 3; ++c)
            CHECK(std::fabs(back.energy[c] - highlight.energy[c]) <= largest / 512.0f * 1.0001f);
    }
    // A light below the format's smallest step still marks its slot as used.
    CHECK(ffxDofPackHighlight(makeHighlight(glm::vec2(1.0f), 4.0f, 0.0f, glm::vec3(1e-12f))).x != 0u);
}

TEST_CASE("A pixel gives light above its floor, only where it is bright, far brighter than the floor and far enough",
          "[highlights]") {
    const float scale = 1.0f, floor = 0.05f, far = -FFX_DOF_HIGHLIGHT_FULL_RADIUS;
    // Fully past every threshold: what lies above the floor.
    CHECK(shareOverFloor(50.0f, far, floor, scale) == Approx(1.0f - floor / 50.0f));
    // Not above white, not brighter than the floor by the contrast, not beyond the radius: nothing.
    CHECK(shareOverFloor(FFX_DOF_HIGHLIGHT_MIN_LUMINANCE, far, 0.0f, scale) == 0.0f);
    CHECK(shareOverFloor(FFX_DOF_HIGHLIGHT_CONTRAST * 10.0f, far, 10.0f, scale) == 0.0f);
    CHECK(shareOverFloor(50.0f, -FFX_DOF_HIGHLIGHT_MIN_RADIUS, floor, scale) == 0.0f);
    CHECK(shareOverFloor(50.0f, FFX_DOF_NEAR_HIGHLIGHT_MIN_RADIUS, floor, scale) == 0.0f);
    CHECK(shareOverFloor(50.0f, FFX_DOF_NEAR_HIGHLIGHT_FULL_RADIUS, floor, scale) == Approx(1.0f - floor / 50.0f));
    CHECK(shareOverFloor(0.0f, far, 0.0f, scale) == 0.0f);
    // White is in the input's units: the HDR range's scale moves it with the colour.
    CHECK(shareOverFloor(1.5f * 0.25f, far, 0.0f, 0.25f) == Approx(0.5f));
    // Each ramp is continuous and rises with what it ramps.
    float previous = 0.0f;
    for (float luminance = 0.5f; luminance < 8.0f; luminance += 0.01f) {
        const float share = shareOverFloor(luminance, far, 0.5f, scale);
        REQUIRE(share >= previous - 1e-6f);
        REQUIRE(share - previous <= 0.02f);
        previous = share;
    }
    previous = 0.0f;
    for (float radius = 0.0f; radius < 4.0f; radius += 0.01f) {
        const float share = shareOverFloor(50.0f, -radius, floor, scale);
        REQUIRE(share >= previous - 1e-6f);
        REQUIRE(share - previous <= 0.03f);
        previous = share;
    }
}

// Pass 2 reads a tile's far floors only in waves with a pixel of nonzero brightness, and stores a quad's highlight
// sums only in waves where some quad gives light, the others' reading as ffxDofNoHighlightSums: both skips must change
// nothing.
TEST_CASE("A pixel of no brightness gives no light over any floors, and a quad without light sums to no highlight",
          "[highlights]") {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_real_distribution<float> exponent(-14.0f, 16.0f);
    std::uniform_real_distribution<float> radius(-40.0f, 40.0f);
    int dark = 0, bright = 0;
    for (int i = 0; i < 20000; ++i) {
        const float scale = std::exp2(std::floor(-8.0f * unit(rng)));
        const float luminance = std::exp2(exponent(rng)) * scale;
        const glm::vec2 floors(std::exp2(exponent(rng)) * unit(rng), std::exp2(exponent(rng)) * unit(rng));
        const float coc = radius(rng);
        const float share = ffxDofHighlightShare(luminance, coc, floors, scale);
        if (ffxDofHighlightBrightness(luminance, scale) == 0.0f) {
            ++dark;
            REQUIRE(share == 0.0f);
        } else {
            ++bright;
            // Independently of the function: above white by its definition.
            REQUIRE(luminance > FFX_DOF_HIGHLIGHT_MIN_LUMINANCE * scale);
        }
    }
    CHECK(dark > 1000);
    CHECK(bright > 1000);

    const FfxDofHighlightSums none = ffxDofNoHighlightSums();
    CHECK_FALSE(ffxDofHighlightSumsHoldLight(none));
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 colors[4];
        for (glm::vec3& color : colors) color = glm::vec3(unit(rng), unit(rng), unit(rng)) * 1000.0f;
        const glm::vec4 cocs(radius(rng), radius(rng), radius(rng), radius(rng));
        const glm::vec2 inTile(2.0f * float(i % 8), 2.0f * float((i / 8) % 8));
        const FfxDofHighlightSums sums =
            ffxDofQuadHighlightSums(colors[0], colors[1], colors[2], colors[3], cocs, glm::vec4(0.0f), inTile);
        REQUIRE(sums.energyLight == none.energyLight);
        REQUIRE(sums.placeRadius == none.placeRadius);
        REQUIRE(sums.anisotropy == none.anisotropy);
        REQUIRE(sums.nearLight == none.nearLight);
    }
}

TEST_CASE("The highlights take all of a bright far pixel's light above its floor where the layers would draw any",
          "[highlights]") {
    // From FFX_DOF_HIGHLIGHT_FULL_RADIUS on the half-res layers take part of a pixel's own light (the rest is
    // gathered at full resolution): a bright point on black must leave them entirely there.
    CHECK(ffxDofOwnGatherShare(-FFX_DOF_HIGHLIGHT_FULL_RADIUS) == Approx(1.0f));
    CHECK(ffxDofOwnGatherShare(-(FFX_DOF_HIGHLIGHT_FULL_RADIUS + 0.25f)) < 1.0f);
    CHECK(shareOverFloor(50.0f, -FFX_DOF_HIGHLIGHT_FULL_RADIUS, 0.0f, 1.0f) == Approx(1.0f));
    CHECK(shareOverFloor(50.0f, -FFX_DOF_HIGHLIGHT_MIN_RADIUS, 0.0f, 1.0f) == 0.0f);
}

TEST_CASE("The composite knows what pass 2 took of a pixel, but for a quad the image's edge cuts", "[highlights]") {
    const glm::uvec2 size(33u, 20u);
    const glm::vec3 light(40.0f, 60.0f, 20.0f);
    const float coc = -2.5f, floor = 0.1f, scale = 0.5f;
    const float taken = shareOverFloor(ffxDofLuminance32(light), coc, floor, scale);
    REQUIRE(taken > 0.5f);
    // The far floor (the low 10 bits) for a far pixel, among its surround (the high 10 bits, here below it).
    const glm::vec3 floors(floor, 7.0f, 0.05f);
    CHECK(ffxDofPixelHighlightShare(glm::uvec2(31u, 19u), light, coc, floors, scale, size) == taken);
    // Column 32 is the last, alone in its quad; rows 18 and 19 make the last quad row.
    CHECK(ffxDofPixelHighlightShare(glm::uvec2(32u, 4u), light, coc, floors, scale, size) == 0.0f);
    CHECK(ffxDofPixelHighlightShare(glm::uvec2(10u, 19u), light, coc, floors, scale, size) == taken);
    // The near floor for a near pixel.
    CHECK(ffxDofPixelHighlightShare(glm::uvec2(10u, 19u), light, -coc, floors, scale, size) ==
          shareOverFloor(ffxDofLuminance32(light), -coc, floors.y, scale));
}

TEST_CASE("A bright far field behind nearer far content gives no far light", "[highlights]") {
    // A far pixel adds its luminance, 1, its radius before the limit and whether it is above white (here 1).
    const float white = 1.0f;
    CHECK(ffxDofFarSums(glm::vec2(2.3f, -5.0f), -12.0f, white) == glm::vec4(2.3f, 1.0f, -12.0f, 1.0f));
    CHECK(ffxDofFarSums(glm::vec2(0.05f, -5.0f), -7.0f, white) == glm::vec4(0.05f, 1.0f, -7.0f, 0.0f));
    CHECK(ffxDofFarSums(glm::vec2(2.3f, -0.25f), -0.25f, white) == glm::vec4(0.0f));
    CHECK(ffxDofFarSums(glm::vec2(2.3f, 4.0f), 4.0f, white) == glm::vec4(0.0f));
    // A tile's sums from `bright` pixels above white at radius `brightRadius` and `other` pixels at `otherRadius`.
    auto behind = [](float bright, float brightRadius, float other, float otherRadius) {
        const glm::vec4 sums(bright * 2.3f + other * 0.05f, bright + other, bright * brightRadius + other * otherRadius,
                             bright);
        return ffxDofBrightFieldBehind(sums, bright * brightRadius);
    };
    // A tile of 324 px, a quarter sky at radius -12 behind branches at -7: a field. In front of them, or at their
    // depth but for less than FFX_DOF_BRIGHT_FIELD_DEPTH_GAP: lights.
    CHECK(behind(81.0f, -12.0f, 243.0f, -7.0f));
    CHECK_FALSE(behind(81.0f, -7.0f, 243.0f, -12.0f));
    CHECK_FALSE(behind(81.0f, -7.9f, 243.0f, -7.0f));
    // A light of 4 x 4 px behind the branches (16 of 324, below FFX_DOF_BRIGHT_FIELD_MIN_SHARE) stays one; from 21 px
    // on it is a field.
    CHECK_FALSE(behind(16.0f, -12.0f, 308.0f, -7.0f));
    CHECK(behind(21.0f, -12.0f, 303.0f, -7.0f));
    // Only bright pixels, or none: no field.
    CHECK_FALSE(behind(324.0f, -12.0f, 0.0f, 0.0f));
    CHECK_FALSE(behind(0.0f, 0.0f, 324.0f, -12.0f));
}

TEST_CASE("A far pixel is a light by its far surround, and gives what it has above its floor", "[highlights]") {
    // A tile (with its border: 18 x 18 = 324 px) half sky at 2.3, half branch at 0.05: against the dimmest pixel the
    // sky was a light (more than twice it); against the mean (1.175) it is not.
    const float sky = 2.3f, branch = 0.05f;
    const float surround = ffxDofFarSurround(glm::vec2(162.0f * sky + 162.0f * branch, 324.0f));
    CHECK(surround == Approx((sky + branch) * 0.5f));
    CHECK(shareOverFloor(sky, -8.0f, branch, 1.0f) > 0.9f);
    CHECK(ffxDofHighlightShare(sky, -8.0f, glm::vec2(branch, surround), 1.0f) == 0.0f);
    // A light of 3 x 3 px at 100 on 0.05 raises the mean to 2.8, far below half its light: it gives all it has
    // above the floor, as on a uniform far field.
    const float lightSurround = ffxDofFarSurround(glm::vec2(9.0f * 100.0f + 315.0f * 0.05f, 324.0f));
    CHECK(lightSurround == Approx((900.0f + 315.0f * 0.05f) / 324.0f));
    CHECK(ffxDofHighlightShare(100.0f, -8.0f, glm::vec2(0.05f, lightSurround), 1.0f) ==
          shareOverFloor(100.0f, -8.0f, 0.05f, 1.0f));
    // A surround below the floor (rounding may put the mean there) is the floor; no far pixel: none.
    CHECK(ffxDofHighlightShare(3.0f, -8.0f, glm::vec2(1.0f, 0.5f), 1.0f) == shareOverFloor(3.0f, -8.0f, 1.0f, 1.0f));
    CHECK(ffxDofFarSurround(glm::vec2(0.0f, 0.0f)) == 0.0f);
    // A near pixel's surround is its floor, or the far surround where that is larger.
    CHECK(ffxDofHighlightFloor(glm::vec3(0.1f, 0.2f, 0.1f), 3.0f) == glm::vec2(0.2f, 0.2f));
    CHECK(ffxDofHighlightFloor(glm::vec3(0.1f, 0.2f, 0.3f), 3.0f) == glm::vec2(0.2f, 0.3f));
    // A near leaf's rim pixel, half leaf (0.05) and half sky (2.3), over that sky: no light against the sky's mean; a
    // near speck of 50 there is one, and gives what it has above the leaf.
    const glm::vec3 leafOverSky(0.05f, 0.05f, 2.3f);
    CHECK(ffxDofHighlightShare(0.5f * (0.05f + 2.3f), 3.0f, ffxDofHighlightFloor(leafOverSky, 3.0f), 1.0f) == 0.0f);
    CHECK(ffxDofHighlightShare(50.0f, 3.0f, ffxDofHighlightFloor(leafOverSky, 3.0f), 1.0f) ==
          shareOverFloor(50.0f, 3.0f, 0.05f, 1.0f));
    CHECK(ffxDofHighlightFloor(glm::vec3(0.1f, 0.2f, 0.3f), -3.0f) == glm::vec2(0.1f, 0.3f));
}

TEST_CASE("A tile's floors survive their word, and a tile without highlights gives no light", "[highlights]") {
    // Far floor, near floor, far surround, 10 bits each (5 of exponent, 5 of mantissa, cut): what pass 2 takes its
    // shares over, each lowered by less than one step of 1/32.
    const glm::vec3 floors(0.0371f, 2.5f, 1300.0f);
    const glm::vec3 back = ffxDofUnpackHighlightFloors(ffxDofPackHighlightFloors(floors));
    for (int k = 0; k < 3; ++k) {
        CHECK(back[k] <= floors[k]);
        CHECK(back[k] > floors[k] * (1.0f - 1.0f / 32.0f));
    }
    // Read back, the same word again: the composite takes pass 2's shares to the bit.
    CHECK(ffxDofPackHighlightFloors(back) == ffxDofPackHighlightFloors(floors));
    CHECK(ffxDofUnpackHighlightFloors(ffxDofPackHighlightFloors(back)) == back);
    // Every code the encoding gives (0, exponents 1 to 30, all ones) decodes to a value that encodes to it again, and
    // the values rise with the codes; the rest (exponent 0 but code 0, exponent 31) read as their neighbours.
    float previous = 0.0f;
    for (uint32_t code = 0u; code <= FFX_DOF_HIGHLIGHT_FLOOR_MASK; ++code) {
        const float value = ffxDofDecodeHighlightFloor(code);
        const uint32_t exponent = code >> 5u;
        if (code == 0u || (exponent >= 1u && exponent <= 30u) || code == FFX_DOF_HIGHLIGHT_FLOOR_MASK) {
            REQUIRE(ffxDofEncodeHighlightFloor(value) == code);
            if (code != 0u) REQUIRE(value > previous);
            previous = value;
        } else {
            REQUIRE(value == (exponent == 0u ? 0.0f : FFX_DOF_HIGHLIGHT_NO_FLOOR));
        }
    }
    // Below the smallest step a floor is 0, negative or NaN ones too; zero stays zero.
    CHECK(ffxDofDecodeHighlightFloor(ffxDofEncodeHighlightFloor(FFX_DOF_HIGHLIGHT_SMALLEST_FLOOR * 0.99f)) == 0.0f);
    CHECK(ffxDofEncodeHighlightFloor(-1.0f) == 0u);
    CHECK(ffxDofDecodeHighlightFloor(ffxDofEncodeHighlightFloor(FFX_DOF_HIGHLIGHT_SMALLEST_FLOOR)) ==
          FFX_DOF_HIGHLIGHT_SMALLEST_FLOOR);
    // No pixel of a kind (FLT_MAX) is the reserved code, which reads back as FFX_DOF_HIGHLIGHT_NO_FLOOR, over which no
    // pixel of the HDR range gives light; bits 30 and 31 stay free for the composite's flag.
    const uint32_t none =
        ffxDofPackHighlightFloors(glm::vec3(FFX_DOF_FLOAT32_MAX, FFX_DOF_FLOAT32_MAX, FFX_DOF_FLOAT32_MAX));
    CHECK(none == ffxDofNoHighlightFloors());
    CHECK((none & 0xc0000000u) == 0u);
    CHECK(ffxDofUnpackHighlightFloors(none) == glm::vec3(FFX_DOF_HIGHLIGHT_NO_FLOOR));
    CHECK(ffxDofEncodeHighlightFloor(std::nanf("")) == FFX_DOF_HIGHLIGHT_FLOOR_MASK);
    CHECK(ffxDofDecodeHighlightFloor(ffxDofEncodeHighlightFloor(64000.0f)) < FFX_DOF_HIGHLIGHT_NO_FLOOR);
    CHECK(shareOverFloor(FFX_DOF_COLOR_RANGE_LIMIT, -5.0f, FFX_DOF_HIGHLIGHT_NO_FLOOR, 1.0f) == 0.0f);
    CHECK(shareOverFloor(FFX_DOF_COLOR_RANGE_LIMIT, 5.0f, FFX_DOF_HIGHLIGHT_NO_FLOOR, 1.0f) == 0.0f);
}

TEST_CASE("A highlight is near where more than half of its light is", "[highlights]") {
    const glm::vec3 dark(0.0f), light(10.0f, 20.0f, 30.0f);
    const FfxDofHighlightSums near =
        ffxDofQuadHighlightSums(light, dark, dark, dark, glm::vec4(6.0f, -5.0f, 0.0f, 0.0f),
                                glm::vec4(1.0f, 0.0f, 0.0f, 0.0f), glm::vec2(2.0f));
    const FfxDofHighlightSums far = ffxDofQuadHighlightSums(dark, light, dark, dark, glm::vec4(6.0f, -5.0f, 0.0f, 0.0f),
                                                            glm::vec4(0.0f, 0.6f, 0.0f, 0.0f), glm::vec2(2.0f));
    CHECK(near.nearLight == Approx(ffxDofLuminance32(light)));
    CHECK(far.nearLight == 0.0f);
    const FfxDofHighlight nearAlone = ffxDofFinishHighlight(near);
    CHECK(nearAlone.near);
    CHECK(nearAlone.radius == Approx(6.0f));
    CHECK_FALSE(ffxDofFinishHighlight(far).near);
    // Together: the near light is the larger part, so the slot is near; its light is all kept.
    const FfxDofHighlight both = ffxDofFinishHighlight(ffxDofAddHighlightSums(near, far));
    CHECK(both.near);
    CHECK(both.energy.z == Approx(30.0f * 1.6f));
    CHECK_FALSE(ffxDofFinishHighlight(ffxDofAddHighlightSums(far, ffxDofAddHighlightSums(far, near))).near);
}

TEST_CASE("Highlight sums give the light-weighted place, radius, axis and spread of what they gather", "[highlights]") {
    // One lit pixel (the bottom-right of the quad at (4, 6)): its centre, its radius, no spread, its light.
    const glm::vec3 dark(0.0f), light(10.0f, 20.0f, 30.0f);
    const FfxDofHighlightSums one =
        ffxDofQuadHighlightSums(dark, dark, dark, light, glm::vec4(-5.0f, -5.0f, -5.0f, -7.0f),
                                glm::vec4(0.0f, 0.0f, 0.0f, 0.5f), glm::vec2(4.0f, 6.0f));
    REQUIRE(ffxDofHighlightSumsHoldLight(one));
    const FfxDofHighlight single = ffxDofFinishHighlight(one);
    CHECK(single.position.x == Approx(5.5f));
    CHECK(single.position.y == Approx(7.5f));
    CHECK(single.radius == Approx(7.0f));
    CHECK(single.spread == Approx(0.0f).margin(1e-3));
    CHECK(single.axis.x == 0.0f);
    CHECK(single.axis.y == 0.0f);
    CHECK(ffxDofHighlightDiscCount(single) == 1u);
    CHECK(single.energy.z == Approx(15.0f));
    // Two equal lights 6 px apart in two quads: their middle, each one's radius weighed by its light, an axis of 3
    // px toward either and no spread across it: its discs lie on the two lights.
    const FfxDofHighlightSums left = ffxDofQuadHighlightSums(light, dark, dark, dark, glm::vec4(-4.0f),
                                                             glm::vec4(1.0f, 0.0f, 0.0f, 0.0f), glm::vec2(0.0f, 2.0f));
    const FfxDofHighlightSums right = ffxDofQuadHighlightSums(light, dark, dark, dark, glm::vec4(-8.0f),
                                                              glm::vec4(1.0f, 0.0f, 0.0f, 0.0f), glm::vec2(6.0f, 2.0f));
    const FfxDofHighlight pair = ffxDofFinishHighlight(ffxDofAddHighlightSums(left, right));
    CHECK(pair.position.x == Approx(3.5f));
    CHECK(pair.position.y == Approx(2.5f));
    CHECK(pair.radius == Approx(6.0f));
    CHECK(std::fabs(pair.axis.x) == Approx(3.0f).margin(1e-3));
    CHECK(pair.axis.y == Approx(0.0f).margin(1e-3));
    CHECK(pair.spread == Approx(0.0f).margin(2e-3));
    CHECK(pair.energy.x == Approx(20.0f));
    REQUIRE(ffxDofHighlightDiscCount(pair) == 2u);
    const glm::vec2 first = ffxDofHighlightDiscCentre(pair, 0u), second = ffxDofHighlightDiscCentre(pair, 1u);
    CHECK(std::min(first.x, second.x) == Approx(0.5f).margin(1e-3));
    CHECK(std::max(first.x, second.x) == Approx(6.5f).margin(1e-3));
    CHECK(first.y == Approx(2.5f));
    CHECK(second.y == Approx(2.5f));
    // The same pair on a diagonal: the axis along it, of half their distance.
    const FfxDofHighlightSums lower = ffxDofQuadHighlightSums(dark, dark, dark, light, glm::vec4(-4.0f),
                                                              glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), glm::vec2(4.0f, 4.0f));
    const FfxDofHighlight diagonal = ffxDofFinishHighlight(ffxDofAddHighlightSums(left, lower));
    CHECK(glm::length(diagonal.axis) == Approx(0.5f * glm::length(glm::vec2(5.5f, 5.5f) - glm::vec2(0.5f, 2.5f))));
    CHECK(std::fabs(glm::dot(glm::normalize(diagonal.axis), glm::normalize(glm::vec2(5.0f, 3.0f)))) ==
          Approx(1.0f).margin(1e-4));
    CHECK(diagonal.spread == Approx(0.0f).margin(2e-3));
    // A square of four equal lights spreads alike every way: one disc, a spread of the corners' distance.
    const FfxDofHighlight square = ffxDofFinishHighlight(
        ffxDofQuadHighlightSums(light, light, light, light, glm::vec4(-4.0f), glm::vec4(1.0f), glm::vec2(2.0f, 2.0f)));
    CHECK(ffxDofHighlightDiscCount(square) == 1u);
    CHECK(square.spread == Approx(std::sqrt(0.5f)).margin(1e-3));
    // Discs stay within the tile.
    FfxDofHighlight edge = pair;
    edge.axis = glm::vec2(20.0f, -20.0f);
    CHECK(ffxDofHighlightDiscCentre(edge, 0u).x == 16.0f);
    CHECK(ffxDofHighlightDiscCentre(edge, 0u).y == 0.0f);
    // A quad that gives nothing holds no light.
    CHECK_FALSE(ffxDofHighlightSumsHoldLight(
        ffxDofQuadHighlightSums(light, light, light, light, glm::vec4(-9.0f), glm::vec4(0.0f), glm::vec2(0.0f))));
}

TEST_CASE("A highlight's disc on the pixel grid holds its energy and ends at its radius", "[highlights]") {
    const FfxDofPixelAperture round = ffxDofRoundAperture();
    // Down to rims wider than the disc (radius 1 and 1.5 half-res px at a spread of 3.2 px: a rim of 9).
    for (float radius : {1.0f, 1.5f, 3.0f, 4.5f, 9.1f, 13.0f, 27.0f}) {  // half-res px
        for (float spread : {0.0f, 0.7f, 2.0f, 3.2f}) {                  // full-res px
            for (glm::vec2 place : {glm::vec2(0.5f), glm::vec2(0.3f, 0.85f)}) {
                const FfxDofHighlight highlight = makeHighlight(place, radius, spread, glm::vec3(1.0f, 2.0f, 3.0f));
                const float rim =
                    std::min(std::max(1.0f, 2.0f * std::sqrt(2.0f) * spread), FFX_DOF_HIGHLIGHT_MAX_RIM_WIDTH);
                const int extent = int(std::ceil(2.0f * radius + rim)) + 2;
                double sum = 0.0, beyond = 0.0;
                for (int y = -extent; y <= extent; ++y)
                    for (int x = -extent; x <= extent; ++x) {
                        const glm::vec2 offset = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - place;
                        const float added = ffxDofHighlightAt(highlight, offset, round).y;
                        sum += added;
                        if (glm::length(offset) > 2.0f * radius + 0.5f * rim + 1e-3f) beyond += added;
                    }
                INFO("radius " << radius << ", spread " << spread);
                // The disc on the grid holds pi r^2 up to its rim's lattice error.
                CHECK(sum == Approx(2.0).epsilon(0.03));
                CHECK(beyond == 0.0);
            }
        }
    }
    // A shaped aperture: its own area (areaScale), the same energy.
    FfxDofPixelAperture wide = round;
    wide.anamorphicRatio = 0.5f;  // twice as wide: half the gauge across, twice the area
    wide.areaScale = 0.5f;
    const FfxDofHighlight highlight = makeHighlight(glm::vec2(0.5f), 10.0f, 0.0f, glm::vec3(1.0f));
    double sum = 0.0;
    for (int y = -25; y <= 25; ++y)
        for (int x = -45; x <= 45; ++x)
            sum += ffxDofHighlightAt(highlight, glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - glm::vec2(0.5f), wide).x;
    CHECK(sum == Approx(1.0).epsilon(0.03));
}

TEST_CASE("What hides a highlight: a surface in front of the light where the rays to it cross, not beside it",
          "[highlights]") {
    // The light at radius 9.1 half-res px (18.2 full-res), at the origin.
    const glm::vec2 light(0.0f);
    const float lightRadius = 9.1f;
    glm::vec2 blocker;
    // A pixel of a farther surface, or in focus, or near: nothing it sees hides the light.
    CHECK_FALSE(ffxDofHighlightBlockerPoint(glm::vec2(10.0f, 0.0f), light, -16.0f, lightRadius, blocker));
    CHECK_FALSE(ffxDofHighlightBlockerPoint(glm::vec2(10.0f, 0.0f), light, 0.2f, lightRadius, blocker));
    CHECK_FALSE(ffxDofHighlightBlockerPoint(glm::vec2(10.0f, 0.0f), light, -9.0f, lightRadius, blocker));
    // A pixel 16 px away on a surface of radius 3 (the light pair of docs/quality.md): the rays from it to the light
    // cross that depth 16 (1 - 3 / 9.1) px from the light, where the pinhole image shows what lies there.
    REQUIRE(ffxDofHighlightBlockerPoint(glm::vec2(-16.0f, 0.0f), light, -3.0f, lightRadius, blocker));
    CHECK(blocker.x == Approx(-16.0f * (1.0f - 3.0f / 9.1f)));
    CHECK(blocker.y == Approx(0.0f).margin(1e-6));
    // What lies there decides: the background (farther than the light) lets it through, a surface in front of it,
    // an in-focus one or a near one does not.
    CHECK(ffxDofHighlightVisibility(-16.0f, lightRadius) == 1.0f);
    CHECK(ffxDofHighlightVisibility(-lightRadius, lightRadius) == 1.0f);
    CHECK(ffxDofHighlightVisibility(-3.0f, lightRadius) == 0.0f);
    CHECK(ffxDofHighlightVisibility(0.0f, lightRadius) == 0.0f);
    CHECK(ffxDofHighlightVisibility(4.0f, lightRadius) == 0.0f);
    CHECK(ffxDofHighlightVisibility(-(lightRadius - 1.0f), lightRadius) == Approx(0.5f));
}

TEST_CASE("The walk from a light to a pixel meets every texel column it crosses and tries far surfaces in front",
          "[highlights]") {
    // One step per half-res texel along the longer axis (offsets in full-res px), at most
    // FFX_DOF_HIGHLIGHT_WALK_MAX_STEPS.
    CHECK(ffxDofHighlightWalkSteps(glm::vec2(0.0f)) == 0u);
    CHECK(ffxDofHighlightWalkSteps(glm::vec2(1.0f, -0.5f)) == 1u);
    CHECK(ffxDofHighlightWalkSteps(glm::vec2(-3.0f, 20.0f)) == 10u);
    CHECK(ffxDofHighlightWalkSteps(glm::vec2(21.0f, 3.0f)) == 11u);
    CHECK(ffxDofHighlightWalkSteps(glm::vec2(0.0f, 200.0f)) == FFX_DOF_HIGHLIGHT_WALK_MAX_STEPS);
    for (float x = 0.25f; x < 64.0f; x += 0.5f) {
        // Consecutive steps lie at most a texel apart along the longer axis.
        const glm::vec2 offset(x, 0.37f * x);
        const uint32_t steps = ffxDofHighlightWalkSteps(offset);
        if (0.5f * x <= FFX_DOF_HIGHLIGHT_WALK_SPACING * float(FFX_DOF_HIGHLIGHT_WALK_MAX_STEPS))
            CHECK(0.5f * x / float(steps) <= FFX_DOF_HIGHLIGHT_WALK_SPACING);
    }
    // A light at radius 9.1 half-res px: the far surfaces tried are those in front of it by 1.5 px or more (where
    // ffxDofHighlightVisibility hides all of it), not in focus, near, at the light's depth or behind it.
    const float lightRadius = 9.1f;
    CHECK(ffxDofHighlightMayCross(-3.0f, lightRadius));
    CHECK(ffxDofHighlightMayCross(-(lightRadius - 1.5f), lightRadius));
    CHECK_FALSE(ffxDofHighlightMayCross(-(lightRadius - 1.0f), lightRadius));
    CHECK_FALSE(ffxDofHighlightMayCross(-lightRadius, lightRadius));
    CHECK_FALSE(ffxDofHighlightMayCross(-16.0f, lightRadius));
    CHECK_FALSE(ffxDofHighlightMayCross(0.0f, lightRadius));
    CHECK_FALSE(ffxDofHighlightMayCross(4.0f, lightRadius));
    // A depth tried is crossed where the surface at its crossing point lies at that depth, not nearer or farther.
    CHECK(ffxDofHighlightCrossed(-3.0f, -3.0f));
    CHECK(ffxDofHighlightCrossed(-3.4f, -3.0f));
    CHECK_FALSE(ffxDofHighlightCrossed(-16.0f, -3.0f));
    CHECK_FALSE(ffxDofHighlightCrossed(0.0f, -3.0f));
    CHECK_FALSE(ffxDofHighlightCrossed(-2.0f, -3.0f));
}

TEST_CASE("The composite's window of tiles covers every highlight whose disc can reach its tile", "[highlights]") {
    for (float cocLimit : {2.0f, 8.0f, 27.0f, 54.0f})
        for (float extent : {1.0f, 1.5f}) {
            const int range = ffxDofHighlightTileRange(cocLimit, extent);
            // A light in a tile `range + 1` tiles away lies at least range * 16 full-res px from any pixel of the
            // central tile; its disc reaches 2 cocLimit extent plus half its widest rim.
            CHECK(float(range) * 2.0f * FFX_DOF_TILE_SIZE >=
                  2.0f * cocLimit * extent + 0.5f * FFX_DOF_HIGHLIGHT_MAX_RIM_WIDTH);
        }
}
