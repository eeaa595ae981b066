// ffx-dof demo: renders a built-in scene with the reference renderer (pinhole input, linear depth and the
// thin-lens truth), applies the effect on Vulkan, and writes the images and a side-by-side.
#include "cli_error.h"
#include "commands.h"
#include "effect_run.h"
#include "ffx_dof_metrics.h"
#include "ffx_dof_reference.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

namespace ffxdof::cli {
namespace {

// input | ours | truth, with a dark gap between the panels.
io::ImageRGBA sideBySide(const std::vector<const io::ImageRGBA*>& panels) {
    constexpr uint32_t kGap = 8;
    const uint32_t width = panels[0]->width, height = panels[0]->height;
    const uint32_t count = uint32_t(panels.size());
    io::ImageRGBA combined(count * width + (count - 1) * kGap, height);
    for (float& value : combined.pixels) value = 0.02f;
    for (uint32_t panel = 0; panel < count; ++panel) {
        for (uint32_t y = 0; y < height; ++y) {
            for (uint32_t x = 0; x < width; ++x) {
                const float* source = panels[panel]->at(x, y);
                float* target = combined.at(panel * (width + kGap) + x, y);
                std::copy(source, source + 3, target);
                target[3] = 1.0f;
            }
        }
    }
    return combined;
}

}  // namespace

void runDemo(const DemoOptions& options) {
    checkEffectOptions(options.effect);
    if (options.width < 1 || options.height < 1 || options.width > 8192 || options.height > 8192) {
        throw CliError(ExitCode::InvalidValue, "--width and --height must be 1 to 8192");
    }
    if (options.lensSamples < 1) {
        throw CliError(ExitCode::InvalidValue, "--lens-samples must be at least 1");
    }
    if (options.autofocus) checkAutofocusRegion(*options.autofocus);
    ref::SceneSetup setup;
    try {
        setup = ref::makeScene(options.scene, options.width, options.height);
    } catch (const std::invalid_argument& error) {
        throw CliError(ExitCode::InvalidValue, std::string("--scene: ") + error.what());
    }
    // The truth is rendered through the aperture the effect is given (docs/aperture.md).
    const ApertureOptions& aperture = options.effect.aperture;
    setup.camera.aperture = ref::ApertureShape{aperture.blades, aperture.bladeRotationDegrees, aperture.roundness,
                                               aperture.anamorphicRatio, aperture.catEye};
    namespace fs = std::filesystem;
    const fs::path directory(options.outputDirectory);
    std::error_code error;
    fs::create_directories(directory, error);
    if (error || !fs::is_directory(directory)) {
        throw CliError(ExitCode::OutputWrite, "cannot create the output folder " + directory.string() + ": " +
                                                  (error ? error.message() : "a file of that name exists"));
    }

    // The device is opened before the (slow) rendering so that a machine without Vulkan fails at once.
    std::unique_ptr<vkrun::Device> device = openDevice(options.effect);

    std::printf("rendering scene \"%s\" (%s), %ux%u, %u lens samples per pixel...\n", setup.name.c_str(),
                setup.description.c_str(), options.width, options.height, options.lensSamples);
    std::fflush(stdout);
    ref::RenderSettings renderSettings;
    renderSettings.lensSamples = options.lensSamples;
    const ref::PinholeImages pinhole = ref::renderPinhole(setup.scene, setup.camera, renderSettings);
    const ref::ThinLensImage truth = ref::renderThinLens(setup.scene, setup.camera, renderSettings);

    const ref::Camera& camera = setup.camera;
    ThinLens lens{camera.apertureRadius, camera.focalLength, camera.focusDistance, camera.sensorWidth};
    const EffectDepth depth = linearToEffectDepth(pinhole.depth, "scene depth");
    CocParameters coc;
    float largestRadius = 0.0f;
    std::optional<FfxDofAutofocus> autofocus;
    if (options.autofocus) {
        // As apply does: the limit holds the radii of every focus autofocus can choose.
        const FocusRange range = autofocusRange(lens, depth.projection);
        autofocus = makeAutofocus(lens, depth.projection, camera.width, *options.autofocus, range);
        const FocusRange reachable = reachableAutofocus(depth.deviceDepth, camera.width, camera.height,
                                                        depth.projection, *options.autofocus, range);
        for (const double focus : {reachable.nearest, reachable.farthest}) {
            ThinLens at = lens;
            at.focusDistance = focus;
            largestRadius = std::fmax(
                largestRadius,
                largestCocRadius(depth.deviceDepth,
                                 computeCocParameters(at, depth.projection, camera.width, depth.projectionOrigin)));
        }
    } else {
        coc = computeCocParameters(lens, depth.projection, camera.width, depth.projectionOrigin);
        largestRadius = largestCocRadius(depth.deviceDepth, coc);
    }
    EffectOptions effect = options.effect;
    effect.cocLimit = effectiveCocLimit(options.effect, largestRadius, camera.height);
    const vkrun::RunResult result = runEffectOrThrow(
        *device, toHostImage(pinhole.color), toHostImage(camera.width, camera.height, depth.deviceDepth),
        makeRunSettings(effect, coc, depth.projection.reversed, autofocus ? &*autofocus : nullptr));
    const io::ImageRGBA output = toImageRGBA(result.output);
    if (autofocus) {
        // The radii and clamp of the chosen focus. The truth keeps the scene's focus (a focus of its own
        // would change the framing: the image distance moves with the focus).
        lens.focusDistance = result.autofocusDistance;
        coc = computeCocParameters(lens, depth.projection, camera.width, depth.projectionOrigin);
        largestRadius = largestCocRadius(depth.deviceDepth, coc);
    }

    std::vector<std::string> written;
    const auto write = [&](const char* name, auto&& writeFile) {
        const std::string path = (directory / name).string();
        try {
            writeFile(path);
        } catch (const io::IoError& ioError) {
            throw CliError(ExitCode::OutputWrite, ioError.what());
        }
        written.push_back(path);
    };
    const auto writeColorExr = [&](const std::string& path, const io::ImageRGBA& image) {
        io::writeExr(path, image, chooseExrPixelType(options.outType, image, path));
    };
    write("input.exr", [&](const std::string& path) { writeColorExr(path, pinhole.color); });
    write("input.png", [&](const std::string& path) { io::writePng(path, pinhole.color); });
    write("depth.exr",
          [&](const std::string& path) { io::writeExr(path, pinhole.depth, io::ExrPixelType::Float, "Z"); });
    write("output.exr", [&](const std::string& path) { writeColorExr(path, output); });
    write("output.png", [&](const std::string& path) { io::writePng(path, output); });
    write("truth.exr", [&](const std::string& path) { writeColorExr(path, truth.color); });
    write("truth.png", [&](const std::string& path) { io::writePng(path, truth.color); });
    write("side-by-side.png", [&](const std::string& path) {
        io::writePng(path, sideBySide({&pinhole.color, &output, &truth.color}));
    });
    write("camera.json", [&](const std::string& path) { ref::writeCameraJson(path, camera); });

    std::printf("applied depth of field on %s: focus %.2f m, f/%.2f, %.0f mm\n", device->name().c_str(),
                lens.focusDistance, camera.fstop(), camera.focalLength * 1000.0);
    if (autofocus) {
        std::printf("%s (autofocus at %g,%g, region %g; the scene's camera and the truth focus at %.2f m)\n",
                    focusText(lens.focusDistance).c_str(), options.autofocus->x, options.autofocus->y,
                    options.autofocus->size, camera.focusDistance);
    }
    size_t clamped = 0;
    const float radiusLimit = float(effect.cocLimit * camera.height * 0.5);
    for (float d : depth.deviceDepth) clamped += std::fabs(d * coc.cocScale + coc.cocBias) > radiusLimit;
    if (options.effect.cocLimitFollowsImage) {
        std::printf("largest CoC radius %.2f half-res px; no clamp (cocLimitFactor %.4g follows the image)\n",
                    largestRadius, effect.cocLimit);
    } else {
        std::printf("largest CoC radius %.2f half-res px; --coc-limit %g clamps %zu pixels at %.2f half-res px\n",
                    largestRadius, effect.cocLimit, clamped, radiusLimit);
    }
    std::printf("truth convergence (RMS, half vs all lens samples): %.4f\n", truth.convergenceRms);
    const io::ImageR radius = metrics::cocRadiusMap(camera, pinhole.depth);
    const metrics::Comparison inputScore = metrics::compareImages(truth.color, pinhole.color, &radius);
    const metrics::Comparison outputScore = metrics::compareImages(truth.color, output, &radius);
    std::printf("PSNR against the truth: input %.2f dB, ffx-dof %.2f dB; SSIM: input %.4f, ffx-dof %.4f\n",
                inputScore.psnr, outputScore.psnr, inputScore.ssim, outputScore.ssim);
    std::printf("wrote:\n");
    for (const std::string& path : written) std::printf("  %s\n", path.c_str());
    std::printf("side-by-side.png is input | ffx-dof | thin-lens truth\n");
}

}  // namespace ffxdof::cli
