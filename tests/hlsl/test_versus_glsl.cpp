// The HLSL-compiled SPIR-V against the GLSL-compiled SPIR-V, run through the Vulkan backend on the
// same device, inputs and settings, for every permutation lavapipe can run: FFX_HALF 0/1 x reversed
// depth 0/1 x ring merge 0/1 x in-place 0/1 (FFX_DOF_OPTION_WAVE64=1 needs 64-wide subgroups).
//
// Both languages are compiled from the same algorithm headers, so they must compute the same image up
// to floating-point rounding (instruction order, fused multiply-adds, 16-bit intermediates). The
// thresholds (measured on lavapipe with headroom; docs/integration-d3d12.md, "HLSL on lavapipe") are:
//   PSNR (clamped to [0, 1], peak 1)                 >= kMinPsnrDb
//   max |difference| (clamped to [0, 1])             <= kMaxAbsDifference
//   max |difference| / max(1, |glsl|) (unclamped)    <= kMaxRelativeDifference  (HDR highlights)
// A semantic difference between the HLSL and GLSL callbacks (a wrong sign, a swapped channel, a lost
// saturate, a different LOD) moves whole regions and fails all three by a wide margin.
#include "hlsl_test_support.h"

#include "ffx_dof_metrics.h"

#include <cmath>
#include <cstdio>

using namespace ffxdof;
using namespace ffxdof::hlsltest;

namespace {

constexpr double kMinPsnrDb = 60.0;
constexpr double kMaxAbsDifference = 0.02;
constexpr double kMaxRelativeDifference = 0.02;

struct Permutation {
    bool half, reversedDepth, ringMerge, inPlace;
};

std::string describe(const Permutation& p) {
    return std::string("FFX_HALF=") + (p.half ? "1" : "0") + " reverse=" + (p.reversedDepth ? "1" : "0") +
           " ringMerge=" + (p.ringMerge ? "1" : "0") + " inPlace=" + (p.inPlace ? "1" : "0");
}

io::ImageRGBA toImage(const vkrun::HostImage& host) {
    REQUIRE(host.channels == 4);
    io::ImageRGBA image(host.width, host.height);
    image.pixels = host.pixels;
    return image;
}

// Largest RGB |a - b| / max(1, |a|): absolute below 1, relative for HDR values (highlights reach tens).
double maxRelativeDifference(const io::ImageRGBA& reference, const io::ImageRGBA& test) {
    double largest = 0.0;
    for (size_t i = 0; i < reference.pixels.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha: not part of the effect's output contract
        const double a = reference.pixels[i], b = test.pixels[i];
        largest = std::max(largest, std::abs(a - b) / std::max(1.0, std::abs(a)));
    }
    return largest;
}

vkrun::HostImage runEffect(const EffectInput& input, const Permutation& permutation, bool useHlsl,
                           const FfxDofAperture& aperture = FfxDofAperture{0, 0.0f, 0.0f, 1.0f, 0.0f}) {
    vkrun::Device& device = validatedDevice();
    vkrun::RunSettings settings;
    settings.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.depthFormat = VK_FORMAT_D32_SFLOAT;
    settings.outputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.quality = 10;
    settings.cocScale = input.cocScale;
    settings.cocBias = input.cocBias;
    settings.cocLimitFactor = input.cocLimitFactor;
    settings.contextFlags = contextFlags(permutation.reversedDepth, permutation.ringMerge);
    settings.inPlace = permutation.inPlace;
    settings.forceFloat32 = !permutation.half;
    settings.useHlsl = useHlsl;
    settings.disableWave64 = true;  // lavapipe has 8-wide subgroups; wave64 is never selected there
    settings.aperture = aperture;
    const vkrun::RunResult result = vkrun::runEffect(device, input.color, input.depth, settings);
    requireNoValidationMessages(device,
                                std::string(useHlsl ? "HLSL " : "GLSL ") + input.name + " " + describe(permutation));
    REQUIRE(result.output.width == input.color.width);
    REQUIRE(result.output.height == input.color.height);
    bool finite = true;
    for (float value : result.output.pixels) finite = finite && std::isfinite(value);
    REQUIRE(finite);
    return result.output;
}

void compareEveryPermutation(const std::string& scene, uint32_t width, uint32_t height) {
    const vkrun::DeviceFeatures& features = validatedDevice().features();
    // Without these the backend silently runs the 32-bit shaders for FFX_HALF=1: the half cases would
    // test nothing. Lavapipe has both.
    INFO("device " << validatedDevice().name());
    REQUIRE(features.shaderFloat16);
    REQUIRE(features.storageBuffer16BitAccess);

    const SceneInputs inputs = makeSceneInputs(scene, width, height);
    bool anyBitDifference = false;
    for (uint32_t bits = 0; bits < 16; ++bits) {
        const Permutation permutation{(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0, (bits & 8) != 0};
        const EffectInput& input = permutation.reversedDepth ? inputs.reversed : inputs.standard;
        CAPTURE(input.name, describe(permutation));
        const io::ImageRGBA glsl = toImage(runEffect(input, permutation, false));
        const io::ImageRGBA hlsl = toImage(runEffect(input, permutation, true));
        const double psnr = metrics::psnr(glsl, hlsl);
        const double maxAbs = metrics::maxAbsDifference(glsl, hlsl);
        const double maxRelative = maxRelativeDifference(glsl, hlsl);
        const double psnrVsInput = metrics::psnr(toImage(input.color), glsl);
        anyBitDifference = anyBitDifference || glsl.pixels != hlsl.pixels;
        // The measured figures, for the CI log and for re-deriving the thresholds.
        std::printf("hlsl-vs-glsl: %-32s %-45s psnr %7.2f dB  max|d| %.6f  max rel %.6f  (vs input %.2f dB)\n",
                    input.name.c_str(), describe(permutation).c_str(), psnr, maxAbs, maxRelative, psnrVsInput);
        CHECK(psnr >= kMinPsnrDb);
        CHECK(maxAbs <= kMaxAbsDifference);
        CHECK(maxRelative <= kMaxRelativeDifference);
    }
    std::printf("hlsl-vs-glsl: %s %ux%u: HLSL and GLSL outputs are %s\n", scene.c_str(), width, height,
                anyBitDifference ? "not all bit-identical" : "bit-identical in every permutation");
}

}  // namespace

TEST_CASE("HLSL matches GLSL in every permutation on near-object 96x64", "[vulkan][hlsl]") {
    compareEveryPermutation("near-object", 96, 64);
}

TEST_CASE("HLSL matches GLSL in every permutation on far-highlights 67x41", "[vulkan][hlsl]") {
    compareEveryPermutation("far-highlights", 67, 41);
}

// The aperture's constants reach both languages' shaders alike (docs/aperture.md): odd blades (whose
// near and far discs differ), rounded blades with an anamorphic squeeze, and the cat's eye; the first
// and the last run the general blur pipeline, the second the compact one (docs/permutations.md).
TEST_CASE("HLSL matches GLSL with aperture shapes on far-highlights 67x41", "[vulkan][hlsl][aperture]") {
    const SceneInputs inputs = makeSceneInputs("far-highlights", 67, 41);
    const FfxDofAperture apertures[] = {
        {5, 0.35f, 0.0f, 1.0f, 0.0f}, {6, 0.0f, 0.4f, 1.5f, 0.0f}, {0, 0.0f, 0.0f, 1.0f, 1.0f}};
    for (const FfxDofAperture& aperture : apertures) {
        for (const bool half : {false, true}) {
            const Permutation permutation{half, false, true, false};
            CAPTURE(aperture.bladeCount, aperture.anamorphicRatio, aperture.catEye, describe(permutation));
            const io::ImageRGBA glsl = toImage(runEffect(inputs.standard, permutation, false, aperture));
            const io::ImageRGBA hlsl = toImage(runEffect(inputs.standard, permutation, true, aperture));
            const io::ImageRGBA round = toImage(runEffect(inputs.standard, permutation, false));
            CHECK(metrics::psnr(glsl, hlsl) >= kMinPsnrDb);
            CHECK(metrics::maxAbsDifference(glsl, hlsl) <= kMaxAbsDifference);
            CHECK(maxRelativeDifference(glsl, hlsl) <= kMaxRelativeDifference);
            CHECK(glsl.pixels != round.pixels);  // the aperture reached the shaders
        }
    }
}

// The in-place composite is deterministic. With FFX_DOF_OPTION_OUTPUT_PRE_INIT the output is the colour
// image: the composite once read neighbouring colour pixels for its fixed 3x3 blur that other
// invocations of the same dispatch might already have overwritten, and repeated runs of one binary
// differed by up to about 2e-3 (relative) on lavapipe, about one run in seven. Each workgroup now reads
// its tile into group-shared memory before any write and takes the pixels outside its tile from the
// half-res color (ffx_dof_composite.h), so every run must give the same bits, in both languages.
TEST_CASE("the in-place composite gives the same image on every run", "[vulkan][hlsl][race]") {
    const SceneInputs inputs = makeSceneInputs("near-object", 96, 64);
    for (const bool useHlsl : {false, true}) {
        for (const bool half : {false, true}) {
            const Permutation permutation{half, false, true, true};
            CAPTURE(useHlsl, describe(permutation));
            const vkrun::HostImage first = runEffect(inputs.standard, permutation, useHlsl);
            for (int run = 1; run < 8; ++run) {
                CAPTURE(run);
                const vkrun::HostImage again = runEffect(inputs.standard, permutation, useHlsl);
                CHECK(again.pixels == first.pixels);
            }
        }
    }
}
