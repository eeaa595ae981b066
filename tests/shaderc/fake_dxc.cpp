// A stand-in for dxc (not available on Linux here) that checks the command line ffx-dof-shaderc
// gives it and writes a container whose content is derived from that command line, so a test
// can tell, for every permutation key, that its blob came from exactly that key's arguments.
//
//   output: "DXBC" + "profile=<T>;16bit=<0|1>;entry=<E>;defines=<N=V,...>;" padded with NUL to 4 bytes
//
// Like a compiler, whose output does not change with a macro the source never mentions, only the
// defines whose name occurs in the source text are part of the output (so a no-op axis dedups).
// Test hooks, as defines: FFX_DOF_FAKE_DXC_FAIL=1 -> exit 1 with two lines on stderr;
// FFX_DOF_FAKE_DXC_NO_OUTPUT=1 -> exit 0 without writing the output.
// Any check that fails -> exit 3 and "fake-dxc: bad arguments: ..." on stderr.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

int badArguments(const std::string& why) {
    std::fprintf(stderr, "fake-dxc: bad arguments: %s\n", why.c_str());
    return 3;
}

}  // namespace

int main(int argc, char** argv) {
    std::string profile, entry, language, output;
    bool sixteenBit = false;
    std::vector<std::string> sources, includeDirs;
    std::map<std::string, std::string> defines;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        const bool hasValue = i + 1 < argc;
        if (argument == "-enable-16bit-types") {
            sixteenBit = true;
        } else if (argument == "-T" || argument == "-E" || argument == "-HV" || argument == "-I" || argument == "-D" ||
                   argument == "-Fo") {
            if (!hasValue) return badArguments(argument + " without a value");
            const std::string value = argv[++i];
            if (argument == "-T") profile = value;
            if (argument == "-E") entry = value;
            if (argument == "-HV") language = value;
            if (argument == "-I") includeDirs.push_back(value);
            if (argument == "-Fo") output = value;
            if (argument == "-D") {
                const size_t equals = value.find('=');
                if (equals == std::string::npos) return badArguments("-D " + value + " has no value");
                if (!defines.emplace(value.substr(0, equals), value.substr(equals + 1)).second) {
                    return badArguments("-D " + value + " given twice");
                }
            }
        } else if (!argument.empty() && argument[0] == '-') {
            return badArguments("unknown option " + argument);
        } else {
            sources.push_back(argument);
        }
    }
    auto defineIs = [&defines](const char* name, const char* value) {
        const auto it = defines.find(name);
        return it != defines.end() && it->second == value;
    };
    if (sources.size() != 1) return badArguments(std::to_string(sources.size()) + " source files, expected 1");
    if (output.empty()) return badArguments("no -Fo");
    if (entry != "main") return badArguments("entry point '" + entry + "', expected main");
    if (language != "2021") return badArguments("-HV '" + language + "', expected 2021");
    const char* expectedProfile = defineIs("FFX_DOF_OPTION_WAVE64", "1") ? "cs_6_6" : "cs_6_2";
    if (profile != expectedProfile) return badArguments("profile '" + profile + "', expected " + expectedProfile);
    if (sixteenBit != defineIs("FFX_HALF", "1")) {
        return badArguments(sixteenBit ? "-enable-16bit-types without FFX_HALF=1"
                                       : "FFX_HALF=1 without -enable-16bit-types");
    }
    // The glslang-only defines of the reflection compile must not reach dxc.
    for (const char* name : {"binding", "__DXC_VERSION_MAJOR"}) {
        if (defines.count(name)) return badArguments(std::string("-D ") + name + " must not be passed");
    }
    for (const std::string& dir : includeDirs) {
        if (!fs::is_directory(dir)) return badArguments("include folder " + dir + " does not exist");
    }
    std::ifstream sourceFile(sources[0], std::ios::binary);
    if (!sourceFile) return badArguments("cannot read " + sources[0]);
    std::ostringstream sourceText;
    sourceText << sourceFile.rdbuf();

    if (defineIs("FFX_DOF_FAKE_DXC_FAIL", "1")) {
        std::fprintf(stderr, "%s:1:1: error: fake failure requested\nnote: second line of the fake message\n",
                     sources[0].c_str());
        return 1;
    }
    if (defineIs("FFX_DOF_FAKE_DXC_NO_OUTPUT", "1")) return 0;

    std::string blob =
        "DXBCprofile=" + profile + ";16bit=" + (sixteenBit ? "1" : "0") + ";entry=" + entry + ";defines=";
    bool first = true;
    for (const auto& [name, value] : defines) {  // std::map: sorted by name
        if (sourceText.str().find(name) == std::string::npos) continue;
        blob += (first ? "" : ",") + name + "=" + value;
        first = false;
    }
    blob += ";";
    blob.append((4 - blob.size() % 4) % 4, '\0');
    std::ofstream out(output, std::ios::binary | std::ios::trunc);
    out << blob;
    out.close();
    if (!out) {
        std::fprintf(stderr, "fake-dxc: cannot write %s\n", output.c_str());
        return 1;
    }
    return 0;
}
