// Runs the built ffx-dof program with generated inputs and checks exit codes, the one-line error
// messages, and (tag [vulkan]) real runs of apply, bench and demo on the Vulkan device.
#include "ffx_dof_imageio.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using ffxdof::io::ImageR;
using ffxdof::io::ImageRGBA;

namespace {

struct ProgramResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

std::string readText(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// A fresh folder per test case, removed at the end.
class TempFolder {
public:
    TempFolder() {
        static std::atomic<int> counter{0};
        path_ = fs::temp_directory_path() /
                ("ffx_dof_cli_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(path_);
    }
    ~TempFolder() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    std::string operator/(const std::string& name) const { return (path_ / name).string(); }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

std::string quote(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

ProgramResult runProgram(const std::string& arguments) {
    TempFolder folder;
    const std::string command =
        quote(FFX_DOF_CLI_PROGRAM) + " " + arguments + " > " + quote(folder / "out") + " 2> " + quote(folder / "err");
    const int status = std::system(command.c_str());
    ProgramResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = readText(folder.path() / "out");
    result.err = readText(folder.path() / "err");
    return result;
}

// A failure is exactly one line on stderr, "ffx-dof: error: ...", and the documented exit code.
void requireError(const ProgramResult& result, int exitCode, const std::string& fragment) {
    INFO("stderr: " << result.err);
    CHECK(result.exitCode == exitCode);
    CHECK(result.err.rfind("ffx-dof: error: ", 0) == 0);
    CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
    CHECK_THAT(result.err, Catch::Contains(fragment));
}

// A scene a few tiles wide: a checker texture everywhere; depth in three vertical bands, near (left),
// in focus (middle), far (right).
constexpr uint32_t kWidth = 96, kHeight = 64;
// The lens focuses at 4 m (applyArguments). The middle band sits just in front of it (a CoC of +0.07
// half-res px): exactly at the focus the CoC is 0 up to rounding, and its sign, which decides near or far
// field, would then depend on the depth encoding.
constexpr double kMiddleDepth = 3.9;

double bandDepth(uint32_t x) { return x < kWidth / 3 ? 0.6 : (x < 2 * kWidth / 3 ? kMiddleDepth : 40.0); }

ImageRGBA makeColor() {
    ImageRGBA color(kWidth, kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const bool bright = ((x / 2) + (y / 2)) % 2 == 0;
            float* pixel = color.at(x, y);
            pixel[0] = bright ? 0.9f : 0.1f;
            pixel[1] = bright ? 0.8f : 0.2f;
            pixel[2] = bright ? 0.7f : 0.05f;
            pixel[3] = 1.0f;
        }
    }
    return color;
}

template <typename DepthOf>
ImageR makeDepth(DepthOf depthOf) {
    ImageR depth(kWidth, kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) depth.at(x, y) = float(depthOf(bandDepth(x)));
    }
    return depth;
}

// Writes color.exr and depth.exr (linear metres, channel Z) into the folder.
void writeScene(const TempFolder& folder) {
    ffxdof::io::writeExr(folder / "color.exr", makeColor(), ffxdof::io::ExrPixelType::Float);
    ffxdof::io::writeExr(folder / "depth.exr", makeDepth([](double z) { return z; }), ffxdof::io::ExrPixelType::Float,
                         "Z");
}

// apply with the scene of writeScene and a fast lens; overrides replace or add options ("" for a flag).
// The narrow sensor makes the blur of this small image large: about 15 half-res px (clamped to 9.6 by
// the CoC limit) in the near band and 2.4 in the far band.
using Options = std::map<std::string, std::string>;
std::string applyArguments(const TempFolder& folder, const Options& overrides = {}) {
    Options options = {{"--color", folder / "color.exr"},
                       {"--depth", folder / "depth.exr"},
                       {"--out", folder / "out.exr"},
                       {"--focus", "4"},
                       {"--focal-length", "50"},
                       {"--fstop", "1.4"},
                       {"--sensor-width", "4"},
                       {"--coc-limit", "0.3"},
                       {"--validate", ""}};
    for (const auto& [name, value] : overrides) options[name] = value;
    std::string arguments = "apply";
    for (const auto& [name, value] : options) {
        arguments += " " + name + (value.empty() ? "" : " " + quote(value));
    }
    return arguments;
}

// Mean absolute difference of RGB over the pixels of columns [x0, x1).
double meanDifference(const ImageRGBA& a, const ImageRGBA& b, uint32_t x0, uint32_t x1) {
    double sum = 0.0;
    for (uint32_t y = 0; y < a.height; ++y) {
        for (uint32_t x = x0; x < x1; ++x) {
            for (int c = 0; c < 3; ++c) sum += std::fabs(a.at(x, y)[c] - b.at(x, y)[c]);
        }
    }
    return sum / (3.0 * a.height * (x1 - x0));
}

}  // namespace

TEST_CASE("usage errors", "[cli]") {
    const ProgramResult none = runProgram("");
    requireError(none, 1, "subcommand");
    requireError(runProgram("shrink"), 1, "shrink");
    requireError(runProgram("apply --color a.exr"), 1, "--depth");
    requireError(runProgram("apply --color a.exr --depth b.exr --out c.exr --focus 2 --frobnicate"), 1, "--frobnicate");
    requireError(runProgram("apply --color a.exr --depth b.exr --out c.exr --focus two"), 1, "--focus");
    requireError(runProgram("apply --color a.exr --depth b.exr --out c.jpg --focus 2"), 1, ".exr or .png");
    requireError(runProgram("apply --color a.exr --depth b.exr --out c.exr --focus 2 --fstop 2 --aperture-radius 0.1"),
                 1, "--aperture-radius");
    requireError(runProgram("apply --color a.exr --depth b.exr --out c.exr --focus 2 --depth-kind device"), 1,
                 "--near and --far, or --proj");
    requireError(runProgram("apply --color a.exr --depth b.exr --out c.exr --focus 2 --near 0.1 --far 9"), 1,
                 "--near needs --depth-kind device");
    requireError(runProgram("apply --color a.exr --depth b.exr --out c.exr --focus 2 --depth-kind device --proj 1,2,3"),
                 1, "--proj");
    requireError(runProgram("apply --color a.exr --depth b.exr --out c.exr --focus 2 --depth-kind stereo"), 1,
                 "stereo");
    requireError(runProgram("bench --width 9x9"), 1, "--width");
}

TEST_CASE("help and version", "[cli]") {
    const ProgramResult help = runProgram("--help");
    CHECK(help.exitCode == 0);
    CHECK_THAT(help.out, Catch::Contains("Exit codes:") && Catch::Contains("apply") && Catch::Contains("bench"));
    const ProgramResult applyHelp = runProgram("apply --help");
    CHECK(applyHelp.exitCode == 0);
    CHECK_THAT(applyHelp.out, Catch::Contains("--focal-length") && Catch::Contains("--reverse-depth"));
    const ProgramResult version = runProgram("--version");
    CHECK(version.exitCode == 0);
    CHECK_THAT(version.out, Catch::StartsWith("1."));
}

TEST_CASE("input file errors", "[cli]") {
    TempFolder folder;
    writeScene(folder);
    requireError(runProgram(applyArguments(folder, {{"--color", folder / "missing.exr"}})), 2, "missing.exr");
    requireError(runProgram("apply --color " + quote(folder / "color.tif") + " --depth " + quote(folder / "depth.exr") +
                            " --out " + quote(folder / "o.exr") + " --focus 4"),
                 2, "OpenEXR");

    {
        std::ofstream corrupt(folder / "corrupt.exr", std::ios::binary);
        corrupt << "v/1\x01 this is not an OpenEXR file";
    }
    const ProgramResult corrupt = runProgram(applyArguments(folder, {{"--color", folder / "corrupt.exr"}}));
    requireError(corrupt, 2, "corrupt.exr");

    // Color without R, G, B; depth with four channels and no name given; a channel that is not there.
    ffxdof::io::writeExr(folder / "grey.exr", makeDepth([](double z) { return z; }));
    requireError(runProgram(applyArguments(folder, {{"--color", folder / "grey.exr"}})), 2, "grey.exr");
    requireError(runProgram(applyArguments(folder, {{"--depth", folder / "color.exr"}})), 2, "color.exr");
    requireError(runProgram(applyArguments(folder, {{"--depth-channel", "depth.V"}})), 2, "depth.V");
    requireError(runProgram(applyArguments(folder, {{"--color-layer", "beauty"}})), 2, "beauty.R");
}

TEST_CASE("invalid values", "[cli]") {
    TempFolder folder;
    writeScene(folder);
    requireError(runProgram(applyArguments(folder, {{"--focus", "0.04"}})), 3, "must be greater than --focal-length");
    requireError(runProgram(applyArguments(folder, {{"--fstop", "0"}})), 3, "--fstop");
    requireError(runProgram(applyArguments(folder, {{"--fstop", "nan"}})), 3, "--fstop");
    requireError(runProgram(applyArguments(folder, {{"--focus", "-3"}})), 3, "--focus");
    requireError(runProgram(applyArguments(folder, {{"--quality", "0"}})), 3, "--quality");
    requireError(runProgram(applyArguments(folder, {{"--quality", "33"}})), 3, "--quality");
    requireError(runProgram(applyArguments(folder, {{"--coc-limit", "-1"}})), 3, "--coc-limit");
    requireError(runProgram(applyArguments(folder, {{"--depth-kind", "device"}, {"--near", "1"}, {"--far", "0.5"}})), 3,
                 "--far");
    requireError(
        runProgram(applyArguments(folder, {{"--depth-kind", "device"}, {"--proj", "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1"}})),
        3, "not a perspective projection");

    // Linear depth read as device depth: values above 1.
    requireError(runProgram(applyArguments(folder, {{"--depth-kind", "device"}, {"--near", "0.1"}, {"--far", "100"}})),
                 3, "outside [0, 1]");

    ImageR small(kWidth, kHeight - 1);
    std::fill(small.pixels.begin(), small.pixels.end(), 2.0f);
    ffxdof::io::writeExr(folder / "small.exr", small);
    requireError(runProgram(applyArguments(folder, {{"--depth", folder / "small.exr"}})), 3, "differ in size");

    ImageR holes = makeDepth([](double z) { return z; });
    holes.at(7, 5) = NAN;
    holes.at(8, 9) = INFINITY;
    holes.at(9, 9) = -INFINITY;
    ffxdof::io::writeExr(folder / "holes.exr", holes, ffxdof::io::ExrPixelType::Float, "Z");
    requireError(runProgram(applyArguments(folder, {{"--depth", folder / "holes.exr"}})), 3,
                 "3 values are not finite in the depth (first at x=7, y=5: nan)");

    ImageR negative = makeDepth([](double z) { return z; });
    negative.at(2, 3) = -1.0f;
    ffxdof::io::writeExr(folder / "negative.exr", negative, ffxdof::io::ExrPixelType::Float, "Z");
    requireError(runProgram(applyArguments(folder, {{"--depth", folder / "negative.exr"}})), 3,
                 "1 value is 0 or negative in the linear depth");
}

TEST_CASE("compare", "[cli]") {
    TempFolder folder;
    writeScene(folder);
    ImageRGBA darker = makeColor();
    for (float& value : darker.pixels) value *= 0.9f;
    ffxdof::io::writeExr(folder / "darker.exr", darker, ffxdof::io::ExrPixelType::Float);

    const ProgramResult same =
        runProgram("compare --ref " + quote(folder / "color.exr") + " --test " + quote(folder / "color.exr"));
    CHECK(same.exitCode == 0);
    CHECK_THAT(same.out, Catch::Contains("psnr inf") && Catch::Contains("ssim 1.0000"));
    const ProgramResult different =
        runProgram("compare --ref " + quote(folder / "color.exr") + " --test " + quote(folder / "darker.exr"));
    CHECK(different.exitCode == 0);
    CHECK_THAT(different.out, Catch::Contains("psnr ") && !Catch::Contains("psnr inf"));

    requireError(runProgram("compare --ref " + quote(folder / "color.exr") + " --test " + quote(folder / "none.exr")),
                 2, "none.exr");
    ImageRGBA narrow(kWidth - 2, kHeight);
    ffxdof::io::writeExr(folder / "narrow.exr", narrow);
    requireError(runProgram("compare --ref " + quote(folder / "color.exr") + " --test " + quote(folder / "narrow.exr")),
                 3, "94x64 but the reference is 96x64");
    requireError(runProgram("compare --ref " + quote(folder / "color.exr") + " --test " + quote(folder / "color.exr") +
                            " --depth " + quote(folder / "depth.exr")),
                 1, "--camera");
}

TEST_CASE("apply: linear, device and reversed depth give the same image", "[vulkan]") {
    TempFolder folder;
    writeScene(folder);
    const ImageRGBA input = makeColor();

    const ProgramResult linear = runProgram(applyArguments(folder));
    INFO(linear.err);
    REQUIRE(linear.exitCode == 0);
    CHECK_THAT(linear.out, Catch::Contains("wrote"));
    const ImageRGBA linearOut = ffxdof::io::readExrColor(folder / "out.exr");
    REQUIRE(linearOut.width == kWidth);
    REQUIRE(linearOut.height == kHeight);

    // The in-focus band keeps its detail (away from its edges, where neighbours bleed in); the near and far
    // bands lose it.
    CHECK(meanDifference(linearOut, input, kWidth / 3 + 12, 2 * kWidth / 3 - 12) < 0.02);
    CHECK(meanDifference(linearOut, input, 0, kWidth / 3 - 8) > 0.1);
    CHECK(meanDifference(linearOut, input, 2 * kWidth / 3 + 8, kWidth) > 0.1);

    // The same scene as z-buffers of D3D-style projections, standard and reversed.
    const double n = 0.1, f = 100.0;
    const auto standardDepth = [&](double z) { return f / (f - n) - n * f / ((f - n) * z); };
    ffxdof::io::writeExr(folder / "device.exr", makeDepth(standardDepth), ffxdof::io::ExrPixelType::Float);
    ffxdof::io::writeExr(folder / "reversed.exr", makeDepth([&](double z) { return 1.0 - standardDepth(z); }),
                         ffxdof::io::ExrPixelType::Float);
    std::ostringstream matrix;
    matrix.precision(17);
    matrix << "1,0,0,0,0,1,0,0,0,0," << f / (f - n) << "," << -n * f / (f - n) << ",0,0,1,0";
    for (const std::string variant : {"device", "reversed", "proj"}) {
        INFO(variant);
        Options options = {{"--depth-kind", "device"},
                           {"--depth", folder / (variant == "reversed" ? "reversed.exr" : "device.exr")},
                           {"--out", folder / "dev.exr"}};
        if (variant == "proj") {
            options["--proj"] = matrix.str();
        } else {
            options["--near"] = "0.1";
            options["--far"] = "100";
        }
        if (variant == "reversed") options["--reverse-depth"] = "";
        const ProgramResult device = runProgram(applyArguments(folder, options));
        INFO(device.err);
        REQUIRE(device.exitCode == 0);
        const ImageRGBA deviceOut = ffxdof::io::readExrColor(folder / "dev.exr");
        CHECK(meanDifference(deviceOut, linearOut, 0, kWidth) < 0.002);
    }
}

TEST_CASE("apply: PNG output, named depth channel, write errors, existing output kept on failure", "[vulkan]") {
    TempFolder folder;
    writeScene(folder);
    const ProgramResult png =
        runProgram(applyArguments(folder, {{"--out", folder / "out.png"}, {"--depth-channel", "Z"}}));
    INFO(png.err);
    REQUIRE(png.exitCode == 0);
    CHECK(readText(folder.path() / "out.png").substr(1, 3) == "PNG");

    requireError(runProgram(applyArguments(folder, {{"--out", folder / "no-such-folder/out.exr"}})), 5,
                 "no-such-folder");

    {
        std::ofstream precious(folder / "out.exr");
        precious << "precious";
    }
    requireError(runProgram(applyArguments(folder, {{"--fstop", "-1"}})), 3, "--fstop");
    CHECK(readText(folder.path() / "out.exr") == "precious");
    REQUIRE(runProgram(applyArguments(folder)).exitCode == 0);
    CHECK(ffxdof::io::readExrColor(folder / "out.exr").width == kWidth);
    // No temporary files are left next to the output.
    size_t entries = 0;
    for (const auto& entry : fs::directory_iterator(folder.path())) {
        (void)entry;
        ++entries;
    }
    CHECK(entries == 4);  // color.exr, depth.exr, out.exr, out.png
}

TEST_CASE("device selection errors", "[vulkan]") {
    TempFolder folder;
    writeScene(folder);
    requireError(runProgram(applyArguments(folder, {{"--device", "97"}})), 4, "97");
}

TEST_CASE("bench --json", "[vulkan]") {
    const ProgramResult bench = runProgram("bench --width 80 --height 48 --repeat 3 --json --validate");
    INFO(bench.err);
    REQUIRE(bench.exitCode == 0);
    const nlohmann::json json = nlohmann::json::parse(bench.out);
    CHECK(json.at("width") == 80);
    CHECK(json.at("passMs").size() == 5);
    double sum = 0.0;
    for (const auto& pass : json.at("passMs").items()) {
        CHECK(pass.value().get<double>() >= 0.0);
        sum += pass.value().get<double>();
    }
    CHECK(json.at("totalMs").get<double>() > 0.0);
    CHECK(json.at("totalMs").get<double>() >= 0.5 * sum);
    CHECK(json.at("copyMs").get<double>() > 0.0);
    CHECK(json.at("ratio").get<double>() == Approx(json.at("totalMs").get<double>() / json.at("copyMs").get<double>()));
    CHECK(json.at("memoryBytes").get<uint64_t>() > 0);
}

TEST_CASE("demo writes every image", "[vulkan]") {
    TempFolder folder;
    const ProgramResult demo =
        runProgram("demo --out " + quote(folder / "demo") + " --width 48 --height 32 --lens-samples 4 --validate");
    INFO(demo.err);
    REQUIRE(demo.exitCode == 0);
    for (const char* name : {"input.exr", "input.png", "depth.exr", "output.exr", "output.png", "truth.exr",
                             "truth.png", "side-by-side.png", "camera.json"}) {
        INFO(name);
        CHECK(fs::is_regular_file(folder.path() / "demo" / name));
        CHECK_THAT(demo.out, Catch::Contains(name));
    }
    // compare with the demo's depth and camera reports every region.
    const std::string demoFolder = folder / "demo";
    const ProgramResult regions = runProgram(
        "compare --ref " + quote(demoFolder + "/truth.exr") + " --test " + quote(demoFolder + "/output.exr") +
        " --depth " + quote(demoFolder + "/depth.exr") + " --camera " + quote(demoFolder + "/camera.json"));
    INFO(regions.err);
    CHECK(regions.exitCode == 0);
    CHECK_THAT(regions.out, Catch::Contains("in-focus") && Catch::Contains("near-field") &&
                                Catch::Contains("far-field") && Catch::Contains("halo-band"));

    requireError(runProgram("demo --out " + quote(folder / "demo/input.png") + " --width 8 --height 8"), 5,
                 "input.png");
    requireError(runProgram("demo --scene nowhere"), 3, "nowhere");
}
