// ffx-dof-shaderc: compiles every permutation of one pass into C++ tables. See docs/permutations.md.
#include "shaderc.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>

namespace {

using namespace ffxdof::shaderc;

struct Arguments {
    std::string pass;
    std::string language;
    std::string source;
    std::vector<std::string> includeDirs;
    std::vector<std::string> defines;
    std::vector<std::string> axes;
    std::vector<std::string> hlslShifts;
    std::string outDir;
    std::string basename;
    std::string cppNamespace = "ffxdof::shaders";
    std::string depfile;
    std::string dxc;
    std::string cacheDir;
    unsigned jobs = 0;
};

HlslBindingShifts parseShifts(const std::vector<std::string>& texts) {
    HlslBindingShifts shifts;
    for (const std::string& text : texts) {
        const size_t equals = text.find('=');
        const std::string register_ = text.substr(0, equals);
        uint32_t* target = register_ == "t"   ? &shifts.texture
                           : register_ == "u" ? &shifts.uav
                           : register_ == "s" ? &shifts.sampler
                           : register_ == "b" ? &shifts.constantBuffer
                                              : nullptr;
        const std::string value = equals == std::string::npos ? "" : text.substr(equals + 1);
        if (!target || value.empty() || value.size() > 6 ||
            value.find_first_not_of("0123456789") != std::string::npos) {
            throw Error("--hlsl-shift '" + text + "': expected t=N, u=N, s=N or b=N");
        }
        *target = static_cast<uint32_t>(std::stoul(value));
    }
    return shifts;
}

int run(const Arguments& args) {
    CompileOptions options;
    options.pass = args.pass;
    options.source = args.source;
    if (!args.language.empty()) {
        options.language = parseLanguage(args.language);
    } else {
        const std::string extension = options.source.extension().string();
        if (extension != ".glsl" && extension != ".hlsl") {
            throw Error("cannot tell the language of " + args.source + ": pass --language glsl|hlsl");
        }
        options.language = parseLanguage(extension.substr(1));
    }
    for (const std::string& dir : args.includeDirs) {
        std::error_code ec;
        if (!fs::is_directory(dir, ec)) throw Error("include folder not found: " + dir);
        options.includeDirs.push_back(dir);
    }
    for (const std::string& define : args.defines) options.defines.push_back(parseDefine(define));
    options.hlslShifts = parseShifts(args.hlslShifts);
    if (!args.dxc.empty()) {
        if (options.language != Language::Hlsl) throw Error("--dxc needs an HLSL source (--language hlsl)");
        // Shifts are the Vulkan mapping of registers; DXIL binds the registers themselves.
        if (!args.hlslShifts.empty()) throw Error("--hlsl-shift applies to SPIR-V only, not with --dxc");
        options.dxc = args.dxc;
    }
    std::vector<Axis> axes;
    for (const std::string& text : args.axes) {
        Axis axis = parseAxis(text);
        for (const Axis& other : axes) {
            if (other.macro == axis.macro) throw Error("axis '" + axis.macro + "' is given twice");
        }
        for (const Define& define : options.defines) {
            if (define.name == axis.macro) throw Error("'" + axis.macro + "' is both an axis and a plain define");
        }
        axes.push_back(std::move(axis));
    }

    std::unique_ptr<PermutationCache> cache;
    if (!args.cacheDir.empty()) {
        if (!args.dxc.empty()) throw Error("--cache-dir keeps SPIR-V only; it cannot be combined with --dxc");
        cache = std::make_unique<PermutationCache>(args.cacheDir);
        options.cache = cache.get();
    }

    const PassBuild build = buildPass(options, axes, args.jobs);

    const fs::path outDir = args.outDir;
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (!fs::is_directory(outDir, ec)) throw Error("cannot create output folder " + outDir.string());
    const std::string basename =
        args.basename.empty() ? "ffx_dof_" + args.pass + "_" + tableLanguage(options) : args.basename;
    EmitOptions emit;
    emit.cppNamespace = args.cppNamespace;
    const fs::path header = outDir / (basename + ".h");
    std::vector<std::pair<fs::path, std::string>> files = {
        {header, emitHeader(build, emit)},
        {outDir / (basename + ".cpp"), emitSource(build, emit, basename + ".h")},
        {outDir / (basename + ".json"), emitManifest(build)},
    };
    if (!args.depfile.empty()) files.emplace_back(args.depfile, emitDepfile(header, build.dependencies));
    writeFilesAtomically(files);
    std::printf("ffx-dof-shaderc: %s (%s): %zu permutations, %zu unique blobs", args.pass.c_str(),
                tableLanguage(options), build.permutationToBlob.size(), build.blobs.size());
    if (cache) std::printf(", %u from the cache, %u compiled", cache->hits(), cache->misses());
    std::printf("\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "ffx-dof-shaderc: compiles every permutation of one ffx-dof pass to SPIR-V (or DXIL with dxc) and emits C++ "
        "tables"};
    Arguments args;
    app.add_option("source", args.source, "Pass source (.glsl or .hlsl)")->required();
    app.add_option("--pass", args.pass, "Pass name, used in messages and table names")->required();
    app.add_option("--language", args.language, "glsl or hlsl (default: from the source extension)");
    app.add_option("-I,--include-dir", args.includeDirs, "Include folder (repeatable)");
    app.add_option("--define", args.defines, "Plain define NAME=VALUE in every permutation (repeatable)");
    app.add_option("-D", args.axes, "Permutation axis NAME={v1,v2,...} (repeatable)");
    app.add_option("--hlsl-shift", args.hlslShifts, "HLSL register class binding shift: t=N, u=N, s=N or b=N");
    app.add_option("-o,--out-dir", args.outDir, "Output folder for <basename>.h/.cpp/.json")->required();
    app.add_option("--basename", args.basename, "Output file name stem (default ffx_dof_<pass>_<language>)");
    app.add_option("--namespace", args.cppNamespace, "C++ namespace of the generated table")->capture_default_str();
    app.add_option("--depfile", args.depfile, "Write a Makefile-syntax depfile of every file read");
    app.add_option("--dxc", args.dxc,
                   "Emit DXIL (table language \"dxil\") by running this dxc per permutation; HLSL only");
    app.add_option("--cache-dir", args.cacheDir,
                   "Look each permutation's SPIR-V up in this folder before compiling it, and file it there after "
                   "(keyed by this executable, the options and the preprocessed source); not with --dxc");
    app.add_option("-j,--jobs", args.jobs, "Worker threads (default: all cores)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::ParseError& error) {
        std::fprintf(stderr, "ffx-dof-shaderc: error: %s (see --help)\n", error.what());
        return 2;
    }
    try {
        GlslangProcess glslang;
        return run(args);
    } catch (const Error& error) {
        std::fprintf(stderr, "ffx-dof-shaderc: error: %s\n", error.what());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "ffx-dof-shaderc: internal error: %s\n", error.what());
    }
    return 1;
}
