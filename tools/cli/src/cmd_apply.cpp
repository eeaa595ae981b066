// ffx-dof apply: EXR color + depth in, the effect on Vulkan, EXR or PNG out.
#include "cli_error.h"
#include "commands.h"
#include "effect_run.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include <sys/stat.h>

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
    if (options.outType != "auto" && !io::hasExtension(options.outputPath, ".exr")) {
        throw CliError(ExitCode::Usage, "--out-type applies to .exr outputs only: " + options.outputPath);
    }
    checkEffectOptions(options.effect);
}

// Writing the output over an input would destroy it (and a depth file turned into RGBA breaks the next
// run). Files are compared by device and inode, with symbolic links followed, so every spelling of the
// same file is caught: "./c.exr", an absolute path, a symbolic link, a hard link.
void checkOutputIsNoInput(const ApplyOptions& options) {
    struct stat output {};
    if (::stat(options.outputPath.c_str(), &output) != 0) return;  // not there yet: it cannot be an input
    for (const auto& [option, path] :
         {std::pair{"--color", &options.colorPath}, std::pair{"--depth", &options.depthPath}}) {
        struct stat input {};
        if (::stat(path->c_str(), &input) == 0 && input.st_dev == output.st_dev && input.st_ino == output.st_ino) {
            throw CliError(ExitCode::Usage, "--out " + options.outputPath + " is the same file as " + option + " " +
                                                *path + "; writing it would destroy the input");
        }
    }
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
    checkOutputIsNoInput(options);
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
        effectDepth.projectionOrigin = options.projection ? "--proj" : "--near/--far";
    }
    const CocParameters coc =
        computeCocParameters(lens, effectDepth.projection, color.width, effectDepth.projectionOrigin);

    float largestRadius = 0.0f;
    for (float d : effectDepth.deviceDepth) {
        largestRadius = std::fmax(largestRadius, std::fabs(d * coc.cocScale + coc.cocBias));
    }
    const double radiusLimit = options.effect.cocLimit * color.height * 0.5;

    std::unique_ptr<vkrun::Device> device = openDevice(options.effect);
    const vkrun::RunResult result =
        runEffectOrThrow(*device, toHostImage(color), toHostImage(depth.width, depth.height, effectDepth.deviceDepth),
                         makeRunSettings(options.effect, coc, effectDepth.projection.reversed));

    const io::ImageRGBA output = toImageRGBA(result.output);
    const io::ExrPixelType exrType = chooseExrPixelType(options.outType, output, options.outputPath);
    writeOutput(options.outputPath, output, exrType);
    const bool exr = io::hasExtension(options.outputPath, ".exr");
    std::printf("wrote %s (%ux%u%s) on %s\n", options.outputPath.c_str(), color.width, color.height,
                exr ? (exrType == io::ExrPixelType::Half ? ", half" : ", float") : "", device->name().c_str());
    std::printf("largest CoC radius %.2f half-res px, limit %.2f (--coc-limit %g); aperture radius %.4g m\n",
                largestRadius, radiusLimit, options.effect.cocLimit, lens.apertureRadius);
}

}  // namespace ffxdof::cli
