#include "ffx_dof_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <thread>

namespace ffxdof::ref {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNoHit = std::numeric_limits<double>::infinity();

struct Ray {
    glm::dvec3 origin;
    glm::dvec3 direction;  // not normalised: t = 1 is one unit of view depth times direction's view z
};

struct Hit {
    double t = kNoHit;
    const Primitive* primitive = nullptr;
    glm::dvec2 uv{0.0};
};

bool intersectSphere(const Primitive& sphere, const Ray& ray, double tMin, Hit& hit) {
    const glm::dvec3 oc = ray.origin - sphere.center;
    const double a = glm::dot(ray.direction, ray.direction);
    const double b = glm::dot(oc, ray.direction);
    const double c = glm::dot(oc, oc) - sphere.radius * sphere.radius;
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0) return false;
    const double root = std::sqrt(discriminant);
    double t = (-b - root) / a;
    if (t <= tMin) t = (-b + root) / a;
    if (t <= tMin || t >= hit.t) return false;
    const glm::dvec3 normal = (ray.origin + t * ray.direction - sphere.center) / sphere.radius;
    hit.t = t;
    hit.primitive = &sphere;
    hit.uv = {std::atan2(normal.z, normal.x) * sphere.radius,
              std::asin(std::clamp(normal.y, -1.0, 1.0)) * sphere.radius};
    return true;
}

bool intersectQuad(const Primitive& quad, const Ray& ray, double tMin, Hit& hit) {
    const glm::dvec3 normal = glm::cross(quad.axisU, quad.axisV);
    const double denominator = glm::dot(ray.direction, normal);
    if (std::abs(denominator) < 1e-300) return false;
    const double t = glm::dot(quad.center - ray.origin, normal) / denominator;
    if (t <= tMin || t >= hit.t) return false;
    const glm::dvec3 local = ray.origin + t * ray.direction - quad.center;
    const double lengthU2 = glm::dot(quad.axisU, quad.axisU);
    const double lengthV2 = glm::dot(quad.axisV, quad.axisV);
    const double a = glm::dot(local, quad.axisU) / lengthU2;
    const double b = glm::dot(local, quad.axisV) / lengthV2;
    if (std::abs(a) > 1.0 || std::abs(b) > 1.0) return false;
    hit.t = t;
    hit.primitive = &quad;
    hit.uv = {a * std::sqrt(lengthU2), b * std::sqrt(lengthV2)};
    return true;
}

bool intersectBox(const Primitive& box, const Ray& ray, double tMin, Hit& hit) {
    double tNear = -kNoHit, tFar = kNoHit;
    int nearAxis = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = box.center[axis] - box.halfExtents[axis] - ray.origin[axis];
        const double hi = box.center[axis] + box.halfExtents[axis] - ray.origin[axis];
        if (ray.direction[axis] == 0.0) {
            if (lo > 0.0 || hi < 0.0) return false;
            continue;
        }
        double t0 = lo / ray.direction[axis], t1 = hi / ray.direction[axis];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > tNear) {
            tNear = t0;
            nearAxis = axis;
        }
        tFar = std::min(tFar, t1);
    }
    if (tNear > tFar) return false;
    double t = tNear;
    int faceAxis = nearAxis;
    if (t <= tMin) {
        t = tFar;  // inside the box: the exit face (its axis is not needed for a plausible texture)
        faceAxis = (nearAxis + 1) % 3;
    }
    if (t <= tMin || t >= hit.t) return false;
    const glm::dvec3 local = ray.origin + t * ray.direction - box.center;
    hit.t = t;
    hit.primitive = &box;
    hit.uv = {local[(faceAxis + 1) % 3], local[(faceAxis + 2) % 3]};
    return true;
}

Hit traceRay(const Scene& scene, const Ray& ray) {
    Hit hit;
    const double tMin = 1e-9;
    for (const Primitive& primitive : scene.primitives) {
        switch (primitive.kind) {
            case Primitive::Kind::Sphere:
                intersectSphere(primitive, ray, tMin, hit);
                break;
            case Primitive::Kind::Quad:
                intersectQuad(primitive, ray, tMin, hit);
                break;
            case Primitive::Kind::Box:
                intersectBox(primitive, ray, tMin, hit);
                break;
        }
    }
    return hit;
}

// ---- sampling -----------------------------------------------------------------------------------

uint32_t hashInteger(uint32_t value) {
    value ^= value >> 16;
    value *= 0x7feb352dU;
    value ^= value >> 15;
    value *= 0x846ca68bU;
    value ^= value >> 16;
    return value;
}

double hashUnit(uint32_t x, uint32_t y, uint32_t seed, uint32_t dimension) {
    const uint32_t h =
        hashInteger(x * 0x9e3779b9U ^ hashInteger(y * 0x85ebca6bU ^ hashInteger(seed * 31U + dimension)));
    return (h >> 8) * (1.0 / 16777216.0);
}

double radicalInverse(uint32_t index, uint32_t base) {
    double result = 0.0;
    double scale = 1.0 / base;
    while (index > 0) {
        result += (index % base) * scale;
        index /= base;
        scale /= base;
    }
    return result;
}

// Sample i of a pixel: the sub-pixel position cycles through the 4x4 strata centres of the pinhole
// image (in bit-reversed order, so any prefix of 2^k samples is spread over the pixel), so that
// in-focus pixels get exactly the input's anti-aliasing and a zero aperture reproduces the pinhole
// image; the lens position is a 2D Halton point (bases 3 and 5, independent of i mod 16) shifted per
// pixel (Cranley-Patterson rotation). Every prefix is well stratified, so the N/2 estimate is a fair
// convergence check.
struct SamplePoint {
    double pixelX, pixelY, lensU, lensV;
};

constexpr int kPixelGrid = 4;

SamplePoint samplePoint(uint32_t index, const double rotation[2]) {
    const auto rotate = [](double value, double offset) {
        const double shifted = value + offset;
        return shifted >= 1.0 ? shifted - 1.0 : shifted;
    };
    const uint32_t stratum = ((index & 1) << 3) | ((index & 2) << 1) | ((index & 4) >> 1) | ((index & 8) >> 3);
    return {(stratum % kPixelGrid + 0.5) / kPixelGrid, (stratum / kPixelGrid + 0.5) / kPixelGrid,
            rotate(radicalInverse(index, 3), rotation[0]), rotate(radicalInverse(index, 5), rotation[1])};
}

// Shirley-Chiu concentric map of the unit square onto the unit disc (area-preserving, low distortion).
glm::dvec2 concentricDisc(double u, double v) {
    const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
    if (a == 0.0 && b == 0.0) return {0.0, 0.0};
    double radius, angle;
    if (std::abs(a) > std::abs(b)) {
        radius = a;
        angle = (kPi / 4.0) * (b / a);
    } else {
        radius = b;
        angle = kPi / 2.0 - (kPi / 4.0) * (a / b);
    }
    return {radius * std::cos(angle), radius * std::sin(angle)};
}

// The weights of a pixel's lens samples in one estimate (all N samples, or the first N/2 for the
// convergence figure) under a shaped aperture. Sample i sits at sub-pixel position i mod 16; the samples
// of a position average those that land in the aperture (weight count / accepted), so every position
// keeps its share count / N of the pixel and in focus the anti-aliasing stays exactly the pinhole
// image's, whatever the shape. A position where none lands falls back to the lens centre for all its
// samples (weight 1; u = 0 is in S as |o| <= catEye <= 1): its pinhole ray. For the round aperture every
// weight is exactly 1, so the sums are bit for bit those of the renderer before shapes.
struct LensWeights {
    static constexpr uint32_t kPositions = kPixelGrid * kPixelGrid;
    std::array<uint32_t, kPositions> count{}, accepted{};

    void add(uint32_t i, bool inside) {
        ++count[i % kPositions];
        if (inside) ++accepted[i % kPositions];
    }
    bool includes(uint32_t i, bool inside) const { return inside || accepted[i % kPositions] == 0; }
    double weight(uint32_t i, bool inside) const {
        return inside ? double(count[i % kPositions]) / accepted[i % kPositions] : 1.0;
    }
};

// ---- camera geometry ----------------------------------------------------------------------------

struct CameraFrame {
    glm::dvec3 position, right, up, forward;
    double imageDistance, sensorWidth, sensorHeight, focus, aperture;
    uint32_t width, height;

    explicit CameraFrame(const Camera& camera)
        : position(camera.position),
          imageDistance(camera.imageDistance()),
          sensorWidth(camera.sensorWidth),
          sensorHeight(camera.sensorHeight()),
          focus(camera.focusDistance),
          aperture(camera.apertureRadius),
          width(camera.width),
          height(camera.height) {
        forward = glm::normalize(camera.target - camera.position);
        right = glm::normalize(glm::cross(camera.up, forward));
        up = glm::cross(forward, right);
    }

    // View-space direction (view z = 1) of the pinhole ray through continuous pixel position (px, py).
    glm::dvec3 pinholeDirection(double px, double py) const {
        const double sensorX = (px / width - 0.5) * sensorWidth;
        const double sensorY = (0.5 - py / height) * sensorHeight;
        return {sensorX / imageDistance, sensorY / imageDistance, 1.0};
    }
    glm::dvec3 toWorldDirection(const glm::dvec3& view) const {
        return view.x * right + view.y * up + view.z * forward;
    }
    glm::dvec3 toWorldPoint(const glm::dvec3& view) const { return position + toWorldDirection(view); }
    glm::dvec3 toView(const glm::dvec3& world) const {
        const glm::dvec3 d = world - position;
        return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)};
    }
    // The thin-lens ray from view-space lens point (lensX, lensY, 0) through the focus-plane point of
    // the pinhole ray; its direction has view z = focus, so view depth = t * focus.
    Ray lensRay(const glm::dvec3& pinhole, double lensX, double lensY) const {
        const glm::dvec3 lensPoint{lensX, lensY, 0.0};
        return {toWorldPoint(lensPoint), toWorldDirection(pinhole * focus - lensPoint)};
    }
};

glm::dvec3 surfaceColor(const Hit& hit) { return glm::dvec3(hit.primitive->texture.evaluate(hit.uv)); }

// Radiance of the pinhole image: emitters shine with their full emission.
glm::dvec3 pinholeRadiance(const Scene& scene, const Hit& hit) {
    if (!hit.primitive) return glm::dvec3(scene.background);
    const glm::dvec3 color = surfaceColor(hit);
    return hit.primitive->emitter ? color * double(hit.primitive->emission) : color;
}

// Radiance of the thin-lens lens-sampling pass: emitters are black here because their emission is
// added by the footprint-sampling pass (their occlusion of what is behind them still counts).
glm::dvec3 lensSampleRadiance(const Scene& scene, const Hit& hit) {
    if (!hit.primitive) return glm::dvec3(scene.background);
    return hit.primitive->emitter ? glm::dvec3(0.0) : surfaceColor(hit);
}

struct EmitterView {
    const Primitive* primitive;
    glm::dvec3 center;  // view space
    glm::dvec3 radiance;
    double footprintRadius;  // radius on the lens of the points whose ray through P can hit it
    double footprintMotion;  // how far the footprint moves on the lens per unit of focus-plane motion
};

void forEachRow(uint32_t height, uint32_t threads, const std::function<void(uint32_t)>& renderRow) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = std::min(threads, height);
    std::atomic<uint32_t> nextRow{0};
    const auto worker = [&] {
        for (uint32_t row = nextRow++; row < height; row = nextRow++) renderRow(row);
    };
    std::vector<std::thread> pool;
    for (uint32_t i = 1; i < threads; ++i) pool.emplace_back(worker);
    worker();
    for (std::thread& thread : pool) thread.join();
}

void checkInputs(const Scene& scene, const Camera& camera) {
    camera.validate();
    for (const Primitive& primitive : scene.primitives) {
        if (primitive.emitter && primitive.kind != Primitive::Kind::Sphere) {
            throw std::invalid_argument("only spheres can be emitters");
        }
    }
}

}  // namespace

PinholeImages renderPinhole(const Scene& scene, const Camera& camera, const RenderSettings& settings) {
    checkInputs(scene, camera);
    const CameraFrame frame(camera);
    const ProjectionTerms standard = camera.projection(), reversed = camera.reversedProjection();
    PinholeImages images{io::ImageRGBA(camera.width, camera.height), io::ImageR(camera.width, camera.height),
                         io::ImageR(camera.width, camera.height), io::ImageR(camera.width, camera.height)};
    constexpr int kGrid = kPixelGrid;  // 4x4 stratified sub-pixel samples at the strata centres (no noise)
    forEachRow(camera.height, settings.threads, [&](uint32_t y) {
        for (uint32_t x = 0; x < camera.width; ++x) {
            glm::dvec3 sum(0.0);
            for (int sy = 0; sy < kGrid; ++sy) {
                for (int sx = 0; sx < kGrid; ++sx) {
                    const glm::dvec3 view = frame.pinholeDirection(x + (sx + 0.5) / kGrid, y + (sy + 0.5) / kGrid);
                    sum += pinholeRadiance(scene, traceRay(scene, {frame.position, frame.toWorldDirection(view)}));
                }
            }
            sum /= double(kGrid * kGrid);
            float* pixel = images.color.at(x, y);
            pixel[0] = float(sum.r), pixel[1] = float(sum.g), pixel[2] = float(sum.b), pixel[3] = 1.0f;

            const glm::dvec3 center = frame.pinholeDirection(x + 0.5, y + 0.5);
            const Hit hit = traceRay(scene, {frame.position, frame.toWorldDirection(center)});
            const double depth = std::min(hit.t * center.z, camera.farPlane);
            images.depth.at(x, y) = float(depth);
            images.deviceDepth.at(x, y) = float(standard.deviceDepth(depth));
            images.deviceDepthReversed.at(x, y) = float(reversed.deviceDepth(depth));
        }
    });
    return images;
}

ThinLensImage renderThinLens(const Scene& scene, const Camera& camera, const RenderSettings& settings) {
    checkInputs(scene, camera);
    if (settings.lensSamples == 0) throw std::invalid_argument("lensSamples must be at least 1");
    const CameraFrame frame(camera);
    const UnitAperture shape(camera.aperture);
    const bool roundAperture = shape.isDisc();
    const uint32_t sampleCount = settings.lensSamples;
    const uint32_t halfCount = sampleCount / 2;
    const double aperture = camera.apertureRadius;
    const double squeeze = camera.aperture.anamorphicRatio;
    // The lens region A (ux / s, uy) lies between these radii around the lens centre.
    const double apertureInner = aperture * std::min(1.0, 1.0 / squeeze);
    const double apertureOuter = aperture * std::max(1.0, 1.0 / squeeze);
    const double focus = camera.focusDistance;
    const double focusPixelPitch = focus * (camera.sensorWidth / camera.width) / frame.imageDistance;
    // Footprint area / lens area = pi r^2 / (A^2 area(S) / s) = (r / A)^2 * (pi s / area(S)), the last
    // factor exactly 1 for the round aperture. With a cat's eye area(S) depends on the pixel.
    const auto discOverShapeArea = [&](glm::dvec2 catEyeCenter) { return kPi * squeeze / shape.area(catEyeCenter); };
    const std::optional<double> fixedDiscOverShapeArea =
        camera.aperture.catEye > 0.0 ? std::nullopt : std::optional<double>(discOverShapeArea(glm::dvec2(0.0)));

    std::vector<EmitterView> emitters;
    for (const Primitive& primitive : scene.primitives) {
        if (!primitive.emitter) continue;
        EmitterView emitter{&primitive, frame.toView(primitive.center),
                            glm::dvec3(primitive.texture.evaluate({0.0, 0.0})) * double(primitive.emission), 0.0, 0.0};
        if (emitter.center.z <= 0.0) continue;  // behind the lens
        const double defocus = std::abs(focus - emitter.center.z);
        // The line from lens point L to focus point P crosses depth Z at L (1 - Z/F) + P Z/F, so it
        // passes the sphere's centre within its radius for L in a disc of radius r F / |F - Z|
        // centred at (C F - P Z) / (F - Z). The margin covers the silhouette of an oblique ray.
        emitter.footprintRadius = defocus > 0.0 ? 1.3 * primitive.radius * focus / defocus : kNoHit;
        emitter.footprintMotion = defocus > 0.0 ? emitter.center.z / defocus : kNoHit;
        emitters.push_back(emitter);
    }

    ThinLensImage result{io::ImageRGBA(camera.width, camera.height), 0.0};
    std::vector<double> squaredChangePerRow(camera.height, 0.0);
    forEachRow(camera.height, settings.threads, [&](uint32_t y) {
        // Sample i of a pass: its lens point, and whether it lies in the shaped aperture at its own
        // sensor position (which moves the cat's eye). The concentric map's points are in the unit disc
        // by construction, so the round aperture tests nothing (a rounding at the rim must not drop a
        // sample). Outside, the lens point is the centre, the fallback of LensWeights.
        struct LensSample {
            glm::dvec3 pinhole;
            glm::dvec2 lens;
            bool inside;
        };
        const auto lensSample = [&](uint32_t x, uint32_t i, const double rotation[2]) {
            const SamplePoint s = samplePoint(i, rotation);
            const double px = x + s.pixelX, py = y + s.pixelY;
            const glm::dvec2 u = concentricDisc(s.lensU, s.lensV);
            const bool inside =
                roundAperture || shape.contains(u, shape.catEyeCenter(px, py, camera.width, camera.height));
            return LensSample{frame.pinholeDirection(px, py), inside ? shape.lensPoint(u, aperture) : glm::dvec2(0.0),
                              inside};
        };
        struct PassWeights {
            LensWeights all, half;  // the estimate from all N samples, from the first N/2
        };
        const auto passWeights = [&](uint32_t x, const double rotation[2]) {
            PassWeights weights;
            for (uint32_t i = 0; i < sampleCount; ++i) {
                const bool inside = roundAperture || lensSample(x, i, rotation).inside;
                weights.all.add(i, inside);
                if (i < halfCount) weights.half.add(i, inside);
            }
            return weights;
        };
        // Calls use(sample, allWeight, halfWeight) for the samples of a pass that enter either estimate
        // (weight 0: not in that one).
        const auto forEachLensSample = [&](uint32_t x, const double rotation[2], const PassWeights& weights,
                                           const auto& use) {
            for (uint32_t i = 0; i < sampleCount; ++i) {
                const LensSample s = lensSample(x, i, rotation);
                const double allWeight = weights.all.includes(i, s.inside) ? weights.all.weight(i, s.inside) : 0.0;
                const double halfWeight =
                    i < halfCount && weights.half.includes(i, s.inside) ? weights.half.weight(i, s.inside) : 0.0;
                if (allWeight != 0.0 || halfWeight != 0.0) use(s, allWeight, halfWeight);
            }
        };

        for (uint32_t x = 0; x < camera.width; ++x) {
            double rotation[2], emitterRotation[2];
            for (uint32_t d = 0; d < 2; ++d) {
                rotation[d] = hashUnit(x, y, settings.seed, d);
                emitterRotation[d] = hashUnit(x, y, settings.seed, 2 + d);
            }
            glm::dvec3 sumHalf(0.0), sum(0.0);
            forEachLensSample(
                x, rotation, passWeights(x, rotation), [&](const LensSample& s, double allWeight, double halfWeight) {
                    const glm::dvec3 radiance =
                        lensSampleRadiance(scene, traceRay(scene, frame.lensRay(s.pinhole, s.lens.x, s.lens.y)));
                    if (allWeight != 0.0) sum += allWeight * radiance;
                    if (halfWeight != 0.0) sumHalf += halfWeight * radiance;
                });
            // Emission: sample the lens points whose ray can reach each emitter (its footprint), or the
            // whole aperture when the footprint is larger. Footprint weight = sampled area / lens area;
            // the whole aperture is weighted like the pass above.
            std::optional<PassWeights> emitterWeights;
            std::optional<double> pixelDiscOverShapeArea = fixedDiscOverShapeArea;
            const glm::dvec3 centerPinhole = frame.pinholeDirection(x + 0.5, y + 0.5);
            for (const EmitterView& emitter : emitters) {
                const double z = emitter.center.z;
                const bool sampleFootprint = emitter.footprintRadius < apertureInner;
                if (std::isfinite(emitter.footprintMotion)) {
                    const glm::dvec2 footprintCenter =
                        (glm::dvec2(emitter.center) * focus - glm::dvec2(centerPinhole) * focus * z) / (focus - z);
                    const double margin = 0.7072 * focusPixelPitch * emitter.footprintMotion;
                    if (glm::length(footprintCenter) > emitter.footprintRadius + apertureOuter + margin) continue;
                }
                if (sampleFootprint) {
                    if (!pixelDiscOverShapeArea) {
                        // The cat's eye barely changes across a pixel: its area at the centre will do.
                        pixelDiscOverShapeArea =
                            discOverShapeArea(shape.catEyeCenter(x + 0.5, y + 0.5, camera.width, camera.height));
                    }
                    const double weight = (emitter.footprintRadius * emitter.footprintRadius) / (aperture * aperture) *
                                          *pixelDiscOverShapeArea;
                    for (uint32_t i = 0; i < sampleCount; ++i) {
                        const SamplePoint s = samplePoint(i, emitterRotation);
                        const double px = x + s.pixelX, py = y + s.pixelY;
                        const glm::dvec3 pinhole = frame.pinholeDirection(px, py);
                        const glm::dvec2 footprintCenter =
                            (glm::dvec2(emitter.center) * focus - glm::dvec2(pinhole) * focus * z) / (focus - z);
                        const glm::dvec2 lens =
                            footprintCenter + emitter.footprintRadius * concentricDisc(s.lensU, s.lensV);
                        const glm::dvec2 catEye = shape.catEyeCenter(px, py, camera.width, camera.height);
                        if (!shape.contains({lens.x * squeeze, lens.y}, catEye, aperture)) continue;
                        const Hit hit = traceRay(scene, frame.lensRay(pinhole, lens.x, lens.y));
                        if (hit.primitive != emitter.primitive) continue;
                        const glm::dvec3 radiance = weight * emitter.radiance;
                        sum += radiance;
                        if (i < halfCount) sumHalf += radiance;
                    }
                } else {
                    if (!emitterWeights) emitterWeights = passWeights(x, emitterRotation);
                    forEachLensSample(x, emitterRotation, *emitterWeights,
                                      [&](const LensSample& s, double allWeight, double halfWeight) {
                                          const Hit hit = traceRay(scene, frame.lensRay(s.pinhole, s.lens.x, s.lens.y));
                                          if (hit.primitive != emitter.primitive) return;
                                          if (allWeight != 0.0) sum += allWeight * emitter.radiance;
                                          if (halfWeight != 0.0) sumHalf += halfWeight * emitter.radiance;
                                      });
                }
            }
            sum /= double(sampleCount);
            float* pixel = result.color.at(x, y);
            pixel[0] = float(sum.r), pixel[1] = float(sum.g), pixel[2] = float(sum.b), pixel[3] = 1.0f;
            if (halfCount > 0) {
                const glm::dvec3 half = sumHalf / double(halfCount);
                for (int c = 0; c < 3; ++c) {
                    const double change = std::clamp(half[c], 0.0, 1.0) - std::clamp(sum[c], 0.0, 1.0);
                    squaredChangePerRow[y] += change * change;
                }
            }
        }
    });
    double total = 0.0;
    for (double rowSum : squaredChangePerRow) total += rowSum;
    result.convergenceRms = halfCount > 0 ? std::sqrt(total / (3.0 * camera.width * camera.height))
                                          : std::numeric_limits<double>::quiet_NaN();
    return result;
}

}  // namespace ffxdof::ref
