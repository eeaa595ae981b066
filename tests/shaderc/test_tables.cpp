// The generated tables of the test pass, as the backends use them.
#include "ffx_dof_test_shaders_glsl.h"
#include "ffx_dof_test_shaders_hlsl.h"
#include "shaderc.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <set>

using ffxdof::shaders::Blob;
using ffxdof::shaders::Feature;
using ffxdof::shaders::featureBit;
using ffxdof::shaders::PassTable;

namespace {

const PassTable& testTable(const char* language) {
    const PassTable* table = std::strcmp(language, "glsl") == 0 ? ffxdof::test::glsl::findPassTable("test")
                                                                : ffxdof::test::hlsl::findPassTable("test");
    REQUIRE(table != nullptr);
    return *table;
}

uint32_t defineValue(const std::vector<ffxdof::shaders::Define>& defines, const char* macro) {
    for (const auto& define : defines) {
        if (define.first == macro) return define.second;
    }
    FAIL("no define " << macro);
    return 0;
}

}  // namespace

TEST_CASE("aggregate lookup knows exactly the built passes", "[tables]") {
    CHECK(ffxdof::test::glsl::kPassTableCount == 1);
    CHECK(ffxdof::test::glsl::findPassTable("test") == &ffxdof::test::glsl::pass_test);
    CHECK(ffxdof::test::glsl::findPassTable("blur") == nullptr);
    CHECK(ffxdof::test::glsl::findPassTable(nullptr) == nullptr);
    CHECK(std::strcmp(ffxdof::test::hlsl::pass_test.language, "hlsl") == 0);
}

TEST_CASE("permutation count is the product of the axes and every key resolves", "[tables]") {
    for (const char* language : {"glsl", "hlsl"}) {
        INFO(language);
        const PassTable& table = testTable(language);
        REQUIRE(table.axisCount == 4);
        uint32_t product = 1;
        for (uint32_t a = 0; a < table.axisCount; ++a) product *= table.axes[a].valueCount;
        CHECK(product == 2 * 2 * 3 * 2);
        CHECK(table.permutationCount == product);
        for (uint32_t p = 0; p < table.permutationCount; ++p) {
            const auto defines = ffxdof::shaders::permutationDefines(table, p);
            std::string error;
            uint32_t index = ~0u;
            REQUIRE(ffxdof::shaders::findPermutationIndex(table, defines, &index, &error));
            CHECK(index == p);
            const Blob* blob = ffxdof::shaders::findPermutation(table, defines, &error);
            REQUIRE(blob != nullptr);
            CHECK(blob == &table.blobs[table.permutationToBlob[p]]);
            CHECK(blob->wordCount > 5);
            CHECK(blob->words[0] == 0x07230203u);  // SPIR-V magic
            // The 16-bit permutations really use 16-bit floats; the 32-bit ones do not.
            CHECK(((blob->requiredFeatures & featureBit(Feature::Float16)) != 0) ==
                  (defineValue(defines, "FFX_HALF") == 1));
            const bool wide = defineValue(defines, "FFX_DOF_TEST_WIDE") == 1;
            CHECK(blob->localSize[0] == (wide ? 64u : 8u));
            CHECK(blob->localSize[1] == (wide ? 1u : 8u));
        }
    }
}

TEST_CASE("an axis that changes no code is deduplicated", "[tables]") {
    for (const char* language : {"glsl", "hlsl"}) {
        INFO(language);
        const PassTable& table = testTable(language);
        CHECK(table.blobCount == table.permutationCount / 2);  // FFX_DOF_TEST_UNUSED has two values
        std::set<std::vector<uint32_t>> distinct;
        for (uint32_t b = 0; b < table.blobCount; ++b) {
            distinct.emplace(table.blobs[b].words, table.blobs[b].words + table.blobs[b].wordCount);
        }
        CHECK(distinct.size() == table.blobCount);
        for (uint32_t p = 0; p < table.permutationCount; ++p) {
            auto flipped = ffxdof::shaders::permutationDefines(table, p);
            for (auto& define : flipped) {
                if (define.first == "FFX_DOF_TEST_UNUSED") define.second ^= 1u;
            }
            CHECK(ffxdof::shaders::findPermutation(table, flipped, nullptr) ==
                  &table.blobs[table.permutationToBlob[p]]);
        }
    }
}

TEST_CASE("each key's blob is the binary of exactly those defines", "[tables]") {
    ffxdof::shaderc::GlslangProcess glslang;
    for (const char* language : {"glsl", "hlsl"}) {
        INFO(language);
        const PassTable& table = testTable(language);
        ffxdof::shaderc::CompileOptions options;
        options.pass = "test";
        options.language = ffxdof::shaderc::parseLanguage(language);
        options.source = std::string(FFX_DOF_TEST_SHADER_DIR "/ffx_dof_test.") + language;
        options.includeDirs = {FFX_DOF_TEST_SHADER_DIR};
        options.hlslShifts.uav = 16;
        // A few keys spread over the table, each compiled again on its own.
        for (uint32_t p : {0u, 5u, 13u, table.permutationCount - 1}) {
            std::vector<ffxdof::shaderc::Define> defines;
            for (const auto& define : ffxdof::shaders::permutationDefines(table, p)) {
                defines.push_back({define.first, std::to_string(define.second)});
            }
            const auto compiled = ffxdof::shaderc::compilePermutation(options, defines);
            const Blob& blob = table.blobs[table.permutationToBlob[p]];
            CHECK(std::vector<uint32_t>(blob.words, blob.words + blob.wordCount) == compiled.spirv);
        }
    }
}

TEST_CASE("an unknown key is an error, never a fallback", "[tables]") {
    const PassTable& table = testTable("glsl");
    const std::vector<ffxdof::shaders::Define> valid = {
        {"FFX_HALF", 1}, {"FFX_DOF_TEST_WIDE", 0}, {"FFX_DOF_TEST_SCALE", 3}, {"FFX_DOF_TEST_UNUSED", 1}};
    std::string error;
    REQUIRE(ffxdof::shaders::findPermutation(table, valid, &error) != nullptr);

    auto unknownMacro = valid;
    unknownMacro.push_back({"FFX_DOF_OPTION_NOT_AN_AXIS", 0});
    CHECK(ffxdof::shaders::findPermutation(table, unknownMacro, &error) == nullptr);
    CHECK(error.find("FFX_DOF_OPTION_NOT_AN_AXIS") != std::string::npos);

    auto missing = valid;
    missing.pop_back();
    CHECK(ffxdof::shaders::findPermutation(table, missing, &error) == nullptr);
    CHECK(error.find("FFX_DOF_TEST_UNUSED") != std::string::npos);

    auto outOfRange = valid;
    outOfRange[2].second = 4;
    CHECK(ffxdof::shaders::findPermutation(table, outOfRange, &error) == nullptr);
    CHECK(error.find("no value 4") != std::string::npos);

    auto twice = valid;
    twice.push_back({"FFX_HALF", 1});
    CHECK(ffxdof::shaders::findPermutation(table, twice, &error) == nullptr);
    CHECK(error.find("twice") != std::string::npos);

    CHECK(ffxdof::shaders::findPermutation(table, {}, nullptr) == nullptr);  // no error text asked for
}

TEST_CASE("bindings and push constant offsets are reflected", "[tables][reflection]") {
    for (const char* language : {"glsl", "hlsl"}) {
        INFO(language);
        const PassTable& table = testTable(language);
        using ffxdof::shaders::BindingKind;
        const auto* input = ffxdof::shaders::findBinding(table, "ffxDofTestInput");
        REQUIRE(input != nullptr);
        CHECK(input->kind == BindingKind::SampledImage);
        CHECK(input->binding == 0);
        const auto* output = ffxdof::shaders::findBinding(table, "ffxDofTestOutput");
        REQUIRE(output != nullptr);
        CHECK(output->kind == BindingKind::StorageImage);
        CHECK(output->binding == 16);
        CHECK(output->set == 0);
        const auto* constants = ffxdof::shaders::findBinding(table, "ffxDofTestConstants");
        REQUIRE(constants != nullptr);
        CHECK(constants->kind == BindingKind::PushConstants);
        CHECK(constants->size == 24);
        uint32_t buffers = 0;
        for (uint32_t b = 0; b < table.bindingCount; ++b) {
            if (table.bindings[b].kind != BindingKind::StorageBuffer) continue;
            ++buffers;
            CHECK(table.bindings[b].binding == 40);
        }
        CHECK(buffers == 1);
        CHECK(table.bindingCount == 4);
        REQUIRE(table.pushConstantMemberCount == 4);
        const std::pair<const char*, uint32_t> expected[] = {
            {"scale", 0}, {"flags", 4}, {"size", 8}, {"texelSize", 16}};
        for (uint32_t m = 0; m < 4; ++m) {
            CHECK(std::string(table.pushConstantMembers[m].name) == expected[m].first);
            CHECK(table.pushConstantMembers[m].offset == expected[m].second);
        }
    }
}
