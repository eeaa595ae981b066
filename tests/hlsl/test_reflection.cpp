// The HLSL- and GLSL-compiled tables the Vulkan backend embeds, checked without a device:
//  - each pass binds the same slots in both languages: the reflected union of the table, and, per
//    permutation, the (set, binding) decorations of the resources the blob still uses after
//    optimisation (a resource one language drops and the other reads means the two compute
//    different things);
//  - the FFX_HALF=1 blobs of the colour passes really compute in 16-bit floats (the Float16
//    capability and a 16-bit OpTypeFloat), the FFX_HALF=0 blobs never, and the depth/CoC passes
//    use 16-bit floats in HLSL exactly when they do in GLSL.
// The SPIR-V is read with SPIRV-Tools' binary parser.
#include "ffx_dof_pass_list.h"
#include "ffx_dof_vk_shaders_glsl.h"
#include "ffx_dof_vk_shaders_hlsl.h"

#include <catch2/catch.hpp>
#include <spirv-tools/libspirv.h>
#include <spirv/unified1/spirv.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace ffxdof;
using shaders::PassTable;

namespace {

// Whether a pass's FFX_HALF=1 permutations carry colour in 16-bit floats (depth and CoC stay 32-bit
// in the others: docs/technique.md); ffx_dof_permutations.json says which.
bool isFloat16ColorPass(const std::string& pass) {
    for (uint32_t p = 0; p < kPassCount; ++p) {
        if (pass == kPassNames[p]) return kPassFloat16Color[p];
    }
    return false;
}

// DescriptorSet and Binding decorations of one id; -1 until seen.
struct Slot {
    int64_t set = -1;
    int64_t binding = -1;
};

struct BlobFacts {
    std::set<std::pair<uint32_t, uint32_t>> slots;  // (set, binding) of every decorated resource
    bool float16Capability = false;
    bool float16Type = false;
};

struct ParseState {
    BlobFacts facts;
    std::map<uint32_t, Slot> decorations;  // by result id
};

spv_result_t onInstruction(void* user, const spv_parsed_instruction_t* instruction) {
    ParseState& state = *static_cast<ParseState*>(user);
    const uint32_t* w = instruction->words;
    switch (instruction->opcode) {
        case SpvOpCapability:
            if (w[1] == SpvCapabilityFloat16) state.facts.float16Capability = true;
            break;
        case SpvOpTypeFloat:
            if (w[2] == 16) state.facts.float16Type = true;
            break;
        case SpvOpDecorate:
            if (instruction->num_words >= 4 && w[2] == SpvDecorationDescriptorSet) state.decorations[w[1]].set = w[3];
            if (instruction->num_words >= 4 && w[2] == SpvDecorationBinding) state.decorations[w[1]].binding = w[3];
            break;
        default:
            break;
    }
    return SPV_SUCCESS;
}

BlobFacts parse(const shaders::Blob& blob) {
    ParseState state;
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_1);
    spv_diagnostic diagnostic = nullptr;
    const spv_result_t result =
        spvBinaryParse(context, &state, blob.words, blob.wordCount, nullptr, &onInstruction, &diagnostic);
    const std::string message = diagnostic ? diagnostic->error : "";
    spvDiagnosticDestroy(diagnostic);
    spvContextDestroy(context);
    INFO(message);
    REQUIRE(result == SPV_SUCCESS);
    BlobFacts facts = state.facts;
    for (const auto& [id, slot] : state.decorations) {
        INFO("id " << id << " has only one of DescriptorSet and Binding");
        REQUIRE(slot.set >= 0);
        REQUIRE(slot.binding >= 0);
        facts.slots.emplace(uint32_t(slot.set), uint32_t(slot.binding));
    }
    return facts;
}

std::vector<const PassTable*> glslTables() {
    std::vector<const PassTable*> tables(shaders::glsl::kPassTables,
                                         shaders::glsl::kPassTables + shaders::glsl::kPassTableCount);
    return tables;
}

const PassTable& hlslTableOf(const PassTable& glsl) {
    const PassTable* hlsl = shaders::hlsl::findPassTable(glsl.pass);
    INFO("pass " << glsl.pass);
    REQUIRE(hlsl != nullptr);
    REQUIRE(std::string(hlsl->language) == "hlsl");
    return *hlsl;
}

// A pass without the axis (autofocus has no FFX_HALF) is compiled with the macro's default, 0.
uint32_t axisValue(const std::vector<shaders::Define>& key, const char* macro) {
    for (const auto& [name, value] : key) {
        if (name == macro) return value;
    }
    return 0;
}

}  // namespace

TEST_CASE("both languages have the same passes and axes", "[hlsl][reflection]") {
    REQUIRE(shaders::glsl::kPassTableCount == shaders::hlsl::kPassTableCount);
    for (const PassTable* glsl : glslTables()) {
        const PassTable& hlsl = hlslTableOf(*glsl);
        INFO("pass " << glsl->pass);
        REQUIRE(glsl->axisCount == hlsl.axisCount);
        REQUIRE(glsl->permutationCount == hlsl.permutationCount);
        for (uint32_t a = 0; a < glsl->axisCount; ++a) CHECK(std::string(glsl->axes[a].macro) == hlsl.axes[a].macro);
    }
}

TEST_CASE("HLSL and GLSL bind the same slots in every pass and permutation", "[hlsl][reflection]") {
    for (const PassTable* glsl : glslTables()) {
        const PassTable& hlsl = hlslTableOf(*glsl);
        INFO("pass " << glsl->pass);
        // The reflected union (names differ: GLSL reflects block names, HLSL variable names).
        auto reflected = [](const PassTable& table) {
            std::set<std::tuple<uint32_t, uint32_t, shaders::BindingKind, uint32_t, uint32_t>> slots;
            for (uint32_t b = 0; b < table.bindingCount; ++b) {
                const shaders::Binding& binding = table.bindings[b];
                slots.emplace(binding.set, binding.binding, binding.kind, binding.arraySize, binding.size);
            }
            return slots;
        };
        CHECK(reflected(*glsl) == reflected(hlsl));
        // Per permutation: the slots each blob still uses.
        for (uint32_t p = 0; p < glsl->permutationCount; ++p) {
            const std::vector<shaders::Define> key = shaders::permutationDefines(*glsl, p);
            std::string keyText;
            for (const auto& [macro, value] : key) keyText += macro + "=" + std::to_string(value) + " ";
            INFO("permutation " << keyText);
            std::string error;
            const shaders::Blob* glslBlob = shaders::findPermutation(*glsl, key, &error);
            const shaders::Blob* hlslBlob = shaders::findPermutation(hlsl, key, &error);
            INFO(error);
            REQUIRE(glslBlob != nullptr);
            REQUIRE(hlslBlob != nullptr);
            const BlobFacts glslFacts = parse(*glslBlob);
            const BlobFacts hlslFacts = parse(*hlslBlob);
            // The parser found the resources at all; the composite's copy class has nothing to do in place
            // (the core never dispatches that permutation), so it binds nothing.
            const bool copyInPlace = std::string(glsl->pass) == "composite" &&
                                     axisValue(key, "FFX_DOF_OPTION_COMPOSITE_CLASS") == FFX_DOF_COMPOSITE_CLASS_COPY &&
                                     axisValue(key, "FFX_DOF_OPTION_OUTPUT_PRE_INIT") != 0;
            CHECK(glslFacts.slots.empty() == copyInPlace);
            CHECK(glslFacts.slots == hlslFacts.slots);
            // Every slot a blob uses is one the table reflects (the table is what the backend binds).
            for (const auto& [set, binding] : hlslFacts.slots) {
                bool inTable = false;
                for (uint32_t b = 0; b < hlsl.bindingCount; ++b) {
                    inTable = inTable || (hlsl.bindings[b].set == set && hlsl.bindings[b].binding == binding);
                }
                CHECK(inTable);
            }
        }
    }
}

// The composite's copy class moves the input to the output unchanged: no colour arithmetic in any precision.
static bool copiesOnly(const char* pass, const std::vector<shaders::Define>& key) {
    return std::string(pass) == "composite" &&
           axisValue(key, "FFX_DOF_OPTION_COMPOSITE_CLASS") == FFX_DOF_COMPOSITE_CLASS_COPY;
}

TEST_CASE("HLSL FFX_HALF=1 colour passes compute in 16-bit floats, FFX_HALF=0 never", "[hlsl][reflection]") {
    for (const PassTable* glsl : glslTables()) {
        const PassTable& hlsl = hlslTableOf(*glsl);
        const bool colorPass = isFloat16ColorPass(glsl->pass);
        for (uint32_t p = 0; p < hlsl.permutationCount; ++p) {
            const std::vector<shaders::Define> key = shaders::permutationDefines(hlsl, p);
            const bool half = axisValue(key, "FFX_HALF") != 0;
            const shaders::Blob& hlslBlob = hlsl.blobs[hlsl.permutationToBlob[p]];
            const shaders::Blob& glslBlob = glsl->blobs[glsl->permutationToBlob[p]];
            const BlobFacts facts = parse(hlslBlob);
            INFO("pass " << glsl->pass << " permutation " << p << " FFX_HALF=" << half);
            // The table's flag is the reflected capability; the parsed type shows it is used.
            const uint32_t float16 = shaders::featureBit(shaders::Feature::Float16);
            CHECK(((hlslBlob.requiredFeatures & float16) != 0) == facts.float16Capability);
            if (!half) {
                CHECK_FALSE(facts.float16Capability);
                CHECK_FALSE(facts.float16Type);
            } else if (colorPass && !copiesOnly(glsl->pass, key)) {
                CHECK(facts.float16Capability);
                CHECK(facts.float16Type);
            }
            CHECK((hlslBlob.requiredFeatures & float16) == (glslBlob.requiredFeatures & float16));
        }
    }
}
