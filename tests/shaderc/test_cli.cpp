// The command line: bad input gets one line naming the problem, a non-zero exit, and no output.
#include <catch2/catch.hpp>

#include "run_tool.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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

TEST_CASE("the permutation cache: a second build reads every permutation back, a changed header compiles again",
          "[cli][cache]") {
    // The test pass copied, so that its header can change.
    const fs::path work = freshOutDir("cache");
    const fs::path shaders = work / "shaders", cache = work / "cache";
    fs::create_directories(shaders);
    for (const char* file : {"ffx_dof_test.glsl", "ffx_dof_test_common.h"})
        fs::copy_file(fs::path(kShaders) / file, shaders / file);
    const auto build = [&](const fs::path& out, bool cached) {
        return runTool("'" + (shaders / "ffx_dof_test.glsl").string() + "' --pass test -I '" + shaders.string() +
                       "' '-DFFX_HALF={0,1}' '-DFFX_DOF_TEST_SCALE={1,2}' --define FFX_DOF_TEST_WIDE=0 -o '" +
                       out.string() + "'" + (cached ? " --cache-dir '" + cache.string() + "'" : std::string()));
    };
    const auto cacheFiles = [&] {
        std::vector<fs::path> files;
        for (const auto& entry : fs::directory_iterator(cache)) files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        return files;
    };
    const auto sameOutputs = [&](const fs::path& a, const fs::path& b) {
        for (const char* file : {"ffx_dof_test_glsl.h", "ffx_dof_test_glsl.cpp", "ffx_dof_test_glsl.json"}) {
            INFO(file);
            if (readText(a / file) != readText(b / file)) return false;
        }
        return true;
    };

    const RunResult uncached = build(work / "uncached", false);
    REQUIRE(uncached.exitCode == 0);
    const RunResult first = build(work / "first", true);
    INFO(first.stderrText);
    REQUIRE(first.exitCode == 0);
    CHECK(first.stdoutText.find("0 from the cache, 4 compiled") != std::string::npos);
    CHECK(sameOutputs(work / "uncached", work / "first"));
    const std::vector<fs::path> filed = cacheFiles();
    REQUIRE(filed.size() == 4);
    for (const fs::path& file : filed) CHECK(file.extension() == ".spv");

    const RunResult second = build(work / "second", true);
    REQUIRE(second.exitCode == 0);
    CHECK(second.stdoutText.find("4 from the cache, 0 compiled") != std::string::npos);
    CHECK(sameOutputs(work / "first", work / "second"));

    // An entry that is not SPIR-V (a disk error, an interrupted copy) is compiled again and filed anew.
    std::ofstream(filed[0], std::ios::binary | std::ios::trunc) << "not SPIR-V";
    const RunResult repaired = build(work / "repaired", true);
    REQUIRE(repaired.exitCode == 0);
    CHECK(repaired.stdoutText.find("3 from the cache, 1 compiled") != std::string::npos);
    CHECK(sameOutputs(work / "first", work / "repaired"));
    CHECK(readText(filed[0]).rfind("not SPIR-V", 0) != 0);

    // The entries are what a hit returns: two swapped, the tables change (so nothing was compiled).
    const std::string a = readText(filed[0]), b = readText(filed[1]);
    std::ofstream(filed[0], std::ios::binary | std::ios::trunc) << b;
    std::ofstream(filed[1], std::ios::binary | std::ios::trunc) << a;
    REQUIRE(build(work / "swapped", true).exitCode == 0);
    CHECK_FALSE(sameOutputs(work / "first", work / "swapped"));
    std::ofstream(filed[0], std::ios::binary | std::ios::trunc) << a;
    std::ofstream(filed[1], std::ios::binary | std::ios::trunc) << b;

    // An included header changes the key of every permutation that includes it.
    std::string header = readText(shaders / "ffx_dof_test_common.h");
    const size_t at = header.find("FFX_DOF_TEST_GROUP_SIZE 8");
    REQUIRE(at != std::string::npos);
    header.replace(at, std::string("FFX_DOF_TEST_GROUP_SIZE 8").size(), "FFX_DOF_TEST_GROUP_SIZE 4");
    std::ofstream(shaders / "ffx_dof_test_common.h", std::ios::binary | std::ios::trunc) << header;
    const RunResult changed = build(work / "changed", true);
    REQUIRE(changed.exitCode == 0);
    CHECK(changed.stdoutText.find("0 from the cache, 4 compiled") != std::string::npos);
    CHECK_FALSE(sameOutputs(work / "first", work / "changed"));
    CHECK(cacheFiles().size() == 8);
    for (const fs::path& file : cacheFiles()) CHECK(file.extension() == ".spv");  // no temporaries left

    // Bad use: a folder that cannot be made, and DXIL (the cache keeps SPIR-V only).
    const fs::path blocker = work / "not_a_folder";
    std::ofstream(blocker) << "x";
    const std::pair<std::string, std::string> bad[] = {
        {" --cache-dir '" + (blocker / "cache").string() + "'", "not_a_folder"},
        {" --language hlsl --dxc /bin/true --cache-dir '" + cache.string() + "'", "--dxc"},
    };
    for (const auto& [arguments, expected] : bad) {
        const fs::path out = work / "bad";
        const RunResult result =
            runTool("'" + (shaders / "ffx_dof_test.glsl").string() + "' --pass test -I '" + shaders.string() +
                    "' '-DFFX_HALF={0,1}' -o '" + out.string() + "'" + arguments);
        INFO(arguments << "\n" << result.stderrText);
        CHECK(result.exitCode == 1);
        CHECK(result.stderrText.rfind("ffx-dof-shaderc: error: ", 0) == 0);
        CHECK(result.stderrText.find(expected) != std::string::npos);
        CHECK(lineCount(result.stderrText) == 1);
        CHECK(isEmptyOrAbsent(out));
    }
}
