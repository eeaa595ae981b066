// Running ffx-dof-shaderc from the tests (its command line, exit code and stderr), shared by the
// command-line tests of SPIR-V and DXIL output.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace ffxdof::test {

namespace fs = std::filesystem;

struct RunResult {
    int exitCode = -1;
    std::string stderrText;
    std::string stdoutText;
};

// Runs the tool with `arguments` (shell-quoted by the caller), capturing stderr and stdout.
inline RunResult runTool(const std::string& arguments) {
    // One file per process: CTest runs the test cases of this file in parallel processes.
    const std::string pid = std::to_string(getpid());
    const fs::path errFile = fs::path(FFX_DOF_TEST_WORK_DIR) / ("stderr." + pid + ".txt");
    const fs::path outFile = fs::path(FFX_DOF_TEST_WORK_DIR) / ("stdout." + pid + ".txt");
    fs::create_directories(FFX_DOF_TEST_WORK_DIR);
    const std::string command = std::string("'") + FFX_DOF_SHADERC_EXE + "' " + arguments + " 2>'" + errFile.string() +
                                "' >'" + outFile.string() + "'";
    const int status = std::system(command.c_str());
    RunResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    const auto read = [](const fs::path& path) {
        std::ifstream in(path);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    };
    result.stderrText = read(errFile);
    result.stdoutText = read(outFile);
    return result;
}

inline size_t lineCount(const std::string& text) {
    size_t lines = 0;
    for (char c : text) lines += c == '\n';
    return lines;
}

inline fs::path freshOutDir(const char* name) {
    const fs::path dir = fs::path(FFX_DOF_TEST_WORK_DIR) / name;
    fs::remove_all(dir);
    return dir;
}

inline bool isEmptyOrAbsent(const fs::path& dir) { return !fs::exists(dir) || fs::is_empty(dir); }

inline std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace ffxdof::test
