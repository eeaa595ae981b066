// Tile-shaped artifacts: the passes work in tiles of 16 x 16 full-res px, and nothing they decide per
// tile may show in the image. A smooth far-field blur over a textured scene must have no more
// gradient energy across tile borders than elsewhere, and ring merging (FFX_DOF_OPTION_MAX_RING_
// MERGE_LOG) may change the image only by a difference that has no tile-periodic component.
#include "ffx_dof.h"
#include "ffx_dof_vkrun.h"
#include "quality_scenes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace ffxdof;

namespace {

constexpr uint32_t kTilePixels = 16;  // full-res px per blur and composite tile

// A textured far field whose blur radius changes smoothly over the image (7.6 to 12.4 half-res px):
// value noise of a few pixels per cell, so the MIP levels that ring merging reads differ from level 0.
struct TileScene {
    vkrun::HostImage color, depth;
    float cocScale = -20.0f;  // radius = depth * cocScale (device depth 0.38 .. 0.62)
};

TileScene makeTileScene(uint32_t width, uint32_t height) {
    TileScene scene;
    scene.color = vkrun::HostImage(width, height, 4);
    scene.depth = vkrun::HostImage(width, height, 1);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const uint32_t cell = 3;
    const uint32_t cellsX = width / cell + 2, cellsY = height / cell + 2;
    std::vector<float> cells(size_t(cellsX) * cellsY * 3);
    for (float& c : cells) c = unit(rng);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const uint32_t cx = x / cell, cy = y / cell;
            float* p = scene.color.at(x, y);
            for (uint32_t c = 0; c < 3; ++c) p[c] = 0.1f + 0.8f * cells[(size_t(cy) * cellsX + cx) * 3 + c];
            p[3] = 1.0f;
            // Radius -10 +- 2.4 half-res px in gentle waves: the CoC spread around a pixel goes in and
            // out of what counts as flat for ring merging many times over the image.
            const float radius = -10.0f + 1.2f * std::sin(float(x) * (6.2831853f / 150.0f)) +
                                 1.2f * std::sin(float(y) * (6.2831853f / 110.0f));
            scene.depth.at(x, y)[0] = radius / scene.cocScale;
        }
    }
    return scene;
}

vkrun::HostImage runScene(const TileScene& scene, bool ringMerge) {
    vkrun::RunSettings settings;
    settings.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.depthFormat = VK_FORMAT_D32_SFLOAT;
    settings.outputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.quality = 10;
    settings.cocScale = scene.cocScale;
    settings.cocBias = 0.0f;
    // The limit is a fraction of the full-res height in full-res px: 32 full-res px = 16 half-res px.
    settings.cocLimitFactor = 32.0f / float(scene.color.height);
    settings.contextFlags = ringMerge ? 0u : uint32_t(FFX_DOF_DISABLE_RING_MERGE);
    return vkrun::runEffect(quality::validatedDevice(), scene.color, scene.depth, settings).output;
}

double luminanceAt(const vkrun::HostImage& image, uint32_t x, uint32_t y) {
    const float* p = image.at(x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// Mean squared step between neighbouring pixels across tile borders, divided by that across the
// lines half a tile away (columns and rows together). 1 means no tile structure. (The half-tile
// lines are borders of MIP 0..2 texels as well, so a MIP grid alone does not count as tile structure.)
double tileBorderGradientRatio(const vkrun::HostImage& image) {
    double border = 0.0, halfway = 0.0;
    auto add = [&](uint32_t position, double step) {
        if (position % kTilePixels == 0) border += step * step;
        if (position % kTilePixels == kTilePixels / 2) halfway += step * step;
    };
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 1; x < image.width; ++x) add(x, luminanceAt(image, x, y) - luminanceAt(image, x - 1, y));
    for (uint32_t y = 1; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) add(y, luminanceAt(image, x, y) - luminanceAt(image, x, y - 1));
    return border / std::max(halfway, 1e-20);
}

// How much the RMS of `image` jumps between neighbouring 16 x 16 blocks (mean of |a - b| / (a + b) over
// pairs of blocks sharing an edge) on the tile grid, divided by the same on a grid shifted by half a
// tile. A change that switches on or off per tile makes aligned neighbours differ more than shifted
// ones (each shifted block straddles two tiles); a change that follows the content gives about 1.
double tileAlignedBlockContrast(const vkrun::HostImage& image) {
    auto contrast = [&](uint32_t shift) {
        const uint32_t blocksX = (image.width - shift) / kTilePixels, blocksY = (image.height - shift) / kTilePixels;
        std::vector<double> rms(size_t(blocksX) * blocksY, 0.0);
        for (uint32_t by = 0; by < blocksY; ++by)
            for (uint32_t bx = 0; bx < blocksX; ++bx) {
                double sum = 0.0;
                for (uint32_t y = 0; y < kTilePixels; ++y)
                    for (uint32_t x = 0; x < kTilePixels; ++x)
                        sum += std::pow(luminanceAt(image, shift + bx * kTilePixels + x, shift + by * kTilePixels + y),
                                        2.0);
                rms[size_t(by) * blocksX + bx] = std::sqrt(sum / double(kTilePixels * kTilePixels));
            }
        double total = 0.0;
        size_t pairs = 0;
        auto pair = [&](double a, double b) {
            total += a + b > 0.0 ? std::abs(a - b) / (a + b) : 0.0;
            ++pairs;
        };
        for (uint32_t by = 0; by < blocksY; ++by)
            for (uint32_t bx = 0; bx < blocksX; ++bx) {
                if (bx + 1 < blocksX) pair(rms[size_t(by) * blocksX + bx], rms[size_t(by) * blocksX + bx + 1]);
                if (by + 1 < blocksY) pair(rms[size_t(by) * blocksX + bx], rms[size_t(by + 1) * blocksX + bx]);
            }
        return total / double(pairs);
    };
    return contrast(0) / std::max(contrast(kTilePixels / 2), 1e-12);
}

vkrun::HostImage difference(const vkrun::HostImage& a, const vkrun::HostImage& b) {
    vkrun::HostImage d(a.width, a.height, 4);
    for (size_t i = 0; i < a.pixels.size(); ++i) d.pixels[i] = a.pixels[i] - b.pixels[i];
    return d;
}

}  // namespace

TEST_CASE("no tile-shaped structure in a smooth far-field blur, ring merging on or off", "[quality][vulkan][tiles]") {
    const TileScene scene = makeTileScene(320, 192);
    quality::validatedDevice().clearValidationMessages();
    const vkrun::HostImage merged = runScene(scene, true);
    const vkrun::HostImage full = runScene(scene, false);
    const double mergedRatio = tileBorderGradientRatio(merged);
    const double fullRatio = tileBorderGradientRatio(full);
    const vkrun::HostImage change = difference(merged, full);
    const double changeRatio = tileBorderGradientRatio(change);
    const double changeBlockContrast = tileAlignedBlockContrast(change);
    double changeRms = 0.0;
    for (uint32_t y = 0; y < change.height; ++y)
        for (uint32_t x = 0; x < change.width; ++x) changeRms += std::pow(luminanceAt(change, x, y), 2.0);
    changeRms = std::sqrt(changeRms / double(change.width * change.height));
    INFO("tile-border / elsewhere gradient energy: merged "
         << mergedRatio << ", full " << fullRatio << ", merged - full " << changeRatio
         << "; block contrast of merged - full, tile grid / shifted grid " << changeBlockContrast
         << " (rms of merged - full " << changeRms << ")");
    CHECK(quality::validatedDevice().validationMessages().empty());
    // Measured on lavapipe (docs/technique.md, ring merging): with the per-tile switch of merging,
    // merged 0.869 vs full 0.833, merged - full 1.19, block contrast 1.84; with the per-texel
    // continuous merge amount, 0.827 vs 0.829, 1.12 and 1.20. The gradient ratio of the difference
    // (about 1e-3 rms) is too noisy to gate; the block contrast is the check of the difference.
    CHECK(fullRatio < 1.05);
    CHECK(mergedRatio < fullRatio * 1.02);
    CHECK(changeBlockContrast < 1.45);
}
