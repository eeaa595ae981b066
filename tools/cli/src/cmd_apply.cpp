// ffx-dof apply: EXR color + depth in, the effect on Vulkan, EXR or PNG out.
#include "cli_error.h"
#include "commands.h"
#include "effect_run.h"

#include <cmath>
#include <cstdio>

namespace ffxdof::cli {
namespace {

// Everything that can be checked without reading a file, so a typo costs no device start-up.
void checkArguments(const ApplyOptions& options) {
    if (!io::hasExtension(options.outputPath, ".exr") && !io::hasExtension(options.outputPath, ".png")) {
        throw CliError(ExitCode::Usage, "--out must end in .exr or .png: " + options.outputPath);
    }
    for (const std::string* input : {&options.colorPath, &options.depthPath}) {
        if (!io::hasExtension(*input, ".exr")) {
            throw CliError(ExitCode::InputFile, "inputs must be OpenEXR files (.exr): " + *input);
        }
    }
    checkEffectOptions(options.effect);
}

DepthProjection deviceProjection(const ApplyOptions& options) {
    if (options.projection) {
        return projectionFromMatrix(*options.projection, options.reverseDepth);
    }
    return projectionFromNearFar(*options.nearPlane, *options.farPlane, options.reverseDepth);
}

}  // namespace

void runApply(const ApplyOptions& options) {
    checkArguments(options);
    const ThinLens lens = makeThinLens(options.lens);
    // Validates the projection before the (possibly large) files are read.
    std::optional<DepthProjection> projection;
    if (options.depthKind == DepthKind::Device) {
        projection = deviceProjection(options);
    }

    const io::ImageRGBA color = readInput([&] { return io::readExrColor(options.colorPath, options.colorLayer); });
    const io::ImageR depth = readInput([&] { return io::readExrChannel(options.depthPath, options.depthChannel); });
    checkResolutions(color, options.colorPath, depth, options.depthPath);
    checkColorFinite(color, options.colorPath);

    EffectDepth effectDepth;
    if (options.depthKind == DepthKind::Linear) {
        effectDepth = linearToEffectDepth(depth, options.depthPath);
    } else {
        checkDeviceDepth(depth, options.depthPath);
        effectDepth.deviceDepth = depth.pixels;
        effectDepth.projection = *projection;
    }
    const CocParameters coc = computeCocParameters(lens, effectDepth.projection, color.width);

    float largestRadius = 0.0f;
    for (float d : effectDepth.deviceDepth) {
        largestRadius = std::fmax(largestRadius, std::fabs(d * coc.cocScale + coc.cocBias));
    }
    const double radiusLimit = options.effect.cocLimit * color.height * 0.5;

    std::unique_ptr<vkrun::Device> device = openDevice(options.effect);
    const vkrun::RunResult result =
        runEffectOrThrow(*device, toHostImage(color), toHostImage(depth.width, depth.height, effectDepth.deviceDepth),
                         makeRunSettings(options.effect, coc, effectDepth.projection.reversed));

    writeOutput(options.outputPath, toImageRGBA(result.output));
    std::printf("wrote %s (%ux%u) on %s\n", options.outputPath.c_str(), color.width, color.height,
                device->name().c_str());
    std::printf("largest CoC radius %.2f half-res px, limit %.2f (--coc-limit %g); aperture radius %.4g m\n",
                largestRadius, radiusLimit, options.effect.cocLimit, lens.apertureRadius);
}

}  // namespace ffxdof::cli
