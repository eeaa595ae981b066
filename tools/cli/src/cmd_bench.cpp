// ffx-dof bench: GPU timestamps of every pass, the total, the internal memory, a plain copy pass
// measured in the same run (the device floor), the host CPU time of recording one dispatch and of
// creating the context (the first, and again at half the size), on a reproducible procedural scene (a
// built-in scene of the reference renderer, the floor by default).
#include "cli_error.h"
#include "commands.h"
#include "effect_run.h"
#include "ffx_dof_reference.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>
#include <ctime>
#include <optional>
#include <stdexcept>
#include <string>

namespace ffxdof::cli {
namespace {

// ffxDofContextDispatch calls timed on the host (recorded, never submitted) after the GPU runs.
constexpr uint32_t kHostRecordCalls = 1000;

std::string utcDate() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof(text), "%Y-%m-%d", std::gmtime(&now));
    return text;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n == 0 ? 0.0 : (n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]));
}

double blurAndCompositeMs(const vkrun::RunResult& result) {
    double sum = 0.0;
    for (uint32_t pass = 0; pass < vkrun::kPassCount; ++pass) {
        const std::string name = vkrun::passName(pass);
        if (name == "blur" || name == "composite") sum += result.passMilliseconds[pass];
    }
    return sum;
}

// The given aperture against the round one: `repeat` pairs of single dispatches, in turn. Each side
// has a context of its own and the GPU idles while the host makes it; on a GPU these dispatches run
// cold (an H200: about 4 ms, against 0.74 ms in a run of 50 back to back; 3 dispatches per context
// measured the same, so not the context's first use): the ratio compares, the milliseconds do not.
struct ApertureCost {
    double shapedMs = 0.0;  // median blur + composite
    double roundMs = 0.0;
    double ratio = 0.0;  // median over pairs of shaped / round
};
ApertureCost measureAgainstRound(vkrun::Device& device, const vkrun::HostImage& color, const vkrun::HostImage& depth,
                                 vkrun::RunSettings settings, uint32_t repeat) {
    settings.repeat = 1;
    settings.measureCopyPass = false;
    settings.hostRecordCalls = 0;
    vkrun::RunSettings round = settings;
    round.aperture = FfxDofAperture{0, 0.0f, 0.0f, 1.0f, 0.0f};
    std::vector<double> shaped, circle, ratios;
    for (uint32_t i = 0; i < repeat; ++i) {
        shaped.push_back(blurAndCompositeMs(runEffectOrThrow(device, color, depth, settings)));
        circle.push_back(blurAndCompositeMs(runEffectOrThrow(device, color, depth, round)));
        ratios.push_back(shaped.back() / circle.back());
    }
    return {median(shaped), median(circle), median(ratios)};
}

}  // namespace

void runBench(const BenchOptions& options) {
    checkEffectOptions(options.effect);
    if (options.width < 1 || options.height < 1 || options.width > FFX_DOF_MAX_RESOLUTION ||
        options.height > FFX_DOF_MAX_RESOLUTION) {
        throw CliError(ExitCode::InvalidValue,
                       "--width and --height must be 1 to " + std::to_string(FFX_DOF_MAX_RESOLUTION) + ", got " +
                           std::to_string(options.width) + "x" + std::to_string(options.height));
    }
    if (options.repeat < 1 || options.repeat > 10000) {
        throw CliError(ExitCode::InvalidValue, "--repeat must be 1 to 10000, got " + std::to_string(options.repeat));
    }
    if (options.autofocus) checkAutofocusRegion(*options.autofocus);

    ref::SceneSetup setup;
    try {
        setup = ref::makeScene(options.scene, options.width, options.height);
    } catch (const std::invalid_argument& error) {
        throw CliError(ExitCode::InvalidValue, std::string("--scene: ") + error.what());
    }
    ref::RenderSettings renderSettings;
    const ref::PinholeImages pinhole = ref::renderPinhole(setup.scene, setup.camera, renderSettings);

    const ThinLens lens{setup.camera.apertureRadius, setup.camera.focalLength, setup.camera.focusDistance,
                        setup.camera.sensorWidth};
    const EffectDepth depth = linearToEffectDepth(pinhole.depth, "bench scene depth");
    const CocParameters coc = computeCocParameters(lens, depth.projection, options.width);

    std::optional<FfxDofAutofocus> autofocus;
    if (options.autofocus) {
        autofocus = makeAutofocus(lens, depth.projection, options.width, *options.autofocus,
                                  autofocusRange(lens, depth.projection));
    }

    std::unique_ptr<vkrun::Device> device = openDevice(options.effect);
    vkrun::RunSettings settings =
        makeRunSettings(options.effect, coc, depth.projection.reversed, autofocus ? &*autofocus : nullptr);
    // What an engine would typically bind: half-float color and output.
    settings.colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    settings.outputFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    settings.repeat = options.repeat;
    settings.measureCopyPass = true;
    settings.forceFloat32 = options.float32;
    settings.hostRecordCalls = kHostRecordCalls;
    const vkrun::RunResult result = runEffectOrThrow(
        *device, toHostImage(pinhole.color), toHostImage(options.width, options.height, depth.deviceDepth), settings);

    // A context made again at another resolution (a resized window): the backend kept the pipelines.
    const uint32_t resizedWidth = std::max(1u, options.width / 2), resizedHeight = std::max(1u, options.height / 2);
    const double contextCreateAgainMs = vkrun::timeContextCreate(*device, settings, resizedWidth, resizedHeight);

    std::optional<ApertureCost> apertureCost;
    if (options.againstRound) {
        apertureCost = measureAgainstRound(*device, toHostImage(pinhole.color),
                                           toHostImage(options.width, options.height, depth.deviceDepth), settings,
                                           options.repeat);
    }

    const double ratio = result.totalMilliseconds / result.copyPassMilliseconds;
    double autofocusMilliseconds = 0.0;
    for (uint32_t pass = 0; pass < vkrun::kPassCount; ++pass) {
        if (std::string(vkrun::passName(pass)) == "autofocus") autofocusMilliseconds = result.passMilliseconds[pass];
    }
    const double autofocusShare =
        result.totalMilliseconds > 0.0 ? autofocusMilliseconds / result.totalMilliseconds : 0.0;
    const vkrun::DeviceFeatures& features = device->features();
    // The backend runs the 16-bit shaders wherever shaderFloat16 is enabled (ffx_dof_vk.h).
    const bool float16 = !options.float32 && features.shaderFloat16;
    if (options.json) {
        nlohmann::ordered_json json;
        json["date"] = utcDate();
        json["device"] = device->name();
        json["width"] = options.width;
        json["height"] = options.height;
        json["quality"] = options.effect.quality;
        json["cocLimit"] = options.effect.cocLimit;
        json["ringMerge"] = !options.effect.noRingMerge;
        json["float16"] = float16;
        json["scene"] = options.scene;
        json["repeat"] = options.repeat;
        nlohmann::ordered_json passes;
        for (uint32_t pass = 0; pass < vkrun::kPassCount; ++pass) {
            passes[vkrun::passName(pass)] = result.passMilliseconds[pass];
        }
        json["passMs"] = passes;
        json["totalMs"] = result.totalMilliseconds;
        json["copyMs"] = result.copyPassMilliseconds;
        json["ratio"] = ratio;
        json["memoryBytes"] = result.internalMemoryBytes;
        json["aliasableMemoryBytes"] = result.aliasableMemoryBytes;
        json["hostRecordUs"] = result.hostRecordMicroseconds;
        json["hostRecordCalls"] = kHostRecordCalls;
        json["contextCreateMs"] = {{"first", result.contextCreateMilliseconds},
                                   {"again", contextCreateAgainMs},
                                   {"againWidth", resizedWidth},
                                   {"againHeight", resizedHeight}};
        if (options.autofocus) {
            json["autofocus"] = {
                {"x", options.autofocus->x}, {"y", options.autofocus->y}, {"region", options.autofocus->size}};
            json["autofocusDistance"] = result.autofocusDistance;
            json["autofocusShare"] = autofocusShare;  // passMs.autofocus / totalMs
        }
        if (apertureCost) {
            json["againstRound"] = {{"blurCompositeMs", apertureCost->shapedMs},
                                    {"roundBlurCompositeMs", apertureCost->roundMs},
                                    {"ratio", apertureCost->ratio}};
        }
        std::printf("%s\n", json.dump(2).c_str());
        return;
    }
    std::printf("ffx-dof bench, %s, %s\n", utcDate().c_str(), device->name().c_str());
    std::printf("%ux%u, quality %u, coc-limit %g, ring merge %s, 16-bit %s, scene %s, median of %u\n", options.width,
                options.height, options.effect.quality, options.effect.cocLimit,
                options.effect.noRingMerge ? "off" : "on", float16 ? "yes" : "no", options.scene.c_str(),
                options.repeat);
    for (uint32_t pass = 0; pass < vkrun::kPassCount; ++pass) {
        std::printf("  %-24s %10.3f ms\n", vkrun::passName(pass), result.passMilliseconds[pass]);
    }
    std::printf("  %-24s %10.3f ms\n", "total", result.totalMilliseconds);
    std::printf("  %-24s %10.3f ms\n", "copy pass (floor)", result.copyPassMilliseconds);
    std::printf("  %-24s %10.2f\n", "ratio total / copy", ratio);
    std::printf("  %-24s %10llu bytes (%.2f MiB), aliasable %llu bytes\n", "internal memory",
                static_cast<unsigned long long>(result.internalMemoryBytes),
                double(result.internalMemoryBytes) / (1024.0 * 1024.0),
                static_cast<unsigned long long>(result.aliasableMemoryBytes));
    std::printf("  %-24s %10.1f us (median of %u ffxDofContextDispatch calls)\n", "host record",
                result.hostRecordMicroseconds, kHostRecordCalls);
    std::printf("  %-24s %10.1f ms the first (compiles the pipelines), %.1f ms again at %ux%u (a resize)\n",
                "context create", result.contextCreateMilliseconds, contextCreateAgainMs, resizedWidth, resizedHeight);
    if (apertureCost) {
        std::printf("  %-24s %10.3f (blur + composite %.3f ms against %.3f ms round; median of %u pairs in turn)\n",
                    "aperture / round", apertureCost->ratio, apertureCost->shapedMs, apertureCost->roundMs,
                    options.repeat);
    }
    if (options.autofocus) {
        std::printf("  %-24s %10.3g %% of the total (%.3f of %.3f ms); %s (autofocus at %g,%g, region %g)\n",
                    "autofocus share", 100.0 * autofocusShare, autofocusMilliseconds, result.totalMilliseconds,
                    focusText(result.autofocusDistance).c_str(), options.autofocus->x, options.autofocus->y,
                    options.autofocus->size);
    }
}

}  // namespace ffxdof::cli
