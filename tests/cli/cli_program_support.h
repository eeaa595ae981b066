// Running the built ffx-dof program from a test (FFX_DOF_CLI_PROGRAM): its exit code, stdout and
// stderr, and the check of a failure's one-line message.
#pragma once

#include "ffx_dof_temp_folder.h"

#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace ffxdof::clitest {

struct ProgramResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

// Single-quoted for sh, with embedded quotes escaped.
inline std::string quote(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

// stdout goes to a file: not a terminal, so sequences print a plain line per frame.
inline ProgramResult runProgram(const std::string& arguments) {
    const ffxdof::testing::TempFolder folder("ffx_dof_cli_run_");
    const std::string command =
        quote(FFX_DOF_CLI_PROGRAM) + " " + arguments + " > " + quote(folder / "out") + " 2> " + quote(folder / "err");
    const int status = std::system(command.c_str());
    ProgramResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = ffxdof::testing::readText(folder.path() / "out");
    result.err = ffxdof::testing::readText(folder.path() / "err");
    return result;
}

// A failure is exactly one line on stderr, "ffx-dof: error: ...", and the documented exit code.
inline void requireError(const ProgramResult& result, int exitCode, const std::string& fragment) {
    INFO("stderr: " << result.err);
    CHECK(result.exitCode == exitCode);
    CHECK(result.err.rfind("ffx-dof: error: ", 0) == 0);
    CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
    CHECK_THAT(result.err, Catch::Contains(fragment));
}

}  // namespace ffxdof::clitest
