// The quality gates of ffx-dof, shared by the Vulkan tests (test_quality.cpp) and the generator of
// docs/quality.md (quality_report.cpp), so the documented figures are the gated ones.
#pragma once

#include "ffx_dof_metrics.h"
#include "ffx_dof_reference.h"
#include "ffx_dof_vkrun.h"

#include <string>
#include <vector>

namespace ffxdof::quality {

// Resolution and lens samples of every gate (and of the pictures in docs/quality.md).
constexpr uint32_t kWidth = 320;
constexpr uint32_t kHeight = 180;
constexpr uint32_t kLensSamples = 256;
constexpr uint32_t kEffectQuality = 10;

struct SceneGate {
    std::string scene;
    // PSNR(ours, truth) must beat PSNR(pinhole input, truth) by at least this many dB.
    double psnrMarginDb;
    // Why this margin: written into docs/quality.md next to the figures.
    std::string rationale;
    // Whether ffx-dof's overall PSNR reaches the circular gather's (issue 17: an effect that knows depth
    // order must not lose to one that ignores it). false: a known failure, checked as such.
    bool atLeastGather = true;
};
const std::vector<SceneGate>& sceneGates();

// The reference renders of one scene.
struct SceneRender {
    ref::SceneSetup setup;
    ref::PinholeImages pinhole;
    io::ImageRGBA truth;
    double convergenceRms = 0.0;
    io::ImageR radius;  // signed CoC radius, full-resolution pixels (positive near)
};
// A built-in scene rendered through the given aperture (default: round).
SceneRender renderScene(const std::string& scene, uint32_t width = kWidth, uint32_t height = kHeight,
                        uint32_t lensSamples = kLensSamples, const ref::ApertureShape& aperture = {});
// Any scene setup (its camera's aperture included), e.g. one built by the test itself.
SceneRender renderSetup(ref::SceneSetup setup, uint32_t lensSamples = kLensSamples);

// The effect's description of the reference camera's aperture: the same fields, the rotation in
// radians (degrees in ref::ApertureShape). The one conversion between the two.
FfxDofAperture effectAperture(const ref::ApertureShape& shape);

// A plain circular gather: every pixel averages the input over a disc of its own CoC radius, with no
// regard for depth order (sharp foreground bleeds into blurred background: the halo to beat).
io::ImageRGBA circularGatherBaseline(const io::ImageRGBA& color, const io::ImageR& radiusPixels);

// In-focus pixels (|radius| < 1) farther than the largest near-field radius from every near-field
// pixel: the truth shows them unchanged, so ffx-dof must leave them within 1/255 of the input. (In-focus
// pixels that a blurred near object may cover are excluded: there the truth itself changes.)
metrics::Mask undisturbedInFocusMask(const io::ImageR& radiusPixels);

struct GateResult {
    io::ImageRGBA ours, baseline;
    metrics::Comparison input, effect, gather;  // each against the truth, with regions
    double inFocusMaxDifference = 0.0;          // |ours - input| over undisturbedInFocusMask, clamped
    size_t inFocusPixels = 0;
    float cocScale = 0.0f, cocBias = 0.0f, cocLimitFactor = 0.0f;

    bool psnrGate(double marginDb) const { return effect.psnr >= input.psnr + marginDb; }
    bool inFocusGate() const { return inFocusMaxDifference <= 1.0 / 255.0; }
    bool haloGate() const { return !(effect.haloBand.psnr < gather.haloBand.psnr); }  // NaN (empty) passes
    bool gatherGate() const { return effect.psnr >= gather.psnr; }
};
// Runs ffx-dof on the scene's pinhole colour and standard device depth, with cocScale/cocBias from
// ffxDofCalculateCocScale/Bias, a cocLimitFactor that covers the scene's largest radius and the
// aperture of the render's camera (effectAperture).
// inPlace: the output is the color image itself (FFX_DOF_OPTION_OUTPUT_PRE_INIT).
GateResult runGate(vkrun::Device& device, const SceneRender& render, bool inPlace = false);

// The single bright point far behind focus (scene "point") through ffx-dof, measured against the
// thin-lens radius; the energy expected is the input's (ffx-dof spreads what the pinhole image has).
struct PointBokeh {
    SceneRender render;
    GateResult result;
    metrics::BokehCheck truth;
    metrics::BokehCheck ours;
};
PointBokeh measurePointBokeh(vkrun::Device& device);

}  // namespace ffxdof::quality
