// ffx-dof-shaderc as a library: parse the permutation axes, compile every permutation of one pass
// (glslang, in process, in parallel), optimize (spirv-opt performance recipe) and validate
// (spirv-val), deduplicate, reflect the bindings (SPIRV-Cross) and emit C++ tables, a JSON
// manifest and a depfile. With a dxc path, the tables hold DXIL made by dxc (one subprocess per
// permutation) instead, with the bindings reflected from the SPIR-V of the same permutation.
// main.cpp is only the command line around this.
#pragma once

#include "ffx_dof_shader_table.h"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace ffxdof::shaderc {

namespace fs = std::filesystem;
using shaders::BindingKind;

// Every failure the tool reports. what() is the complete, user-facing message (one line for bad
// input; a compile error adds its source context on the following lines).
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

enum class Language { Glsl, Hlsl };
const char* languageName(Language language);
Language parseLanguage(const std::string& text);  // "glsl" | "hlsl"

struct Define {
    std::string name;
    std::string value;
};

struct Axis {
    std::string macro;
    std::vector<uint32_t> values;
};

// "NAME=VALUE" or "NAME" (value 1). Throws Error on a malformed name.
Define parseDefine(const std::string& text);
// "NAME={0,1,2}". Throws Error on any other syntax, an empty or repeated value list.
Axis parseAxis(const std::string& text);
// Product of the axes' value counts; throws when it is unreasonably large (> 65535 blobs).
uint32_t permutationCount(const std::vector<Axis>& axes);
// Macro values of permutation `index` (mixed radix, last axis fastest; see ffx_dof_shader_table.h).
std::vector<Define> permutationDefines(const std::vector<Axis>& axes, uint32_t index);

// Initializes glslang for the lifetime of the object (InitializeProcess / FinalizeProcess).
class GlslangProcess {
public:
    GlslangProcess();
    ~GlslangProcess();
    GlslangProcess(const GlslangProcess&) = delete;
    GlslangProcess& operator=(const GlslangProcess&) = delete;
};

// glslang's per-register-class binding shifts for HLSL (t, u, s, b), like dxc's -fvk-*-shift.
struct HlslBindingShifts {
    uint32_t texture = 0;
    uint32_t uav = 0;
    uint32_t sampler = 0;
    uint32_t constantBuffer = 0;
};

class PermutationCache;

struct CompileOptions {
    std::string pass;  // for messages and table names
    Language language = Language::Glsl;
    fs::path source;
    std::vector<fs::path> includeDirs;
    std::vector<Define> defines;  // plain defines, in every permutation
    HlslBindingShifts hlslShifts;
    bool optimize = true;
    // Not empty: HLSL only; the blobs are DXIL from this dxc, the table's language is "dxil" and
    // the SPIR-V is compiled only to reflect the bindings (registers and spaces, not shifted).
    fs::path dxc;
    // Not null: SPIR-V permutations are looked up there before they are compiled, and filed there after
    // (--cache-dir; not with dxc). Not owned.
    PermutationCache* cache = nullptr;
};

// The permutation cache (--cache-dir, cache.cpp): each compiled permutation's SPIR-V in a file named by a
// 128-bit XXH3 of everything that decides it: this executable's bytes (glslang and SPIRV-Tools are linked
// into it), the compile options, the defines and the preprocessed source with every include. A build of
// another configuration, another commit or a clean build folder that compiles the same permutation reads it
// back instead of compiling it again. Thread-safe; several processes may share one folder (files are written
// whole and renamed into place).
class PermutationCache {
public:
    // Creates the folder if needed; throws Error when it cannot, or when this executable cannot be read.
    explicit PermutationCache(const fs::path& folder);

    // The key of one permutation: `identity` is everything but the preprocessed source (options, defines).
    std::string key(const std::string& identity, const std::string& preprocessed) const;
    // The SPIR-V filed under key, or empty when there is none, or the file is not a whole SPIR-V module.
    std::vector<uint32_t> find(const std::string& key);
    // Files the SPIR-V under key. A failure to write (a full disk) is reported once on stderr, not thrown:
    // the build's outputs do not depend on the cache.
    void store(const std::string& key, const std::vector<uint32_t>& spirv);

    uint32_t hits() const { return hits_; }
    uint32_t misses() const { return misses_; }

private:
    fs::path folder_;
    std::string toolDigest_;  // XXH3-128 of this executable, hex
    std::atomic<uint32_t> hits_{0}, misses_{0};
    std::atomic<bool> warned_{false};
};

// The language the emitted table names: "glsl", "hlsl" (both SPIR-V) or "dxil".
const char* tableLanguage(const CompileOptions& options);

struct CompiledShader {
    std::vector<uint32_t> spirv;
    std::vector<uint32_t> dxil;      // only with CompileOptions::dxc
    std::set<fs::path> openedFiles;  // the source and every file the includer opened
};

// Compiles, optimizes and validates one permutation: the plain defines plus `permutation`.
// Needs a live GlslangProcess. Throws Error naming the pass, the defines and the compiler
// message with source context.
CompiledShader compilePermutation(const CompileOptions& options, const std::vector<Define>& permutation);

// DXIL (dxil.cpp). The defines that make glslang read the source as dxc does for DXIL (for the
// reflection of the DXIL tables), the dxc command line of one permutation (program first;
// SM 6.6 when FFX_DOF_OPTION_WAVE64=1, else 6.2; -enable-16bit-types when FFX_HALF=1), and running
// it: the container as words, or an Error naming `where` and dxc's messages on one line.
std::vector<Define> dxilReflectionDefines();
std::vector<std::string> dxcArguments(const CompileOptions& options, const std::vector<Define>& permutation,
                                      const fs::path& output);
std::vector<uint32_t> compileDxil(const CompileOptions& options, const std::vector<Define>& permutation,
                                  const std::string& where);

struct ReflectedBinding {
    std::string name;
    uint32_t set = 0;
    uint32_t binding = 0;
    BindingKind kind = BindingKind::SampledImage;
    uint32_t arraySize = 1;
    uint32_t size = 0;  // push constants: block size in bytes
    bool operator==(const ReflectedBinding& other) const;
};

struct ReflectedMember {
    std::string name;
    uint32_t offset = 0;
    uint32_t size = 0;
    bool operator==(const ReflectedMember& other) const {
        return name == other.name && offset == other.offset && size == other.size;
    }
};

struct Reflection {
    std::vector<ReflectedBinding> bindings;  // sorted by (kind == PushConstants, set, binding)
    std::vector<ReflectedMember> pushConstantMembers;
    uint32_t localSize[3] = {1, 1, 1};
    uint32_t requiredFeatures = 0;  // shaders::Feature bits (see requiredFeatures below)
};

// Throws Error for a blob the reflection cannot describe (among them a capability that
// requiredFeatures cannot classify).
Reflection reflect(const std::vector<uint32_t>& spirv);

// The shaders::Feature bits of these SPIR-V capabilities (capabilities.cpp). Core capabilities add
// nothing; one that is neither core nor a known Feature is an Error naming it, so no blob can need
// something the runtime does not check.
uint32_t requiredFeatures(const std::vector<uint32_t>& capabilities);
// "Float16 StorageImageWriteWithoutFormat": the names of the bits, in bit order; "" for none.
std::string featureNames(uint32_t features);

struct PassBuild {
    CompileOptions options;
    std::vector<Axis> axes;
    std::vector<std::vector<uint32_t>> blobs;  // unique, in order of first use
    std::vector<Reflection> blobReflections;
    std::vector<uint16_t> permutationToBlob;
    std::vector<ReflectedBinding> bindings;  // merged over all permutations
    std::vector<ReflectedMember> pushConstantMembers;
    std::set<fs::path> dependencies;
};

// Compiles every permutation on `threads` workers (0: all cores), deduplicates and reflects.
// Throws Error for the first failing permutation (lowest index) or disagreeing bindings.
PassBuild buildPass(const CompileOptions& options, const std::vector<Axis>& axes, unsigned threads);

// Merges the per-blob reflections; throws Error when two permutations disagree on a binding. For
// DXIL, slots are per register class (t0 and u0 are different slots).
void mergeReflections(PassBuild& build);

struct EmitOptions {
    std::string cppNamespace = "ffxdof::shaders";
    std::string symbol;  // the PassTable variable; default "pass_<pass>"
};

std::string emitHeader(const PassBuild& build, const EmitOptions& options);
std::string emitSource(const PassBuild& build, const EmitOptions& options, const std::string& headerName);
std::string emitManifest(const PassBuild& build);
// Makefile syntax: "<target>: <dep> <dep> ...", spaces escaped.
std::string emitDepfile(const fs::path& target, const std::set<fs::path>& dependencies);

// Writes every file to a temporary next to it, then renames them all into place. On any failure
// nothing is left behind (temporaries removed) and an Error names the path.
void writeFilesAtomically(const std::vector<std::pair<fs::path, std::string>>& files);

std::string symbolFor(const std::string& pass);

}  // namespace ffxdof::shaderc
