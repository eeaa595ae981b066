// DXIL output, with a fake dxc (fake_dxc.cpp; no dxc on this machine): every permutation's blob is
// what dxc made from exactly that key's arguments, blobs dedup, the bindings are the HLSL
// registers, and a dxc failure is one line naming pass and permutation, with no output written.
#include "ffx_dof_test_shaders_dxil.h"
#include "run_tool.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <map>
#include <set>

using ffxdof::shaders::BindingKind;
using ffxdof::shaders::PassTable;
using namespace ffxdof::test;

namespace {

const std::string kShaders = FFX_DOF_TEST_SHADER_DIR;

std::string blobText(const PassTable& table, uint32_t permutation) {
    const ffxdof::shaders::Blob& blob = table.blobs[table.permutationToBlob[permutation]];
    std::string text(reinterpret_cast<const char*>(blob.words), blob.wordCount * sizeof(uint32_t));
    return text.substr(0, text.find('\0'));
}

// What the fake dxc writes for this key: the profile and 16-bit switch the key asks for, and every
// define the source mentions (the plain FFX_DOF_TEST_WIDE=1 and the axes but FFX_DOF_TEST_UNUSED).
std::string expectedBlobText(const std::map<std::string, uint32_t>& key) {
    const bool half = key.at("FFX_HALF") == 1;
    return std::string("DXBCprofile=") + (key.at("FFX_DOF_OPTION_WAVE64") == 1 ? "cs_6_6" : "cs_6_2") +
           ";16bit=" + (half ? "1" : "0") +
           ";entry=main;defines=FFX_DOF_TEST_SCALE=" + std::to_string(key.at("FFX_DOF_TEST_SCALE")) +
           ",FFX_DOF_TEST_WIDE=1,FFX_HALF=" + (half ? "1" : "0") + ";";
}

std::string dxilCommand(const fs::path& out, const std::string& extra) {
    return "'" + kShaders + "/ffx_dof_test.hlsl' --pass test -I '" + kShaders + "' --dxc '" + FFX_DOF_FAKE_DXC +
           "' '-DFFX_HALF={0,1}' '-DFFX_DOF_OPTION_WAVE64={0,1}' --define FFX_DOF_TEST_SCALE=1 --define "
           "FFX_DOF_TEST_WIDE=0 -o '" +
           out.string() + "' " + extra;
}

}  // namespace

TEST_CASE("dxil: one permutation per key, each blob made from exactly that key's dxc arguments", "[dxil]") {
    const PassTable* table = ffxdof::test::dxil::findPassTable("test");
    REQUIRE(table != nullptr);
    CHECK(std::strcmp(table->language, "dxil") == 0);
    REQUIRE(table->permutationCount == 16);
    // FFX_DOF_TEST_UNUSED is in no argument that changes the output: its two values share a blob.
    CHECK(table->blobCount == 8);
    std::map<std::string, uint16_t> blobOfText;
    for (uint32_t p = 0; p < table->permutationCount; ++p) {
        std::map<std::string, uint32_t> key;
        for (const auto& [macro, value] : ffxdof::shaders::permutationDefines(*table, p)) key[macro] = value;
        INFO("permutation " << p);
        const std::string text = blobText(*table, p);
        CHECK(text == expectedBlobText(key));
        const auto [it, inserted] = blobOfText.emplace(text, table->permutationToBlob[p]);
        CHECK(it->second == table->permutationToBlob[p]);  // equal contents, one blob
        // The SPIR-V reflection of the same permutation: the workgroup size and the 16-bit types.
        const ffxdof::shaders::Blob& blob = table->blobs[table->permutationToBlob[p]];
        CHECK(blob.localSize[0] == 64);  // FFX_DOF_TEST_WIDE=1: 8 * 8 threads in x
        const uint32_t float16 = ffxdof::shaders::featureBit(ffxdof::shaders::Feature::Float16);
        CHECK(((blob.requiredFeatures & float16) != 0) == (key.at("FFX_HALF") == 1));
        CHECK(blob.wordCount * sizeof(uint32_t) % 4 == 0);
    }
    CHECK(blobOfText.size() == table->blobCount);
}

TEST_CASE("dxil: bindings are the HLSL registers and spaces, unshifted", "[dxil]") {
    const PassTable& table = ffxdof::test::dxil::pass_test;
    struct Expected {
        const char* name;
        BindingKind kind;
        uint32_t space, reg;
    };
    // t0 and u0 share a number but not a register class, which is no conflict on D3D12. u24 is
    // binding 40 in the SPIR-V tables of this pass (u=16 shift); DXIL gets no shift.
    for (const Expected& expected : {Expected{"ffxDofTestInput", BindingKind::SampledImage, 0, 0},
                                     Expected{"ffxDofTestOutput", BindingKind::StorageImage, 0, 0},
                                     Expected{"ffxDofTestGlobals", BindingKind::StorageBuffer, 0, 24}}) {
        INFO(expected.name);
        const ffxdof::shaders::Binding* binding = ffxdof::shaders::findBinding(table, expected.name);
        REQUIRE(binding != nullptr);
        CHECK(binding->kind == expected.kind);
        CHECK(binding->set == expected.space);
        CHECK(binding->binding == expected.reg);
    }
    CHECK(table.pushConstantMemberCount == 4);
}

TEST_CASE("dxil: the command line writes a dxil table", "[dxil][cli]") {
    const fs::path out = freshOutDir("dxil_ok");
    const RunResult result = runTool(dxilCommand(out, ""));
    INFO(result.stderrText);
    REQUIRE(result.exitCode == 0);
    const std::string manifest = readText(out / "ffx_dof_test_dxil.json");
    CHECK(manifest.find("\"language\": \"dxil\"") != std::string::npos);
    CHECK(manifest.find("\"permutations\": 4") != std::string::npos);
    CHECK(manifest.find("\"uniqueBlobs\": 4") != std::string::npos);
    CHECK(readText(out / "ffx_dof_test_dxil.cpp").find("\"dxil\"") != std::string::npos);
    // No temporaries of the dxc runs are left in the output folder.
    for (const auto& entry : fs::directory_iterator(out)) CHECK(entry.path().extension() != ".tmp");
}

TEST_CASE("dxil: a dxc failure is one line naming pass, permutation and dxc's message, and no output", "[dxil][cli]") {
    const fs::path out = freshOutDir("dxil_fail");
    fs::create_directories(out);
    std::ofstream(out / "ffx_dof_test_dxil.h") << "previous";
    const std::pair<std::string, std::string> cases[] = {
        {"'-DFFX_DOF_FAKE_DXC_FAIL={0,1}'", "fake failure requested | note: second line of the fake message"},
        {"'-DFFX_DOF_FAKE_DXC_NO_OUTPUT={0,1}'", "dxc wrote no output file"},
    };
    for (const auto& [axis, expected] : cases) {
        INFO(axis);
        const RunResult result = runTool(dxilCommand(out, axis));
        INFO(result.stderrText);
        CHECK(result.exitCode == 1);
        CHECK(lineCount(result.stderrText) == 1);
        CHECK(result.stderrText.rfind("ffx-dof-shaderc: error: pass 'test' (dxil), permutation ", 0) == 0);
        // The failing value of the axis is named (value 0 compiles).
        const std::string macro = axis.substr(3, axis.find('=') - 3);
        CHECK(result.stderrText.find(macro + "=1") != std::string::npos);
        CHECK(result.stderrText.find(expected) != std::string::npos);
        CHECK(readText(out / "ffx_dof_test_dxil.h") == "previous");
        CHECK(!fs::exists(out / "ffx_dof_test_dxil.cpp"));
        CHECK(!fs::exists(out / "ffx_dof_test_dxil.json"));
    }
}

TEST_CASE("dxil: bad --dxc use is one line and no output", "[dxil][cli]") {
    const fs::path out = freshOutDir("dxil_bad");
    const std::pair<std::string, std::string> cases[] = {
        {"'" + kShaders + "/ffx_dof_test.hlsl' --pass test -I '" + kShaders +
             "' --dxc /no/such/dxc --define FFX_HALF=0 --define FFX_DOF_TEST_SCALE=1 --define FFX_DOF_TEST_WIDE=0 -o "
             "'" +
             out.string() + "'",
         "cannot run dxc '/no/such/dxc'"},
        {"'" + kShaders + "/ffx_dof_test.glsl' --pass test --dxc '" + FFX_DOF_FAKE_DXC + "' -o '" + out.string() + "'",
         "--dxc needs an HLSL source"},
        {dxilCommand(out, "--hlsl-shift u=16"), "--hlsl-shift applies to SPIR-V only"},
    };
    for (const auto& [arguments, expected] : cases) {
        INFO(arguments);
        const RunResult result = runTool(arguments);
        INFO(result.stderrText);
        CHECK(result.exitCode == 1);
        CHECK(lineCount(result.stderrText) == 1);
        CHECK(result.stderrText.find(expected) != std::string::npos);
        CHECK(isEmptyOrAbsent(out));
    }
}
