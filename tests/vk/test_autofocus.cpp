// Autofocus on the device: targets at known distances, a region straddling an edge, the smoothing of
// a step change, the clamp, the reset, the readback's errors, and the image it gives against manual
// focus at the same distance. 16- and 32-bit, GLSL- and HLSL-compiled shaders; validation on.
#include "vk_test_support.h"

#include <cmath>
#include <functional>
#include <vector>

using namespace ffxdof;
using namespace ffxdof::vktest;

namespace {

// A perspective projection looking down -Z with depth 0 at the near plane (Vulkan [0, 1]):
// device depth of a point at distance D is -p33 + p34 / D.
struct Camera {
    float nearPlane = 0.1f, farPlane = 100.0f;
    float proj33() const { return farPlane / (nearPlane - farPlane); }
    float proj34() const { return nearPlane * farPlane / (nearPlane - farPlane); }
    float proj43() const { return -1.0f; }
    float depthAt(float distance) const { return -proj33() + proj34() / distance; }
};

constexpr uint32_t kWidth = 128, kHeight = 96;
constexpr float kFocalLength = 0.05f, kSensorWidth = 0.036f;
constexpr float kAperture = kFocalLength / (2.0f * 2.0f);  // f/2

FfxDofAutofocus autofocusAt(float centerX, float centerY, float size, const Camera& camera) {
    FfxDofAutofocus a{};
    a.regionCenter[0] = centerX;
    a.regionCenter[1] = centerY;
    a.regionSize[0] = a.regionSize[1] = size;
    a.aperture = kAperture;
    a.focalLength = kFocalLength;
    a.conversion = 0.5f * float(kWidth) / kSensorWidth;
    a.proj33 = camera.proj33();
    a.proj34 = camera.proj34();
    a.proj43 = camera.proj43();
    a.minFocusDistance = 0.2f;
    a.maxFocusDistance = 1000.0f;
    return a;
}

// Depth: `distanceAt(x, y)` in metres for every pixel. Color: a texture, so blur shows.
Scene sceneOf(const Camera& camera, const std::function<float(uint32_t, uint32_t)>& distanceAt) {
    Scene scene{vkrun::HostImage(kWidth, kHeight, 4), vkrun::HostImage(kWidth, kHeight, 1)};
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            float* c = scene.color.at(x, y);
            const bool checker = ((x / 3) + (y / 3)) % 2;
            c[0] = checker ? 0.9f : 0.1f;
            c[1] = checker ? 0.5f : 0.2f;
            c[2] = float(x) / float(kWidth);
            c[3] = 1.0f;
            scene.depth.at(x, y)[0] = camera.depthAt(distanceAt(x, y));
        }
    }
    return scene;
}

// A target of `targetDistance` over the middle third of the image, in front of a wall at 20 m.
Scene targetScene(const Camera& camera, float targetDistance) {
    return sceneOf(camera, [&](uint32_t x, uint32_t y) {
        const bool target = x >= kWidth / 3 && x < 2 * kWidth / 3 && y >= kHeight / 3 && y < 2 * kHeight / 3;
        return target ? targetDistance : 20.0f;
    });
}

vkrun::RunSettings autofocusSettings(const FfxDofAutofocus& autofocus, bool float32, bool hlsl) {
    vkrun::RunSettings settings;
    settings.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.outputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.quality = 6;
    settings.cocLimitFactor = 0.1f;
    settings.useAutofocus = true;
    settings.autofocus = autofocus;
    settings.forceFloat32 = float32;
    settings.useHlsl = hlsl;
    return settings;
}

}  // namespace

TEST_CASE("autofocus finds a target at a known distance and leaves it sharp", "[vulkan][autofocus]") {
    vkrun::Device& device = validatedDevice();
    const Camera camera;
    for (const float distance : {0.8f, 2.5f, 7.0f}) {
        const Scene scene = targetScene(camera, distance);
        for (const bool float32 : {false, true}) {
            float glslDistance = 0.0f;
            for (const bool hlsl : {false, true}) {
                CAPTURE(distance, float32, hlsl);
                const vkrun::RunSettings settings =
                    autofocusSettings(autofocusAt(0.5f, 0.5f, 0.2f, camera), float32, hlsl);
                const vkrun::RunResult result = vkrun::runEffect(device, scene.color, scene.depth, settings);
                CHECK(std::abs(result.autofocusDistance - distance) <= 0.01f * distance);
                if (!hlsl) glslDistance = result.autofocusDistance;
                if (hlsl) CHECK(result.autofocusDistance == glslDistance);  // HLSL gives the same bits

                // The target's interior (away from the wall's blur) is the input, untouched.
                double worst = 0.0;
                for (uint32_t y = kHeight / 3 + 8; y < 2 * kHeight / 3 - 8; ++y) {
                    for (uint32_t x = kWidth / 3 + 8; x < 2 * kWidth / 3 - 8; ++x) {
                        for (int ch = 0; ch < 3; ++ch) {
                            worst = std::max(worst,
                                             double(std::abs(result.output.at(x, y)[ch] - scene.color.at(x, y)[ch])));
                        }
                    }
                }
                CHECK(worst <= 2e-3);

                // The same image as manual focus at the chosen distance, with the host's CoC line.
                vkrun::RunSettings manual = settings;
                manual.useAutofocus = false;
                const FfxDofAutofocus& a = settings.autofocus;
                const float focus = -result.autofocusDistance;  // the camera looks down -Z
                manual.cocScale = ffxDofCalculateCocScale(a.aperture, focus, a.focalLength, a.conversion, a.proj33,
                                                          a.proj34, a.proj43);
                manual.cocBias = ffxDofCalculateCocBias(a.aperture, focus, a.focalLength, a.conversion, a.proj33,
                                                        a.proj34, a.proj43);
                const vkrun::RunResult reference = vkrun::runEffect(device, scene.color, scene.depth, manual);
                CHECK(difference(result.output, reference.output).psnr >= 50.0);
            }
        }
    }
    requireNoValidationMessages(device);
}

TEST_CASE("a region straddling an edge focuses on the surface under its centre", "[vulkan][autofocus]") {
    vkrun::Device& device = validatedDevice();
    const Camera camera;
    // Left of x = 64: a wall at 2 m; right: a wall at 10 m. Regions 40% wide straddle the edge.
    const Scene scene = sceneOf(camera, [](uint32_t x, uint32_t) { return x < kWidth / 2 ? 2.0f : 10.0f; });
    const struct { float centerX, expected; } cases[] = {{0.44f, 2.0f}, {0.56f, 10.0f}, {0.30f, 2.0f}, {0.70f, 10.0f}};
    for (const auto& c : cases) {
        CAPTURE(c.centerX);
        const vkrun::RunResult result =
            vkrun::runEffect(device, scene.color, scene.depth,
                             autofocusSettings(autofocusAt(c.centerX, 0.5f, 0.4f, camera), false, false));
        CHECK(std::abs(result.autofocusDistance - c.expected) <= 0.01f * c.expected);
    }
    requireNoValidationMessages(device);
}

TEST_CASE("the focus distance is clamped to the dispatch's range", "[vulkan][autofocus]") {
    vkrun::Device& device = validatedDevice();
    const Camera camera;
    const Scene scene = targetScene(camera, 12.0f);
    FfxDofAutofocus autofocus = autofocusAt(0.5f, 0.5f, 0.1f, camera);
    autofocus.maxFocusDistance = 5.0f;
    CHECK(vkrun::runEffect(device, scene.color, scene.depth, autofocusSettings(autofocus, false, false))
              .autofocusDistance == Approx(5.0f).epsilon(1e-5));
    autofocus = autofocusAt(0.5f, 0.5f, 0.1f, camera);
    autofocus.minFocusDistance = 15.0f;
    autofocus.maxFocusDistance = 30.0f;
    CHECK(vkrun::runEffect(device, scene.color, scene.depth, autofocusSettings(autofocus, false, false))
              .autofocusDistance == Approx(15.0f).epsilon(1e-5));
    requireNoValidationMessages(device);
}

TEST_CASE("a step change converges as the time constant says and a reset jumps", "[vulkan][autofocus]") {
    vkrun::Device& device = validatedDevice();
    const Camera camera;
    const Scene nearScene = targetScene(camera, 2.0f);
    const Scene farScene = targetScene(camera, 8.0f);
    const auto usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    vkrun::GpuImage color(device, kWidth, kHeight, VK_FORMAT_R16G16B16A16_SFLOAT, usage);
    vkrun::GpuImage nearDepth(device, kWidth, kHeight, VK_FORMAT_R32_SFLOAT, usage);
    vkrun::GpuImage farDepth(device, kWidth, kHeight, VK_FORMAT_R32_SFLOAT, usage);
    vkrun::GpuImage output(
        device, kWidth, kHeight, VK_FORMAT_R16G16B16A16_SFLOAT,
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    color.upload(nearScene.color, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    nearDepth.upload(nearScene.depth, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    farDepth.upload(farScene.depth, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    output.upload(nearScene.color, VK_IMAGE_LAYOUT_GENERAL);

    FfxDofBackendDescriptionVK backendInfo = device.backendDescription();
    backendInfo.maxFramesInFlight = 2;
    FfxDofBackend backend = nullptr;
    REQUIRE(ffxDofBackendCreateVK(&backendInfo, &backend) == FFX_DOF_OK);
    FfxDofContextDescription contextInfo{};
    contextInfo.quality = 4;
    contextInfo.resolution = {kWidth, kHeight};
    contextInfo.backendInterface = backend;
    contextInfo.cocLimitFactor = 0.05f;
    FfxDofContext context = nullptr;
    REQUIRE(ffxDofContextCreate(&context, &contextInfo) == FFX_DOF_OK);

    FfxDofAutofocus autofocus = autofocusAt(0.5f, 0.5f, 0.2f, camera);
    autofocus.timeConstant = 0.5f;
    autofocus.deltaTime = 0.1f;
    // One dispatch, submitted and waited for; with autofocus, the distance it chose (0 without).
    const auto dispatchWith = [&](const vkrun::GpuImage& depth, const FfxDofAutofocus* focus) {
        FfxDofDispatchDescription d{};
        d.color = ffxDofGetResourceVK(color.image(), color.format(), kWidth, kHeight,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, 0);
        d.depth = ffxDofGetResourceVK(depth.image(), depth.format(), kWidth, kHeight,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, 0);
        d.output = ffxDofGetResourceVK(output.image(), output.format(), kWidth, kHeight, VK_IMAGE_LAYOUT_GENERAL, 0);
        d.pAutofocus = focus;
        VkCommandBuffer commandBuffer = device.beginCommands();
        d.commandList = ffxDofGetCommandListVK(commandBuffer);
        const FfxDofErrorCode code = ffxDofContextDispatch(&context, &d);
        device.endSubmitAndWait(commandBuffer);
        REQUIRE(code == FFX_DOF_OK);
        float distance = 0.0f;
        if (focus) REQUIRE(ffxDofContextGetAutofocusDistance(&context, 0, &distance) == FFX_DOF_OK);
        return distance;
    };

    // The first dispatch has no history: it focuses at once.
    CHECK(dispatchWith(nearDepth, &autofocus) == Approx(2.0f).epsilon(0.01));
    // Then the target moves to 8 m: in dioptres the gap closes by exp(-dt / tau) per frame.
    for (int frame = 1; frame <= 10; ++frame) {
        const float distance = dispatchWith(farDepth, &autofocus);
        const double gap = (1.0 / 2.0 - 1.0 / 8.0) * std::exp(-frame * 0.1 / 0.5);
        CAPTURE(frame, distance);
        CHECK(1.0 / distance == Approx(1.0 / 8.0 + gap).epsilon(0.01));
    }
    // A cut: after ffxDofContextResetAutofocus the next dispatch takes the new distance at once.
    CHECK(dispatchWith(nearDepth, &autofocus) > 2.5f);  // still smoothing
    REQUIRE(ffxDofContextResetAutofocus(&context) == FFX_DOF_OK);
    CHECK(dispatchWith(nearDepth, &autofocus) == Approx(2.0f).epsilon(0.01));

    // The readback: earlier dispatches up to maxFramesInFlight back, and only autofocus dispatches.
    float previous = 0.0f;
    CHECK(ffxDofContextGetAutofocusDistance(&context, 2, &previous) == FFX_DOF_OK);
    CHECK(previous > 2.5f);
    CHECK(ffxDofContextGetAutofocusDistance(&context, 3, &previous) == FFX_DOF_ERROR_INVALID_ARGUMENT);
    CHECK(ffxDofContextGetAutofocusDistance(&context, 0, nullptr) == FFX_DOF_ERROR_INVALID_POINTER);
    dispatchWith(nearDepth, nullptr);  // manual focus
    CHECK(ffxDofContextGetAutofocusDistance(&context, 0, &previous) == FFX_DOF_ERROR_INVALID_ARGUMENT);
    CHECK(std::string(ffxDofGetLastErrorMessage()).find("did not run autofocus") != std::string::npos);
    CHECK(ffxDofContextGetAutofocusDistance(&context, 1, &previous) == FFX_DOF_OK);

    REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
    CHECK(ffxDofContextGetAutofocusDistance(&context, 0, &previous) == FFX_DOF_ERROR_INVALID_CONTEXT);
    REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    requireNoValidationMessages(device);
}
