// The subcommands of ffx-dof. Each run* function throws CliError on failure and prints what it
// wrote or measured on stdout.
#pragma once

#include "inputs.h"
#include "lens.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace ffxdof::cli {

// The aperture options (docs/aperture.md): --blades, --blade-rotation, --roundness, --anamorphic,
// --cat-eye. The defaults are the round aperture.
struct ApertureOptions {
    uint32_t blades = 0;  // 0 = round, 3..16
    double bladeRotationDegrees = 0.0;
    double roundness = 0.0;        // 0..1
    double anamorphicRatio = 1.0;  // 0.5..2
    double catEye = 0.0;           // 0..1
};

// Effect settings shared by apply, demo and bench.
struct EffectOptions {
    uint32_t quality = 10;   // FfxDofContextDescription::quality, 1..FFX_DOF_MAX_QUALITY
    double cocLimit = 0.05;  // FfxDofContextDescription::cocLimitFactor, finite, >= 0
    // apply and demo without --coc-limit: no clamp; the limit follows each image's largest radius
    // (effectiveCocLimit). bench keeps cocLimit.
    bool cocLimitFollowsImage = false;
    bool noRingMerge = false;  // FFX_DOF_DISABLE_RING_MERGE
    int device = -1;           // Vulkan physical device index; -1 = the first
    bool validate = false;     // Khronos validation layer on; any message fails the command
    ApertureOptions aperture;
};

// The dispatch's aperture (FfxDofDispatchDescription::pAperture) for checked options.
FfxDofAperture toDofAperture(const ApertureOptions& aperture);

// Throws CliError(InvalidValue) for a quality or CoC limit the effect does not accept.
void checkEffectOptions(const EffectOptions& options);

// The cocLimitFactor a run uses: options.cocLimit, or with cocLimitFollowsImage one just above the
// image's largest radius (half-res px) for an image `height` pixels high, at most kLargestAutoCocLimit.
constexpr double kLargestAutoCocLimit = 1.0;
double effectiveCocLimit(const EffectOptions& options, double largestRadius, uint32_t height);

struct ApplyOptions {
    std::string colorPath;
    std::string depthPath;
    std::string outputPath;
    std::string outType = "auto";  // EXR output pixels: "half", "float", or "auto" (see chooseExrPixelType)
    std::string colorLayer;        // empty: the default layer's R, G, B (A)
    std::string depthChannel;      // empty: the file's only channel
    DepthKind depthKind = DepthKind::Linear;
    std::optional<double> nearPlane;
    std::optional<double> farPlane;
    std::optional<std::array<double, 16>> projection;
    bool reverseDepth = false;
    LensSettings lens;
    EffectOptions effect;
    // Sequences (docs/cli.md, "Sequences"): --frames, --chunk, --camera-track, --keep-layers,
    // --overwrite, --no-overlap.
    std::string frames;       // empty: one file per option, no frame numbers
    std::string chunk;        // "I/N" or empty
    std::string cameraTrack;  // JSON or CSV, or empty
    bool focusGiven = true;   // --focus was given (a camera track may supply it instead)
    // --autofocus X,Y [--focus-region R] instead of --focus: the effect chooses each frame's focus.
    std::optional<AutofocusRegion> autofocus;
    bool keepLayers = false;
    bool overwrite = false;
    bool noOverlap = false;  // read, compute and write one frame after the other
};
void runApply(const ApplyOptions& options);

struct DemoOptions {
    std::string outputDirectory = "demo-out";
    std::string scene = "busy-background";  // a built-in scene of the reference renderer
    uint32_t width = 960;
    uint32_t height = 540;
    uint32_t lensSamples = 64;     // thin-lens samples per pixel of the truth
    std::string outType = "auto";  // the EXR images' pixels, as apply's --out-type
    EffectOptions effect;
    // --autofocus: the effect chooses the focus (and the truth is rendered at it) instead of the scene's.
    std::optional<AutofocusRegion> autofocus;
};
void runDemo(const DemoOptions& options);

struct BenchOptions {
    // A built-in scene of the reference renderer. The floor (default) has every tile class of the blur and
    // the composite; mid-lights and far-highlights have small sources above white, which the floor has not.
    std::string scene = "floor";
    uint32_t width = 1920;
    uint32_t height = 1080;
    uint32_t repeat = 20;
    bool json = false;
    bool float32 = false;  // 32-bit shaders even where the device has 16-bit float and storage
    EffectOptions effect;
    std::optional<AutofocusRegion> autofocus;  // --autofocus: the autofocus pass runs (and is timed)
    // --against-round: the aperture options' cost against the round aperture, measured in turn in one
    // process (lavapipe's speed differs from process to process by up to 2x).
    bool againstRound = false;
};
void runBench(const BenchOptions& options);

struct CompareOptions {
    std::string referencePath;
    std::string testPath;
    std::string depthPath;
    std::string cameraPath;
    std::string frames;  // sequences: --ref and --test with a frame-number field; adds the flicker figures
};
void runCompare(const CompareOptions& options);

}  // namespace ffxdof::cli
