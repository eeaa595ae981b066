#include "quality_scenes.h"

#include "ffx_dof.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace ffxdof::quality {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

vkrun::Device& validatedDevice() {
    static std::unique_ptr<vkrun::Device> device = [] {
        vkrun::DeviceOptions options;
        options.validation = true;
        return std::make_unique<vkrun::Device>(options);
    }();
    return *device;
}

const std::vector<SceneGate>& sceneGates() {
    // Margins are about 1.5 dB below what the effect measured on lavapipe (gains of 19.3, 8.5, 7.8, 6.4,
    // 15.1 and 14.1 dB after the composite's full-resolution own-surface gather of small radii;
    // docs/quality.md has the current figures), so a regression of 1.5 dB or more fails. The truth is
    // deterministic (seeded), so the figures repeat.
    static const std::vector<SceneGate> gates = {
        {"near-object", 17.5,
         "a large blurred near sphere: most of the input's error is there and the effect removes most of it"},
        {"far-highlights", 6.0,
         "bright far bokeh: the discs' rims, anti-aliased at half resolution and upsampled, are softer and wider "
         "than the truth's, which a disc brighter than display white shows as a wider disc with colour fringes; the "
         "circular gather, at full resolution, keeps them sharp. Above the gather since the lights' "
         "anti-aliased rims take the light's radius (docs/technique.md, light rims); below it until then"},
        {"mid-lights", 6.0,
         "small lights nearer than a far background (issue 17): each must spread into its own disc, no sharp "
         "core left, no light lost"},
        {"fence", 4.0,
         "thin near posts over a sharp wall: partial occlusion, which a post-process can only "
         "approximate, so the gain is smaller"},
        {"busy-background", 13.5, "a 40+ px background blur: nearly every background pixel changes"},
        {"floor", 12.5, "blur grows continuously with distance in front of and behind the focus"},
        {"bright-window", 15.0,
         "a far field brighter than display white behind thin dark bars in focus: the far layer must stay out of "
         "the bars, whose thin-lens halo (the truth sees the sky around them) a post-process of the pinhole image "
         "cannot draw"},
        {"near-and-far", 13.5,
         "small near objects, strongly blurred, over a blurred far field: their veils are faint and the far field "
         "behind them must show no edge where their pinhole silhouettes lie (docs/technique.md, \"The far field "
         "behind a small near object\")"},
        {"far-branches", 24.5,
         "thin dark branches in the far field against a sky brighter than display white that lies farther still: "
         "the sky shows through their veils, which hold no step where a tile's bright pixels were taken for lights "
         "(docs/technique.md, \"A bright far field is not a light\")",
         true,
         "two branches cross behind the in-focus sphere. Beside it the thin lens sees the branches go on behind "
         "the sphere, which the pinhole input hides; ffx-dof fills the part of those far pixels' discs that the "
         "sphere hides with the far field it sees around them, mostly sky, and draws the veil up to 0.3 brighter "
         "there (green 1.06 against 0.77 at (172, 120)). The circular gather mixes the sphere's own colours in and "
         "comes "
         "nearer by chance. The same limit as mid-lights' partly hidden lights: a post-process of the pinhole image "
         "cannot know what an object in focus hides"},
        {"lights-through-branches", 8.5,
         "lights of 1 to 3 px far behind dark far branches. The thin lens draws a branch in front of a light as a "
         "dark band across its whole disc, where the rays from the disc's pixels to the light pass the branch; the "
         "composite walks from each light to each quad and hides the highlight where a far surface it meets lies "
         "in front of the light at that pixel's blocker point (ffxDofHighlightVisibilityPast), so the band crosses "
         "the whole disc. A light the branch hides from the pinhole camera stays missing, and a branch one pixel "
         "wide can slip between the walk's steps (docs/technique.md, \"What lies between a pixel "
         "and a light\")"},
        {"near-leaves-sky", 22.0,
         "dark near leaves, strongly blurred, against a sky above white: their veils must let the bright sky "
         "through as the thin lens does, and the sky, brighter than display white, must not be taken for lights "
         "(docs/technique.md, \"A sky above white takes the cheap paths\")"},
        {"far-steps", 21.5,
         "large far objects in front of a farther high-contrast wall: far-field content nearer than the far field "
         "around it, at the object's edges the wall's blur passes behind them"},
    };
    return gates;
}

SceneRender renderScene(const std::string& scene, uint32_t width, uint32_t height, uint32_t lensSamples,
                        const ref::ApertureShape& aperture) {
    ref::SceneSetup setup = ref::makeScene(scene, width, height);
    setup.camera.aperture = aperture;
    return renderSetup(std::move(setup), lensSamples);
}

SceneRender renderSetup(ref::SceneSetup setup, uint32_t lensSamples) {
    SceneRender render;
    render.setup = std::move(setup);
    ref::RenderSettings settings;
    settings.lensSamples = lensSamples;
    render.pinhole = ref::renderPinhole(render.setup.scene, render.setup.camera, settings);
    ref::ThinLensImage truth = ref::renderThinLens(render.setup.scene, render.setup.camera, settings);
    render.truth = std::move(truth.color);
    render.convergenceRms = truth.convergenceRms;
    render.radius = metrics::cocRadiusMap(render.setup.camera, render.pinhole.depth);
    return render;
}

FfxDofAperture effectAperture(const ref::ApertureShape& shape) {
    constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
    FfxDofAperture aperture{};
    aperture.bladeCount = shape.bladeCount;
    aperture.bladeRotation = float(shape.bladeRotationDegrees * kRadiansPerDegree);
    aperture.roundness = float(shape.roundness);
    aperture.anamorphicRatio = float(shape.anamorphicRatio);
    aperture.catEye = float(shape.catEye);
    return aperture;
}

io::ImageRGBA circularGatherBaseline(const io::ImageRGBA& color, const io::ImageR& radiusPixels) {
    const int w = int(color.width), h = int(color.height);
    io::ImageRGBA result(color.width, color.height);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double r = std::abs(radiusPixels.at(uint32_t(x), uint32_t(y)));
            const int extent = int(std::floor(r));
            double sum[4] = {};
            int count = 0;
            for (int dy = -extent; dy <= extent; ++dy) {
                for (int dx = -extent; dx <= extent; ++dx) {
                    if (dx * dx + dy * dy > r * r && (dx || dy)) continue;
                    const float* p =
                        color.at(uint32_t(std::clamp(x + dx, 0, w - 1)), uint32_t(std::clamp(y + dy, 0, h - 1)));
                    for (int c = 0; c < 4; ++c) sum[c] += p[c];
                    ++count;
                }
            }
            float* out = result.at(uint32_t(x), uint32_t(y));
            for (int c = 0; c < 4; ++c) out[c] = float(sum[c] / count);
        }
    }
    return result;
}

io::ImageRGBA halfResolutionGatherBaseline(const io::ImageRGBA& color, const io::ImageR& radiusPixels) {
    const uint32_t w = color.width, h = color.height;
    const uint32_t hw = (w + 1) / 2, hh = (h + 1) / 2;
    io::ImageRGBA halfColor(hw, hh);
    io::ImageR halfRadius(hw, hh);
    for (uint32_t y = 0; y < hh; ++y) {
        for (uint32_t x = 0; x < hw; ++x) {
            double sum[4] = {}, radius = 0.0;
            for (uint32_t q = 0; q < 4; ++q) {
                const uint32_t sx = std::min(2 * x + (q & 1u), w - 1), sy = std::min(2 * y + (q >> 1u), h - 1);
                for (int c = 0; c < 4; ++c) sum[c] += color.at(sx, sy)[c];
                radius += std::abs(radiusPixels.at(sx, sy));
            }
            for (int c = 0; c < 4; ++c) halfColor.at(x, y)[c] = float(sum[c] / 4.0);
            halfRadius.at(x, y) = float(radius / 8.0);  // mean |radius| of four, in half-res px
        }
    }
    const io::ImageRGBA halfGather = circularGatherBaseline(halfColor, halfRadius);
    io::ImageRGBA result(w, h);
    for (uint32_t y = 0; y < h; ++y) {
        // Full-res pixel centre in half-res texels, less half a texel: the bilinear taps.
        const double fy = std::clamp((y + 0.5) / 2.0 - 0.5, 0.0, double(hh - 1));
        const uint32_t y0 = uint32_t(fy), y1 = std::min(y0 + 1, hh - 1);
        const double ty = fy - y0;
        for (uint32_t x = 0; x < w; ++x) {
            const double fx = std::clamp((x + 0.5) / 2.0 - 0.5, 0.0, double(hw - 1));
            const uint32_t x0 = uint32_t(fx), x1 = std::min(x0 + 1, hw - 1);
            const double tx = fx - x0;
            for (int c = 0; c < 4; ++c) {
                const double top = halfGather.at(x0, y0)[c] * (1.0 - tx) + halfGather.at(x1, y0)[c] * tx;
                const double bottom = halfGather.at(x0, y1)[c] * (1.0 - tx) + halfGather.at(x1, y1)[c] * tx;
                result.at(x, y)[c] = float(top * (1.0 - ty) + bottom * ty);
            }
        }
    }
    return result;
}

metrics::Mask undisturbedInFocusMask(const io::ImageR& radiusPixels) {
    const int w = int(radiusPixels.width), h = int(radiusPixels.height);
    float nearest = 0.0f;
    for (float r : radiusPixels.pixels) nearest = std::max(nearest, r);
    const int reach = int(std::ceil(nearest)) + 1;
    const metrics::RegionMasks regions = metrics::classifyRegions(radiusPixels);
    metrics::Mask mask = regions.inFocus;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!regions.nearField[size_t(y) * w + x]) continue;
            for (int sy = std::max(0, y - reach); sy <= std::min(h - 1, y + reach); ++sy) {
                for (int sx = std::max(0, x - reach); sx <= std::min(w - 1, x + reach); ++sx) {
                    if ((sx - x) * (sx - x) + (sy - y) * (sy - y) <= reach * reach) mask[size_t(sy) * w + sx] = 0;
                }
            }
        }
    }
    return mask;
}

vkrun::RunSettings sceneRunSettings(const SceneRender& render) {
    const ref::Camera& camera = render.setup.camera;
    const ref::ProjectionTerms projection = camera.projection();
    // The SDK's radius is in half-resolution pixels: conversion = 0.5 * width / sensorWidth.
    const float conversion = float(0.5 * camera.width / camera.sensorWidth);
    float largest = 0.0f;
    for (float r : render.radius.pixels) largest = std::max(largest, std::abs(r));
    vkrun::RunSettings settings;
    settings.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.depthFormat = VK_FORMAT_D32_SFLOAT;
    settings.outputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.quality = kEffectQuality;
    // The limit is a fraction of the full-resolution height: cover the largest radius of the scene.
    settings.cocLimitFactor = largest / float(camera.height) * 1.02f + 1e-3f;
    settings.cocScale = ffxDofCalculateCocScale(float(camera.apertureRadius), float(camera.focusDistance),
                                                float(camera.focalLength), conversion, float(projection.proj33),
                                                float(projection.proj34), float(projection.proj43));
    settings.cocBias = ffxDofCalculateCocBias(float(camera.apertureRadius), float(camera.focusDistance),
                                              float(camera.focalLength), conversion, float(projection.proj33),
                                              float(projection.proj34), float(projection.proj43));
    settings.aperture = effectAperture(camera.aperture);
    return settings;
}

GateResult runGate(vkrun::Device& device, const SceneRender& render, bool inPlace) {
    const ref::Camera& camera = render.setup.camera;
    const uint32_t w = camera.width, h = camera.height;
    vkrun::HostImage color(w, h, 4), depth(w, h, 1);
    color.pixels = render.pinhole.color.pixels;
    depth.pixels = render.pinhole.deviceDepth.pixels;

    GateResult result;
    vkrun::RunSettings settings = sceneRunSettings(render);
    settings.inPlace = inPlace;
    result.cocScale = settings.cocScale;
    result.cocBias = settings.cocBias;
    result.cocLimitFactor = settings.cocLimitFactor;
    const vkrun::RunResult run = vkrun::runEffect(device, color, depth, settings);
    result.ours = io::ImageRGBA(w, h);
    result.ours.pixels = run.output.pixels;
    result.baseline = circularGatherBaseline(render.pinhole.color, render.radius);

    result.input = metrics::compareImages(render.truth, render.pinhole.color, &render.radius);
    result.effect = metrics::compareImages(render.truth, result.ours, &render.radius);
    result.gather = metrics::compareImages(render.truth, result.baseline, &render.radius);
    result.halfGather = metrics::compareImages(
        render.truth, halfResolutionGatherBaseline(render.pinhole.color, render.radius), &render.radius);
    const metrics::Mask inFocus = undisturbedInFocusMask(render.radius);
    result.inFocusPixels = metrics::countPixels(inFocus);
    result.inFocusMaxDifference = metrics::maxAbsDifference(render.pinhole.color, result.ours, &inFocus);
    return result;
}

PointBokeh measurePointBokeh(vkrun::Device& device) {
    PointBokeh bokeh{renderScene("point"), {}, {}, {}};
    bokeh.result = runGate(device, bokeh.render);
    const double expectedRadius =
        std::abs(bokeh.render.setup.camera.cocRadiusPixels(bokeh.render.setup.scene.primitives[0].center.z));
    const double inputEnergy = metrics::measureBokeh(bokeh.render.pinhole.color).energy;
    const metrics::BokehMeasurement truth = metrics::measureBokeh(bokeh.render.truth);
    bokeh.truth = metrics::checkBokeh(truth, expectedRadius, truth.energy);
    bokeh.ours = metrics::checkBokeh(metrics::measureBokeh(bokeh.result.ours), expectedRadius, inputEnergy);
    return bokeh;
}

std::string PointDiscCase::describe() const {
    std::ostringstream text;
    text << (nearField ? "near point, radius " : "far point, radius ") << radius << " px, offset (" << offsetX << ", "
         << offsetY << "), ring merging " << (ringMerge ? "on" : "off") << ": measured radius " << disc.radius
         << ", flatness " << disc.flatness << ", centre / inner level " << disc.centreLevel / disc.innerLevel
         << ", rim deviation " << disc.rimDeviation << " px, glow " << glow << ", energy " << energyRatio;
    return text.str();
}

PointDiscCase runPointDisc(vkrun::Device& device, double radius, int offsetX, int offsetY, bool ringMerge,
                           bool nearField) {
    constexpr uint32_t kSide = 160;
    constexpr double kLargestRadius = 54.0;
    vkrun::HostImage color(kSide, kSide, 4), depth(kSide, kSide, 1);
    for (size_t i = 0; i < size_t(kSide) * kSide; ++i) {
        color.pixels[i * 4 + 3] = 1.0f;
        depth.pixels[i] = 1.0f;
    }
    const double energy = 0.25 * kPi * radius * radius;
    float* point = color.at(80u + uint32_t(offsetX), 80u + uint32_t(offsetY));
    point[0] = point[1] = point[2] = float(energy);
    // Near: the point at depth 0, of radius +R/2 half-res px; the wall at depth 1, of radius 0.
    if (nearField) depth.pixels[size_t(80u + uint32_t(offsetY)) * kSide + 80u + uint32_t(offsetX)] = 0.0f;

    vkrun::RunSettings settings;
    settings.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.depthFormat = VK_FORMAT_R32_SFLOAT;
    settings.outputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.quality = kEffectQuality;
    // Radius (half-res px) = depth * cocScale + cocBias, negative: far field.
    settings.cocScale = -float(0.5 * radius);
    settings.cocBias = nearField ? float(0.5 * radius) : 0.0f;
    settings.cocLimitFactor = float(kLargestRadius / kSide);
    settings.contextFlags = ringMerge ? 0u : uint32_t(FFX_DOF_DISABLE_RING_MERGE);
    const vkrun::RunResult run = vkrun::runEffect(device, color, depth, settings);

    PointDiscCase result;
    result.radius = radius;
    result.offsetX = offsetX;
    result.offsetY = offsetY;
    result.ringMerge = ringMerge;
    result.nearField = nearField;
    result.output = io::ImageRGBA(kSide, kSide);
    result.output.pixels = run.output.pixels;
    result.disc = metrics::measureBokeh(result.output);
    result.energyRatio = result.disc.energy / energy;
    result.glow = metrics::bokehGlow(result.output, result.disc, radius + 1.5);
    return result;
}

std::vector<PointDiscCase> runPointDiscCases(vkrun::Device& device) {
    std::vector<PointDiscCase> cases;
    for (bool ringMerge : {true, false})
        for (double radius : kPointDiscRadii)
            for (const auto& offset : kPointDiscOffsets)
                cases.push_back(runPointDisc(device, radius, offset[0], offset[1], ringMerge));
    return cases;
}

std::vector<PointDiscCase> runNearPointDiscCases(vkrun::Device& device) {
    std::vector<PointDiscCase> cases;
    for (double radius : kNearPointDiscRadii)
        for (const auto& offset : kPointDiscOffsets)
            cases.push_back(runPointDisc(device, radius, offset[0], offset[1], true, true));
    return cases;
}

std::string ThinBarCase::describe() const {
    std::ostringstream text;
    text << "bar " << width << " px from column " << left << " at near radius " << radius << " px: opacity summed "
         << opacitySum << " (truth " << width << "), largest step " << largestStep << " (truth " << truthLargestStep
         << ")";
    return text.str();
}

namespace {

// The thin-lens veil of a bar [x0, x0 + width) blurred by a disc of `radius`, at pixel column `column`:
// the disc's share over the bar, averaged over the pixel (numerically, 64 x 64 points per pixel).
double thinBarTruth(double x0, double width, double radius, int column) {
    constexpr int kSteps = 64;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double x = column + (i + 0.5) / kSteps;
        // Offsets u from the pixel to the bar's points: the disc covers the chord 2 sqrt(R^2 - u^2).
        for (int j = 0; j < kSteps; ++j) {
            const double u = x0 + width * (j + 0.5) / kSteps - x;
            if (std::abs(u) < radius) sum += 2.0 * std::sqrt(radius * radius - u * u) * (width / kSteps);
        }
    }
    return sum / kSteps / (kPi * radius * radius);
}

}  // namespace

ThinBarCase runThinBar(vkrun::Device& device, double width, double radius, uint32_t left) {
    constexpr uint32_t kWidth = 192, kHeight = 96;
    const uint32_t barLeft = left;
    const uint32_t barColumns = uint32_t(std::ceil(width));
    vkrun::HostImage depth(kWidth, kHeight, 1);
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x)
            depth.at(x, y)[0] = x >= barLeft && x < barLeft + barColumns ? 0.0f : 1.0f;
    const auto wallAt = [](uint32_t x, uint32_t y) { return ((x / 3 + y / 3) % 2) ? 0.6f : 0.2f; };  // 3 px checker
    vkrun::HostImage color(kWidth, kHeight, 4);
    const auto runWithBar = [&](float barValue) {
        for (uint32_t y = 0; y < kHeight; ++y) {
            for (uint32_t x = 0; x < kWidth; ++x) {
                float* p = color.at(x, y);
                const bool bar = x >= barLeft && x < barLeft + barColumns;
                p[0] = p[1] = p[2] = bar ? barValue : wallAt(x, y);
                p[3] = 1.0f;
            }
        }
        vkrun::RunSettings settings;
        settings.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
        settings.depthFormat = VK_FORMAT_R32_SFLOAT;
        settings.outputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
        settings.quality = kEffectQuality;
        // Radius (half-res px) = depth * cocScale + cocBias: the wall (depth 1) in focus, the bar (0) near.
        settings.cocBias = float(0.5 * radius);
        settings.cocScale = -settings.cocBias;
        settings.cocLimitFactor = float(radius / kHeight) * 1.02f;
        return vkrun::runEffect(device, color, depth, settings).output;
    };
    const vkrun::HostImage black = runWithBar(0.0f), white = runWithBar(1.0f);

    ThinBarCase result;
    result.width = width;
    result.radius = radius;
    result.left = left;
    result.input = io::ImageRGBA(kWidth, kHeight);
    result.input.pixels = color.pixels;  // the white bar's
    result.output = io::ImageRGBA(kWidth, kHeight);
    result.output.pixels = white.pixels;
    for (uint32_t x = 0; x < kWidth; ++x) {
        double sum = 0.0;
        for (uint32_t y = kHeight / 2 - 8; y < kHeight / 2 + 8; ++y) sum += white.at(x, y)[1] - black.at(x, y)[1];
        result.opacity.push_back(sum / 16.0);
        result.truthOpacity.push_back(thinBarTruth(barLeft, width, radius, int(x)));
        result.opacitySum += result.opacity.back();
        if (x > 0) {
            result.largestStep = std::max(result.largestStep, std::abs(result.opacity[x] - result.opacity[x - 1]));
            result.truthLargestStep =
                std::max(result.truthLargestStep, std::abs(result.truthOpacity[x] - result.truthOpacity[x - 1]));
        }
    }
    // The truth: the wall, behind the bar too, under the veil of the white bar.
    result.truth = io::ImageRGBA(kWidth, kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            float* p = result.truth.at(x, y);
            const float opacity = float(result.truthOpacity[x]);
            p[0] = p[1] = p[2] = wallAt(x, y) * (1.0f - opacity) + opacity;
            p[3] = 1.0f;
        }
    }
    return result;
}

std::vector<ThinBarCase> runThinBarCases(vkrun::Device& device) {
    std::vector<ThinBarCase> cases;
    for (uint32_t left : kThinBarLefts)
        for (double radius : kThinBarRadii)
            for (double width : kThinBarWidths) cases.push_back(runThinBar(device, width, radius, left));
    return cases;
}

std::string SmallLightCase::describe() const {
    std::ostringstream text;
    text << (near ? "near " : "") << "light " << size << " px at radius " << radius << " px, offset (" << offsetX
         << ", " << offsetY << "), " << (float32 ? "32" : "16") << "-bit: energy added " << energyRatio
         << " of the input's, centre " << centre << " (truth " << truthCentre << "), disc " << discShift
         << " px from the light";
    return text.str();
}

std::string SceneLightCase::describe() const {
    std::ostringstream text;
    text << scene << " light " << emitter << " at radius " << radius << " px" << (partlyHidden ? ", partly hidden" : "")
         << ", " << (float32 ? "32" : "16") << "-bit: adds " << oursAdded << " (input " << inputAdded;
    if (partlyHidden) text << ", truth " << truthAdded;
    text << "): " << energyRatio() << " of " << (partlyHidden ? "the truth's" : "the input's") << ", "
         << oursAddedOwnDisc / referenceAdded() << " within its own disc";
    return text.str();
}

namespace {

// RGB summed over the frame, unclipped.
double imageEnergy(const std::vector<float>& rgba) {
    double sum = 0.0;
    for (size_t i = 0; i < rgba.size(); i += 4) sum += double(rgba[i]) + rgba[i + 1] + rgba[i + 2];
    return sum;
}

std::vector<float> runOnPinhole(vkrun::Device& device, const ref::PinholeImages& pinhole,
                                const vkrun::RunSettings& settings) {
    const uint32_t w = pinhole.color.width, h = pinhole.color.height;
    vkrun::HostImage color(w, h, 4), depth(w, h, 1);
    color.pixels = pinhole.color.pixels;
    depth.pixels = pinhole.deviceDepth.pixels;
    return vkrun::runEffect(device, color, depth, settings).output.pixels;
}

// Where the input changes with a light: its own pixels, anti-aliased rim included, and their centre
// weighted by how much each changes. The two reaches from it differ on purpose: lightPartlyHidden asks
// whether the disc of any changed pixel (|radius| + 1) meets an in-focus pixel, discEnergyAdded sums
// the light's own disc about its centre (|radius| + 3, the "own disc" of docs/quality.md).
struct LightFootprint {
    std::vector<std::pair<uint32_t, uint32_t>> changedPixels;
    double totalChange = 0.0;  // RGB |with - without| summed: 0 where the light changes nothing
    double centreX = 0.0, centreY = 0.0;
};

LightFootprint lightFootprint(const io::ImageRGBA& with, const io::ImageRGBA& without) {
    LightFootprint footprint;
    double weightedX = 0.0, weightedY = 0.0;
    for (uint32_t y = 0; y < with.height; ++y)
        for (uint32_t x = 0; x < with.width; ++x) {
            const size_t i = (size_t(y) * with.width + x) * 4;
            double change = 0.0;
            bool changed = false;
            for (size_t c = 0; c < 3; ++c) {
                changed = changed || with.pixels[i + c] != without.pixels[i + c];
                change += std::abs(double(with.pixels[i + c]) - without.pixels[i + c]);
            }
            if (changed) footprint.changedPixels.emplace_back(x, y);
            weightedX += change * x;
            weightedY += change * y;
            footprint.totalChange += change;
        }
    if (footprint.totalChange > 0.0) {
        footprint.centreX = weightedX / footprint.totalChange;
        footprint.centreY = weightedY / footprint.totalChange;
    }
    return footprint;
}

// Whether an in-focus pixel lies within reach of the light's disc: its changed pixels, widened by its
// radius.
bool lightPartlyHidden(const SceneRender& full, const LightFootprint& footprint, double radius) {
    const uint32_t width = full.pinhole.color.width, height = full.pinhole.color.height;
    const double reach = std::abs(radius) + 1.0;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            if (!(std::abs(full.radius.pixels[size_t(y) * width + x]) < 1.0f)) continue;
            for (const auto& [fx, fy] : footprint.changedPixels) {
                const double dx = double(x) - fx, dy = double(y) - fy;
                if (dx * dx + dy * dy <= reach * reach) return true;
            }
        }
    return false;
}

// A light's own disc: |radius| + 3 px about its footprint's centre.
bool inOwnDisc(const LightFootprint& footprint, double radius, uint32_t x, uint32_t y) {
    const double reach = std::abs(radius) + 3.0;
    const double dx = x - footprint.centreX, dy = y - footprint.centreY;
    return dx * dx + dy * dy <= reach * reach;
}

// The RGB sum of with - without over the own disc of the light `inside`, less the pixels of the own disc
// of `outside` (nullptr: none).
struct LightDisc {
    const LightFootprint* footprint;
    double radius;
};
double discEnergyAdded(const SceneRender& full, LightDisc inside, const LightDisc* outside,
                       const std::vector<float>& with, const std::vector<float>& withoutOutput) {
    if (!(inside.footprint->totalChange > 0.0)) return 0.0;
    const uint32_t width = full.pinhole.color.width, height = full.pinhole.color.height;
    double added = 0.0;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            if (!inOwnDisc(*inside.footprint, inside.radius, x, y)) continue;
            if (outside != nullptr && inOwnDisc(*outside->footprint, outside->radius, x, y)) continue;
            const size_t i = (size_t(y) * width + x) * 4;
            for (size_t c = 0; c < 3; ++c) added += double(with[i + c]) - withoutOutput[i + c];
        }
    return added;
}

}  // namespace

std::vector<SceneLightCase> runSceneLightCases(vkrun::Device& device, const std::string& scene) {
    const SceneRender full = renderScene(scene);
    const ref::Camera& camera = full.setup.camera;
    ref::RenderSettings renderSettings;
    renderSettings.lensSamples = kLensSamples;
    const double inputEnergy = imageEnergy(full.pinhole.color.pixels);
    const double truthEnergy = imageEnergy(full.truth.pixels);

    struct Removed {
        size_t emitter;
        double radius;
        ref::PinholeImages pinhole;
        LightFootprint footprint;
        bool partlyHidden;
        double truthAdded;
    };
    std::vector<Removed> removed;
    size_t emitter = 0;
    for (size_t i = 0; i < full.setup.scene.primitives.size(); ++i) {
        const ref::Primitive& light = full.setup.scene.primitives[i];
        if (!light.emitter) continue;
        ref::Scene without = full.setup.scene;
        without.primitives.erase(without.primitives.begin() + std::ptrdiff_t(i));
        const double radius = camera.cocRadiusPixels(light.center.z);
        ref::PinholeImages pinhole = ref::renderPinhole(without, camera, renderSettings);
        LightFootprint footprint = lightFootprint(full.pinhole.color, pinhole.color);
        const bool partlyHidden = lightPartlyHidden(full, footprint, radius);
        const double truthAdded =
            partlyHidden ? truthEnergy - imageEnergy(ref::renderThinLens(without, camera, renderSettings).color.pixels)
                         : 0.0;
        removed.push_back({emitter++, radius, std::move(pinhole), std::move(footprint), partlyHidden, truthAdded});
    }

    std::vector<SceneLightCase> cases;
    for (bool float32 : {false, true}) {
        vkrun::RunSettings settings = sceneRunSettings(full);
        settings.forceFloat32 = float32;
        const std::vector<float> oursWith = runOnPinhole(device, full.pinhole, settings);
        const double oursEnergy = imageEnergy(oursWith);
        for (const Removed& entry : removed) {
            SceneLightCase light;
            light.scene = scene;
            light.emitter = entry.emitter;
            light.radius = entry.radius;
            light.float32 = float32;
            light.partlyHidden = entry.partlyHidden;
            light.inputAdded = inputEnergy - imageEnergy(entry.pinhole.color.pixels);
            const std::vector<float> oursWithout = runOnPinhole(device, entry.pinhole, settings);
            light.oursAdded = oursEnergy - imageEnergy(oursWithout);
            const LightDisc own{&entry.footprint, entry.radius};
            light.oursAddedOwnDisc = discEnergyAdded(full, own, nullptr, oursWith, oursWithout);
            // Which other light's disc (outside this one's) changes most while this light is there.
            for (const Removed& other : removed) {
                if (other.emitter == entry.emitter) continue;
                const double changed =
                    discEnergyAdded(full, {&other.footprint, other.radius}, &own, oursWith, oursWithout);
                if (std::abs(changed) > std::abs(light.mostChangedOtherAdded)) {
                    light.mostChangedOther = other.emitter;
                    light.mostChangedOtherAdded = changed;
                }
            }
            light.truthAdded = entry.truthAdded;
            cases.push_back(light);
        }
    }
    return cases;
}

namespace {

// Issue 17's minimal case: square lights on a background of 0.05 at far radius 32 full-res px, 160 x 128 px.
constexpr uint32_t kLightsWidth = 160, kLightsHeight = 128;
constexpr double kLightsBackground = 0.05, kLightsBackgroundRadius = 32.0;

// The near variant: the same background of 0.05 in focus, the lights in front of it at near radii up to this.
constexpr double kNearLightsMaxRadius = 40.0, kNearLightsFocusDepth = 32.0;

struct SquareLight {
    int x0 = 0, y0 = 0, size = 0;      // first pixel, px per side
    double value = 0.0, radius = 0.0;  // radius: full-res px, in the far field (or the near field: `near` below)
};

// The effect's output (RGBA32F) for the lights on the background. Far (issue 17's minimal case): radius
// (half-res px) = depth * cocScale, so the depth is the full-res radius. `near`: the background lies at the
// focus (radius 0) and a light of radius r at depth kNearLightsFocusDepth - r, nearer.
vkrun::HostImage runSquareLights(vkrun::Device& device, const std::vector<SquareLight>& lights, bool float32,
                                 uint32_t contextFlags = 0, bool near = false) {
    const double backgroundDepth = near ? kNearLightsFocusDepth : kLightsBackgroundRadius;
    const auto lightDepth = [&](double radius) { return near ? kNearLightsFocusDepth - radius : radius; };
    vkrun::HostImage color(kLightsWidth, kLightsHeight, 4), depth(kLightsWidth, kLightsHeight, 1);
    for (uint32_t y = 0; y < kLightsHeight; ++y) {
        for (uint32_t x = 0; x < kLightsWidth; ++x) {
            float* p = color.at(x, y);
            p[0] = p[1] = p[2] = float(kLightsBackground);
            p[3] = 1.0f;
            depth.at(x, y)[0] = float(backgroundDepth);
            for (const SquareLight& light : lights)
                if (int(x) >= light.x0 && int(x) < light.x0 + light.size && int(y) >= light.y0 &&
                    int(y) < light.y0 + light.size) {
                    p[0] = p[1] = p[2] = float(light.value);
                    depth.at(x, y)[0] = float(lightDepth(light.radius));
                }
        }
    }
    vkrun::RunSettings settings;
    settings.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.depthFormat = VK_FORMAT_R32_SFLOAT;
    settings.outputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.quality = kEffectQuality;
    settings.cocScale = -0.5f;
    settings.cocBias = near ? float(0.5 * kNearLightsFocusDepth) : 0.0f;
    settings.cocLimitFactor = float((near ? kNearLightsMaxRadius : kLightsBackgroundRadius) / kLightsHeight) * 1.02f;
    settings.forceFloat32 = float32;
    settings.contextFlags = contextFlags;
    return vkrun::runEffect(device, color, depth, settings).output;
}

// The green channel of a - b, summed.
double addedGreen(const vkrun::HostImage& a, const vkrun::HostImage& b) {
    double added = 0.0;
    for (size_t i = 1; i < a.pixels.size(); i += 4) added += double(a.pixels[i]) - b.pixels[i];
    return added;
}

}  // namespace

namespace {
std::vector<std::array<int, 2>> smallLightOffsets() {
    std::vector<std::array<int, 2>> offsets;
    for (const auto& offset : kSmallLightOffsets) offsets.push_back({offset[0], offset[1]});
    return offsets;
}
}  // namespace

std::vector<SmallLightCase> runSmallLightCases(vkrun::Device& device) {
    return runSmallLightCases(device, {std::begin(kSmallLightRadii), std::end(kSmallLightRadii)},
                              {std::begin(kSmallLightSizes), std::end(kSmallLightSizes)}, smallLightOffsets());
}

std::vector<SmallLightCase> runSmallLightCasesBelowGate(vkrun::Device& device) {
    return runSmallLightCases(device, {std::begin(kSmallLightRadiiBelowGate), std::end(kSmallLightRadiiBelowGate)},
                              {std::begin(kSmallLightSizesBelowGate), std::end(kSmallLightSizesBelowGate)},
                              smallLightOffsets());
}

std::vector<SmallLightCase> runNearLightCases(vkrun::Device& device) {
    return runSmallLightCases(device, {std::begin(kNearLightRadii), std::end(kNearLightRadii)},
                              {std::begin(kNearLightSizes), std::end(kNearLightSizes)}, smallLightOffsets(), true);
}

std::vector<SmallLightCase> runSmallLightCases(vkrun::Device& device, const std::vector<double>& radii,
                                               const std::vector<int>& sizes,
                                               const std::vector<std::array<int, 2>>& offsets, bool near) {
    constexpr uint32_t kWidth = kLightsWidth, kHeight = kLightsHeight;
    constexpr double kBackground = kLightsBackground, kLight = 50.0;
    // The truth's centre: the light's share of the disc about its centre (64 x 64 points per pixel of the
    // square), at the light's value, the background's at the rest.
    const auto truthCentre = [&](int size, double radius) {
        const double half = 0.5 * size;
        constexpr int kSteps = 64;
        double covered = 0.0;
        for (int j = 0; j < size * kSteps; ++j)
            for (int i = 0; i < size * kSteps; ++i) {
                const double dx = -half + (i + 0.5) / kSteps, dy = -half + (j + 0.5) / kSteps;
                if (dx * dx + dy * dy <= radius * radius) covered += 1.0 / (kSteps * kSteps);
            }
        const double share = covered / (kPi * radius * radius);
        return kLight * share + kBackground * (1.0 - share);
    };
    std::vector<SmallLightCase> cases;
    for (bool float32 : {false, true}) {
        const vkrun::HostImage without = runSquareLights(device, {}, float32, 0, near);
        for (const auto& offset : offsets) {
            for (double radius : radii) {
                for (int size : sizes) {
                    const int x0 = int(kWidth) / 2 - size / 2 + offset[0], y0 = int(kHeight) / 2 - size / 2 + offset[1];
                    const vkrun::HostImage with =
                        runSquareLights(device, {{x0, y0, size, kLight, radius}}, float32, 0, near);
                    SmallLightCase light;
                    light.near = near;
                    light.size = size;
                    light.radius = radius;
                    light.offsetX = offset[0];
                    light.offsetY = offset[1];
                    light.float32 = float32;
                    double added = 0.0, momentX = 0.0, momentY = 0.0;
                    for (uint32_t y = 0; y < kHeight; ++y)
                        for (uint32_t x = 0; x < kWidth; ++x) {
                            const double change = double(with.at(x, y)[1]) - without.at(x, y)[1];
                            added += change;
                            momentX += change * (x + 0.5);
                            momentY += change * (y + 0.5);
                        }
                    light.energyRatio = added / (double(size) * size * (kLight - kBackground));
                    const double lightX = x0 + 0.5 * size, lightY = y0 + 0.5 * size;
                    light.discShift = std::hypot(momentX / added - lightX, momentY / added - lightY);
                    // The light's centre: between pixels for an even size; the mean of the 2 x 2 there.
                    const uint32_t span = size % 2 == 0 ? 2 : 1;
                    const uint32_t cx = uint32_t(x0 + (size - 1) / 2), cy = uint32_t(y0 + (size - 1) / 2);
                    double centre = 0.0;
                    for (uint32_t y = cy; y < cy + span; ++y)
                        for (uint32_t x = cx; x < cx + span; ++x) centre += with.at(x, y)[1];
                    light.centre = centre / (span * span);
                    light.truthCentre = truthCentre(size, radius);
                    cases.push_back(light);
                }
            }
        }
    }
    return cases;
}

namespace {
// The thin lens's figure of a light pair (LightPairCase::thinLensRatio). The dim light, nearer than the bright one,
// hides each point q of the bright light from the pixels p whose rays to q cross the dim light's depth inside the
// dim light: the point q + (p - q)(1 - rDim / rBright) lies in it. So its shadow from q is the dim square scaled by
// 1 / (1 - rDim / rBright) about q, and it takes q's share of the bright disc's level (the bright light's energy
// over pi rBright^2) wherever it lies inside q's disc, of radius rBright about q. Integrated over 8 x 8 points of
// each of the bright light's pixels and a grid of 1/32 px over the dim square.
double thinLensPairRatio(const SquareLight& bright, const SquareLight& dim, double background) {
    const double scale = 1.0 / (1.0 - dim.radius / bright.radius);
    const int sourceSteps = 8 * bright.size, shadowSteps = 32 * dim.size;
    const double sourceCell = double(bright.size) / sourceSteps, shadowCell = double(dim.size) / shadowSteps;
    double inside = 0.0;  // shadow area inside the source point's disc, summed over the source points
    for (int qj = 0; qj < sourceSteps; ++qj)
        for (int qi = 0; qi < sourceSteps; ++qi) {
            const double qx = bright.x0 + (qi + 0.5) * sourceCell, qy = bright.y0 + (qj + 0.5) * sourceCell;
            for (int j = 0; j < shadowSteps; ++j)
                for (int i = 0; i < shadowSteps; ++i) {
                    const double x = (dim.x0 + (i + 0.5) * shadowCell - qx) * scale;
                    const double y = (dim.y0 + (j + 0.5) * shadowCell - qy) * scale;
                    if (x * x + y * y <= bright.radius * bright.radius) inside += 1.0;
                }
        }
    inside *= shadowCell * shadowCell * scale * scale / (double(sourceSteps) * sourceSteps);
    const double brightLevel = bright.size * bright.size * (bright.value - background) /
                               (3.14159265358979323846 * bright.radius * bright.radius);
    // The rays the dim light hides from the bright one would have carried the bright light in place of the background.
    const double dimInput = dim.size * dim.size * (dim.value - background);
    return 1.0 - brightLevel * inside / dimInput;
}
}  // namespace

std::vector<LightPairCase> runLightPairCases(vkrun::Device& device) {
    return runLightPairCases(device, {std::begin(kLightPairDimRadii), std::end(kLightPairDimRadii)},
                             {std::begin(kLightPairDistances), std::end(kLightPairDistances)}, {true, false});
}

std::vector<LightPairCase> runLightPairCases(vkrun::Device& device, const std::vector<double>& dimRadii,
                                             const std::vector<int>& distances, const std::vector<bool>& ringMerges) {
    // The bright light: 3 x 3 px of 1000 at radius 18.2 px, as mid-lights' light 3 (value and radius); the
    // dim one: 2 x 2 px of 50, `distance` px to its left and 3 px higher.
    const SquareLight bright{80, 60, 3, 1000.0, 18.2};
    std::vector<LightPairCase> cases;
    for (bool ringMerge : ringMerges) {
        const uint32_t flags = ringMerge ? 0u : uint32_t(FFX_DOF_DISABLE_RING_MERGE);
        const vkrun::HostImage none = runSquareLights(device, {}, false, flags);
        const vkrun::HostImage brightOnly = runSquareLights(device, {bright}, false, flags);
        for (double dimRadius : dimRadii) {
            for (int distance : distances) {
                const SquareLight dim{bright.x0 - distance, bright.y0 - 3, 2, 50.0, dimRadius};
                const double dimInput = dim.size * dim.size * (dim.value - kLightsBackground);
                LightPairCase pair;
                pair.dimRadius = dimRadius;
                pair.distance = distance;
                pair.ringMerge = ringMerge;
                pair.thinLensRatio = thinLensPairRatio(bright, dim, kLightsBackground);
                pair.aloneRatio = addedGreen(runSquareLights(device, {dim}, false, flags), none) / dimInput;
                pair.besideRatio =
                    addedGreen(runSquareLights(device, {bright, dim}, false, flags), brightOnly) / dimInput;
                cases.push_back(pair);
            }
        }
    }
    return cases;
}

std::string LightPairCase::describe() const {
    std::ostringstream text;
    text << "dim light at radius " << dimRadius << " px, " << distance << " px from the bright one, ring merging "
         << (ringMerge ? "on" : "off") << ": adds " << aloneRatio << " of its input alone, " << besideRatio
         << " beside the bright light";
    return text.str();
}

LightProfile measureLightProfile(vkrun::Device& device, const std::string& scene, size_t emitter, int reach) {
    if (reach < 0) throw std::invalid_argument("a light profile's reach must not be negative");
    const SceneRender full = renderScene(scene);
    ref::RenderSettings renderSettings;
    renderSettings.lensSamples = kLensSamples;
    size_t index = 0;
    for (size_t i = 0; i < full.setup.scene.primitives.size(); ++i) {
        const ref::Primitive& light = full.setup.scene.primitives[i];
        if (!light.emitter || index++ != emitter) continue;
        ref::Scene without = full.setup.scene;
        without.primitives.erase(without.primitives.begin() + std::ptrdiff_t(i));
        const ref::PinholeImages pinhole = ref::renderPinhole(without, full.setup.camera, renderSettings);
        const io::ImageRGBA truthWithout = ref::renderThinLens(without, full.setup.camera, renderSettings).color;
        const LightFootprint footprint = lightFootprint(full.pinhole.color, pinhole.color);
        vkrun::RunSettings settings = sceneRunSettings(full);
        settings.forceFloat32 = true;
        const std::vector<float> oursWith = runOnPinhole(device, full.pinhole, settings);
        const std::vector<float> oursWithout = runOnPinhole(device, pinhole, settings);

        LightProfile profile;
        profile.scene = scene;
        profile.emitter = emitter;
        profile.radius = full.setup.camera.cocRadiusPixels(light.center.z);
        profile.centreX = footprint.centreX;
        profile.centreY = footprint.centreY;
        const int w = int(full.pinhole.color.width), h = int(full.pinhole.color.height);
        profile.x0 = std::clamp(int(footprint.centreX) - reach, 0, w - 1);
        profile.y0 = std::clamp(int(footprint.centreY) - reach, 0, h - 1);
        profile.width = std::min(int(footprint.centreX) + reach + 1, w) - profile.x0;
        profile.height = std::min(int(footprint.centreY) + reach + 1, h) - profile.y0;
        const auto added = [&](const std::vector<float>& a, const std::vector<float>& b, size_t pixel) {
            return double(a[4 * pixel]) + a[4 * pixel + 1] + a[4 * pixel + 2] -
                   (double(b[4 * pixel]) + b[4 * pixel + 1] + b[4 * pixel + 2]);
        };
        for (int y = profile.y0; y < profile.y0 + profile.height; ++y) {
            for (int x = profile.x0; x < profile.x0 + profile.width; ++x) {
                const size_t pixel = size_t(y) * size_t(w) + size_t(x);
                profile.inputAdded.push_back(added(full.pinhole.color.pixels, pinhole.color.pixels, pixel));
                profile.oursAdded.push_back(added(oursWith, oursWithout, pixel));
                profile.truthAdded.push_back(added(full.truth.pixels, truthWithout.pixels, pixel));
                profile.pixelRadius.push_back(full.setup.camera.cocRadiusPixels(full.pinhole.depth.pixels[pixel]));
            }
        }
        return profile;
    }
    throw std::invalid_argument("scene " + scene + " has " + std::to_string(index) + " emitters, no emitter " +
                                std::to_string(emitter));
}

}  // namespace ffxdof::quality
