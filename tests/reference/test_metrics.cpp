#include "ffx_dof_metrics.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace ffxdof;

namespace {

io::ImageRGBA checkerImage(uint32_t width, uint32_t height, float low, float high) {
    io::ImageRGBA image(width, height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            const float value = ((x / 3 + y / 3) % 2) ? high : low;
            p[0] = value, p[1] = 0.5f * value, p[2] = 1.0f - value, p[3] = 1.0f;
        }
    }
    return image;
}

// A uniform disc of the given radius and total luminance energy, anti-aliased by 8x8 sub-samples.
io::ImageRGBA discImage(uint32_t size, double cx, double cy, double radius, double energy) {
    io::ImageRGBA image(size, size);
    const double level = energy / (M_PI * radius * radius);
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            int inside = 0;
            for (int sy = 0; sy < 8; ++sy) {
                for (int sx = 0; sx < 8; ++sx) {
                    const double dx = x + (sx + 0.5) / 8 - cx, dy = y + (sy + 0.5) / 8 - cy;
                    inside += dx * dx + dy * dy <= radius * radius ? 1 : 0;
                }
            }
            float* p = image.at(x, y);
            p[0] = p[1] = p[2] = float(level * inside / 64.0);
            p[3] = 1.0f;
        }
    }
    return image;
}

}  // namespace

TEST_CASE("PSNR: identical images are infinite, known noise gives the formula", "[metrics]") {
    const io::ImageRGBA image = checkerImage(30, 20, 0.2f, 0.7f);
    CHECK(std::isinf(metrics::psnr(image, image)));
    CHECK(metrics::psnr(image, image) > 0.0);
    // +-0.05 on every channel, alternating: MSE = 0.0025, PSNR = 10 log10(1 / 0.0025) = 26.0206 dB.
    io::ImageRGBA noisy = image;
    for (size_t i = 0; i < noisy.pixels.size(); ++i) {
        if (i % 4 != 3) noisy.pixels[i] += (i / 4) % 2 ? 0.05f : -0.05f;
    }
    CHECK(metrics::meanSquaredError(image, noisy) == Approx(0.0025).epsilon(1e-4));
    CHECK(metrics::psnr(image, noisy) == Approx(10.0 * std::log10(1.0 / 0.0025)).epsilon(1e-4));
    CHECK(metrics::maxAbsDifference(image, noisy) == Approx(0.05).epsilon(1e-4));
    // Values are clamped to [0, 1]: a highlight of 50 against 1 counts as no difference.
    io::ImageRGBA bright = image, clipped = image;
    bright.pixels[0] = 50.0f, clipped.pixels[0] = 1.0f;
    CHECK(std::isinf(metrics::psnr(bright, clipped)));
    // An empty mask gives NaN, and a mask restricts the average.
    const metrics::Mask none(600, 0);
    CHECK(std::isnan(metrics::psnr(image, noisy, &none)));
    metrics::Mask first(600, 0);
    first[0] = 1;
    CHECK(metrics::psnr(image, noisy, &first) == Approx(26.0206).epsilon(1e-4));
    CHECK_THROWS_AS(metrics::psnr(image, checkerImage(31, 20, 0.2f, 0.7f)), std::invalid_argument);
}

TEST_CASE("SSIM: 1 for identical images, lower for noise and blur, symmetric", "[metrics]") {
    const io::ImageRGBA image = checkerImage(40, 32, 0.1f, 0.9f);
    CHECK(metrics::ssim(image, image) == Approx(1.0).margin(1e-12));
    io::ImageRGBA noisy = image;
    for (size_t i = 0; i < noisy.pixels.size(); ++i) noisy.pixels[i] += ((i * 7919) % 13) * 0.03f - 0.18f;
    const double noisySsim = metrics::ssim(image, noisy);
    CHECK(noisySsim < 0.95);
    CHECK(noisySsim > 0.0);
    CHECK(metrics::ssim(noisy, image) == Approx(noisySsim).margin(1e-12));
    // A flat grey of the same mean loses all structure: SSIM near 0.
    io::ImageRGBA flat = image;
    for (size_t i = 0; i < flat.pixels.size(); ++i) flat.pixels[i] = i % 4 == 3 ? 1.0f : 0.5f;
    CHECK(metrics::ssim(image, flat) < 0.2);
    // Tiny images work (the window is clamped at the border).
    CHECK(metrics::ssim(checkerImage(2, 1, 0.2f, 0.3f), checkerImage(2, 1, 0.2f, 0.3f)) == Approx(1.0));
}

TEST_CASE("CoC regions on a synthetic radius map", "[metrics]") {
    // Left 20 columns in focus (radius 0), the rest far field (-5), except the top 4 rows near (+3).
    io::ImageR radius(50, 12);
    for (uint32_t y = 0; y < 12; ++y) {
        for (uint32_t x = 0; x < 50; ++x) radius.at(x, y) = x < 20 ? 0.0f : (y < 4 ? 3.0f : -5.0f);
    }
    radius.at(0, 0) = 0.99f;   // still in focus
    radius.at(1, 0) = -0.99f;  // still in focus
    const metrics::RegionMasks masks = metrics::classifyRegions(radius);
    CHECK(metrics::countPixels(masks.inFocus) == 20 * 12);
    CHECK(metrics::countPixels(masks.nearField) == 30 * 4);
    CHECK(metrics::countPixels(masks.farField) == 30 * 8);
    // Far pixels in columns 20..27 are within 8 px of column 19 (distance x - 19 <= 8).
    CHECK(metrics::countPixels(masks.haloBand) == 8 * 8);
    CHECK(masks.haloBand[size_t(5) * 50 + 27] == 1);
    CHECK(masks.haloBand[size_t(5) * 50 + 28] == 0);
    CHECK(masks.haloBand[size_t(1) * 50 + 21] == 0);  // near field is never halo
    // Near pixels within 2 px of one outside the near field: rows 2 and 3 (the far field from row 4), and
    // columns 20 and 21 of rows 0 and 1 (in focus up to column 19).
    CHECK(metrics::countPixels(masks.nearEdge) == 30 * 2 + 2 * 2);
    CHECK(masks.nearEdge[size_t(1) * 50 + 21] == 1);
    CHECK(masks.nearEdge[size_t(1) * 50 + 22] == 0);
    CHECK(masks.nearEdge[size_t(5) * 50 + 30] == 0);  // far field is never near edge

    // Euclidean, not city-block: one in-focus pixel at the centre of a far field.
    io::ImageR spot(41, 41);
    for (float& r : spot.pixels) r = -4.0f;
    spot.at(20, 20) = 0.0f;
    const metrics::RegionMasks spotMasks = metrics::classifyRegions(spot, 8.0);
    CHECK(spotMasks.haloBand[size_t(20) * 41 + 28] == 1);  // (8, 0)
    CHECK(spotMasks.haloBand[size_t(26) * 41 + 26] == 0);  // (6, 6): 8.49 px
    CHECK(spotMasks.haloBand[size_t(25) * 41 + 26] == 1);  // (6, 5): 7.81 px
    size_t expected = 0;
    for (int dy = -8; dy <= 8; ++dy) {
        for (int dx = -8; dx <= 8; ++dx) expected += (dx || dy) && dx * dx + dy * dy <= 64 ? 1 : 0;
    }
    CHECK(metrics::countPixels(spotMasks.haloBand) == expected);
}

TEST_CASE("CoC radius map from a camera and linear depth", "[metrics]") {
    ref::Camera camera;
    camera.width = 3;
    camera.height = 1;
    camera.focusDistance = 4.0;
    camera.setFstop(1.4);
    io::ImageR depth(3, 1);
    depth.pixels = {2.0f, 4.0f, 40.0f};
    const io::ImageR radius = metrics::cocRadiusMap(camera, depth);
    CHECK(radius.pixels[0] > 0.0f);
    CHECK(radius.pixels[0] == Approx(camera.cocRadiusPixels(2.0)));
    CHECK(radius.pixels[1] == Approx(0.0).margin(1e-6));
    CHECK(radius.pixels[2] < 0.0f);
    CHECK(radius.pixels[2] == Approx(camera.cocRadiusPixels(40.0)));
    depth.pixels[1] = std::numeric_limits<float>::quiet_NaN();
    CHECK_THROWS_WITH(metrics::cocRadiusMap(camera, depth), Catch::Contains("pixel 1,0"));
    CHECK_THROWS_AS(metrics::cocRadiusMap(camera, io::ImageR(2, 1)), std::invalid_argument);
}

TEST_CASE("compareImages fills the region scores", "[metrics]") {
    const io::ImageRGBA image = checkerImage(30, 10, 0.2f, 0.6f);
    io::ImageRGBA test = image;
    for (uint32_t y = 0; y < 10; ++y) test.at(25, y)[0] += 0.1f;  // a difference only in the far field
    io::ImageR radius(30, 10);
    for (uint32_t y = 0; y < 10; ++y) {
        for (uint32_t x = 0; x < 30; ++x) radius.at(x, y) = x < 15 ? 0.0f : -3.0f;
    }
    const metrics::Comparison comparison = metrics::compareImages(image, test, &radius);
    CHECK(comparison.hasRegions);
    CHECK(std::isinf(comparison.inFocus.psnr));
    CHECK(std::isinf(comparison.haloBand.psnr));  // column 25 is 10 px from column 14
    CHECK(std::isfinite(comparison.farField.psnr));
    CHECK(std::isnan(comparison.nearField.psnr));
    CHECK(comparison.nearField.pixels == 0);
    CHECK(comparison.haloBand.pixels == 8 * 10);
    CHECK_THAT(metrics::formatComparison(comparison), Catch::Contains("halo-band inf dB (80 px)"));
}

TEST_CASE("bokeh measurement: radius, flatness and energy of synthetic discs", "[metrics][bokeh]") {
    for (double r : {3.0, 7.5, 12.25}) {
        const io::ImageRGBA disc = discImage(48, 24.3, 23.6, r, 500.0);
        const metrics::BokehMeasurement m = metrics::measureBokeh(disc);
        INFO("radius " << r);
        CHECK(m.radius == Approx(r).margin(0.35));
        CHECK(m.centerX == Approx(24.3).margin(0.05));
        CHECK(m.centerY == Approx(23.6).margin(0.05));
        CHECK(m.energy == Approx(500.0).epsilon(1e-3));
        CHECK(m.flatness < 0.01);
        CHECK(m.centreLevel == Approx(m.innerLevel).epsilon(0.01));
        CHECK(m.rimDeviation < 0.5);
        CHECK(metrics::bokehGlow(disc, m, r + 1.0) == 0.0);
        CHECK(metrics::bokehGlow(disc, m, r - 1.5) == Approx(1.0).epsilon(0.01));
        CHECK(metrics::checkBokeh(m, r, 500.0).ok());
        CHECK_FALSE(metrics::checkBokeh(m, r + 1.5, 500.0).radiusOk);
        CHECK_FALSE(metrics::checkBokeh(m, r, 550.0).energyOk);
    }
    // Two overlapping discs 4 px apart: an oval whose rim is more than 1 px off its circle (a disc's
    // is within 0.5).
    io::ImageRGBA oval = discImage(48, 22.0, 24.0, 8.0, 500.0);
    const io::ImageRGBA shifted = discImage(48, 26.0, 24.0, 8.0, 500.0);
    for (size_t i = 0; i < oval.pixels.size(); ++i) oval.pixels[i] = std::max(oval.pixels[i], shifted.pixels[i]);
    CHECK(metrics::measureBokeh(oval).rimDeviation > 1.2);
    // A Gaussian blob is not flat; a background is subtracted before measuring.
    io::ImageRGBA blob(48, 48), background(48, 48);
    for (uint32_t y = 0; y < 48; ++y) {
        for (uint32_t x = 0; x < 48; ++x) {
            const double d2 = (x - 23.5) * (x - 23.5) + (y - 23.5) * (y - 23.5);
            float* p = blob.at(x, y);
            p[0] = p[1] = p[2] = float(0.25 + std::exp(-d2 / (2.0 * 16.0)));
            float* b = background.at(x, y);
            b[0] = b[1] = b[2] = 0.25f;
        }
    }
    const metrics::BokehMeasurement gaussian = metrics::measureBokeh(blob, &background);
    CHECK(gaussian.energy == Approx(2.0 * M_PI * 16.0).epsilon(1e-3));
    CHECK(gaussian.flatness > 0.1);
    CHECK(gaussian.centreLevel > gaussian.innerLevel);
    CHECK_FALSE(metrics::checkBokeh(gaussian, gaussian.radius, gaussian.energy).flatOk);
    CHECK_THROWS_AS(metrics::measureBokeh(io::ImageRGBA(4, 4)), std::invalid_argument);
}
