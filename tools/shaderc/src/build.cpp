// All permutations of one pass: a pool of worker threads, each with its own glslang objects
// (glslang is thread-safe after InitializeProcess), then deduplication and reflection.
#include "shaderc.h"

#include <atomic>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

namespace ffxdof::shaderc {
namespace {

std::string describe(const ReflectedBinding& binding) {
    std::string text = std::string(shaders::bindingKindName(binding.kind)) + " '" + binding.name + "'";
    if (binding.kind == BindingKind::PushConstants) return text + " of " + std::to_string(binding.size) + " bytes";
    text += " at set " + std::to_string(binding.set) + " binding " + std::to_string(binding.binding);
    if (binding.arraySize != 1) text += " [" + std::to_string(binding.arraySize) + "]";
    return text;
}

std::string describeKey(const PassBuild& build, uint32_t permutation) {
    std::string text;
    for (const Define& define : permutationDefines(build.axes, permutation)) {
        text += (text.empty() ? "" : " ") + define.name + "=" + define.value;
    }
    return text.empty() ? "(no axes)" : text;
}

}  // namespace

void mergeReflections(PassBuild& build) {
    build.bindings.clear();
    build.pushConstantMembers.clear();
    std::vector<uint32_t> firstUser(build.blobs.size(), 0);
    for (uint32_t p = static_cast<uint32_t>(build.permutationToBlob.size()); p-- > 0;) {
        firstUser[build.permutationToBlob[p]] = p;
    }
    std::map<std::string, std::pair<ReflectedBinding, uint32_t>> byName;  // binding, first permutation
    std::optional<uint32_t> membersFrom;
    for (size_t blob = 0; blob < build.blobs.size(); ++blob) {
        const Reflection& reflection = build.blobReflections[blob];
        const uint32_t permutation = firstUser[blob];
        for (const ReflectedBinding& binding : reflection.bindings) {
            auto [it, inserted] = byName.emplace(binding.name, std::make_pair(binding, permutation));
            if (!inserted && !(it->second.first == binding)) {
                throw Error("pass '" + build.options.pass + "': permutations disagree on bindings: " +
                            describe(it->second.first) + " in " + describeKey(build, it->second.second) + ", but " +
                            describe(binding) + " in " + describeKey(build, permutation));
            }
        }
        if (!reflection.pushConstantMembers.empty()) {
            if (!membersFrom) {
                build.pushConstantMembers = reflection.pushConstantMembers;
                membersFrom = permutation;
            } else if (build.pushConstantMembers != reflection.pushConstantMembers) {
                throw Error("pass '" + build.options.pass + "': permutations disagree on the push constant layout: " +
                            describeKey(build, *membersFrom) + " and " + describeKey(build, permutation));
            }
        }
    }
    // Vulkan: one binding number space per set (push constants apart). D3D12: one per register
    // class and space (t, u, s, b; root constants are b registers too).
    const bool dxil = !build.options.dxc.empty();
    auto slotClass = [dxil](BindingKind kind) -> char {
        if (!dxil) return kind == BindingKind::PushConstants ? '1' : '0';  // push constants last
        switch (kind) {
            case BindingKind::SampledImage:
                return 't';
            case BindingKind::StorageImage:
            case BindingKind::StorageBuffer:
                return 'u';
            case BindingKind::Sampler:
                return 's';
            case BindingKind::UniformBuffer:
            case BindingKind::PushConstants:
                return 'b';
        }
        return '?';
    };
    std::map<std::tuple<char, uint32_t, uint32_t>, const ReflectedBinding*> bySlot;
    for (const auto& [name, entry] : byName) {
        const ReflectedBinding& binding = entry.first;
        const auto slot = std::make_tuple(slotClass(binding.kind), binding.set, binding.binding);
        auto [it, inserted] = bySlot.emplace(slot, &binding);
        if (!inserted) {
            throw Error("pass '" + build.options.pass + "': permutations disagree on bindings: " +
                        describe(*it->second) + " and " + describe(binding) + " share one slot");
        }
    }
    for (const auto& [slot, binding] : bySlot) build.bindings.push_back(*binding);
}

PassBuild buildPass(const CompileOptions& options, const std::vector<Axis>& axes, unsigned threads) {
    PassBuild build;
    build.options = options;
    build.axes = axes;
    const uint32_t count = permutationCount(axes);
    std::error_code ec;
    if (!fs::is_regular_file(options.source, ec)) throw Error("source file not found: " + options.source.string());

    std::vector<std::optional<CompiledShader>> compiled(count);
    std::vector<std::string> errors(count);
    std::atomic<uint32_t> next{0};
    std::atomic<bool> failed{false};
    auto worker = [&] {
        for (uint32_t p = next++; p < count && !failed; p = next++) {
            try {
                compiled[p] = compilePermutation(options, permutationDefines(axes, p));
            } catch (const Error& error) {
                errors[p] = error.what();
                failed = true;
            }
        }
    };
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = std::min(threads, count);
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& thread : pool) thread.join();
    for (uint32_t p = 0; p < count; ++p) {
        if (!errors[p].empty()) throw Error(errors[p]);
    }

    std::map<std::vector<uint32_t>, uint16_t> unique;
    for (uint32_t p = 0; p < count; ++p) {
        build.dependencies.insert(compiled[p]->openedFiles.begin(), compiled[p]->openedFiles.end());
        // DXIL tables store (and deduplicate) the DXIL; the SPIR-V is there for the reflection.
        std::vector<uint32_t>& blob = options.dxc.empty() ? compiled[p]->spirv : compiled[p]->dxil;
        auto [it, inserted] = unique.emplace(blob, static_cast<uint16_t>(build.blobs.size()));
        if (inserted) {
            try {
                build.blobReflections.push_back(reflect(compiled[p]->spirv));
            } catch (const Error& error) {
                throw Error("pass '" + options.pass + "' (" + languageName(options.language) + "), permutation " +
                            describeKey(build, p) + ": " + error.what());
            }
            build.blobs.push_back(std::move(blob));
        }
        build.permutationToBlob.push_back(it->second);
    }
    mergeReflections(build);
    return build;
}

}  // namespace ffxdof::shaderc
