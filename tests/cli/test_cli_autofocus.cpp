// `--autofocus X,Y [--focus-region R]` of apply, demo and bench, run as the built program: usage and
// range errors with their exit codes ([cli]), and on the Vulkan device ([vulkan]) the printed focus of a
// target at a known distance, the target left sharp, a focus per frame of a sequence (each frame equal
// to the frame run alone), and bench's autofocus figures.
#include "cli_program_support.h"
#include "ffx_dof_imageio.h"

#include <catch2/catch.hpp>

#include "ffx_dof_temp_folder.h"
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

using ffxdof::io::ImageR;
using ffxdof::io::ImageRGBA;

using namespace ffxdof::clitest;

namespace {

class TempFolder : public ffxdof::testing::TempFolder {
public:
    TempFolder() : ffxdof::testing::TempFolder("ffx_dof_autofocus_cli_test_") {}
};
using ffxdof::testing::readText;

// A checker texture; depth: a target of `targetDistance` metres over the middle third of the image (in
// both directions) before a wall at 20 m.
constexpr uint32_t kWidth = 96, kHeight = 64;
constexpr double kWall = 20.0;

bool inTarget(uint32_t x, uint32_t y) {
    return x >= kWidth / 3 && x < 2 * kWidth / 3 && y >= kHeight / 3 && y < 2 * kHeight / 3;
}

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

void writeScene(const std::string& colorPath, const std::string& depthPath, double targetDistance) {
    ffxdof::io::writeExr(colorPath, makeColor(), ffxdof::io::ExrPixelType::Float);
    ImageR depth(kWidth, kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) depth.at(x, y) = float(inTarget(x, y) ? targetDistance : kWall);
    }
    ffxdof::io::writeExr(depthPath, depth, ffxdof::io::ExrPixelType::Float, "Z");
}

// apply on color.exr / depth.exr of the folder with a fast lens (the blur of the wall is large on this
// small image); overrides replace or add options ("" for a flag, kRemove drops one).
using Options = std::map<std::string, std::string>;
const std::string kRemove = "\x01remove";
std::string applyArguments(const TempFolder& folder, const Options& overrides = {}) {
    Options options = {{"--color", folder / "color.exr"},
                       {"--depth", folder / "depth.exr"},
                       {"--out", folder / "out.exr"},
                       {"--autofocus", "0.5,0.5"},
                       {"--fstop", "1.4"},
                       {"--sensor-width", "4"},
                       {"--validate", ""}};
    for (const auto& [name, value] : overrides) options[name] = value;
    std::string arguments = "apply";
    for (const auto& [name, value] : options) {
        if (value == kRemove) continue;
        arguments += " " + name + (value.empty() ? "" : " " + quote(value));
    }
    return arguments;
}

// The distances of every "focus: D m" in the text, in order.
std::vector<double> printedFocus(const std::string& text) {
    std::vector<double> found;
    const std::regex pattern("focus: ([0-9]+(\\.[0-9]+)?) m");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator(); ++it) {
        found.push_back(std::stod((*it)[1].str()));
    }
    return found;
}

// Mean absolute RGB difference over the target's interior (away from the wall's blur).
double targetDifference(const ImageRGBA& a, const ImageRGBA& b) {
    double sum = 0.0;
    size_t count = 0;
    for (uint32_t y = kHeight / 3 + 6; y < 2 * kHeight / 3 - 6; ++y) {
        for (uint32_t x = kWidth / 3 + 6; x < 2 * kWidth / 3 - 6; ++x) {
            for (int c = 0; c < 3; ++c) sum += std::fabs(a.at(x, y)[c] - b.at(x, y)[c]);
            count += 3;
        }
    }
    return sum / double(count);
}

}  // namespace

TEST_CASE("autofocus: --focus with --autofocus and malformed points are usage errors", "[cli]") {
    TempFolder folder;
    writeScene(folder / "color.exr", folder / "depth.exr", 2.5);
    const ProgramResult both = runProgram(applyArguments(folder, {{"--focus", "4"}}));
    requireError(both, 1, "--autofocus");
    CHECK_THAT(both.err, Catch::Contains("--focus"));
    for (const std::string point : {"0.5", "a,b", "", "0.5,0.5,1", "0.5,", ",0.5", "0.5;0.5", " 0.5,0.5", "0.5, 0.5"}) {
        INFO("--autofocus '" << point << "'");
        requireError(runProgram(applyArguments(folder, {{"--autofocus", point}})), 1, "--autofocus");
    }
    requireError(runProgram(applyArguments(folder, {{"--focus-region", "big"}})), 1, "--focus-region");
    requireError(runProgram(applyArguments(folder, {{"--focus-region", ""}})), 1, "--focus-region");
    requireError(
        runProgram(applyArguments(folder, {{"--autofocus", kRemove}, {"--focus", "4"}, {"--focus-region", "0.2"}})), 1,
        "--focus-region");
    requireError(runProgram(applyArguments(folder, {{"--autofocus", kRemove}})), 1, "--focus is required");
    requireError(runProgram("bench --autofocus 0.5"), 1, "--autofocus");
    requireError(runProgram("demo --autofocus x,y"), 1, "--autofocus");
    requireError(runProgram("bench --focus-region 0.2"), 1, "--focus-region");

    // A camera track that gives the focus contradicts --autofocus.
    {
        std::ofstream track(folder / "track.csv");
        track << "frame,focus\n1,3\n";
    }
    requireError(runProgram(applyArguments(folder, {{"--color", folder / "color.exr"},
                                                    {"--out", folder / "o.####.exr"},
                                                    {"--frames", "1"},
                                                    {"--camera-track", folder / "track.csv"}})),
                 1, "--autofocus chooses the focus");
}

TEST_CASE("autofocus: points and regions out of range exit 3 naming the option", "[cli]") {
    TempFolder folder;
    writeScene(folder / "color.exr", folder / "depth.exr", 2.5);
    for (const std::string point : {"1.5,0.5", "0.5,-0.1", "-0,1.01", "nan,0.5", "0.5,inf", "1e9,0"}) {
        INFO("--autofocus " << point);
        requireError(runProgram(applyArguments(folder, {{"--autofocus", point}})), 3, "--autofocus");
    }
    for (const std::string region : {"0", "-0.1", "1.5", "nan", "inf"}) {
        INFO("--focus-region " << region);
        requireError(runProgram(applyArguments(folder, {{"--focus-region", region}})), 3, "--focus-region");
    }
    requireError(runProgram("bench --autofocus 2,0.5"), 3, "--autofocus");
    requireError(runProgram("demo --autofocus 0.5,0.5 --focus-region 0"), 3, "--focus-region");
    // The nearest focus autofocus takes is twice the focal length: a far plane before it is refused.
    requireError(
        runProgram(applyArguments(
            folder, {{"--depth-kind", "device"}, {"--near", "0.01"}, {"--far", "0.08"}, {"--focal-length", "50"}})),
        3, "twice --focal-length");
}

TEST_CASE("apply --autofocus prints the distance of the target at the point and keeps it sharp", "[vulkan]") {
    TempFolder folder;
    const ImageRGBA input = makeColor();
    for (const double target : {0.8, 2.5, 7.0}) {
        INFO("target at " << target << " m");
        writeScene(folder / "color.exr", folder / "depth.exr", target);
        std::filesystem::remove(folder / "out.exr");
        const ProgramResult result = runProgram(applyArguments(folder));
        INFO(result.out << result.err);
        REQUIRE(result.exitCode == 0);
        const std::vector<double> focus = printedFocus(result.out);
        REQUIRE(focus.size() == 1);
        CHECK(std::fabs(focus[0] - target) <= 0.01 * target);
        CHECK_THAT(result.out, Catch::Contains("wrote ") && Catch::Contains("(autofocus at 0.5,0.5, region 0.1)"));
        const ImageRGBA output = ffxdof::io::readExrColor(folder / "out.exr");
        REQUIRE(output.width == kWidth);
        CHECK(targetDifference(output, input) < 0.01);
    }

    // A point on the wall focuses on the wall (the target blurs); device depth gives the same distance.
    writeScene(folder / "color.exr", folder / "depth.exr", 2.5);
    const ProgramResult wall =
        runProgram(applyArguments(folder, {{"--autofocus", "0.1,0.2"}, {"--focus-region", "0.05"}}));
    INFO(wall.out << wall.err);
    REQUIRE(wall.exitCode == 0);
    REQUIRE(printedFocus(wall.out).size() == 1);
    CHECK(std::fabs(printedFocus(wall.out)[0] - kWall) <= 0.01 * kWall);
    CHECK(targetDifference(ffxdof::io::readExrColor(folder / "out.exr"), input) > 0.05);

    const double n = 0.1, f = 100.0;
    ImageR device(kWidth, kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const double z = inTarget(x, y) ? 2.5 : kWall;
            device.at(x, y) = float(f / (f - n) - n * f / ((f - n) * z));
        }
    }
    ffxdof::io::writeExr(folder / "device.exr", device, ffxdof::io::ExrPixelType::Float, "Z");
    const ProgramResult fromDevice = runProgram(applyArguments(
        folder, {{"--depth", folder / "device.exr"}, {"--depth-kind", "device"}, {"--near", "0.1"}, {"--far", "100"}}));
    INFO(fromDevice.out << fromDevice.err);
    REQUIRE(fromDevice.exitCode == 0);
    REQUIRE(printedFocus(fromDevice.out).size() == 1);
    CHECK(std::fabs(printedFocus(fromDevice.out)[0] - 2.5) <= 0.025);
}

TEST_CASE("apply --autofocus over a sequence prints each frame's focus and keeps frames as run alone", "[vulkan]") {
    TempFolder folder;
    const double targets[] = {1.5, 3.0, 6.0};
    for (int frame = 1; frame <= 3; ++frame) {
        char color[32], depth[32];
        std::snprintf(color, sizeof(color), "c.%04d.exr", frame);
        std::snprintf(depth, sizeof(depth), "z.%04d.exr", frame);
        writeScene(folder / color, folder / depth, targets[frame - 1]);
    }
    const ProgramResult sequence = runProgram(applyArguments(folder, {{"--color", folder / "c.####.exr"},
                                                                      {"--depth", folder / "z.####.exr"},
                                                                      {"--out", folder / "o.####.exr"},
                                                                      {"--frames", "1-3"}}));
    INFO(sequence.out << sequence.err);
    REQUIRE(sequence.exitCode == 0);
    // "frame 2: wrote .../o.0002.exr (half); focus: 3.00 m; 2/3 frames, ..." (plain lines: not a terminal)
    const std::regex line("frame ([0-9]+): wrote [^\n]* \\((half|float)\\); focus: ([0-9.]+) m; [0-9]+/3 frames");
    std::map<int, double> focusOf;
    for (auto it = std::sregex_iterator(sequence.out.begin(), sequence.out.end(), line); it != std::sregex_iterator();
         ++it) {
        focusOf[std::stoi((*it)[1].str())] = std::stod((*it)[3].str());
    }
    REQUIRE(focusOf.size() == 3);
    for (int frame = 1; frame <= 3; ++frame) {
        CAPTURE(frame);
        CHECK(std::fabs(focusOf[frame] - targets[frame - 1]) <= 0.01 * targets[frame - 1]);
    }
    CHECK_THAT(sequence.out, Catch::Contains("written 3, skipped 0"));

    // Frame 2 alone: the same focus and the same bytes.
    const ProgramResult alone = runProgram(applyArguments(
        folder,
        {{"--color", folder / "c.0002.exr"}, {"--depth", folder / "z.0002.exr"}, {"--out", folder / "alone.exr"}}));
    INFO(alone.out << alone.err);
    REQUIRE(alone.exitCode == 0);
    REQUIRE(printedFocus(alone.out).size() == 1);
    CHECK(printedFocus(alone.out)[0] == focusOf[2]);
    CHECK((readText(folder / "alone.exr") == readText(folder / "o.0002.exr")));
}

TEST_CASE("bench and demo with --autofocus", "[vulkan]") {
    const ProgramResult json =
        runProgram("bench --width 80 --height 48 --repeat 3 --json --validate --autofocus 0.5,0.6");
    INFO(json.err);
    REQUIRE(json.exitCode == 0);
    const nlohmann::json bench = nlohmann::json::parse(json.out);
    CHECK(bench.at("autofocusDistance").get<double>() > 0.0);
    CHECK(bench.at("passMs").at("autofocus").get<double>() > 0.0);
    CHECK(bench.at("autofocusShare").get<double>() ==
          Approx(bench.at("passMs").at("autofocus").get<double>() / bench.at("totalMs").get<double>()));
    CHECK(bench.at("autofocus").at("y").get<double>() == Approx(0.6));
    CHECK(bench.at("autofocus").at("region").get<double>() == Approx(0.1));

    // Without --autofocus the JSON has no autofocus figures (and the pass takes no time).
    const ProgramResult plain = runProgram("bench --width 80 --height 48 --repeat 1 --json");
    REQUIRE(plain.exitCode == 0);
    CHECK_FALSE(nlohmann::json::parse(plain.out).contains("autofocusDistance"));

    const ProgramResult text = runProgram("bench --width 80 --height 48 --repeat 1 --autofocus 0.5,0.6");
    INFO(text.err);
    REQUIRE(text.exitCode == 0);
    CHECK_THAT(text.out, Catch::Contains("autofocus share") && Catch::Contains("% of the total"));
    CHECK(printedFocus(text.out).size() == 1);

    TempFolder folder;
    const ProgramResult demo = runProgram("demo --out " + quote(folder / "demo") +
                                          " --width 48 --height 32 --lens-samples 4 --validate --autofocus 0.5,0.5");
    INFO(demo.out << demo.err);
    REQUIRE(demo.exitCode == 0);
    CHECK(printedFocus(demo.out).size() == 1);
    CHECK(std::filesystem::is_regular_file(folder.path() / "demo" / "output.exr"));
}
