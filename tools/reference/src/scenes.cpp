#include "ffx_dof_reference.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace ffxdof::ref {
namespace {

uint32_t latticeHash(int32_t x, int32_t y) {
    uint32_t h = uint32_t(x) * 0x8da6b343U ^ uint32_t(y) * 0xd8163841U;
    h ^= h >> 15;
    h *= 0x2c1b3c6dU;
    h ^= h >> 12;
    h *= 0x297a2d39U;
    h ^= h >> 15;
    return h;
}

float latticeValue(int32_t x, int32_t y) { return (latticeHash(x, y) >> 8) * (1.0f / 16777216.0f); }

// Smoothly interpolated value noise in [0, 1].
float valueNoise(double u, double v) {
    const double fu = std::floor(u), fv = std::floor(v);
    const int32_t iu = int32_t(fu), iv = int32_t(fv);
    const auto fade = [](double t) { return float(t * t * (3.0 - 2.0 * t)); };
    const float su = fade(u - fu), sv = fade(v - fv);
    const float top = glm::mix(latticeValue(iu, iv), latticeValue(iu + 1, iv), su);
    const float bottom = glm::mix(latticeValue(iu, iv + 1), latticeValue(iu + 1, iv + 1), su);
    return glm::mix(top, bottom, sv);
}

int parity(double value) { return int(std::floor(value)) & 1; }

Texture solid(glm::vec3 color) { return {Texture::Kind::Solid, color, color, 1.0f}; }
Texture checker(glm::vec3 a, glm::vec3 b, float size) { return {Texture::Kind::Checker, a, b, size}; }
Texture noise(glm::vec3 a, glm::vec3 b, float size) { return {Texture::Kind::Noise, a, b, size}; }
Texture bricks(glm::vec3 brick, glm::vec3 mortar, float size) { return {Texture::Kind::Bricks, brick, mortar, size}; }
Texture stripes(glm::vec3 a, glm::vec3 b, float size) { return {Texture::Kind::Stripes, a, b, size}; }

// Aperture radius that gives a CoC of radiusPixels (full-resolution pixels) at view depth Z.
void setApertureForBlur(Camera& camera, double viewDepth, double radiusPixels) {
    const double f = camera.focalLength, focus = camera.focusDistance;
    camera.apertureRadius =
        radiusPixels / camera.pixelsPerSensorUnit() * viewDepth * (focus - f) / (f * std::abs(focus - viewDepth));
}

// A camera at the origin looking down +Z with a 36 mm wide sensor.
Camera baseCamera(uint32_t width, uint32_t height, double focalLength, double focus) {
    Camera camera;
    camera.width = width;
    camera.height = height;
    camera.focalLength = focalLength;
    camera.sensorWidth = 0.036;
    camera.focusDistance = focus;
    camera.nearPlane = 0.1;
    camera.farPlane = 100.0;
    return camera;
}

// Emitter radius (metres) whose pinhole image has the given radius in pixels at depth Z.
double emitterRadiusForPixels(const Camera& camera, double viewDepth, double pixels) {
    return pixels / camera.pixelsPerSensorUnit() * viewDepth / camera.imageDistance();
}

// The point at view depth Z that the pinhole camera sees at the centre of pixel (px, py) (each rounded down to its
// pixel). An emitter placed there is in the depth buffer, which is traced through pixel centres only: between
// them a light would be missing from it (blurred with the background's radius), a mismatch of the input, not of
// the effect.
// Half the width the pinhole camera sees at view depth 1.
double halfWidthAtUnitDepth(const Camera& camera) { return 0.5 * camera.sensorWidth / camera.imageDistance(); }

glm::dvec3 pixelCentreAt(const Camera& camera, double px, double py, double z) {
    const double halfWidth = halfWidthAtUnitDepth(camera);
    const double halfHeight = halfWidth * camera.height / camera.width;
    return glm::dvec3((2.0 * (std::floor(px) + 0.5) / camera.width - 1.0) * halfWidth * z,
                      (1.0 - 2.0 * (std::floor(py) + 0.5) / camera.height) * halfHeight * z, z);
}

const glm::dvec3 kRight{1, 0, 0}, kUp{0, 1, 0}, kForward{0, 0, 1};
// The tints of the highlight scenes' lights (warm, cool, red, green), cycled.
const glm::vec3 kLightColors[] = {{1.0f, 0.8f, 0.5f}, {0.6f, 0.8f, 1.0f}, {1.0f, 0.4f, 0.3f}, {0.7f, 1.0f, 0.6f}};

SceneSetup nearObject(uint32_t width, uint32_t height) {
    SceneSetup setup{"near-object",
                     "a near sphere, strongly blurred, over a sharp midground of boxes at the focus",
                     {},
                     baseCamera(width, height, 0.035, 4.0)};
    Scene& scene = setup.scene;
    scene.background = {0.55f, 0.65f, 0.8f};
    scene.addQuad({0, -1, 10}, kRight * 20.0, kForward * 10.0, checker({0.3f, 0.3f, 0.32f}, {0.6f, 0.58f, 0.5f}, 0.5f));
    scene.addQuad({0, 1.5, 9}, kRight * 12.0, kUp * 2.5, bricks({0.55f, 0.25f, 0.18f}, {0.8f, 0.8f, 0.75f}, 0.4f));
    scene.addBox({-0.9, -0.5, 4.0}, {0.4, 0.5, 0.4}, checker({0.9f, 0.9f, 0.9f}, {0.1f, 0.2f, 0.6f}, 0.1f));
    scene.addBox({0.6, -0.4, 4.2}, {0.35, 0.6, 0.3}, stripes({0.95f, 0.8f, 0.2f}, {0.15f, 0.1f, 0.1f}, 0.08f));
    scene.addSphere({0.2, 0.35, 4.1}, 0.3, noise({0.1f, 0.6f, 0.2f}, {0.9f, 0.95f, 0.7f}, 0.05f));
    scene.addSphere({-0.35, -0.15, 1.3}, 0.28, checker({0.85f, 0.2f, 0.15f}, {0.95f, 0.9f, 0.85f}, 0.07f));
    setApertureForBlur(setup.camera, 1.3, std::max(4.0, 0.03 * width));
    return setup;
}

SceneSetup farHighlights(uint32_t width, uint32_t height) {
    SceneSetup setup{"far-highlights",
                     "bright point lights far behind a subject in focus at 2 m",
                     {},
                     baseCamera(width, height, 0.05, 2.0)};
    Camera& camera = setup.camera;
    Scene& scene = setup.scene;
    scene.background = {0.02f, 0.02f, 0.04f};
    scene.addQuad({0, 0, 40}, kRight * 40.0, kUp * 30.0, noise({0.02f, 0.02f, 0.05f}, {0.08f, 0.07f, 0.1f}, 1.0f));
    scene.addBox({0.0, -0.35, 2.0}, {0.2, 0.25, 0.2}, checker({0.9f, 0.85f, 0.8f}, {0.2f, 0.3f, 0.5f}, 0.05f));
    scene.addSphere({0.25, 0.1, 2.1}, 0.12, checker({0.9f, 0.5f, 0.1f}, {0.1f, 0.1f, 0.1f}, 0.03f));
    for (int i = 0; i < 14; ++i) {
        const double z = 18.0 + 1.5 * (i % 5);
        const double x = -6.0 + 12.0 * (i / 13.0) + 0.4 * std::sin(i * 2.3);
        const double y = -1.5 + 3.5 * latticeValue(i, 7);
        scene.addEmitter({x, y, z}, emitterRadiusForPixels(camera, z, 1.0), kLightColors[i % 4],
                         150.0f + 50.0f * (i % 3));
    }
    setApertureForBlur(camera, 20.0, std::max(4.0, 0.025 * width));
    return setup;
}

// Issue 17: small lights nearer than a much farther background, the case where a light used to keep
// its sharp core on top of its disc (the ring occlusion) or vanish (the bilateral downsample).
SceneSetup midLights(uint32_t width, uint32_t height) {
    SceneSetup setup{"mid-lights",
                     "lights of 1 to 4 px at 2.2 to 15 m in front of a background at 40 m, focus at 2 m, two "
                     "partly behind a sharp box",
                     {},
                     baseCamera(width, height, 0.05, 2.0)};
    Camera& camera = setup.camera;
    Scene& scene = setup.scene;
    scene.background = {0.02f, 0.02f, 0.03f};
    scene.addQuad({0, 0, 40}, kRight * 40.0, kUp * 30.0, noise({0.03f, 0.03f, 0.06f}, {0.12f, 0.1f, 0.14f}, 1.5f));
    scene.addBox({0.12, -0.05, 2.0}, {0.08, 0.12, 0.05}, checker({0.9f, 0.85f, 0.8f}, {0.2f, 0.3f, 0.5f}, 0.04f));
    // Depths give radii of about 3 to 27 px against the background's 30 (the aperture below); the
    // lights' pinhole radii are 0.5 to 2 px, their values up to 1000. Each light is centred on a pixel
    // centre (pixelCentreAt).
    const double depths[] = {2.2, 2.6, 3.5, 5.0, 8.0, 15.0};
    for (int i = 0; i < 12; ++i) {
        const double z = depths[i % 6];
        const double px = width * (0.1 + 0.8 * (i / 11.0)), py = height * (0.2 + 0.6 * latticeValue(i, 3));
        const double pixels = 0.5 + 0.5 * (i % 4);
        const float emission = i % 3 == 0 ? 1000.0f : (i % 3 == 1 ? 200.0f : 40.0f);
        scene.addEmitter(pixelCentreAt(camera, px, py, z), emitterRadiusForPixels(camera, z, pixels),
                         kLightColors[i % 4], emission);
    }
    // Two lights whose discs are partly hidden by the box: centred on the pixel just right of its
    // right edge, 1.5 px wide, one at 3 m and one at 10 m.
    const double edgePixel = (0.20 / (halfWidthAtUnitDepth(camera) * 1.95) + 1.0) * 0.5 * width;
    scene.addEmitter(pixelCentreAt(camera, edgePixel + 1.0, 0.5 * height, 3.0),
                     emitterRadiusForPixels(camera, 3.0, 1.5), kLightColors[0], 300.0f);
    scene.addEmitter(pixelCentreAt(camera, edgePixel + 1.0, 0.6 * height, 10.0),
                     emitterRadiusForPixels(camera, 10.0, 1.5), kLightColors[1], 300.0f);
    setApertureForBlur(camera, 40.0, std::max(8.0, 0.09 * width));
    return setup;
}

SceneSetup fence(uint32_t width, uint32_t height) {
    SceneSetup setup{"fence",
                     "thin fence posts close to the camera in front of a sharp brick wall (partial occlusion)",
                     {},
                     baseCamera(width, height, 0.035, 3.0)};
    Scene& scene = setup.scene;
    scene.background = {0.5f, 0.6f, 0.75f};
    scene.addQuad({0, 0, 3.0}, kRight * 6.0, kUp * 4.0, bricks({0.6f, 0.3f, 0.2f}, {0.85f, 0.85f, 0.8f}, 0.25f));
    const Texture paint = stripes({0.08f, 0.22f, 0.1f}, {0.12f, 0.3f, 0.14f}, 0.01f);
    for (int i = -6; i <= 6; ++i) scene.addBox({0.12 * i, 0.0, 0.7}, {0.012, 1.0, 0.012}, paint);
    scene.addBox({0.0, -0.2, 0.68}, {1.0, 0.01, 0.01}, paint);
    setApertureForBlur(setup.camera, 0.7, std::max(4.0, 0.025 * width));
    return setup;
}

SceneSetup busyBackground(uint32_t width, uint32_t height) {
    SceneSetup setup{"busy-background",
                     "a sharp object at 2 m in front of a busy background blurred by at least 40 pixels",
                     {},
                     baseCamera(width, height, 0.05, 2.0)};
    Scene& scene = setup.scene;
    scene.addQuad({0, 0, 12}, kRight * 12.0, kUp * 8.0, noise({0.05f, 0.1f, 0.3f}, {1.0f, 0.9f, 0.4f}, 0.6f));
    scene.addSphere({-0.1, 0.0, 2.0}, 0.22, checker({0.95f, 0.95f, 0.95f}, {0.8f, 0.1f, 0.1f}, 0.05f));
    scene.addBox({0.3, -0.2, 2.05}, {0.08, 0.3, 0.08}, stripes({0.1f, 0.1f, 0.1f}, {0.2f, 0.8f, 0.3f}, 0.03f));
    setApertureForBlur(setup.camera, 12.0, std::max(40.0, 0.045 * width));
    return setup;
}

SceneSetup floorScene(uint32_t width, uint32_t height) {
    SceneSetup setup{"floor",
                     "a checker floor receding from 0.6 m to 60 m, focus at 4 m",
                     {},
                     baseCamera(width, height, 0.035, 4.0)};
    Camera& camera = setup.camera;
    camera.position = {0.0, 1.0, 0.0};
    camera.target = {0.0, 0.55, 4.0};
    Scene& scene = setup.scene;
    scene.background = {0.6f, 0.7f, 0.9f};
    scene.addQuad({0, 0, 30}, kRight * 30.0, kForward * 30.0,
                  checker({0.15f, 0.15f, 0.15f}, {0.85f, 0.8f, 0.7f}, 0.5f));
    scene.addSphere({-0.8, 0.3, 2.0}, 0.3, noise({0.2f, 0.3f, 0.8f}, {0.9f, 0.9f, 1.0f}, 0.05f));
    scene.addSphere({0.6, 0.4, 4.5}, 0.4, checker({0.9f, 0.3f, 0.1f}, {1.0f, 0.9f, 0.6f}, 0.1f));
    scene.addSphere({-1.5, 0.8, 12.0}, 0.8, stripes({0.3f, 0.7f, 0.3f}, {0.9f, 0.9f, 0.6f}, 0.2f));
    setApertureForBlur(camera, 1.2, std::max(4.0, 0.03 * width));
    return setup;
}

SceneSetup singlePoint(uint32_t width, uint32_t height) {
    SceneSetup setup{"point",
                     "one bright point far behind the focus on black: a single bokeh disc",
                     {},
                     baseCamera(width, height, 0.05, 3.0)};
    Camera& camera = setup.camera;
    const double z = 20.0;
    setApertureForBlur(camera, z, std::max(6.0, 0.03 * width));
    // Centred on a pixel centre (half a pixel right of and below the image centre): the pinhole depth
    // is traced through pixel centres only, so a point between four centres would be missing from the
    // depth buffer, and the effect would blur it with the background's radius instead of its own.
    const double halfPixel = emitterRadiusForPixels(camera, z, 0.5);
    setup.scene.addEmitter({halfPixel, -halfPixel, z}, emitterRadiusForPixels(camera, z, 0.4), {1.0f, 1.0f, 1.0f},
                           50.0f);
    return setup;
}

// A far field above display white (2 to 8) behind thin bars in focus: the far layer must not bleed into the
// bars, and the bright field around them is where a half-resolution far layer shows its rims.
SceneSetup brightWindow(uint32_t width, uint32_t height) {
    SceneSetup setup{"bright-window",
                     "dark window bars in focus at 2 m against a bright far sky (values 2 to 8)",
                     {},
                     baseCamera(width, height, 0.05, 2.0)};
    Scene& scene = setup.scene;
    scene.background = {3.0f, 3.2f, 3.6f};
    scene.addQuad({0, 0, 30}, kRight * 40.0, kUp * 30.0, noise({1.5f, 1.8f, 2.4f}, {7.0f, 6.5f, 5.0f}, 1.2f));
    scene.addQuad({0, -3.5, 28}, kRight * 40.0, kUp * 3.0, noise({0.05f, 0.08f, 0.04f}, {0.2f, 0.3f, 0.1f}, 0.8f));
    const Texture wood = stripes({0.25f, 0.15f, 0.08f}, {0.35f, 0.22f, 0.12f}, 0.02f);
    for (int i = -2; i <= 2; ++i) scene.addBox({0.25 * i, 0.0, 2.0}, {0.015, 1.0, 0.015}, wood);
    scene.addBox({0.0, 0.1, 2.0}, {1.0, 0.015, 0.015}, wood);
    scene.addSphere({0.1, -0.25, 1.95}, 0.08, checker({0.9f, 0.9f, 0.85f}, {0.2f, 0.2f, 0.6f}, 0.03f));
    setApertureForBlur(setup.camera, 30.0, std::max(8.0, 0.04 * width));
    return setup;
}

// A row of leaves (thin boxes) in front of the camera: leaf i lies at depth zFirst + i zStep, at x = xFirst + i xStep
// + 0.03 sin(i wobble) and y = yFirst + ySpread latticeValue(i, latticeSeed), with half sizes (width + widthStep (i
// mod 3), height + heightStep (i mod 2), 0.01).
struct LeafRow {
    int count = 0;
    double zFirst = 0.0, zStep = 0.0;
    double xFirst = 0.0, xStep = 0.0, wobble = 0.0;
    double yFirst = 0.0, ySpread = 0.0;
    int latticeSeed = 0;
    double width = 0.0, widthStep = 0.0, height = 0.0, heightStep = 0.0;
};
void addLeaves(Scene& scene, const LeafRow& row, const Texture& texture) {
    for (int i = 0; i < row.count; ++i) {
        const double z = row.zFirst + row.zStep * i;
        const double x = row.xFirst + row.xStep * i + 0.03 * std::sin(i * row.wobble);
        const double y = row.yFirst + row.ySpread * latticeValue(i, row.latticeSeed);
        scene.addBox({x, y, z}, {row.width + row.widthStep * (i % 3), row.height + row.heightStep * (i % 2), 0.01},
                     texture);
    }
}

// Small near objects (leaves) blurred 2.7 to 6.5 times as much as the far field behind them (26 to 63 px against
// 9.6 at 320 x 180), nothing but a small box in focus: faint veils whose pinhole silhouettes must not show
// (issue 17's thin near objects, over a far field rather than an in-focus wall).
SceneSetup nearAndFar(uint32_t width, uint32_t height) {
    SceneSetup setup{"near-and-far",
                     "leaves at 0.6 to 1.2 m and a busy far wall at 30 m, focus at 4 m on two small boxes",
                     {},
                     baseCamera(width, height, 0.035, 4.0)};
    Scene& scene = setup.scene;
    scene.background = {0.5f, 0.6f, 0.8f};
    scene.addQuad({0, 0, 30}, kRight * 40.0, kUp * 30.0, noise({0.1f, 0.2f, 0.4f}, {1.0f, 0.85f, 0.5f}, 0.7f));
    scene.addBox({0.3, -0.1, 4.0}, {0.15, 0.2, 0.15}, checker({0.9f, 0.9f, 0.9f}, {0.7f, 0.1f, 0.1f}, 0.05f));
    // In focus and out of every leaf's reach, for the in-focus gate.
    scene.addBox({1.5, 0.2, 4.0}, {0.15, 0.25, 0.15}, stripes({0.9f, 0.8f, 0.2f}, {0.1f, 0.1f, 0.3f}, 0.04f));
    // Inside the frame (its half width is 0.51 z; beyond it the thin lens sees what the input does not) and in its
    // left half.
    addLeaves(scene, {9, 0.6, 0.075, -0.26, 0.03, 1.7, -0.25, 0.3, 5, 0.012, 0.01, 0.05, 0.03},
              noise({0.05f, 0.3f, 0.05f}, {0.3f, 0.6f, 0.2f}, 0.02f));
    setApertureForBlur(setup.camera, 30.0, std::max(6.0, 0.03 * width));
    return setup;
}

SceneSetup farBranches(uint32_t width, uint32_t height) {
    SceneSetup setup{"far-branches",
                     "thin dark branches at 7 m against a bright sky at 60 m, focus at 2 m on a small sphere",
                     {},
                     baseCamera(width, height, 0.05, 2.0)};
    Scene& scene = setup.scene;
    scene.background = {1.6f, 1.8f, 2.2f};
    scene.addQuad({0, 0, 60}, kRight * 80.0, kUp * 60.0, noise({0.8f, 1.0f, 1.4f}, {2.5f, 2.6f, 3.0f}, 3.0f));
    const Texture bark = noise({0.04f, 0.03f, 0.02f}, {0.12f, 0.09f, 0.06f}, 0.05f);
    const double widths[] = {0.015, 0.03, 0.06, 0.12};
    for (int i = 0; i < 4; ++i) {
        scene.addBox({-1.6 + 0.9 * i, 0.2, 7.0}, {widths[i] * 0.5, 3.0, 0.05}, bark);
        scene.addBox({0.0, -1.2 + 0.7 * i, 7.2}, {3.0, widths[3 - i] * 0.5, 0.05}, bark);
    }
    scene.addSphere({0.15, -0.1, 2.0}, 0.1, checker({0.9f, 0.9f, 0.85f}, {0.2f, 0.3f, 0.7f}, 0.03f));
    setApertureForBlur(setup.camera, 60.0, std::max(8.0, 0.05 * width));
    return setup;
}

// Lights far away seen through far branches: a light's disc crossed by a branch in front of it shows the branch's
// blurred shadow where the thin lens's rays to the light pass the branch, and nowhere else.
SceneSetup lightsThroughBranches(uint32_t width, uint32_t height) {
    SceneSetup setup{"lights-through-branches",
                     "lights of 1 to 3 px at 25 and 50 m behind dark branches at 6 m, dusk sky at 60 m, focus at 2 m",
                     {},
                     baseCamera(width, height, 0.05, 2.0)};
    Camera& camera = setup.camera;
    Scene& scene = setup.scene;
    scene.background = {0.05f, 0.06f, 0.12f};
    scene.addQuad({0, 0, 60}, kRight * 80.0, kUp * 60.0, noise({0.03f, 0.04f, 0.09f}, {0.12f, 0.1f, 0.2f}, 4.0f));
    const Texture bark = noise({0.02f, 0.015f, 0.01f}, {0.06f, 0.045f, 0.03f}, 0.05f);
    const double widths[] = {0.02, 0.04, 0.08};
    for (int i = 0; i < 3; ++i) {
        scene.addBox({-1.2 + 1.1 * i, 0.0, 6.0}, {widths[i] * 0.5, 3.0, 0.05}, bark);
        scene.addBox({0.0, -0.6 + 0.6 * i, 6.1}, {3.0, widths[2 - i] * 0.5, 0.05}, bark);
    }
    for (int i = 0; i < 14; ++i) {
        const double z = i % 2 == 0 ? 50.0 : 25.0;
        const double px = width * (0.08 + 0.84 * (i / 13.0)), py = height * (0.15 + 0.7 * latticeValue(i, 7));
        const double pixels = 0.5 + 0.5 * (i % 3);
        const float emission = i % 3 == 0 ? 500.0f : (i % 3 == 1 ? 100.0f : 30.0f);
        scene.addEmitter(pixelCentreAt(camera, px, py, z), emitterRadiusForPixels(camera, z, pixels),
                         kLightColors[i % 4], emission);
    }
    scene.addSphere({0.35, 0.25, 2.0}, 0.08, checker({0.9f, 0.9f, 0.85f}, {0.2f, 0.3f, 0.7f}, 0.03f));
    setApertureForBlur(camera, 60.0, std::max(8.0, 0.05 * width));
    return setup;
}

SceneSetup nearLeavesSky(uint32_t width, uint32_t height) {
    SceneSetup setup{"near-leaves-sky",
                     "dark leaves at 0.7 to 1.1 m against a sky above white at 60 m, focus at 3 m on two small boxes",
                     {},
                     baseCamera(width, height, 0.035, 3.0)};
    Scene& scene = setup.scene;
    scene.background = {1.6f, 1.8f, 2.2f};
    scene.addQuad({0, 0, 60}, kRight * 80.0, kUp * 60.0, noise({0.9f, 1.1f, 1.5f}, {2.2f, 2.4f, 3.0f}, 3.0f));
    scene.addBox({0.35, 0.05, 3.0}, {0.1, 0.12, 0.1}, checker({0.9f, 0.9f, 0.9f}, {0.7f, 0.1f, 0.1f}, 0.04f));
    // In focus and out of every leaf's reach, for the in-focus gate.
    scene.addBox({1.1, -0.25, 3.0}, {0.1, 0.15, 0.1}, stripes({0.9f, 0.8f, 0.2f}, {0.1f, 0.1f, 0.3f}, 0.03f));
    addLeaves(scene, {8, 0.7, 0.05, -0.3, 0.05, 2.3, -0.22, 0.35, 11, 0.01, 0.012, 0.04, 0.03},
              noise({0.02f, 0.06f, 0.02f}, {0.08f, 0.2f, 0.06f}, 0.02f));
    setApertureForBlur(setup.camera, 60.0, std::max(6.0, 0.03 * width));
    return setup;
}

SceneSetup farSteps(uint32_t width, uint32_t height) {
    SceneSetup setup{"far-steps",
                     "textured boxes at 4 to 8 m in front of a busy wall at 40 m, focus at 2 m",
                     {},
                     baseCamera(width, height, 0.05, 2.0)};
    Scene& scene = setup.scene;
    scene.addQuad({0, 0, 40}, kRight * 60.0, kUp * 40.0, checker({0.1f, 0.1f, 0.15f}, {0.9f, 0.85f, 0.6f}, 1.2f));
    scene.addBox({-1.5, 0.3, 5.0}, {0.8, 0.5, 0.2}, stripes({0.8f, 0.2f, 0.1f}, {0.2f, 0.1f, 0.05f}, 0.12f));
    scene.addBox({1.2, -0.5, 4.0}, {0.4, 0.6, 0.2}, noise({0.1f, 0.5f, 0.2f}, {0.9f, 0.9f, 0.5f}, 0.1f));
    scene.addBox({0.4, 1.2, 8.0}, {1.0, 0.4, 0.2}, bricks({0.3f, 0.3f, 0.6f}, {0.9f, 0.9f, 0.9f}, 0.2f));
    scene.addSphere({-0.1, -0.15, 2.0}, 0.1, checker({0.9f, 0.9f, 0.85f}, {0.2f, 0.3f, 0.7f}, 0.03f));
    setApertureForBlur(setup.camera, 40.0, std::max(8.0, 0.05 * width));
    return setup;
}

struct SceneEntry {
    const char* name;
    std::function<SceneSetup(uint32_t, uint32_t)> make;
};

const std::vector<SceneEntry>& sceneCatalog() {
    static const std::vector<SceneEntry> catalog = {
        {"near-object", nearObject},
        {"far-highlights", farHighlights},
        {"mid-lights", midLights},
        {"fence", fence},
        {"busy-background", busyBackground},
        {"floor", floorScene},
        {"bright-window", brightWindow},
        {"near-and-far", nearAndFar},
        {"far-branches", farBranches},
        {"far-steps", farSteps},
        {"near-leaves-sky", nearLeavesSky},
        {"lights-through-branches", lightsThroughBranches},
        {"point", singlePoint},
    };
    return catalog;
}

}  // namespace

glm::vec3 Texture::evaluate(glm::dvec2 uv) const {
    const double u = uv.x / scale, v = uv.y / scale;
    switch (kind) {
        case Kind::Solid:
            return colorA;
        case Kind::Checker:
            return (parity(u) ^ parity(v)) ? colorB : colorA;
        case Kind::Stripes:
            return parity(u) ? colorB : colorA;
        case Kind::Noise: {
            // Three octaves of value noise with a contrast boost: a busy, high-frequency pattern.
            const float n =
                0.55f * valueNoise(u, v) + 0.3f * valueNoise(2.7 * u, 2.7 * v) + 0.15f * valueNoise(7.1 * u, 7.1 * v);
            const float t = glm::clamp((n - 0.5f) * 2.2f + 0.5f, 0.0f, 1.0f);
            return glm::mix(colorA, colorB, t);
        }
        case Kind::Bricks: {
            // Bricks twice as wide as tall with a half-brick offset every other row; 8% mortar.
            const double row = std::floor(v * 2.0);
            const double brickU = u + (int(row) & 1) * 0.5;
            const double fracU = brickU - std::floor(brickU), fracV = v * 2.0 - row;
            const bool mortar = fracU < 0.04 || fracU > 0.96 || fracV < 0.08 || fracV > 0.92;
            if (mortar) return colorB;
            const float shade = 0.8f + 0.4f * latticeValue(int32_t(std::floor(brickU)), int32_t(row));
            return colorA * shade;
        }
    }
    return colorA;
}

Primitive& Scene::addSphere(glm::dvec3 center, double radius, Texture texture) {
    Primitive primitive;
    primitive.kind = Primitive::Kind::Sphere;
    primitive.center = center;
    primitive.radius = radius;
    primitive.texture = texture;
    primitives.push_back(primitive);
    return primitives.back();
}

Primitive& Scene::addEmitter(glm::dvec3 center, double radius, glm::vec3 color, float emission) {
    Primitive& primitive = addSphere(center, radius, solid(color));
    primitive.emitter = true;
    primitive.emission = emission;
    return primitive;
}

Primitive& Scene::addQuad(glm::dvec3 center, glm::dvec3 axisU, glm::dvec3 axisV, Texture texture) {
    Primitive primitive;
    primitive.kind = Primitive::Kind::Quad;
    primitive.center = center;
    primitive.axisU = axisU;
    primitive.axisV = axisV;
    primitive.texture = texture;
    primitives.push_back(primitive);
    return primitives.back();
}

Primitive& Scene::addBox(glm::dvec3 center, glm::dvec3 halfExtents, Texture texture) {
    Primitive primitive;
    primitive.kind = Primitive::Kind::Box;
    primitive.center = center;
    primitive.halfExtents = halfExtents;
    primitive.texture = texture;
    primitives.push_back(primitive);
    return primitives.back();
}

std::vector<SceneInfo> listScenes() {
    std::vector<SceneInfo> scenes;
    for (const SceneEntry& entry : sceneCatalog()) {
        const SceneSetup setup = entry.make(64, 64);
        scenes.push_back({setup.name, setup.description});
    }
    return scenes;
}

SceneSetup makeScene(const std::string& name, uint32_t width, uint32_t height) {
    if (width == 0 || height == 0) throw std::invalid_argument("scene width and height must be at least 1");
    std::string names;
    for (const SceneEntry& entry : sceneCatalog()) {
        if (name == entry.name) return entry.make(width, height);
        names += names.empty() ? entry.name : std::string(", ") + entry.name;
    }
    throw std::invalid_argument("unknown scene '" + name + "' (scenes: " + names + ")");
}

}  // namespace ffxdof::ref
