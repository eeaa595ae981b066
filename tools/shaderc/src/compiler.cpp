// One permutation: glslang (GLSL or HLSL front end) -> SPIR-V 1.3 -> spirv-opt -> spirv-val.
#include "shaderc.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include <algorithm>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>

namespace ffxdof::shaderc {
namespace {

// An include chain deeper than this is an unguarded cycle in practice; ffx-dof nests 3 deep.
constexpr int kMaxIncludeDepth = 32;

bool readFile(const fs::path& path, std::string* contents) {
    std::ifstream file(path, std::ios::binary);
    if (!file) return false;
    std::ostringstream stream;
    stream << file.rdbuf();
    *contents = stream.str();
    return static_cast<bool>(file) || file.eof();
}

// Resolves #include "x" against the including file's folder, then the -I folders; #include <x>
// only against the -I folders. Records every file opened (the depfile) and detects cycles.
class Includer : public glslang::TShader::Includer {
public:
    Includer(const CompileOptions& options, std::set<fs::path>* opened) : options_(options), opened_(opened) {}

    IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
        return include(header, fs::path(includer).parent_path(), depth);
    }
    IncludeResult* includeSystem(const char* header, const char*, size_t depth) override {
        return include(header, fs::path(), depth);
    }
    void releaseInclude(IncludeResult* result) override {
        if (!result) return;
        delete static_cast<std::string*>(result->userData);
        delete result;
    }
    const std::string& error() const { return error_; }

private:
    IncludeResult* include(const char* header, const fs::path& localDir, size_t depth) {
        std::vector<fs::path> candidates;
        if (!localDir.empty()) candidates.push_back(localDir / header);
        for (const fs::path& dir : options_.includeDirs) candidates.push_back(dir / header);
        for (const fs::path& candidate : candidates) {
            std::error_code ec;
            if (!fs::is_regular_file(candidate, ec)) continue;
            const fs::path resolved = fs::weakly_canonical(candidate, ec);
            // glslang reports the depth of the new file: 1 for one included by the source.
            chain_.resize(std::min(chain_.size(), depth > 0 ? depth - 1 : 0));
            chain_.push_back(resolved);
            if (static_cast<int>(depth) > kMaxIncludeDepth) {
                error_ = "include cycle: " + describeCycle();
                return nullptr;
            }
            auto contents = std::make_unique<std::string>();
            if (!readFile(resolved, contents.get())) {
                error_ = "cannot read included file " + resolved.string();
                return nullptr;
            }
            opened_->insert(resolved);
            const std::string* data = contents.release();
            return new IncludeResult(resolved.string(), data->data(), data->size(), const_cast<std::string*>(data));
        }
        // glslang retries a failed local include as a system include: keep the first reason.
        if (error_.empty()) error_ = "cannot find include file '" + std::string(header) + "'";
        return nullptr;
    }

    std::string describeCycle() const {
        // The chain ends in the repeating part; show it once, from the first repeated file.
        for (size_t start = 0; start < chain_.size(); ++start) {
            for (size_t next = start + 1; next < chain_.size(); ++next) {
                if (chain_[next] != chain_[start]) continue;
                std::string text;
                for (size_t i = start; i <= next; ++i)
                    text += (i > start ? " -> " : "") + chain_[i].filename().string();
                return text;
            }
        }
        return "include nesting deeper than " + std::to_string(kMaxIncludeDepth);
    }

    const CompileOptions& options_;
    std::set<fs::path>* opened_;
    std::vector<fs::path> chain_;  // chain_[d - 1]: the file included at depth d
    std::string error_;
};

std::string describePermutation(const CompileOptions& options, const std::vector<Define>& permutation) {
    std::string text = "pass '" + options.pass + "' (" + tableLanguage(options) + "), permutation";
    if (permutation.empty()) text += " (no axes)";
    for (const Define& define : permutation) text += " " + define.name + "=" + define.value;
    return text;
}

std::string sourceContext(const fs::path& file, int line) {
    std::string contents;
    if (!readFile(file, &contents)) return "";
    std::istringstream stream(contents);
    std::string text, result;
    for (int number = 1; std::getline(stream, text) && number <= line + 2; ++number) {
        if (number < line - 2) continue;
        if (!text.empty() && text.back() == '\r') text.pop_back();
        char prefix[32];
        std::snprintf(prefix, sizeof(prefix), "%s%5d | ", number == line ? ">" : " ", number);
        result += "    " + std::string(prefix) + text + "\n";
    }
    return result;
}

// glslang's log lines are "ERROR: <file>:<line>: <message>"; each gets the lines around it.
std::string withSourceContext(const std::string& log, const fs::path& source) {
    static const std::regex kLocated(R"(^(ERROR|WARNING): (.*):(\d+): (.*)$)");
    std::istringstream stream(log);
    std::string line, result, shownLocation;
    while (std::getline(stream, line)) {
        if (line.rfind("ERROR: ", 0) != 0 || line.find("compilation errors") != std::string::npos ||
            line.find("compilation terminated") != std::string::npos) {
            continue;
        }
        result += "  " + line + "\n";
        std::smatch match;
        if (!std::regex_match(line, match, kLocated) || std::stoi(match[3].str()) <= 0) continue;
        // glslang often reports several errors on one line; show its context once.
        const std::string location = match[2].str() + ":" + match[3].str();
        if (location == shownLocation) continue;
        shownLocation = location;
        fs::path file = match[2].str();
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) file = source;  // a string index ("0") means the main source
        result += sourceContext(file, std::stoi(match[3].str()));
    }
    return result.empty() ? "  " + log : result;
}

std::vector<uint32_t> optimize(const CompileOptions& options, const std::vector<uint32_t>& spirv,
                               std::string* messages) {
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_1);
    optimizer.SetMessageConsumer([messages](spv_message_level_t, const char*, const spv_position_t&,
                                            const char* message) { *messages += std::string(message) + "\n"; });
    // glslang's HLSL output needs legalization (e.g. resources in function parameters) first.
    if (options.language == Language::Hlsl) optimizer.RegisterLegalizationPasses();
    optimizer.RegisterPerformancePasses();
    spvtools::OptimizerOptions optimizerOptions;
    optimizerOptions.set_run_validator(false);  // validated once, after optimization
    std::vector<uint32_t> optimized;
    if (!optimizer.Run(spirv.data(), spirv.size(), &optimized, optimizerOptions)) return {};
    return optimized;
}

// Sets up `shader` as every permutation of the pass is read: front end, Vulkan target, and for HLSL what
// dxc -spirv does by default. Returns the messages to parse (or preprocess) with.
// The source as glslang takes it: the shader keeps these pointers until it is parsed.
struct ShaderSource {
    const char* strings[1];
    int lengths[1];
    const char* names[1];
    ShaderSource(const std::string& source, const std::string& name)
        : strings{source.c_str()}, lengths{static_cast<int>(source.size())}, names{name.c_str()} {}
};

EShMessages configureShader(glslang::TShader& shader, const CompileOptions& options, const ShaderSource& source,
                            const std::string& preamble) {
    const bool hlsl = options.language == Language::Hlsl;
    shader.setStringsWithLengthsAndNames(source.strings, source.lengths, source.names, 1);
    shader.setPreamble(preamble.c_str());
    shader.setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan,
                       100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
    shader.setEntryPoint("main");
    auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    if (hlsl) {
        // What dxc -spirv does by default: HLSL packing of constant buffers, real 16-bit types
        // (-enable-16bit-types), registers mapped to bindings with per-class shifts.
        messages = static_cast<EShMessages>(messages | EShMsgReadHlsl | EShMsgHlslOffsets | EShMsgHlslEnable16BitTypes);
        shader.setHlslIoMapping(true);
        // RWTexture2D<float3> would otherwise be declared Rgba32f and written with 3 components
        // (VUID-RuntimeSpirv-OpImageWrite-07112): glslang 12 has no [[vk::image_format]], so storage
        // images are typeless (Unknown format) as with dxc's default; the device needs
        // shaderStorageImageWriteWithoutFormat, which the Vulkan backend requires anyway.
        shader.setNoStorageFormat(true);
        // DXIL binds by register: its reflection must see the registers unshifted.
        const HlslBindingShifts shifts = options.dxc.empty() ? options.hlslShifts : HlslBindingShifts{};
        shader.setShiftBinding(glslang::EResTexture, shifts.texture);
        shader.setShiftBinding(glslang::EResUav, shifts.uav);
        shader.setShiftBinding(glslang::EResSampler, shifts.sampler);
        shader.setShiftBinding(glslang::EResUbo, shifts.constantBuffer);
    }
    return messages;
}

int defaultVersion(const CompileOptions& options) { return options.language == Language::Hlsl ? 100 : 450; }

// spirv-val; its messages, indented, in *messages.
bool validate(const std::vector<uint32_t>& spirv, std::string* messages) {
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
    tools.SetMessageConsumer([messages](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        *messages += "  " + std::string(message) + "\n";
    });
    return tools.Validate(spirv.data(), spirv.size(), spvtools::ValidatorOptions());
}

// What decides a permutation's SPIR-V besides the tool and the preprocessed source (PermutationCache::key).
std::string cacheIdentity(const CompileOptions& options, const std::string& preamble) {
    const HlslBindingShifts& shifts = options.hlslShifts;
    return std::string(languageName(options.language)) + (options.optimize ? " optimized" : " unoptimized") +
           " shifts t" + std::to_string(shifts.texture) + " u" + std::to_string(shifts.uav) + " s" +
           std::to_string(shifts.sampler) + " b" + std::to_string(shifts.constantBuffer) + "\n" + preamble;
}

}  // namespace

GlslangProcess::GlslangProcess() { glslang::InitializeProcess(); }
GlslangProcess::~GlslangProcess() { glslang::FinalizeProcess(); }

CompiledShader compilePermutation(const CompileOptions& options, const std::vector<Define>& permutation) {
    CompiledShader result;
    std::string source;
    if (!readFile(options.source, &source)) throw Error("cannot read source file " + options.source.string());
    const fs::path sourcePath = fs::weakly_canonical(options.source);
    result.openedFiles.insert(sourcePath);

    const bool dxil = !options.dxc.empty();
    if (dxil && options.language != Language::Hlsl) {
        throw Error("pass '" + options.pass + "': DXIL (--dxc) needs an HLSL source");
    }
    std::string preamble;
    for (const Define& define : options.defines) preamble += "#define " + define.name + " " + define.value + "\n";
    for (const Define& define : permutation) preamble += "#define " + define.name + " " + define.value + "\n";
    if (dxil) {
        for (const Define& define : dxilReflectionDefines()) {
            preamble += "#define " + define.name + " " + define.value + "\n";
        }
    }

    const std::string sourceName = sourcePath.string();
    const ShaderSource shaderSource(source, sourceName);
    // With a cache (SPIR-V only): the preprocessed source names the permutation; a hit skips the rest.
    std::string cacheKey;
    if (options.cache && !dxil) {
        glslang::TShader preprocessor(EShLangCompute);
        const EShMessages messages = configureShader(preprocessor, options, shaderSource, preamble);
        Includer includer(options, &result.openedFiles);
        std::string preprocessed;
        // A failure here is reported by the parse below, with its source context.
        if (preprocessor.preprocess(GetDefaultResources(), defaultVersion(options), ENoProfile, false, false, messages,
                                    &preprocessed, includer)) {
            cacheKey = options.cache->key(cacheIdentity(options, preamble), preprocessed);
            std::vector<uint32_t> cached = options.cache->find(cacheKey);
            std::string ignored;
            if (!cached.empty() && validate(cached, &ignored)) {
                result.spirv = std::move(cached);
                return result;
            }
        }
    }

    glslang::TShader shader(EShLangCompute);
    const EShMessages messages = configureShader(shader, options, shaderSource, preamble);
    Includer includer(options, &result.openedFiles);
    const std::string where = describePermutation(options, permutation);
    if (!shader.parse(GetDefaultResources(), defaultVersion(options), false, messages, includer)) {
        const std::string includeError = includer.error().empty() ? "" : "  " + includer.error() + "\n";
        throw Error(where + ": compile error\n" + includeError + withSourceContext(shader.getInfoLog(), sourcePath));
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages) || !program.mapIO()) {
        throw Error(where + ": link error\n" + withSourceContext(program.getInfoLog(), sourcePath));
    }
    std::vector<uint32_t> spirv;
    spv::SpvBuildLogger logger;
    glslang::SpvOptions spvOptions;
    spvOptions.disableOptimizer = true;  // spirv-opt runs below, with the performance recipe
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &logger, &spvOptions);
    if (spirv.empty()) throw Error(where + ": SPIR-V generation failed\n  " + logger.getAllMessages());

    std::string optimizerMessages;
    if (options.optimize) {
        spirv = optimize(options, spirv, &optimizerMessages);
        if (spirv.empty()) throw Error(where + ": spirv-opt failed\n  " + optimizerMessages);
    }

    std::string validatorMessages;
    if (!validate(spirv, &validatorMessages)) {
        throw Error(where + ": spirv-val rejected the binary\n" + validatorMessages);
    }
    if (!cacheKey.empty()) options.cache->store(cacheKey, spirv);
    result.spirv = std::move(spirv);
    if (dxil) result.dxil = compileDxil(options, permutation, where);
    return result;
}

}  // namespace ffxdof::shaderc
