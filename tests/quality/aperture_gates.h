// The aperture-shape gates of ffx-dof (issue 18), shared by the Vulkan tests (test_aperture.cpp) and the
// generator of docs/images/aperture and the figures of docs/aperture.md (aperture_report.cpp).
//
// Points: one bright point per shape on black, far behind or in front of the focus, through ffx-dof and
// through the thin lens with the same aperture (tools/reference, docs/aperture-reference.md). Each
// image's disc is the set of pixels brighter than half its own level; the discs must overlap (IoU),
// have the same area and the same orientation. Scenes: the highlight scenes rendered with a shaped
// aperture, gated like the circle's (quality_scenes.h) against the shaped truth.
#pragma once

#include "quality_scenes.h"

#include <string>
#include <vector>

namespace ffxdof::quality {

// The points' frame and lens samples (the truth of a lone emitter converges fast: it is sampled over
// its lens footprint).
constexpr uint32_t kPointWidth = 320;
constexpr uint32_t kPointHeight = 180;
constexpr uint32_t kPointLensSamples = 64;

// The bars of every point gate.
constexpr double kPointMinIou = 0.9;
constexpr double kPointMaxAreaError = 0.05;              // |area(ours) / area(truth) - 1|
constexpr double kPointMaxVertexAngleDegrees = 5.0;      // polygons: vertex direction, ours vs truth
constexpr double kPointMinElongation = 1.1;              // the axis is compared from this elongation on
constexpr double kPointMaxAxisDegrees = 5.0;             // principal axis, ours vs truth
constexpr double kPointMaxElongationError = 0.05;        // |elongation(ours) / elongation(truth) - 1|
constexpr double kPointMaxCentroidDistancePixels = 1.0;  // disc centroids, ours vs truth

// One aperture with the names the tests, files and docs use.
struct NamedAperture {
    std::string name;   // file stem and test section: lower case, no spaces
    std::string title;  // for people: "pentagon, rotated 20 degrees"
    ref::ApertureShape shape;
};

// One point: its aperture, its pixel and its CoC radius.
struct PointCase {
    NamedAperture aperture;
    uint32_t pixelX = 0, pixelY = 0;  // the point's pixel (the emitter is centred on its centre)
    double radiusPixels = 0.0;        // signed CoC radius, full-res px: > 0 in front of the focus (near)
    std::string name() const;         // "<aperture>-far" or "<aperture>-near"
    bool nearField() const { return radiusPixels > 0.0; }
};
const std::vector<PointCase>& pointCases();
// Black background, focus 3 m, the emitter at the point's pixel at 20 m (far) or 1.5 m (near), the
// aperture radius chosen for the point's CoC radius.
ref::SceneSetup makePointScene(const PointCase& point, uint32_t width = kPointWidth, uint32_t height = kPointHeight);

// The disc of one image: pixels whose luminance exceeds half the disc's level L, the level being the
// mean over the disc itself (the fixed point of L = energy / #(pixels > L / 2)).
struct DiscShape {
    metrics::Mask mask;
    size_t area = 0;       // pixels
    double level = 0.0;    // L
    double centerX = 0.0;  // the mask's centroid, pixels, y down (pixel centres at +0.5)
    double centerY = 0.0;
    double elongation = 1.0;   // sqrt(largest / smallest eigenvalue of the mask's second moments)
    double axisDegrees = 0.0;  // direction of the long axis, y up, counter-clockwise from +x, (-90, 90]
    // With N >= 3 blades: the direction (y up) of the phase of sum r^N e^{i N theta} over the mask,
    // over N: a vertex of the polygon, modulo 360 / N degrees. NaN otherwise.
    double vertexDegrees = 0.0;
};
DiscShape measureDisc(const io::ImageRGBA& image, uint32_t bladeCount);

// The direction of a vertex of the point's disc by the definition (docs/aperture-reference.md): S has
// side normals at the rotation + 360 k / N degrees, so vertices half a step further; a near-field disc
// is S turned by 180 degrees. Exact for the unsqueezed polygon (anamorphic ratio 1).
double expectedVertexDegrees(const PointCase& point);
// a - b wrapped into (-period / 2, period / 2].
double wrapDegrees(double difference, double period);

struct PointResult {
    PointCase point;
    SceneRender render;
    GateResult result;
    DiscShape truth, ours;
    double iou = 0.0;
    double areaError = 0.0;              // area(ours) / area(truth) - 1
    double vertexDifference = 0.0;       // degrees, ours - truth (wrapped); NaN without blades
    double truthVertexDifference = 0.0;  // degrees, truth - definition (wrapped); NaN without blades
    double axisDifference = 0.0;         // degrees, ours - truth (wrapped to 180); NaN when not elongated
    double elongationError = 0.0;        // elongation(ours) / elongation(truth) - 1
    double centroidDistance = 0.0;       // pixels

    bool iouOk() const { return iou >= kPointMinIou; }
    bool areaOk() const;
    bool orientationOk() const;  // vertex angle (polygons), axis and elongation (elongated discs)
    // Where the disc lies: its overlap with the truth's (IoU) and the centroids' distance.
    bool positionOk() const { return iouOk() && centroidDistance <= kPointMaxCentroidDistancePixels; }
    // What the disc is: its area and orientation.
    bool shapeOk() const { return areaOk() && orientationOk(); }
    bool ok() const { return positionOk() && shapeOk(); }
    std::string summary() const;  // every figure, one line per image
};
PointResult measurePoint(vkrun::Device& device, const PointCase& point);

// A scene gate with a shaped aperture: PSNR(ffx-dof, shaped truth) >= PSNR(input, shaped truth) + margin.
struct ShapedSceneGate {
    std::string scene;
    NamedAperture aperture;
    double psnrMarginDb;
    std::string rationale;  // why this margin, against the circle's (sceneGates)
};
const std::vector<ShapedSceneGate>& shapedSceneGates();

// The apertures of the pictures in docs/aperture.md: circle, hexagon, pentagon rotated, rounded
// hexagon, anamorphic 1.5, cat's eye 1.
const std::vector<NamedAperture>& pictureApertures();

}  // namespace ffxdof::quality
