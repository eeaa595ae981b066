// The ground-truth reference renderer: a multi-threaded CPU ray tracer for procedural scenes of
// textured planes, boxes and spheres with unlit emissive shading (a surface's colour is its texture,
// so the only noise is lens sampling), plus tiny very bright spheres that make bokeh highlights.
//
// For one camera it renders the pinhole image (the input of a post-process DoF: 4x4 stratified
// sub-pixel samples through the pinhole), the depth of the pinhole ray through each pixel centre,
// and the thin-lens image (the truth: N lens samples per pixel, cycling over the same 4x4 sub-pixel
// positions, so that in focus the truth has exactly the input's anti-aliasing; use N a multiple of 16).
//
// Camera convention. View space looks down +Z (x right, y up); view depth Z is the distance along
// the optical axis in metres. The lens is a thin lens of focal length f focused at distance F: its
// image distance is v = f F / (F - f), so a pinhole at the lens centre with the sensor at distance v
// gives the in-focus image, and the horizontal field of view is 2 atan(sensorWidth / (2 v)). A
// thin-lens ray starts at a point of the aperture disc (radius A = f / (2 fstop)) and passes through
// the point where the pinhole ray of the same sensor position meets the plane Z = F. A point at
// depth Z then images to a disc of radius
//     A f |F - Z| / (Z (F - f))   sensor units,   times width / sensorWidth for pixels,
// the thin-lens formula of ffx_dof.h (tested in tests/reference).
//
// Aperture shape: the lens points are A (ux / s, uy) for the points u of a unit shape S (blades,
// roundness, cat's eye; see ApertureShape); every pixel averages over its own shaped aperture, so a
// shape changes the bokeh's outline but not the brightness of a uniform scene.
//
// Depth outputs: linear view depth Z in metres; device z of a D3D-style [0, 1] projection
// (clipZ = proj33 Z + proj34, clipW = proj43 Z = Z, device = clipZ / clipW), standard (near -> 0,
// far -> 1) and reversed (near -> 1, far -> 0). Pixels whose ray hits nothing get Z = far.
#pragma once

#include "ffx_dof_imageio.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace ffxdof::ref {

// The projection terms (row, column, 1-based) of a D3D-style projection matrix.
struct ProjectionTerms {
    double proj33 = 0.0;
    double proj34 = 0.0;
    double proj43 = 1.0;
    // device z for view depth z
    double deviceDepth(double viewDepth) const { return (proj33 * viewDepth + proj34) / (proj43 * viewDepth); }
    // view depth for device z (the inverse of deviceDepth)
    double viewDepth(double deviceDepth) const { return proj34 / (proj43 * deviceDepth - proj33); }
};

// The aperture's shape, in unit aperture space u = (ux, uy): x right, y up (view space of the lens
// plane). For a sensor position p the unit shape S(p) is the intersection of
//   - the unit disc |u| <= 1;
//   - with N = bladeCount >= 3 blades, the half-planes dot(n_k, u) <= a for k = 0..N-1, with
//     n_k = (cos(t + 2 pi k / N), sin(t + 2 pi k / N)), t = bladeRotationDegrees in radians and
//     a = cos(pi / N) + roundness (1 - cos(pi / N)): the regular N-gon inscribed in the unit circle
//     (roundness 0) bulging out to the circle (roundness 1). At rotation 0 a flat side faces +x;
//     positive rotations turn counter-clockwise;
//   - with catEye > 0, the disc |u - o| <= 1, o = catEye q, where q is the sensor position relative to
//     the frame centre, y up, over half the frame diagonal (|q| = 1 at the corners): the optical
//     vignetting that pinches off-axis bokeh into cat's eyes.
// The lens point (view space, metres) of u is A (ux / s, uy), A = apertureRadius, s = anamorphicRatio
// (so Camera::cocRadiusPixels is the blur's vertical radius; horizontally it is divided by s).
// A point far behind the focus plane images to S squeezed horizontally by 1 / s (y up on screen); a
// point in front of it to the same shape turned by 180 degrees. The defaults are the round aperture.
struct ApertureShape {
    uint32_t bladeCount = 0;            // 0: round; otherwise 3..16
    double bladeRotationDegrees = 0.0;  // finite; counter-clockwise with y up
    double roundness = 0.0;             // 0..1: 0 straight blades, 1 the circle
    double anamorphicRatio = 1.0;       // s, 0.5..2: s > 1 makes the aperture s times taller than wide
    double catEye = 0.0;                // 0..1: 0 off, 1 the strongest optical vignetting

    // Throws std::invalid_argument naming the first field (aperture.<name>) that is out of range.
    void validate() const;
};

// The geometry of an ApertureShape's unit shape S, the one definition that the renderer and the tests
// use (side normals precomputed, so the inside test is cheap enough per lens sample).
class UnitAperture {
public:
    explicit UnitAperture(const ApertureShape& shape);  // validates the shape

    const ApertureShape& shape() const { return shape_; }
    // True when S is the unit disc at every sensor position (no blades or fully round ones, no cat's
    // eye); the anamorphic ratio does not enter S.
    bool isDisc() const;
    // o = catEye q for the continuous pixel position (px, py) (x right, y down, as pixel centres are
    // x + 0.5, y + 0.5) of a width x height frame.
    glm::dvec2 catEyeCenter(double px, double py, uint32_t width, uint32_t height) const;
    // Whether point lies in radius * S for the cat's-eye centre o. Radius 1 tests u itself; the
    // renderer tests a lens point L as (s Lx, Ly) with radius A, which keeps the round aperture's test
    // bit for bit the one from before shapes.
    bool contains(glm::dvec2 point, glm::dvec2 catEyeCenter = glm::dvec2(0.0), double radius = 1.0) const;
    // The row of S at height uy: the interval [left, right] of ux, S being convex. False (and the
    // outputs unspecified) when the row misses S.
    bool rowInterval(double uy, glm::dvec2 catEyeCenter, double& left, double& right) const;
    // The area of S: exact without a cat's-eye offset (o = 0), otherwise the integral of the row
    // lengths (relative error well below 1e-4). The lens area is A^2 area(S) / s.
    double area(glm::dvec2 catEyeCenter = glm::dvec2(0.0)) const;
    // The lens point A (ux / s, uy) of u.
    glm::dvec2 lensPoint(glm::dvec2 u, double apertureRadius) const {
        return {apertureRadius * u.x / shape_.anamorphicRatio, apertureRadius * u.y};
    }

private:
    ApertureShape shape_;
    std::vector<glm::dvec2> normals_;  // the blades' side normals n_k
    double inradius_ = 1.0;            // a
};

struct Camera {
    uint32_t width = 0;   // pixels
    uint32_t height = 0;  // pixels
    glm::dvec3 position{0.0};
    glm::dvec3 target{0.0, 0.0, 1.0};  // any point on the optical axis in front of the camera
    glm::dvec3 up{0.0, 1.0, 0.0};
    double focalLength = 0.05;    // f, metres
    double sensorWidth = 0.036;   // metres (36 mm: full frame)
    double focusDistance = 5.0;   // F, metres along the optical axis, > focalLength
    double apertureRadius = 0.0;  // A, metres; focalLength / (2 fstop)
    double nearPlane = 0.1;       // metres, for the device depth
    double farPlane = 1000.0;     // metres
    ApertureShape aperture;       // the default is the round aperture

    double fstop() const { return apertureRadius > 0.0 ? focalLength / (2.0 * apertureRadius) : 0.0; }
    void setFstop(double fstop) { apertureRadius = focalLength / (2.0 * fstop); }
    // v = f F / (F - f): the sensor distance that focuses the plane Z = F.
    double imageDistance() const { return focalLength * focusDistance / (focusDistance - focalLength); }
    double sensorHeight() const { return sensorWidth * height / width; }
    double verticalFovRadians() const;
    // Sets the focal length so that the vertical field of view is fovRadians at the current focus.
    void setVerticalFov(double fovRadians);
    double pixelsPerSensorUnit() const { return width / sensorWidth; }
    // Signed CoC radius in full-resolution pixels of a point at view depth Z: positive in front of
    // the focus plane (near field), negative behind it (far field), the sign convention of ffx_dof.h.
    double cocRadiusPixels(double viewDepth) const;
    ProjectionTerms projection() const;          // standard: near -> 0, far -> 1
    ProjectionTerms reversedProjection() const;  // reversed: near -> 1, far -> 0

    // Throws std::invalid_argument naming the first field that is out of range (aperture included).
    void validate() const;
};

// camera.json: every field above (the shape as an "aperture" object: bladeCount,
// bladeRotationDegrees, roundness, anamorphicRatio, catEye; optional when reading, absent fields
// take the defaults), the derived fstop, imageDistance, verticalFovDegrees,
// pixelsPerSensorUnit and both projections ("projection", "projectionReversed": proj33, proj34,
// proj43). cameraFromJson reads the fields of Camera (the derived ones are ignored) and validates.
nlohmann::json cameraToJson(const Camera& camera);
Camera cameraFromJson(const nlohmann::json& json);
Camera readCameraJson(const std::string& path);  // throws io::IoError on a missing or invalid file
void writeCameraJson(const std::string& path, const Camera& camera);

// ---- scenes ------------------------------------------------------------------------------------

// A procedural texture over world-unit surface coordinates.
struct Texture {
    enum class Kind { Solid, Checker, Stripes, Noise, Bricks };
    Kind kind = Kind::Solid;
    glm::vec3 colorA{0.5f};
    glm::vec3 colorB{0.5f};
    float scale = 1.0f;  // metres per pattern period
    glm::vec3 evaluate(glm::dvec2 uv) const;
};

struct Primitive {
    enum class Kind { Sphere, Quad, Box };
    Kind kind = Kind::Sphere;
    // Sphere: centre, radius. Quad: centre, edge half-vectors axisU and axisV. Box: centre,
    // half-extents (axis-aligned).
    glm::dvec3 center{0.0};
    double radius = 0.0;
    glm::dvec3 axisU{0.0}, axisV{0.0};
    glm::dvec3 halfExtents{0.0};
    Texture texture;
    // An emitter (only spheres may be) adds emission * texture colour; the thin-lens renderer
    // samples its lens footprint directly so highlights converge without fireflies.
    bool emitter = false;
    float emission = 1.0f;
};

struct Scene {
    std::vector<Primitive> primitives;
    glm::vec3 background{0.0f};  // radiance of rays that hit nothing

    Primitive& addSphere(glm::dvec3 center, double radius, Texture texture);
    Primitive& addEmitter(glm::dvec3 center, double radius, glm::vec3 color, float emission);
    Primitive& addQuad(glm::dvec3 center, glm::dvec3 axisU, glm::dvec3 axisV, Texture texture);
    Primitive& addBox(glm::dvec3 center, glm::dvec3 halfExtents, Texture texture);
};

struct SceneSetup {
    std::string name;
    std::string description;
    Scene scene;
    Camera camera;
};

struct SceneInfo {
    std::string name;
    std::string description;
};
// The built-in scenes, in a stable order.
std::vector<SceneInfo> listScenes();
// Builds a built-in scene for the given resolution (the lens is chosen per scene so that the blur, in
// pixels, scales with the width). Throws std::invalid_argument for an unknown name (listing the names).
SceneSetup makeScene(const std::string& name, uint32_t width, uint32_t height);

// ---- rendering ---------------------------------------------------------------------------------

struct RenderSettings {
    uint32_t lensSamples = 64;  // thin-lens samples per pixel, >= 1
    uint32_t threads = 0;       // 0: std::thread::hardware_concurrency()
    uint32_t seed = 1;          // decorrelates the per-pixel sample rotations
};

struct PinholeImages {
    io::ImageRGBA color;             // 4x4 stratified sub-pixel samples, box filter
    io::ImageR depth;                // linear view depth Z of the pixel-centre ray, metres
    io::ImageR deviceDepth;          // standard projection
    io::ImageR deviceDepthReversed;  // reversed projection
};

struct ThinLensImage {
    io::ImageRGBA color;
    // RMS over all pixels and RGB channels of (estimate from the first N/2 samples - estimate from
    // all N), on values clamped to [0, 1] so highlights do not dominate: a convergence figure that
    // falls roughly as 1/sqrt(N).
    double convergenceRms = 0.0;
};

PinholeImages renderPinhole(const Scene& scene, const Camera& camera, const RenderSettings& settings = {});
ThinLensImage renderThinLens(const Scene& scene, const Camera& camera, const RenderSettings& settings = {});

}  // namespace ffxdof::ref
