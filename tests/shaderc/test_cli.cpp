// The command line: bad input gets one line naming the problem, a non-zero exit, and no output.
#include <catch2/catch.hpp>

#include "run_tool.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using namespace ffxdof::test;

namespace {

const std::string kShaders = FFX_DOF_TEST_SHADER_DIR;

}  // namespace

TEST_CASE("the tool writes header, source, manifest and depfile", "[cli]") {
    const fs::path out = freshOutDir("ok");
    const RunResult result =
        runTool("'" + kShaders + "/ffx_dof_test.glsl' --pass test -I '" + kShaders +
                "' '-DFFX_HALF={0,1}' '-DFFX_DOF_TEST_SCALE={1,2}' --define FFX_DOF_TEST_WIDE=0 -o '" + out.string() +
                "' --depfile '" + (out / "test.d").string() + "'");
    INFO(result.stderrText);
    REQUIRE(result.exitCode == 0);
    for (const char* file : {"ffx_dof_test_glsl.h", "ffx_dof_test_glsl.cpp", "ffx_dof_test_glsl.json", "test.d"}) {
        CHECK(fs::is_regular_file(out / file));
    }
    std::ifstream manifest(out / "ffx_dof_test_glsl.json");
    std::string text((std::istreambuf_iterator<char>(manifest)), std::istreambuf_iterator<char>());
    CHECK(text.find("\"permutations\": 4") != std::string::npos);
    CHECK(text.find("\"uniqueBlobs\": 4") != std::string::npos);
    for (const auto& entry : fs::directory_iterator(out)) CHECK(entry.path().extension() != ".tmp");
}

TEST_CASE("bad input: one line, non-zero exit, no output", "[cli]") {
    const fs::path out = freshOutDir("bad");
    const std::string source = "'" + kShaders + "/ffx_dof_test.glsl' --pass test -I '" + kShaders + "' ";
    const std::string axes = "'-DFFX_HALF={0,1}' '-DFFX_DOF_TEST_SCALE={1}' --define FFX_DOF_TEST_WIDE=0 ";
    const std::string outArg = "-o '" + out.string() + "'";
    // A regular file where the output folder's parent should be: the folder cannot be created,
    // whoever runs the test (root ignores permission bits).
    // The work folder may not exist yet when this case runs first in a fresh build: without it the
    // blocker file is never written and the tool would create the folder and succeed.
    fs::create_directories(FFX_DOF_TEST_WORK_DIR);
    const fs::path blocker = fs::path(FFX_DOF_TEST_WORK_DIR) / "not_a_folder";
    fs::remove_all(blocker);
    std::ofstream(blocker) << "x";
    REQUIRE(fs::is_regular_file(blocker));

    const std::pair<std::string, std::string> cases[] = {
        {source + axes + outArg + " --frobnicate", "--frobnicate"},
        {"'" + kShaders + "/no_such_pass.glsl' --pass test " + axes + outArg, "no_such_pass.glsl"},
        {source + axes + "'-DFFX_DOF_TEST_UNUSED={}' " + outArg, "has no values"},
        {source + axes + "-DFFX_DOF_TEST_UNUSED=1 " + outArg, "braces"},
        {source + axes + "'-DFFX_DOF_TEST_UNUSED={0,1' " + outArg, "braces"},
        {source + axes + "-o '" + (blocker / "out").string() + "'", "not_a_folder"},
        {source + axes + "-I /no/such/include/dir " + outArg, "/no/such/include/dir"},
        {source + axes + "--language cobol " + outArg, "cobol"},
        {"'" + kShaders + "/ffx_dof_test_cycle.glsl' --pass cycle " + outArg, "include cycle"},
        {"'" + kShaders + "/ffx_dof_test_cycle.glsl' --pass cycle -I '" + kShaders + "' " + outArg, "include cycle"},
    };
    for (const auto& [arguments, expected] : cases) {
        INFO(arguments);
        const RunResult result = runTool(arguments);
        INFO(result.stderrText);
        CHECK(result.exitCode != 0);
        CHECK(result.exitCode < 128);  // an exit, not a signal
        CHECK(result.stderrText.find(expected) != std::string::npos);
        CHECK(result.stderrText.rfind("ffx-dof-shaderc: error: ", 0) == 0);
        CHECK(isEmptyOrAbsent(out));
        if (expected != "include cycle") CHECK(lineCount(result.stderrText) == 1);
    }
}

TEST_CASE("a compile failure exits non-zero with context and leaves old outputs alone", "[cli]") {
    const fs::path out = freshOutDir("keep");
    fs::create_directories(out);
    std::ofstream(out / "ffx_dof_error_glsl.h") << "previous";
    const RunResult result =
        runTool("'" + kShaders + "/ffx_dof_test_error.glsl' --pass error '-DFFX_DOF_TEST_BROKEN={0,1}' -o '" +
                out.string() + "'");
    CHECK(result.exitCode == 1);
    CHECK(result.stderrText.find("FFX_DOF_TEST_BROKEN=1") != std::string::npos);
    CHECK(result.stderrText.find("ffxDofTestUndeclared") != std::string::npos);
    std::ifstream kept(out / "ffx_dof_error_glsl.h");
    std::string text((std::istreambuf_iterator<char>(kept)), std::istreambuf_iterator<char>());
    CHECK(text == "previous");
    CHECK(!fs::exists(out / "ffx_dof_error_glsl.cpp"));
}
