// The real passes as the Vulkan backend embeds them: counts from the permutations JSON, every key
// resolving, GLSL and HLSL agreeing on slots, and the push constants laid out like FfxDofConstants.
#define FFX_CPU 1
#include "ffx_dof_constants.h"
#include "ffx_dof_vk_shaders_glsl.h"
#include "ffx_dof_vk_shaders_hlsl.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

using ffxdof::shaders::BindingKind;
using ffxdof::shaders::PassTable;

namespace {

nlohmann::json permutationsJson() {
    std::ifstream in(FFX_DOF_PERMUTATIONS_JSON);
    REQUIRE(in);
    return nlohmann::json::parse(in);
}

const PassTable* tableOf(const std::string& language, const std::string& pass) {
    return language == "glsl" ? ffxdof::shaders::glsl::findPassTable(pass.c_str())
                              : ffxdof::shaders::hlsl::findPassTable(pass.c_str());
}

std::string leafName(const std::string& name) { return name.substr(name.rfind('.') + 1); }

}  // namespace

TEST_CASE("every pass has product-of-axes permutations and each key resolves", "[passes]") {
    const nlohmann::json json = permutationsJson();
    for (const char* language : {"glsl", "hlsl"}) {
        for (const auto& pass : json.at("passes")) {
            const std::string name = pass.at("name");
            INFO(language << " " << name);
            const PassTable* table = tableOf(language, name);
            REQUIRE(table != nullptr);
            uint32_t product = 1;
            std::set<std::string> jsonAxes, tableAxes;
            for (const auto& [macro, values] : pass.at("axes").items()) {
                product *= static_cast<uint32_t>(values.size());
                jsonAxes.insert(macro);
            }
            for (uint32_t a = 0; a < table->axisCount; ++a) tableAxes.insert(table->axes[a].macro);
            CHECK(tableAxes == jsonAxes);
            CHECK(table->permutationCount == product);
            size_t bytes = 0;
            for (uint32_t b = 0; b < table->blobCount; ++b) bytes += table->blobs[b].wordCount * 4;
            for (uint32_t p = 0; p < table->permutationCount; ++p) {
                std::string error;
                const auto* blob =
                    ffxdof::shaders::findPermutation(*table, ffxdof::shaders::permutationDefines(*table, p), &error);
                CHECK(blob != nullptr);
            }
            // The CI log shows the counts.
            std::cout << "shaderc: " << name << " (" << language << "): " << table->permutationCount
                      << " permutations, " << table->blobCount << " unique blobs, " << bytes << " bytes\n";
        }
    }
}

TEST_CASE("GLSL and HLSL bind every resource at the same slot", "[passes][reflection]") {
    const nlohmann::json json = permutationsJson();
    for (const auto& pass : json.at("passes")) {
        const std::string name = pass.at("name");
        INFO(name);
        const PassTable* glsl = tableOf("glsl", name);
        const PassTable* hlsl = tableOf("hlsl", name);
        REQUIRE(glsl != nullptr);
        REQUIRE(hlsl != nullptr);
        // Storage buffer names differ by language (GLSL reflects the block name), so compare slots.
        auto slots = [](const PassTable& table) {
            std::set<std::tuple<uint32_t, uint32_t, BindingKind, uint32_t>> result;
            for (uint32_t b = 0; b < table.bindingCount; ++b) {
                const auto& binding = table.bindings[b];
                result.emplace(binding.set, binding.binding, binding.kind, binding.arraySize);
            }
            return result;
        };
        CHECK(slots(*glsl) == slots(*hlsl));
    }
}

TEST_CASE("push constants are laid out like FfxDofConstants", "[passes][reflection]") {
    const std::map<std::string, size_t> offsets = {
        {"cocScale", offsetof(FfxDofConstants, cocScale)},
        {"cocBias", offsetof(FfxDofConstants, cocBias)},
        {"cocLimit", offsetof(FfxDofConstants, cocLimit)},
        {"maxRings", offsetof(FfxDofConstants, maxRings)},
        {"fullSize", offsetof(FfxDofConstants, fullSize)},
        {"halfSize", offsetof(FfxDofConstants, halfSize)},
        {"tileCount", offsetof(FfxDofConstants, tileCount)},
        {"bladeNormal", offsetof(FfxDofConstants, bladeNormal)},
        {"bladeCount", offsetof(FfxDofConstants, bladeCount)},
        {"anamorphicRatio", offsetof(FfxDofConstants, anamorphicRatio)},
        {"frameIndex", offsetof(FfxDofConstants, frameIndex)},
        {"outputFlags", offsetof(FfxDofConstants, outputFlags)},
        {"focusRegionCenter", offsetof(FfxDofConstants, focusRegionCenter)},
        {"focusRegionSize", offsetof(FfxDofConstants, focusRegionSize)},
        {"focusInvZScale", offsetof(FfxDofConstants, focusInvZScale)},
        {"focusInvZBias", offsetof(FfxDofConstants, focusInvZBias)},
        {"focusLensFactor", offsetof(FfxDofConstants, focusLensFactor)},
        {"focusFocalLength", offsetof(FfxDofConstants, focusFocalLength)},
        {"focusMinDistance", offsetof(FfxDofConstants, focusMinDistance)},
        {"focusMaxDistance", offsetof(FfxDofConstants, focusMaxDistance)},
        {"focusBlend", offsetof(FfxDofConstants, focusBlend)},
        {"focusFlags", offsetof(FfxDofConstants, focusFlags)},
        {"catEye", offsetof(FfxDofConstants, catEye)},
        {"apertureAreaScale", offsetof(FfxDofConstants, apertureAreaScale)},
    };
    for (const char* language : {"glsl", "hlsl"}) {
        const nlohmann::json json = permutationsJson();
        for (const auto& pass : json.at("passes")) {
            const std::string name = pass.at("name");
            INFO(language << " " << name);
            const PassTable* table = tableOf(language, name);
            REQUIRE(table != nullptr);
            uint32_t pushBlocks = 0;
            for (uint32_t b = 0; b < table->bindingCount; ++b) {
                if (table->bindings[b].kind != BindingKind::PushConstants) continue;
                ++pushBlocks;
                CHECK(table->bindings[b].size == sizeof(FfxDofConstants));
            }
            CHECK(pushBlocks == 1);
            REQUIRE(table->pushConstantMemberCount == offsets.size());
            for (uint32_t m = 0; m < table->pushConstantMemberCount; ++m) {
                const auto& member = table->pushConstantMembers[m];
                INFO(member.name);
                const auto expected = offsets.find(leafName(member.name));
                REQUIRE(expected != offsets.end());
                CHECK(member.offset == expected->second);
            }
        }
    }
}

// What the real blobs need of a Vulkan device (reflected by ffx-dof-shaderc). A shader change that
// adds a requirement fails here: document it in docs/integration-vulkan.md, then add it below.
TEST_CASE("the real blobs require only the documented features, and the 32-bit ones no 16-bit one", "[passes]") {
    using ffxdof::shaders::Feature;
    using ffxdof::shaders::featureBit;
    const uint32_t documented = featureBit(Feature::Float16) | featureBit(Feature::StorageImageWriteWithoutFormat) |
                                featureBit(Feature::GroupNonUniform) | featureBit(Feature::GroupNonUniformArithmetic);
    const uint32_t sixteenBit =
        featureBit(Feature::Float16) | featureBit(Feature::Int16) | featureBit(Feature::StorageBuffer16BitAccess) |
        featureBit(Feature::UniformAndStorageBuffer16BitAccess) | featureBit(Feature::StoragePushConstant16);
    const nlohmann::json json = permutationsJson();
    for (const char* language : {"glsl", "hlsl"}) {
        for (const auto& entry : json.at("passes")) {
            const std::string pass = entry.at("name");
            const PassTable* table = tableOf(language, pass);
            REQUIRE(table != nullptr);
            for (uint32_t p = 0; p < table->permutationCount; ++p) {
                const auto defines = ffxdof::shaders::permutationDefines(*table, p);
                uint32_t half = 0;
                for (const auto& [macro, value] : defines) half = macro == "FFX_HALF" ? value : half;
                const uint32_t required = table->blobs[table->permutationToBlob[p]].requiredFeatures;
                INFO(language << " " << pass << " permutation " << p << " requires 0x" << std::hex << required);
                CHECK((required & ~documented) == 0);
                if (!half) CHECK((required & sixteenBit) == 0);
            }
        }
    }
}
