// ffx-dof compare: PSNR and SSIM of a test image against a reference, and PSNR per depth-of-field
// region when the reference render's depth and camera are given (tools/metrics does the figures).
#include "cli_error.h"
#include "commands.h"
#include "ffx_dof_metrics.h"
#include "sequence.h"

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

// Two sequences frame by frame: mean PSNR and SSIM, and how much each changes from frame to frame.
void compareSequences(const CompareOptions& options) {
    if (!options.depthPath.empty()) {
        throw CliError(ExitCode::Usage, "--depth and --camera apply to single images, not to --frames");
    }
    const FramePattern reference(options.referencePath, "--ref"), test(options.testPath, "--test");
    if (!reference.hasField() || !test.hasField()) {
        throw CliError(ExitCode::Usage, "--frames needs a frame-number field (#### or %04d) in --ref and --test");
    }
    const std::vector<int64_t> frames = parseFrameList(options.frames);
    metrics::TemporalChange referenceChange, testChange;
    double psnrSum = 0.0, ssimSum = 0.0;
    for (int64_t frame : frames) {
        const io::ImageRGBA ref = readInput([&] { return io::readExrColor(reference.path(frame)); });
        const io::ImageRGBA out = readInput([&] { return io::readExrColor(test.path(frame)); });
        requireSize(out.width, out.height, ref, test.path(frame));
        try {
            referenceChange.add(ref);
            testChange.add(out);
        } catch (const std::invalid_argument&) {
            throw CliError(ExitCode::InvalidValue, reference.path(frame) + ": the frames of a sequence differ in size");
        }
        const metrics::Comparison comparison = metrics::compareImages(ref, out);
        psnrSum += comparison.psnr;
        ssimSum += comparison.ssim;
    }
    const double count = double(frames.size());
    std::printf("frames %lld to %lld (%zu): mean psnr %.2f dB, mean ssim %.4f\n",
                static_cast<long long>(frames.front()), static_cast<long long>(frames.back()), frames.size(),
                psnrSum / count, ssimSum / count);
    if (referenceChange.pairs() > 0) {
        std::printf(
            "frame-to-frame change (mean |luminance difference|): reference %.5f, test %.5f, "
            "flicker ratio %.3f\n",
            referenceChange.mean(), testChange.mean(),
            referenceChange.mean() > 0.0 ? testChange.mean() / referenceChange.mean() : 0.0);
    }
}

}  // namespace

void runCompare(const CompareOptions& options) {
    if (!options.frames.empty()) {
        compareSequences(options);
        return;
    }
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
