// ffx-dof-reference: renders a built-in scene's pinhole colour, depths, thin-lens ground truth and
// camera to a folder. Exit codes: 0 success, 1 bad arguments, 2 file error, 3 other failure.
#include "ffx_dof_reference.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace {

enum ExitCode { kOk = 0, kBadArguments = 1, kFileError = 2, kFailure = 3 };

struct CameraOverrides {
    std::optional<double> focus, fstop, apertureRadius, focalLengthMm, sensorWidthMm, fovDegrees, nearPlane, farPlane;
    std::vector<double> position, lookAt;
    std::optional<uint32_t> blades;
    std::optional<double> bladeRotationDegrees, roundness, anamorphicRatio, catEye;
};

void applyOverrides(ffxdof::ref::Camera& camera, const CameraOverrides& o) {
    // Keep the scene's f-stop when only the focal length or focus changes.
    const double fstop = camera.fstop();
    if (o.position.size() == 3) camera.position = {o.position[0], o.position[1], o.position[2]};
    if (o.lookAt.size() == 3) camera.target = {o.lookAt[0], o.lookAt[1], o.lookAt[2]};
    if (o.sensorWidthMm) camera.sensorWidth = *o.sensorWidthMm * 1e-3;
    if (o.focus) camera.focusDistance = *o.focus;
    if (o.focalLengthMm) camera.focalLength = *o.focalLengthMm * 1e-3;
    if (o.fovDegrees) camera.setVerticalFov(*o.fovDegrees * M_PI / 180.0);
    if (fstop > 0.0) camera.setFstop(fstop);
    if (o.fstop) camera.setFstop(*o.fstop);
    if (o.apertureRadius) camera.apertureRadius = *o.apertureRadius;
    if (o.nearPlane) camera.nearPlane = *o.nearPlane;
    if (o.farPlane) camera.farPlane = *o.farPlane;
    if (o.blades) camera.aperture.bladeCount = *o.blades;
    if (o.bladeRotationDegrees) camera.aperture.bladeRotationDegrees = *o.bladeRotationDegrees;
    if (o.roundness) camera.aperture.roundness = *o.roundness;
    if (o.anamorphicRatio) camera.aperture.anamorphicRatio = *o.anamorphicRatio;
    if (o.catEye) camera.aperture.catEye = *o.catEye;
    camera.validate();
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Renders the ground truth for ffx-dof: pinhole colour, depths, thin-lens image and camera."};
    std::string sceneName, outDir;
    uint32_t width = 320, height = 180, lensSamples = 256, threads = 0;
    bool list = false, previews = false;
    CameraOverrides overrides;
    app.add_flag("--list", list, "list the built-in scenes and exit");
    app.add_option("--scene", sceneName, "scene name (see --list)");
    app.add_option("--width", width, "image width in pixels")->check(CLI::Range(1u, 16384u));
    app.add_option("--height", height, "image height in pixels")->check(CLI::Range(1u, 16384u));
    app.add_option("--lens-samples", lensSamples, "thin-lens samples per pixel")->check(CLI::Range(1u, 1u << 20));
    app.add_option("--threads", threads, "worker threads (0: all cores)");
    app.add_option("--out", outDir, "output folder (created if missing; files in it are replaced)");
    app.add_flag("--png", previews, "also write color.png and truth.png previews (8-bit sRGB)");
    app.add_option("--focus", overrides.focus, "focus distance, metres");
    app.add_option("--fstop", overrides.fstop, "f-number (aperture radius = focal length / (2 fstop))");
    app.add_option("--aperture-radius", overrides.apertureRadius, "aperture radius, metres")->excludes("--fstop");
    app.add_option("--focal-length", overrides.focalLengthMm, "focal length, millimetres");
    app.add_option("--sensor-width", overrides.sensorWidthMm, "sensor width, millimetres");
    app.add_option("--fov", overrides.fovDegrees, "vertical field of view, degrees (sets the focal length)")
        ->excludes("--focal-length");
    app.add_option("--near", overrides.nearPlane, "near plane of the device depth, metres");
    app.add_option("--far", overrides.farPlane, "far plane of the device depth, metres");
    app.add_option("--position", overrides.position, "camera position x y z, metres")->expected(3);
    app.add_option("--look-at", overrides.lookAt, "point the camera looks at, x y z")->expected(3);
    const CLI::Validator bladeCount(
        [](std::string& value) {
            const std::string message = "must be 0 (round) or 3 to 16";
            try {
                size_t end = 0;
                const long count = std::stol(value, &end);
                return end == value.size() && (count == 0 || (count >= 3 && count <= 16)) ? std::string() : message;
            } catch (const std::exception&) {
                return message;
            }
        },
        "0 or 3..16");
    const CLI::Validator finite(
        [](std::string& value) {
            try {
                size_t end = 0;
                const double number = std::stod(value, &end);
                return end == value.size() && std::isfinite(number) ? std::string() : std::string("must be finite");
            } catch (const std::exception&) {
                return std::string("must be a number");
            }
        },
        "FINITE");
    app.add_option("--blades", overrides.blades, "aperture blades: 0 round (default), 3 to 16 a polygon")
        ->check(bladeCount);
    app.add_option("--blade-rotation", overrides.bladeRotationDegrees,
                   "blade rotation, degrees, counter-clockwise (0: a flat side facing right)")
        ->check(finite);
    app.add_option("--roundness", overrides.roundness, "blade roundness: 0 straight blades to 1 a circle")
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--anamorphic", overrides.anamorphicRatio,
                   "anamorphic squeeze s: the aperture is s times taller than wide")
        ->check(CLI::Range(0.5, 2.0));
    app.add_option("--cat-eye", overrides.catEye, "cat's-eye vignetting strength: 0 off to 1")
        ->check(CLI::Range(0.0, 1.0));
    // One line per bad argument, like the other errors below.
    app.failure_message(
        [](const CLI::App*, const CLI::Error& error) { return "error: " + std::string(error.what()) + "\n"; });
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? kOk : kBadArguments;
    }

    if (list) {
        for (const ffxdof::ref::SceneInfo& scene : ffxdof::ref::listScenes()) {
            std::printf("%-16s %s\n", scene.name.c_str(), scene.description.c_str());
        }
        return kOk;
    }
    if (sceneName.empty() || outDir.empty()) {
        std::fprintf(stderr, "error: --scene and --out are required (or --list)\n");
        return kBadArguments;
    }

    ffxdof::ref::SceneSetup setup;
    try {
        setup = ffxdof::ref::makeScene(sceneName, width, height);
        applyOverrides(setup.camera, overrides);
    } catch (const std::invalid_argument& error) {
        std::fprintf(stderr, "error: %s\n", error.what());
        return kBadArguments;
    }

    try {
        std::error_code ec;
        std::filesystem::create_directories(outDir, ec);
        if (!std::filesystem::is_directory(outDir)) {
            std::fprintf(stderr, "error: cannot create output folder %s\n", outDir.c_str());
            return kFileError;
        }
        const std::filesystem::path out(outDir);
        ffxdof::ref::RenderSettings settings;
        settings.lensSamples = lensSamples;
        settings.threads = threads;

        auto start = std::chrono::steady_clock::now();
        const ffxdof::ref::PinholeImages pinhole = ffxdof::ref::renderPinhole(setup.scene, setup.camera, settings);
        std::printf("pinhole   %ux%u: %.2f s\n", width, height, secondsSince(start));
        start = std::chrono::steady_clock::now();
        const ffxdof::ref::ThinLensImage truth = ffxdof::ref::renderThinLens(setup.scene, setup.camera, settings);
        std::printf("thin lens %ux%u, %u lens samples: %.2f s, convergence (RMS change N/2 -> N): %.5f\n", width,
                    height, lensSamples, secondsSince(start), truth.convergenceRms);

        using ffxdof::io::ExrPixelType;
        ffxdof::io::writeExr((out / "color.exr").string(), pinhole.color, ExrPixelType::Float);
        ffxdof::io::writeExr((out / "depth.exr").string(), pinhole.depth, ExrPixelType::Float, "Z");
        ffxdof::io::writeExr((out / "depth_device.exr").string(), pinhole.deviceDepth, ExrPixelType::Float, "Z");
        ffxdof::io::writeExr((out / "depth_device_reversed.exr").string(), pinhole.deviceDepthReversed,
                             ExrPixelType::Float, "Z");
        ffxdof::io::writeExr((out / "truth.exr").string(), truth.color, ExrPixelType::Float);
        if (previews) {
            ffxdof::io::writePng((out / "color.png").string(), pinhole.color);
            ffxdof::io::writePng((out / "truth.png").string(), truth.color);
        }
        ffxdof::ref::writeCameraJson((out / "camera.json").string(), setup.camera);
        const ffxdof::ref::Camera& camera = setup.camera;
        std::printf("scene %s: focus %.3f m, f %.1f mm, f/%.2f (aperture radius %.3f mm); wrote %s\n",
                    setup.name.c_str(), camera.focusDistance, camera.focalLength * 1e3, camera.fstop(),
                    camera.apertureRadius * 1e3, outDir.c_str());
    } catch (const ffxdof::io::IoError& error) {
        std::fprintf(stderr, "error: %s\n", error.what());
        return kFileError;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "error: %s\n", error.what());
        return kFailure;
    }
    return kOk;
}
