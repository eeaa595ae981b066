// ffx-dof compare: PSNR and SSIM of a test image against a reference, and PSNR per depth-of-field
// region when the reference render's depth and camera are given (tools/metrics does the figures).
#include "cli_error.h"
#include "commands.h"
#include "ffx_dof_metrics.h"

#include <cstdio>
#include <string>

namespace ffxdof::cli {
namespace {

void requireSize(uint32_t width, uint32_t height, const io::ImageRGBA& reference, const std::string& what) {
    if (width != reference.width || height != reference.height) {
        throw CliError(ExitCode::InvalidValue, what + " is " + std::to_string(width) + "x" + std::to_string(height) +
                                                   " but the reference is " + std::to_string(reference.width) + "x" +
                                                   std::to_string(reference.height));
    }
}

}  // namespace

void runCompare(const CompareOptions& options) {
    const io::ImageRGBA reference = readInput([&] { return io::readExrColor(options.referencePath); });
    const io::ImageRGBA test = readInput([&] { return io::readExrColor(options.testPath); });
    requireSize(test.width, test.height, reference, options.testPath);

    io::ImageR radius;
    const bool regions = !options.depthPath.empty();
    if (regions) {
        const io::ImageR depth = readInput([&] { return io::readExrChannel(options.depthPath); });
        requireSize(depth.width, depth.height, reference, options.depthPath);
        checkLinearDepth(depth, options.depthPath);
        const ref::Camera camera = readInput([&] { return ref::readCameraJson(options.cameraPath); });
        requireSize(camera.width, camera.height, reference, options.cameraPath + " (camera)");
        radius = metrics::cocRadiusMap(camera, depth);
    }
    const metrics::Comparison comparison = metrics::compareImages(reference, test, regions ? &radius : nullptr);
    std::printf("%s", metrics::formatComparison(comparison).c_str());
}

}  // namespace ffxdof::cli
