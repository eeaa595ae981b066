// DXIL for the D3D12 backend: one dxc process per permutation. dxc is not a library we can link on
// every platform (and not packaged in Debian), so it runs as a subprocess; its output file is read
// back and removed. Bindings are not read from the DXIL: see reflectionDefines below.
#include "shaderc.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#if defined(_WIN32)
#include <process.h>
#include <windows.h>
#else
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
extern char** environ;
#endif

namespace ffxdof::shaderc {
namespace {

constexpr const char* kHalfMacro = "FFX_HALF";
constexpr const char* kWave64Macro = "FFX_DOF_OPTION_WAVE64";
// "DXBC": the magic of every DXIL container (the format D3D12 takes as shader bytecode).
constexpr char kContainerMagic[4] = {'D', 'X', 'B', 'C'};

bool macroIsOne(const CompileOptions& options, const std::vector<Define>& permutation, const char* macro) {
    for (const std::vector<Define>* list : {&options.defines, &permutation}) {
        for (const Define& define : *list) {
            if (define.name == macro) return define.value == "1";
        }
    }
    return false;
}

std::string readWhole(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream stream;
    stream << file.rdbuf();
    return stream.str();
}

// One line: dxc's messages joined with " | ", so the error stays one line per failure.
std::string oneLine(const std::string& text) {
    std::string result;
    std::istringstream stream(text);
    std::string line;
    while (std::getline(stream, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        result += (result.empty() ? "" : " | ") + line;
    }
    return result.empty() ? "(no message)" : result;
}

#if defined(_WIN32)
// CommandLineToArgvW's rules: quote, double the backslashes before a quote, escape quotes.
std::wstring quoteArgument(const std::wstring& argument) {
    if (!argument.empty() && argument.find_first_of(L" \t\"") == std::wstring::npos) return argument;
    std::wstring quoted = L"\"";
    size_t backslashes = 0;
    for (wchar_t c : argument) {
        if (c == L'\\') {
            ++backslashes;
            continue;
        }
        quoted.append(c == L'"' ? backslashes * 2 + 1 : backslashes, L'\\');
        backslashes = 0;
        quoted += c;
    }
    quoted.append(backslashes * 2, L'\\');
    return quoted + L"\"";
}

// Runs `arguments` (arguments[0] the program) with stdout and stderr into `logFile`. Returns the
// exit code, or throws Error when the program cannot be started.
int runProcess(const std::vector<std::string>& arguments, const fs::path& logFile) {
    std::wstring commandLine;
    for (const std::string& argument : arguments) {
        commandLine += (commandLine.empty() ? L"" : L" ") + quoteArgument(fs::u8path(argument).wstring());
    }
    SECURITY_ATTRIBUTES inherit = {sizeof(inherit), nullptr, TRUE};
    HANDLE log = CreateFileW(logFile.wstring().c_str(), GENERIC_WRITE, FILE_SHARE_READ, &inherit, CREATE_ALWAYS,
                             FILE_ATTRIBUTE_TEMPORARY, nullptr);
    if (log == INVALID_HANDLE_VALUE) throw Error("cannot create " + logFile.string());
    STARTUPINFOW startup = {};
    startup.cb = sizeof(startup);
    startup.dwFlags = STARTF_USESTDHANDLES;
    startup.hStdInput = GetStdHandle(STD_INPUT_HANDLE);
    startup.hStdOutput = log;
    startup.hStdError = log;
    PROCESS_INFORMATION process = {};
    const BOOL started = CreateProcessW(nullptr, commandLine.data(), nullptr, nullptr, TRUE, CREATE_NO_WINDOW, nullptr,
                                        nullptr, &startup, &process);
    CloseHandle(log);
    if (!started) {
        throw Error("cannot run dxc '" + arguments[0] + "' (Windows error " + std::to_string(GetLastError()) + ")");
    }
    WaitForSingleObject(process.hProcess, INFINITE);
    DWORD exitCode = 1;
    GetExitCodeProcess(process.hProcess, &exitCode);
    CloseHandle(process.hThread);
    CloseHandle(process.hProcess);
    return static_cast<int>(exitCode);
}

unsigned long processId() { return static_cast<unsigned long>(_getpid()); }
#else
int runProcess(const std::vector<std::string>& arguments, const fs::path& logFile) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::vector<char*> argv;
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    pid_t child = 0;
    const int spawnError = posix_spawnp(&child, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawnError != 0) throw Error("cannot run dxc '" + arguments[0] + "': " + std::strerror(spawnError));
    int status = 0;
    while (waitpid(child, &status, 0) < 0) {
        if (errno != EINTR) throw Error("cannot wait for dxc '" + arguments[0] + "': " + std::strerror(errno));
    }
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

unsigned long processId() { return static_cast<unsigned long>(getpid()); }
#endif

// Temporaries of concurrent workers (and of concurrent tool runs) must not collide.
fs::path temporaryStem(const CompileOptions& options) {
    static std::atomic<unsigned> counter{0};
    return fs::temp_directory_path() / ("ffx-dof-shaderc-" + std::to_string(processId()) + "-" +
                                        symbolFor(options.pass) + "-" + std::to_string(counter++));
}

}  // namespace

std::vector<Define> dxilReflectionDefines() {
    // The bindings of the DXIL tables come from compiling the same source with glslang's HLSL
    // front end and reflecting that SPIR-V, because dxc gives us no reflection API on every host
    // (and parsing the container's RDAT/PSV parts ourselves would be a second, untested reader).
    // For that compile to see the source as dxc does for DXIL:
    // - __DXC_VERSION_MAJOR is defined, so every `#if defined(__DXC_VERSION_MAJOR)` takes the
    //   branch dxc takes (resources that exist only on D3D12 or only on Vulkan);
    // - [[vk::binding]] (Vulkan-only; dxc ignores it for DXIL) must not override the register.
    //   glslang has no switch for that, so `binding` becomes an unknown attribute name, which
    //   glslang warns about and ignores; the `register(uN, spaceM)` then gives binding N, set M.
    return {{"__DXC_VERSION_MAJOR", "1"}, {"binding", "ffxDofDxilIgnoredAttribute"}};
}

std::vector<std::string> dxcArguments(const CompileOptions& options, const std::vector<Define>& permutation,
                                      const fs::path& output) {
    std::vector<std::string> arguments = {options.dxc.string(),
                                          "-T",
                                          macroIsOne(options, permutation, kWave64Macro) ? "cs_6_6" : "cs_6_2",
                                          "-E",
                                          "main",
                                          "-HV",
                                          "2021"};
    if (macroIsOne(options, permutation, kHalfMacro)) arguments.push_back("-enable-16bit-types");
    for (const fs::path& dir : options.includeDirs) {
        arguments.push_back("-I");
        arguments.push_back(dir.string());
    }
    for (const std::vector<Define>* list : {&options.defines, &permutation}) {
        for (const Define& define : *list) {
            arguments.push_back("-D");
            arguments.push_back(define.name + "=" + define.value);
        }
    }
    arguments.push_back("-Fo");
    arguments.push_back(output.string());
    arguments.push_back(options.source.string());
    return arguments;
}

std::vector<uint32_t> compileDxil(const CompileOptions& options, const std::vector<Define>& permutation,
                                  const std::string& where) {
    const fs::path stem = temporaryStem(options);
    fs::path output = stem, log = stem;
    output += ".dxil";
    log += ".log";
    struct Cleanup {
        fs::path a, b;
        ~Cleanup() {
            std::error_code ignored;
            fs::remove(a, ignored);
            fs::remove(b, ignored);
        }
    } cleanup{output, log};

    int exitCode = 0;
    try {
        exitCode = runProcess(dxcArguments(options, permutation, output), log);
    } catch (const Error& error) {
        throw Error(where + ": " + error.what());
    }
    if (exitCode != 0) {
        throw Error(where + ": dxc failed (exit code " + std::to_string(exitCode) + "): " + oneLine(readWhole(log)));
    }
    std::error_code ec;
    if (!fs::is_regular_file(output, ec)) {
        throw Error(where + ": dxc wrote no output file (" + oneLine(readWhole(log)) + ")");
    }
    const std::string bytes = readWhole(output);
    if (bytes.size() < sizeof(kContainerMagic) || std::memcmp(bytes.data(), kContainerMagic, 4) != 0) {
        throw Error(where + ": dxc's output is not a DXIL container (no DXBC magic, " + std::to_string(bytes.size()) +
                    " bytes)");
    }
    // The tables hold 32-bit words; a container's parts are 4-byte aligned, so its size is too.
    if (bytes.size() % 4 != 0) {
        throw Error(where + ": dxc's output size " + std::to_string(bytes.size()) + " is not a multiple of 4");
    }
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    return words;
}

}  // namespace ffxdof::shaderc
