// A bounded, deterministic fuzz test of `ffx-dof apply` (issue 13): valid EXR files mutated
// (truncated, bits flipped, header fields overwritten) and option values mutated (empty, malformed,
// huge, tiny, NaN, negative). Every run must end with a documented exit code; a failure must be one
// line on stderr and leave the output untouched and no temporary file behind; a success must write
// only finite values. A crash, a sanitizer report (more than one line, or exit code 6 or above) or
// a non-finite output fails the test. Runs for at most kTimeBudget.
#include "ffx_dof_imageio.h"

#include <catch2/catch.hpp>

#include "cli_program_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

using ffxdof::clitest::quote;

namespace {

constexpr auto kTimeBudget = std::chrono::seconds(45);
constexpr int kMaxRuns = 160;
constexpr uint32_t kWidth = 32, kHeight = 24;

std::string readBytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << file.rdbuf();
    return bytes.str();
}

void writeBytes(const fs::path& path, const std::string& bytes) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), std::streamsize(bytes.size()));
}

// The EXR mutations: cut the file short, flip bits anywhere, or overwrite bytes of the header (its
// first few hundred bytes hold the attributes: channels, compression, data and display windows).
std::string mutateFile(const std::string& original, std::mt19937& random) {
    std::string bytes = original;
    const auto pick = [&](size_t limit) { return std::uniform_int_distribution<size_t>(0, limit - 1)(random); };
    switch (pick(4)) {
        case 0:
            bytes.resize(pick(bytes.size()));
            break;
        case 1:
            for (size_t flips = 1 + pick(8); flips > 0; --flips) bytes[pick(bytes.size())] ^= char(1 << pick(8));
            break;
        case 2: {
            const size_t headerEnd = std::min<size_t>(bytes.size(), 400);
            for (size_t writes = 1 + pick(4); writes > 0; --writes) bytes[pick(headerEnd)] = char(pick(256));
            break;
        }
        default: {
            // A window attribute: its four int32 corners, one set to an extreme or random value.
            const char* names[] = {"dataWindow", "displayWindow"};
            const size_t at = bytes.find(names[pick(2)]);
            if (at == std::string::npos) break;
            const size_t valueAt = bytes.find('\0', bytes.find('\0', at) + 1) + 5 + 4 * pick(4);
            const int32_t values[] = {0, -1, 1 << 30, -(1 << 30), 15999, int32_t(pick(100000))};
            const int32_t value = values[pick(6)];
            if (valueAt + 4 <= bytes.size()) std::memcpy(&bytes[valueAt], &value, 4);
            break;
        }
    }
    return bytes;
}

}  // namespace

TEST_CASE("fuzz: mutated EXR files and option values never crash, touch the output or write non-finite values",
          "[fuzz]") {
    const fs::path folder = fs::temp_directory_path() / ("ffx_dof_cli_fuzz_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);

    ffxdof::io::ImageRGBA color(kWidth, kHeight);
    ffxdof::io::ImageR depth(kWidth, kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            float* pixel = color.at(x, y);
            pixel[0] = ((x + y) % 2) ? 0.9f : 0.1f;
            pixel[1] = 0.5f;
            pixel[2] = float(x) / kWidth;
            pixel[3] = 1.0f;
            depth.at(x, y) = 0.5f + 0.2f * float(x);
        }
    }
    ffxdof::io::writeExr((folder / "color.exr").string(), color, ffxdof::io::ExrPixelType::Half);
    ffxdof::io::writeExr((folder / "depth.exr").string(), depth, ffxdof::io::ExrPixelType::Float, "Z");
    const std::string colorBytes = readBytes(folder / "color.exr");
    const std::string depthBytes = readBytes(folder / "depth.exr");

    const std::vector<std::string> numericOptions = {
        "--focus",     "--fstop",          "--focal-length",    "--sensor-width", "--quality",
        "--coc-limit", "--device",         "--aperture-radius", "--autofocus",    "--focus-region",
        "--blades",    "--blade-rotation", "--roundness",       "--anamorphic",   "--cat-eye"};
    const std::vector<std::string> values = {"",       "nan", "inf",    "-inf",        "1e300", "-1", "0",
                                             "1e-300", "abc", "3.5e38", "99999999999", "-0",    " 1", "1e-42",
                                             "0x10",   "2,3", "33",     "2.5",         "1e-3",  "1e5"};
    // --autofocus takes a point X,Y: well-formed, malformed and out of range.
    const std::vector<std::string> points = {"0.5,0.5",   "0,0",     "1,1",   "0.3,0.8", "",        "0.5",  "a,b",
                                             "0.5,0.5,1", "nan,0.5", "2,0.5", "-0.1,1",  "1e300,0", ",0.5", "0.5, 0.5"};

    std::mt19937 random(20240613u);  // fixed: every run mutates the same way
    const auto pick = [&](size_t limit) { return std::uniform_int_distribution<size_t>(0, limit - 1)(random); };
    const auto start = std::chrono::steady_clock::now();
    int runs = 0, successes = 0;
    for (; runs < kMaxRuns && std::chrono::steady_clock::now() - start < kTimeBudget; ++runs) {
        writeBytes(folder / "c.exr", colorBytes);
        writeBytes(folder / "d.exr", depthBytes);
        const int what = int(pick(4));  // 0: color file, 1: depth file, 2: an option, 3: a file and an option
        if (what == 0 || (what == 3 && pick(2) == 0)) writeBytes(folder / "c.exr", mutateFile(colorBytes, random));
        if (what == 1 || (what == 3 && pick(2) == 1)) writeBytes(folder / "d.exr", mutateFile(depthBytes, random));
        std::string option, value;
        if (what >= 2) {
            option = numericOptions[pick(numericOptions.size())];
            value = option == "--autofocus" ? points[pick(points.size())] : values[pick(values.size())];
        }
        // Half the runs replace an existing output, which must then survive any failure byte for byte.
        const bool existingOutput = pick(2) == 0;
        fs::remove(folder / "out.exr");
        if (existingOutput) writeBytes(folder / "out.exr", "precious");

        std::string arguments = "apply --color " + quote((folder / "c.exr").string()) + " --depth " +
                                quote((folder / "d.exr").string()) + " --out " + quote((folder / "out.exr").string()) +
                                " --sensor-width 4 --quality 3";
        // Autofocus replaces --focus; a region goes with an autofocus point.
        const bool autofocus = option == "--autofocus" || option == "--focus-region";
        if (option == "--focus-region") arguments += " --autofocus 0.5,0.5";
        for (const auto& [name, standard] : {std::pair<std::string, std::string>{"--focus", "2"}, {"--fstop", "2"}}) {
            if (option != name && !(option == "--aperture-radius" && name == "--fstop") &&
                !(autofocus && name == "--focus")) {
                arguments += " " + name + " " + standard;
            }
        }
        if (!option.empty()) arguments += " " + option + " " + quote(value);
        const std::string command = quote(FFX_DOF_CLI_PROGRAM) + " " + arguments + " > " +
                                    quote((folder / "stdout").string()) + " 2> " + quote((folder / "stderr").string());
        const int status = std::system(command.c_str());
        const std::string err = readBytes(folder / "stderr");
        INFO("run " << runs << ": " << arguments << "\nstderr: " << err);
        REQUIRE(WIFEXITED(status));
        const int code = WEXITSTATUS(status);
        REQUIRE(code >= 0);
        REQUIRE(code <= 5);  // documented; 6 is an internal error, above that a signal through the shell
        if (code == 0) {
            ++successes;
            CHECK(err.empty());
            const ffxdof::io::ImageRGBA output = ffxdof::io::readExrColor((folder / "out.exr").string());
            CHECK(std::all_of(output.pixels.begin(), output.pixels.end(), [](float v) { return std::isfinite(v); }));
        } else {
            CHECK(err.rfind("ffx-dof: error: ", 0) == 0);
            CHECK(std::count(err.begin(), err.end(), '\n') == 1);
            if (existingOutput) {
                CHECK(readBytes(folder / "out.exr") == "precious");
            } else {
                CHECK(!fs::exists(folder / "out.exr"));
            }
        }
        // Nothing but the inputs, the output and the captured streams: no temporary file is left.
        size_t entries = 0;
        for (const auto& entry : fs::directory_iterator(folder)) {
            (void)entry;
            ++entries;
        }
        CHECK(entries == 6u + (fs::exists(folder / "out.exr") ? 1u : 0u));  // color, depth, c, d, stdout, stderr
    }
    CHECK(runs >= 40);      // the budget allowed a meaningful number of runs
    CHECK(successes >= 1);  // the mutations leave some runs valid, so the success path is checked too
    fs::remove_all(folder);
}
