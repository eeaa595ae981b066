// ffx-dof: apply the depth-of-field effect to EXR files, run the demo, benchmark, compare images.
// The option table lives here; the work is in the cmd_*.cpp files. See docs/cli.md.
#include "cli_error.h"
#include "commands.h"

#include "ffx_dof.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <exception>
#include <map>
#include <optional>
#include <vector>

namespace ffxdof::cli {

const char* exitCodeTable() {
    return "Exit codes:\n"
           "  0  success\n"
           "  1  usage: unknown or malformed option, missing or conflicting options, unknown output extension\n"
           "  2  input file: missing, unreadable, corrupt, or without the expected channels\n"
           "  3  invalid value: impossible lens or projection, bad depths, mismatched sizes, out-of-range settings\n"
           "  4  device: no usable Vulkan device, or the effect or Vulkan reported an error\n"
           "  5  output: a file or directory could not be written\n"
           "  6  internal error (a bug; please report it)\n"
           "  130  interrupted by SIGINT (Ctrl-C); 143  by SIGTERM: frames written so far are whole, no partial\n"
           "       or temporary file is left\n";
}

namespace {

// CLI11 converts an empty argument to 0 and is lenient with some malformed text, so every numeric
// option checks its text first: the whole argument must be a number (strtod's syntax, so "inf" and
// "nan" reach the range checks, which name them), or for integers digits with an optional sign. A
// failure is a usage error (exit 1) naming the option; range checks come later (exit 3).
const CLI::Validator kNumber(
    [](std::string& text) -> std::string {
        if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) {
            return "expected a number, got '" + text + "'";
        }
        char* end = nullptr;
        (void)std::strtod(text.c_str(), &end);
        return *end == '\0' ? std::string() : "expected a number, got '" + text + "'";
    },
    "NUMBER", "number");

CLI::Validator integerValidator(bool allowNegative) {
    return CLI::Validator(
        [allowNegative](std::string& text) -> std::string {
            size_t digitsFrom = (!text.empty() && (text[0] == '+' || (allowNegative && text[0] == '-'))) ? 1 : 0;
            const bool digitsOnly = text.size() > digitsFrom && text.size() - digitsFrom <= 10 &&
                                    std::all_of(text.begin() + std::ptrdiff_t(digitsFrom), text.end(),
                                                [](char c) { return c >= '0' && c <= '9'; });
            if (!digitsOnly) {
                return std::string(allowNegative ? "expected a whole number" : "expected a whole number, 0 or more") +
                       ", got '" + text + "'";
            }
            return std::string();
        },
        allowNegative ? "INT" : "UINT", allowNegative ? "integer" : "unsigned integer");
}
const CLI::Validator kInteger = integerValidator(true);
const CLI::Validator kUnsigned = integerValidator(false);

// Returns the --coc-limit option. offline: apply and demo, where no --coc-limit means no clamp.
CLI::Option* addEffectOptions(CLI::App& command, EffectOptions& effect, bool offline = false) {
    command.add_option("--quality", effect.quality, "Maximum number of kernel rings, 1 to 32")
        ->check(kUnsigned)
        ->capture_default_str();
    CLI::Option* cocLimit =
        command
            .add_option("--coc-limit", effect.cocLimit,
                        offline ? "Clamp CoC radii at this fraction of the image height (default: no clamp)"
                                : "Largest CoC radius as a fraction of the image height")
            ->check(kNumber);
    if (!offline) cocLimit->capture_default_str();
    command.add_flag("--no-ring-merge", effect.noRingMerge, "Never gather inner rings from coarser MIP levels");
    // Stored through a wider type so that "-1" (the internal "first device" default) typed by a user is
    // refused as the out-of-range index it is instead of selecting the first device.
    command
        .add_option_function<long long>(
            "--device",
            [&effect](const long long& index) {
                if (index < 0 || index > std::numeric_limits<int>::max()) {
                    throw CliError(ExitCode::InvalidValue,
                                   "--device must be a device index, 0 or more, got " + std::to_string(index));
                }
                effect.device = int(index);
            },
            "Vulkan physical device index (default: the first)")
        ->check(kInteger);
    ApertureOptions& aperture = effect.aperture;
    command.add_option("--blades", aperture.blades, "Aperture blades: 0 = round (default), 3 to 16")->check(kUnsigned);
    command
        .add_option("--blade-rotation", aperture.bladeRotationDegrees,
                    "Rotation of the blades, degrees counter-clockwise (0: flat sides left and right)")
        ->check(kNumber);
    command.add_option("--roundness", aperture.roundness, "0 = straight blades to 1 = round")->check(kNumber);
    command
        .add_option("--anamorphic", aperture.anamorphicRatio,
                    "Bokeh height over width, 0.5 to 2 (1.5: 1.5 times taller than wide)")
        ->check(kNumber);
    command.add_option("--cat-eye", aperture.catEye, "Optical vignetting toward the frame's edges, 0 (off) to 1")
        ->check(kNumber);
    command.add_flag("--validate", effect.validate,
                     "Run with the Khronos validation layer (synchronization included); any message is an error");
    return cocLimit;
}

// --autofocus X,Y and --focus-region R (apply, demo, bench). The point's syntax is checked by the parser
// (exit 1 naming --autofocus), the ranges by checkAutofocusRegion (exit 3).
struct AutofocusArguments {
    std::string point;
    double region = kDefaultFocusRegion;
    CLI::Option *pointOption = nullptr, *regionOption = nullptr;

    std::optional<AutofocusRegion> parsed() const {
        if (pointOption->count() == 0) return std::nullopt;
        return parseAutofocusPoint(point, region);
    }
};

const CLI::Validator kAutofocusPoint([](std::string& text) { return autofocusPointSyntaxError(text); }, "X,Y",
                                     "autofocus point");

void addAutofocusOptions(CLI::App& command, AutofocusArguments& args) {
    args.pointOption =
        command
            .add_option("--autofocus", args.point,
                        "Focus on what lies at X,Y (0 to 1, 0,0 the top-left corner), chosen by the effect from the "
                        "depth; prints 'focus: D m'")
            ->check(kAutofocusPoint);
    args.regionOption = command
                            .add_option("--focus-region", args.region,
                                        "With --autofocus: the region's width and height as fractions of the "
                                        "image's, over 0 to 1")
                            ->check(kNumber)
                            ->capture_default_str();
    args.regionOption->needs(args.pointOption);
}

struct ApplyArguments {
    ApplyOptions options;
    AutofocusArguments autofocus;
    std::string depthKind = "linear";
    std::vector<double> projection;
    double nearPlane = 0.0, farPlane = 0.0, fNumber = 0.0, apertureRadius = 0.0;
    CLI::Option *nearOption = nullptr, *farOption = nullptr, *projOption = nullptr, *fstopOption = nullptr,
                *apertureOption = nullptr, *reverseOption = nullptr, *focusOption = nullptr, *cocLimitOption = nullptr;
};

CLI::App* addApply(CLI::App& app, ApplyArguments& args) {
    CLI::App* apply = app.add_subcommand("apply", "Apply depth of field to an EXR color image with its depth");
    ApplyOptions& o = args.options;
    apply->add_option("--color", o.colorPath, "Color EXR (R, G, B and optional A)")->required();
    apply->add_option("--depth", o.depthPath, "Depth EXR (one channel, or see --depth-channel)")->required();
    apply->add_option("--out", o.outputPath, "Output file: .exr (see --out-type) or .png (8-bit sRGB)")->required();
    apply
        ->add_option("--out-type", o.outType,
                     "EXR output pixels: half, float, or auto (half unless a value exceeds half's largest, 65504)")
        ->check(CLI::IsMember({"auto", "half", "float"}))
        ->capture_default_str();
    apply->add_option("--color-layer", o.colorLayer,
                      "Layer of the color in a multilayer EXR: reads LAYER.R, LAYER.G, LAYER.B (LAYER.A)");
    apply->add_option("--depth-channel", o.depthChannel, "Depth channel name in a multi-channel EXR, e.g. Z");
    apply
        ->add_option("--depth-kind", args.depthKind,
                     "linear: view distance in metres; device: z-buffer values in [0, 1]")
        ->check(CLI::IsMember({"linear", "device"}))
        ->capture_default_str();
    args.nearOption = apply->add_option("--near", args.nearPlane, "Device depth: near plane, metres")->check(kNumber);
    args.farOption =
        apply->add_option("--far", args.farPlane, "Device depth: far plane, metres (inf allowed)")->check(kNumber);
    args.projOption = apply
                          ->add_option("--proj", args.projection,
                                       "Device depth: projection matrix, 16 numbers, row-major, clip = M * view")
                          ->expected(16)
                          ->delimiter(',')
                          ->check(kNumber);
    args.reverseOption =
        apply->add_flag("--reverse-depth", o.reverseDepth, "Device depth: near plane at 1, far plane at 0");
    args.nearOption->excludes(args.projOption);
    args.farOption->excludes(args.projOption);
    args.nearOption->needs(args.farOption);
    args.farOption->needs(args.nearOption);

    args.focusOption = apply
                           ->add_option("--focus", o.lens.focusMetres,
                                        "Distance in focus, metres (required unless "
                                        "--autofocus or --camera-track gives it)")
                           ->check(kNumber);
    apply->add_option("--focal-length", o.lens.focalLengthMm, "Focal length, millimetres")
        ->check(kNumber)
        ->capture_default_str();
    apply->add_option("--sensor-width", o.lens.sensorWidthMm, "Sensor width, millimetres")
        ->check(kNumber)
        ->capture_default_str();
    args.fstopOption =
        apply->add_option("--fstop", args.fNumber, "f-number (default " + CLI::detail::to_string(kDefaultFNumber) + ")")
            ->check(kNumber);
    args.apertureOption =
        apply->add_option("--aperture-radius", args.apertureRadius, "Aperture radius, metres")->check(kNumber);
    args.fstopOption->excludes(args.apertureOption);
    addAutofocusOptions(*apply, args.autofocus);
    args.autofocus.pointOption->excludes(args.focusOption);
    args.cocLimitOption = addEffectOptions(*apply, o.effect, true);

    apply->add_option("--frames", o.frames,
                      "A sequence: frames FIRST-LAST[xSTEP], comma-separated; --color, --depth, --out then name "
                      "files with a frame-number field (shot.####.exr or shot.%04d.exr)");
    apply->add_option("--chunk", o.chunk, "With --frames: only the I-th of N contiguous shares (I/N, 1 to N)");
    apply->add_option("--camera-track", o.cameraTrack,
                      "With --frames: the lens per frame from a JSON or CSV file (frame, focus, fstop or "
                      "aperture_radius, focal_length, sensor_width)");
    apply->add_flag("--keep-layers", o.keepLayers,
                    "Copy the color file's other channels and its header attributes into the output");
    apply->add_flag("--overwrite", o.overwrite, "With --frames: redo frames whose output is already complete");
    apply->add_flag("--no-overlap", o.noOverlap,
                    "With --frames: read, compute and write one frame after the other (for measurements)");
    return apply;
}

// Checks that need the values of several options together, after parsing.
ApplyOptions finishApply(ApplyArguments& args) {
    ApplyOptions o = args.options;
    o.focusGiven = args.focusOption->count() > 0;
    o.autofocus = args.autofocus.parsed();
    o.effect.cocLimitFollowsImage = args.cocLimitOption->count() == 0;
    o.depthKind = args.depthKind == "device" ? DepthKind::Device : DepthKind::Linear;
    if (o.depthKind == DepthKind::Linear) {
        for (const CLI::Option* option : {args.nearOption, args.farOption, args.projOption, args.reverseOption}) {
            if (option->count() > 0) {
                throw CliError(ExitCode::Usage, option->get_name() + " needs --depth-kind device");
            }
        }
    } else if (args.projOption->count() == 0 && args.nearOption->count() == 0) {
        throw CliError(ExitCode::Usage, "--depth-kind device needs --near and --far, or --proj");
    }
    if (args.nearOption->count() > 0) {
        o.nearPlane = args.nearPlane;
        o.farPlane = args.farPlane;
    }
    if (args.projOption->count() > 0) {
        if (args.projection.size() != 16) {
            throw CliError(ExitCode::Usage, "--proj needs 16 numbers, got " + std::to_string(args.projection.size()));
        }
        std::array<double, 16> matrix{};
        std::copy(args.projection.begin(), args.projection.end(), matrix.begin());
        o.projection = matrix;
    }
    if (args.fstopOption->count() > 0) {
        o.lens.fNumber = args.fNumber;
    } else if (args.apertureOption->count() > 0) {
        o.lens.apertureRadiusMetres = args.apertureRadius;
    } else {
        o.lens.fNumber = kDefaultFNumber;
    }
    return o;
}

int run(int argc, char** argv) {
    CLI::App app{"ffx-dof: depth-of-field (bokeh) post-process on Vulkan; see docs/cli.md", "ffx-dof"};
    app.footer(exitCodeTable());
    app.require_subcommand(1);
    app.set_version_flag("--version", std::to_string(FFX_DOF_VERSION_MAJOR) + "." +
                                          std::to_string(FFX_DOF_VERSION_MINOR) + "." +
                                          std::to_string(FFX_DOF_VERSION_PATCH));

    ApplyArguments applyArgs;
    CLI::App* apply = addApply(app, applyArgs);

    DemoOptions demo;
    CLI::App* demoCommand =
        app.add_subcommand("demo", "Render the built-in scene, apply the effect, compare with the thin-lens truth");
    demoCommand->add_option("--out", demo.outputDirectory, "Output folder")->capture_default_str();
    demoCommand->add_option("--scene", demo.scene, "Built-in scene of the reference renderer")->capture_default_str();
    demoCommand->add_option("--width", demo.width, "Width, pixels")->check(kUnsigned)->capture_default_str();
    demoCommand->add_option("--height", demo.height, "Height, pixels")->check(kUnsigned)->capture_default_str();
    demoCommand->add_option("--lens-samples", demo.lensSamples, "Thin-lens samples per pixel of the truth")
        ->check(kUnsigned)
        ->capture_default_str();
    demoCommand
        ->add_option("--out-type", demo.outType,
                     "EXR images: half, float, or auto (half unless a value exceeds half's largest, 65504)")
        ->check(CLI::IsMember({"auto", "half", "float"}))
        ->capture_default_str();
    AutofocusArguments demoAutofocus;
    addAutofocusOptions(*demoCommand, demoAutofocus);
    CLI::Option* demoCocLimit = addEffectOptions(*demoCommand, demo.effect, true);

    BenchOptions bench;
    CLI::App* benchCommand =
        app.add_subcommand("bench", "Time every pass on a procedural scene against a plain copy pass");
    benchCommand
        ->add_option("--scene", bench.scene,
                     "Built-in scene of the reference renderer (floor: every tile class; mid-lights, "
                     "far-highlights: small lights above white)")
        ->capture_default_str();
    benchCommand->add_option("--width", bench.width, "Width, pixels")->check(kUnsigned)->capture_default_str();
    benchCommand->add_option("--height", bench.height, "Height, pixels")->check(kUnsigned)->capture_default_str();
    benchCommand->add_option("--repeat", bench.repeat, "Dispatches to time; the median is printed")
        ->check(kUnsigned)
        ->capture_default_str();
    benchCommand->add_flag("--json", bench.json, "Print one JSON object instead of a table");
    benchCommand->add_flag("--float32", bench.float32,
                           "Run the 32-bit shader permutations even where the device supports 16-bit ones");
    benchCommand->add_flag("--against-round", bench.againstRound,
                           "Also time the round aperture in the same process, run for run in turn with the given "
                           "one, and print the ratio of their blur + composite times");
    AutofocusArguments benchAutofocus;
    addAutofocusOptions(*benchCommand, benchAutofocus);
    addEffectOptions(*benchCommand, bench.effect);

    CompareOptions compare;
    CLI::App* compareCommand = app.add_subcommand("compare", "PSNR and SSIM of a test image against a reference");
    compareCommand->add_option("--ref", compare.referencePath, "Reference EXR")->required();
    compareCommand->add_option("--test", compare.testPath, "Test EXR")->required();
    CLI::Option* depthOption =
        compareCommand->add_option("--depth", compare.depthPath, "Linear depth EXR, for PSNR per region");
    CLI::Option* cameraOption =
        compareCommand->add_option("--camera", compare.cameraPath, "Camera JSON of the reference renderer");
    compareCommand->add_option("--frames", compare.frames,
                               "Sequences (--ref and --test named with ####): mean PSNR and SSIM, and the "
                               "frame-to-frame change of each (flicker)");
    depthOption->needs(cameraOption);
    cameraOption->needs(depthOption);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::fputs(app.help().c_str(), stdout);
        return 0;
    } catch (const CLI::CallForAllHelp&) {
        std::fputs(app.help("", CLI::AppFormatMode::All).c_str(), stdout);
        return 0;
    } catch (const CLI::CallForVersion&) {
        std::printf("%s\n", app.version().c_str());
        return 0;
    } catch (const CLI::ParseError& error) {
        // A subcommand's --help arrives as CallForHelp thrown from the subcommand.
        if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
            return app.exit(error);
        }
        // CLI11 reports an unknown command word as a missing subcommand; name the word instead.
        if (app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-') {
            std::string names;
            for (const CLI::App* command : app.get_subcommands({})) {
                names += (names.empty() ? "" : ", ") + command->get_name();
            }
            throw CliError(ExitCode::Usage, "unknown command '" + std::string(argv[1]) + "' (commands: " + names + ")");
        }
        throw CliError(ExitCode::Usage, std::string(error.what()) + " (see ffx-dof --help)");
    }

    if (apply->parsed()) {
        runApply(finishApply(applyArgs));
    } else if (demoCommand->parsed()) {
        demo.effect.cocLimitFollowsImage = demoCocLimit->count() == 0;
        demo.autofocus = demoAutofocus.parsed();
        runDemo(demo);
    } else if (benchCommand->parsed()) {
        bench.autofocus = benchAutofocus.parsed();
        runBench(bench);
    } else if (compareCommand->parsed()) {
        runCompare(compare);
    }
    return 0;
}

}  // namespace
}  // namespace ffxdof::cli

int main(int argc, char** argv) {
    using ffxdof::cli::ExitCode;
    try {
        return ffxdof::cli::run(argc, argv);
    } catch (const ffxdof::cli::CliError& error) {
        std::fprintf(stderr, "ffx-dof: error: %s\n", error.what());
        return static_cast<int>(error.code());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "ffx-dof: internal error: %s\n", error.what());
        return static_cast<int>(ExitCode::Internal);
    }
}
