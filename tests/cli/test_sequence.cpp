// Frame patterns, frame lists, chunks and camera tracks of `ffx-dof apply --frames` (no device).
#include "cli_error.h"
#include "commands.h"
#include "sequence.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace ffxdof::cli;

namespace {

template <typename Call>
void requireCliError(Call call, ExitCode code, const std::string& fragment) {
    try {
        call();
        FAIL("no error");
    } catch (const CliError& error) {
        INFO(error.what());
        CHECK(error.code() == code);
        CHECK_THAT(error.what(), Catch::Contains(fragment));
    }
}

std::string writeTemp(const std::string& name, const std::string& text) {
    const std::string path = "/tmp/ffx_dof_sequence_test_" + std::to_string(::getpid()) + "_" + name;
    std::ofstream(path) << text;
    return path;
}

}  // namespace

TEST_CASE("frame patterns: #### and %0Nd", "[cpu]") {
    CHECK(FramePattern("shot.####.exr", "--color").path(7) == "shot.0007.exr");
    CHECK(FramePattern("shot.####.exr", "--color").path(1001) == "shot.1001.exr");
    CHECK(FramePattern("shot.##.exr", "--color").path(12345) == "shot.12345.exr");
    CHECK(FramePattern("shot.%04d.exr", "--color").path(42) == "shot.0042.exr");
    CHECK(FramePattern("shot.%d.exr", "--color").path(42) == "shot.42.exr");
    CHECK_FALSE(FramePattern("still.exr", "--depth").hasField());
    CHECK(FramePattern("still.exr", "--depth").path(5) == "still.exr");
    requireCliError([] { FramePattern("a.##.b.##.exr", "--out"); }, ExitCode::Usage, "--out");
    requireCliError([] { FramePattern("a.%4s.exr", "--out"); }, ExitCode::Usage, "%0Nd");
    requireCliError([] { FramePattern("a.%04d.####.exr", "--out"); }, ExitCode::Usage, "more than one");
}

TEST_CASE("frame lists: A-B, A-BxS, lists, errors", "[cpu]") {
    CHECK(parseFrameList("1001-1004") == std::vector<int64_t>{1001, 1002, 1003, 1004});
    CHECK(parseFrameList("1-10x3") == std::vector<int64_t>{1, 4, 7, 10});
    CHECK(parseFrameList("5") == std::vector<int64_t>{5});
    CHECK(parseFrameList("1-3,2-5") == std::vector<int64_t>{1, 2, 3, 4, 5});
    for (const char* bad : {"", "a-b", "1-", "-3", "1-3x", "1-3,", "1.5-3", "1 - 3", "1-3y2", "1234567890"}) {
        INFO(bad);
        requireCliError([&] { parseFrameList(bad); }, ExitCode::Usage, "--frames");
    }
    requireCliError([] { parseFrameList("5-3"); }, ExitCode::InvalidValue, "before the first");
    requireCliError([] { parseFrameList("1-5x0"); }, ExitCode::InvalidValue, "step");
}

TEST_CASE("chunks split the frames into contiguous shares that cover them once", "[cpu]") {
    const std::vector<int64_t> frames = parseFrameList("1-7");
    std::vector<int64_t> joined;
    for (uint32_t i = 1; i <= 3; ++i) {
        const std::vector<int64_t> share = chunkOf(frames, parseChunk(std::to_string(i) + "/3"));
        CHECK(share.size() >= 2);
        CHECK(share.size() <= 3);
        joined.insert(joined.end(), share.begin(), share.end());
    }
    CHECK(joined == frames);
    CHECK(chunkOf(parseFrameList("1-2"), parseChunk("2/4")).size() == 1);
    CHECK(chunkOf(parseFrameList("1-2"), parseChunk("1/4")).empty());
    requireCliError([] { parseChunk("0/3"); }, ExitCode::InvalidValue, "1 to N");
    requireCliError([] { parseChunk("4/3"); }, ExitCode::InvalidValue, "1 to N");
    requireCliError([] { parseChunk("2-3"); }, ExitCode::Usage, "I/N");
}

TEST_CASE("camera tracks: JSON and CSV give the lens per frame", "[cpu]") {
    LensSettings commandLine;
    commandLine.focusMetres = 3.0;
    commandLine.fNumber = 2.8;
    const std::string json = writeTemp("track.json", R"({"frames": [
        {"frame": 1001, "focus": 2.5, "fstop": 2.0},
        {"frame": 1002, "focus": 2.6, "aperture_radius": 0.01, "focal_length": 35, "sensorWidth": 24}]})");
    const CameraTrack fromJson = readCameraTrack(json);
    REQUIRE(fromJson.size() == 2);
    const LensSettings a = lensForFrame(commandLine, fromJson, 1001, json);
    CHECK(a.focusMetres == 2.5);
    CHECK(*a.fNumber == 2.0);
    CHECK(a.focalLengthMm == 50.0);  // from the command line
    const LensSettings b = lensForFrame(commandLine, fromJson, 1002, json);
    CHECK_FALSE(b.fNumber);
    CHECK(*b.apertureRadiusMetres == 0.01);
    CHECK(b.focalLengthMm == 35.0);
    CHECK(b.sensorWidthMm == 24.0);
    requireCliError([&] { lensForFrame(commandLine, fromJson, 1003, json); }, ExitCode::InvalidValue, "frame 1003");

    const std::string csv = writeTemp("track.csv", "frame,focus,f-stop,focal_length\n1,4.0,1.4,50\n2,4.5,,85\n");
    const CameraTrack fromCsv = readCameraTrack(csv);
    REQUIRE(fromCsv.size() == 2);
    const LensSettings c = lensForFrame(commandLine, fromCsv, 2, csv);
    CHECK(c.focusMetres == 4.5);
    CHECK(*c.fNumber == 2.8);  // empty field: the command line's
    CHECK(c.focalLengthMm == 85.0);

    requireCliError([] { readCameraTrack(writeTemp("bad1.csv", "frame,zoom\n1,2\n")); }, ExitCode::InputFile,
                    "unknown column zoom");
    requireCliError([] { readCameraTrack(writeTemp("bad2.csv", "frame,focus\n1,x\n")); }, ExitCode::InputFile,
                    "line 2");
    requireCliError([] { readCameraTrack(writeTemp("bad3.json", "[{\"focus\": 2}]")); }, ExitCode::InputFile,
                    "no frame");
    requireCliError(
        [] { readCameraTrack(writeTemp("bad4.json", "[{\"frame\": 1, \"fstop\": 2, \"aperture_radius\": 1}]")); },
        ExitCode::InputFile, "both");
    requireCliError([] { readCameraTrack("/nonexistent/track.json"); }, ExitCode::InputFile, "cannot open");
    for (const char* name : {"track.json", "track.csv", "bad1.csv", "bad2.csv", "bad3.json", "bad4.json"}) {
        std::remove(("/tmp/ffx_dof_sequence_test_" + std::to_string(::getpid()) + "_" + name).c_str());
    }
}

TEST_CASE("the CoC limit follows the image unless given", "[cpu]") {
    EffectOptions options;
    options.cocLimit = 0.05;
    CHECK(effectiveCocLimit(options, 100.0, 540) == 0.05);
    options.cocLimitFollowsImage = true;
    const double limit = effectiveCocLimit(options, 40.0, 540);
    CHECK(limit * 540 * 0.5 > 40.0);
    CHECK(limit * 540 * 0.5 < 40.1);
    CHECK(effectiveCocLimit(options, 1e9, 540) == kLargestAutoCocLimit);
}
