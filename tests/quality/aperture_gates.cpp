#include "aperture_gates.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace ffxdof::quality {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The black wall behind a near point, as a fraction of the point's depth.
constexpr double kNearWallDistance = 0.035;

ref::ApertureShape shape(uint32_t blades, double rotationDegrees, double roundness, double anamorphic, double catEye) {
    ref::ApertureShape result;
    result.bladeCount = blades;
    result.bladeRotationDegrees = rotationDegrees;
    result.roundness = roundness;
    result.anamorphicRatio = anamorphic;
    result.catEye = catEye;
    return result;
}

const NamedAperture kCircle{"circle", "circle (round aperture, the reference)", {}};
const NamedAperture kHexagon{"hexagon", "hexagon (6 blades)", shape(6, 0.0, 0.0, 1.0, 0.0)};
const NamedAperture kPentagon{"pentagon", "pentagon (5 blades) rotated 20 degrees", shape(5, 20.0, 0.0, 1.0, 0.0)};
const NamedAperture kTriangle{"triangle", "triangle (3 blades) rotated 90 degrees", shape(3, 90.0, 0.0, 1.0, 0.0)};
const NamedAperture kRoundedHexagon{"rounded-hexagon", "hexagon, roundness 0.5", shape(6, 0.0, 0.5, 1.0, 0.0)};
const NamedAperture kAnamorphic{"anamorphic", "anamorphic 1.5 (round)", shape(0, 0.0, 0.0, 1.5, 0.0)};
const NamedAperture kCatEye{"cat-eye", "cat's eye 1 (round)", shape(0, 0.0, 0.0, 1.0, 1.0)};

}  // namespace

std::string PointCase::name() const { return aperture.name + (nearField() ? "-near" : "-far"); }

const std::vector<PointCase>& pointCases() {
    // Radii of 24 px (12 half-res px): large enough that a pixel of outline is a few per cent of the
    // area. The cat's-eye point sits toward the top-right corner (|q| = 0.68), where the disc is a lens.
    static const std::vector<PointCase> cases = {
        {kCircle, 160, 90, -24.0},  {kHexagon, 160, 90, -24.0}, {kPentagon, 160, 90, -24.0},
        {kPentagon, 160, 90, 24.0}, {kTriangle, 160, 90, 24.0}, {kAnamorphic, 160, 90, -24.0},
        {kCatEye, 272, 34, -20.0},
    };
    return cases;
}

ref::SceneSetup makePointScene(const PointCase& point, uint32_t width, uint32_t height) {
    ref::SceneSetup setup;
    setup.name = "point-" + point.name();
    ref::Camera& camera = setup.camera;
    camera.width = width;
    camera.height = height;
    camera.focalLength = 0.05;
    camera.sensorWidth = 0.036;
    camera.focusDistance = 3.0;
    camera.nearPlane = 0.1;
    camera.farPlane = 100.0;
    camera.aperture = point.aperture.shape;
    const double z = point.nearField() ? 1.5 : 20.0;
    const double f = camera.focalLength, focus = camera.focusDistance;
    // The aperture radius that gives the point its CoC radius (ref::Camera::cocRadiusPixels inverted).
    camera.apertureRadius =
        std::abs(point.radiusPixels) / camera.pixelsPerSensorUnit() * z * (focus - f) / (f * std::abs(focus - z));
    // Centred on the pixel's centre, so that the pinhole depth (traced through pixel centres) has it.
    const double halfWidth = 0.5 * camera.sensorWidth / camera.imageDistance();  // at depth 1
    const double halfHeight = halfWidth * height / width;
    const glm::dvec3 center((2.0 * (point.pixelX + 0.5) / width - 1.0) * halfWidth * z,
                            (1.0 - 2.0 * (point.pixelY + 0.5) / height) * halfHeight * z, z);
    const double pixelAtDepth = 2.0 * halfWidth * z / width;  // metres per pixel at the point's depth
    ref::Texture black;
    black.colorA = black.colorB = glm::vec3(0.0f);
    setup.scene.background = {0.0f, 0.0f, 0.0f};
    setup.scene.addEmitter(center, 0.4 * pixelAtDepth, {1.0f, 1.0f, 1.0f}, 50.0f);
    if (point.nearField()) {
        // A black wall just behind a near point (CoC 7% smaller: 22.4 px, 0.8 half-res px less):
        // ffx-dof's downsample keeps a lone bright pixel in a quad of another radius only in the far
        // field (ffxDofLightKeep), so a near point among pixels at the far plane would vanish from the
        // half-res image altogether. Quads whose radii lie within 1 half-res px are plainly averaged.
        const double wall = z * (1.0 + kNearWallDistance);
        setup.scene.addQuad({0.0, 0.0, wall}, {wall, 0.0, 0.0}, {0.0, wall, 0.0}, black);
    }
    std::ostringstream description;
    description << "one bright point " << (point.nearField() ? "in front of" : "behind") << " the focus on black, "
                << point.aperture.title << ", CoC radius " << std::abs(point.radiusPixels) << " px";
    setup.description = description.str();
    return setup;
}

DiscShape measureDisc(const io::ImageRGBA& image, uint32_t bladeCount) {
    const uint32_t w = image.width, h = image.height;
    std::vector<double> level(size_t(w) * h);
    double energy = 0.0, peak = 0.0;
    for (size_t i = 0; i < level.size(); ++i) {
        level[i] = std::max(0.0, metrics::luminance(&image.pixels[i * 4]));
        energy += level[i];
        peak = std::max(peak, level[i]);
    }
    DiscShape disc;
    disc.mask.assign(level.size(), 0);
    if (!(energy > 0.0)) return disc;
    const auto countAbove = [&](double threshold) {
        size_t count = 0;
        for (double value : level) count += value > threshold ? 1 : 0;
        return count;
    };
    // L = energy / #(pixels > L / 2) from below: the map is increasing in L, so the iteration climbs
    // to its smallest fixed point at or above the start (everything above 1% of the peak).
    double mean = energy / double(std::max<size_t>(1, countAbove(0.01 * peak)));
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double next = energy / double(std::max<size_t>(1, countAbove(0.5 * mean)));
        const bool settled = std::abs(next - mean) <= 1e-9 * mean;
        mean = next;
        if (settled) break;
    }
    disc.level = mean;
    double sumX = 0.0, sumY = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (!(level[i] > 0.5 * mean)) continue;
            disc.mask[i] = 1;
            ++disc.area;
            sumX += x + 0.5;
            sumY += y + 0.5;
        }
    }
    if (disc.area == 0) return disc;
    disc.centerX = sumX / double(disc.area);
    disc.centerY = sumY / double(disc.area);
    double sxx = 0.0, syy = 0.0, sxy = 0.0;
    std::complex<double> harmonic = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            if (!disc.mask[size_t(y) * w + x]) continue;
            const double dx = x + 0.5 - disc.centerX, dy = disc.centerY - (y + 0.5);  // y up
            sxx += dx * dx, syy += dy * dy, sxy += dx * dy;
            if (bladeCount >= 3) {
                std::complex<double> power = 1.0;
                for (uint32_t k = 0; k < bladeCount; ++k) power *= std::complex<double>(dx, dy);
                harmonic += power;
            }
        }
    }
    const double half = 0.5 * (sxx + syy), spread = std::hypot(0.5 * (sxx - syy), sxy);
    disc.elongation = std::sqrt((half + spread) / std::max(half - spread, 1e-12));
    disc.axisDegrees = 0.5 * std::atan2(2.0 * sxy, sxx - syy) * 180.0 / kPi;
    disc.vertexDegrees = bladeCount >= 3 ? std::arg(harmonic) / bladeCount * 180.0 / kPi : kNaN;
    return disc;
}

double wrapDegrees(double difference, double period) { return difference - period * std::round(difference / period); }

double expectedVertexDegrees(const PointCase& point) {
    const uint32_t n = point.aperture.shape.bladeCount;
    if (n < 3) return kNaN;
    const double period = 360.0 / n;
    return wrapDegrees(point.aperture.shape.bladeRotationDegrees + 0.5 * period + (point.nearField() ? 180.0 : 0.0),
                       period);
}

bool PointResult::areaOk() const { return std::abs(areaError) <= kPointMaxAreaError; }

bool PointResult::orientationOk() const {
    bool ok = true;
    if (!std::isnan(vertexDifference)) {
        ok = ok && std::abs(vertexDifference) <= kPointMaxVertexAngleDegrees &&
             std::abs(truthVertexDifference) <= kPointMaxVertexAngleDegrees;
    }
    if (!std::isnan(axisDifference)) {
        ok = ok && std::abs(axisDifference) <= kPointMaxAxisDegrees &&
             std::abs(elongationError) <= kPointMaxElongationError;
    }
    return ok;
}

std::string PointResult::summary() const {
    std::ostringstream out;
    const auto line = [&](const char* name, const DiscShape& disc) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "%s: level %.4g, area %zu px, centroid (%.2f, %.2f), elongation %.3f, axis %.1f deg, "
                      "vertex %.1f deg\n",
                      name, disc.level, disc.area, disc.centerX, disc.centerY, disc.elongation, disc.axisDegrees,
                      disc.vertexDegrees);
        out << text;
    };
    out << point.name() << " (" << point.aperture.title << ")\n";
    line("truth", truth);
    line("ffx-dof", ours);
    char text[256];
    std::snprintf(text, sizeof text,
                  "IoU %.4f, area error %+.2f%%, vertex ours - truth %.2f deg (truth - definition %.2f, "
                  "definition %.1f), axis ours - truth %.2f deg, elongation error %+.2f%%, centroid distance %.2f px\n",
                  iou, 100.0 * areaError, vertexDifference, truthVertexDifference, expectedVertexDegrees(point),
                  axisDifference, 100.0 * elongationError, centroidDistance);
    out << text;
    return out.str();
}

PointResult measurePoint(vkrun::Device& device, const PointCase& point) {
    PointResult r;
    r.point = point;
    r.render = renderSetup(makePointScene(point), kPointLensSamples);
    r.result = runGate(device, r.render);
    const uint32_t blades = point.aperture.shape.bladeCount;
    r.truth = measureDisc(r.render.truth, blades);
    r.ours = measureDisc(r.result.ours, blades);
    size_t both = 0, either = 0;
    for (size_t i = 0; i < r.truth.mask.size(); ++i) {
        both += r.truth.mask[i] && r.ours.mask[i] ? 1 : 0;
        either += r.truth.mask[i] || r.ours.mask[i] ? 1 : 0;
    }
    r.iou = either ? double(both) / double(either) : 0.0;
    r.areaError = r.truth.area ? double(r.ours.area) / double(r.truth.area) - 1.0 : kNaN;
    if (blades >= 3) {
        const double period = 360.0 / blades;
        r.vertexDifference = wrapDegrees(r.ours.vertexDegrees - r.truth.vertexDegrees, period);
        r.truthVertexDifference = wrapDegrees(r.truth.vertexDegrees - expectedVertexDegrees(point), period);
    } else {
        r.vertexDifference = r.truthVertexDifference = kNaN;
    }
    if (r.truth.elongation >= kPointMinElongation) {
        r.axisDifference = wrapDegrees(r.ours.axisDegrees - r.truth.axisDegrees, 180.0);
        r.elongationError = r.ours.elongation / r.truth.elongation - 1.0;
    } else {
        r.axisDifference = kNaN;
        r.elongationError = r.ours.elongation / r.truth.elongation - 1.0;
    }
    r.centroidDistance = std::hypot(r.ours.centerX - r.truth.centerX, r.ours.centerY - r.truth.centerY);
    return r;
}

const std::vector<ShapedSceneGate>& shapedSceneGates() {
    // The circle's margins (sceneGates) for every shape. Measured on lavapipe (docs/aperture.md has the
    // current figures), the shapes' gains are at most 1.0 dB below the circle's (mid-lights, cat's eye:
    // +6.78 dB against the circle's +7.77) and up to 1.3 dB above it (far-highlights, hexagon), so the
    // circle's bar leaves a shape 0.8 dB of headroom or more (the circle itself 1.8 and 2.5 dB).
    const auto circleMargin = [](const std::string& scene) {
        for (const SceneGate& gate : sceneGates()) {
            if (gate.scene == scene) return gate.psnrMarginDb;
        }
        // A shape's gate without the circle's margin would gate nothing.
        throw std::logic_error("aperture scene gate: " + scene + " has no circle gate in sceneGates()");
    };
    static const std::vector<ShapedSceneGate> gates = {
        {"far-highlights", kHexagon, circleMargin("far-highlights"),
         "the circle's margin: hexagonal discs of 8 px radius, nearly all of the input's error is the lights"},
        {"far-highlights", kAnamorphic, circleMargin("far-highlights"),
         "the circle's margin: the narrower discs are read with rings spaced by their width"},
        {"far-highlights", kCatEye, circleMargin("far-highlights"),
         "the circle's margin: the lights near the frame's edges become lenses"},
        {"mid-lights", kHexagon, circleMargin("mid-lights"),
         "the circle's margin: discs of 3 to 27 px over a 30 px background blur"},
        {"mid-lights", kAnamorphic, circleMargin("mid-lights"),
         "the circle's margin: tall discs over a tall background blur"},
        {"mid-lights", kCatEye, circleMargin("mid-lights"),
         "the circle's margin: lights spread over the whole frame, cat's eyes toward the corners"},
    };
    return gates;
}

const std::vector<NamedAperture>& pictureApertures() {
    static const std::vector<NamedAperture> apertures = {kCircle,         kHexagon,    kPentagon,
                                                         kRoundedHexagon, kAnamorphic, kCatEye};
    return apertures;
}

}  // namespace ffxdof::quality
