// The compiler library: axis syntax, compile errors, binding agreement across permutations.
#include "shaderc.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace ffxdof::shaderc;

namespace {

CompileOptions testOptions(const char* file) {
    CompileOptions options;
    options.pass = "test";
    options.source = std::string(FFX_DOF_TEST_SHADER_DIR "/") + file;
    options.includeDirs = {FFX_DOF_TEST_SHADER_DIR};
    return options;
}

std::string errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_CASE("axis syntax", "[compiler]") {
    const Axis axis = parseAxis("FFX_DOF_OPTION_REVERSE_DEPTH={0,1}");
    CHECK(axis.macro == "FFX_DOF_OPTION_REVERSE_DEPTH");
    CHECK(axis.values == std::vector<uint32_t>{0, 1});
    CHECK(parseAxis("X={ 3 , 7 }").values == std::vector<uint32_t>{3, 7});
    CHECK(errorOf([] { parseAxis("X={}"); }).find("has no values") != std::string::npos);
    CHECK(errorOf([] { parseAxis("X=1"); }).find("braces") != std::string::npos);
    CHECK(errorOf([] { parseAxis("X"); }).find("no value list") != std::string::npos);
    CHECK(errorOf([] { parseAxis("1X={0}"); }).find("not a macro name") != std::string::npos);
    CHECK(errorOf([] { parseAxis("X={0,0}"); }).find("twice") != std::string::npos);
    CHECK(errorOf([] { parseAxis("X={0,-1}"); }).find("not a non-negative integer") != std::string::npos);
    CHECK(errorOf([] { parseAxis("X={99999999999}"); }).find("32 bits") != std::string::npos);
    CHECK(parseDefine("A=2").value == "2");
    CHECK(parseDefine("A").value == "1");
    CHECK(errorOf([] { parseDefine("=2"); }).find("not a macro name") != std::string::npos);
}

TEST_CASE("permutation keys: last axis fastest", "[compiler]") {
    const std::vector<Axis> axes = {{"A", {0, 1}}, {"B", {5, 6, 7}}};
    CHECK(permutationCount(axes) == 6);
    const auto defines = permutationDefines(axes, 4);  // A index 1, B index 1
    REQUIRE(defines.size() == 2);
    CHECK(defines[0].value == "1");
    CHECK(defines[1].value == "6");
    CHECK(permutationCount({}) == 1);
}

TEST_CASE("a compile error names the pass, the permutation and the source line", "[compiler]") {
    GlslangProcess glslang;
    const std::string message =
        errorOf([] { buildPass(testOptions("ffx_dof_test_error.glsl"), {parseAxis("FFX_DOF_TEST_BROKEN={0,1}")}, 2); });
    CHECK(message.find("pass 'test' (glsl)") != std::string::npos);
    CHECK(message.find("FFX_DOF_TEST_BROKEN=1") != std::string::npos);
    CHECK(message.find("ffx_dof_test_error.glsl:7") != std::string::npos);
    CHECK(message.find("ffxDofTestUndeclared") != std::string::npos);
    // The context shows the failing line itself, marked.
    CHECK(message.find(">    7 |     ffxDofTestResult.value = ffxDofTestUndeclared;") != std::string::npos);
}

TEST_CASE("permutations that disagree on a binding fail the pass", "[compiler][reflection]") {
    GlslangProcess glslang;
    const std::string message = errorOf(
        [] { buildPass(testOptions("ffx_dof_test_disagree.glsl"), {parseAxis("FFX_DOF_TEST_SLOT={0,1}")}, 1); });
    CHECK(message.find("disagree") != std::string::npos);
    CHECK(message.find("ffxDofTestOutput") != std::string::npos);
    CHECK(message.find("FFX_DOF_TEST_SLOT=1") != std::string::npos);
    // One slot is fine: the same pass with the axis pinned builds.
    CHECK_NOTHROW(buildPass(testOptions("ffx_dof_test_disagree.glsl"), {parseAxis("FFX_DOF_TEST_SLOT={1}")}, 1));
}

TEST_CASE("two names on one slot are a disagreement too", "[compiler][reflection]") {
    PassBuild build;
    build.options.pass = "test";
    build.axes = {{"A", {0, 1}}};
    build.blobs = {{1}, {2}};
    build.permutationToBlob = {0, 1};
    Reflection first, second;
    first.bindings = {{"ffxDofA", 0, 16, BindingKind::StorageImage, 1, 0}};
    second.bindings = {{"ffxDofB", 0, 16, BindingKind::StorageImage, 1, 0}};
    build.blobReflections = {first, second};
    CHECK(errorOf([&] { mergeReflections(build); }).find("share one slot") != std::string::npos);
    second.bindings = {{"ffxDofA", 0, 16, BindingKind::StorageImage, 1, 0}};
    second.pushConstantMembers = {{"x", 0, 4}};
    first.pushConstantMembers = {{"x", 4, 4}};
    build.blobReflections = {first, second};
    CHECK(errorOf([&] { mergeReflections(build); }).find("push constant layout") != std::string::npos);
}

TEST_CASE("an include cycle is reported as such", "[compiler]") {
    GlslangProcess glslang;
    const std::string message = errorOf([] { compilePermutation(testOptions("ffx_dof_test_cycle.glsl"), {}); });
    CHECK(message.find("include cycle: ffx_dof_test_cycle_a.h -> ffx_dof_test_cycle_b.h -> ffx_dof_test_cycle_a.h") !=
          std::string::npos);
}

TEST_CASE("the depfile names every included header", "[compiler]") {
    GlslangProcess glslang;
    CompileOptions options = testOptions("ffx_dof_test.glsl");
    options.defines = {{"FFX_DOF_TEST_WIDE", "0"}, {"FFX_DOF_TEST_SCALE", "2"}};
    const PassBuild build = buildPass(options, {parseAxis("FFX_HALF={0,1}")}, 2);
    const std::string depfile = emitDepfile("/out/ffx_dof_test_glsl.h", build.dependencies);
    CHECK(depfile.rfind("/out/ffx_dof_test_glsl.h:", 0) == 0);
    CHECK(depfile.find("/ffx_dof_test_common.h") != std::string::npos);
    CHECK(depfile.find("/ffx_dof_test.glsl") != std::string::npos);
    CHECK(emitDepfile("/a b/t.h", {"/c d/e.h"}) == "/a\\ b/t.h: \\\n  /c\\ d/e.h\n");
}

TEST_CASE("capabilities become the feature bits a device must enable, an unknown one is an error",
          "[compiler][reflection]") {
    using ffxdof::shaders::Feature;
    using ffxdof::shaders::featureBit;
    // SPIR-V capability numbers: Shader 1, StorageImageExtendedFormats 49 and ImageQuery 50 are core.
    CHECK(requiredFeatures({1, 49, 50}) == 0);
    // Float16 9, StorageImageWriteWithoutFormat 56, GroupNonUniform 61, GroupNonUniformArithmetic 63,
    // StorageBuffer16BitAccess 4433, StoragePushConstant16 4435, Int16 22.
    CHECK(requiredFeatures({1, 9, 56}) ==
          (featureBit(Feature::Float16) | featureBit(Feature::StorageImageWriteWithoutFormat)));
    CHECK(requiredFeatures({61, 63}) ==
          (featureBit(Feature::GroupNonUniform) | featureBit(Feature::GroupNonUniformArithmetic)));
    CHECK(requiredFeatures({4433, 4435, 22}) ==
          (featureBit(Feature::StorageBuffer16BitAccess) | featureBit(Feature::StoragePushConstant16) |
           featureBit(Feature::Int16)));
    // Geometry (2) needs a feature the runtime does not check; Kernel (6) is not Vulkan at all.
    for (uint32_t unknown : {2u, 6u}) {
        const std::string message = errorOf([unknown] { requiredFeatures({1, unknown}); });
        CHECK(message.find("capability " + std::to_string(unknown)) != std::string::npos);
        CHECK(message.find("capabilities.cpp") != std::string::npos);
    }
}

TEST_CASE("every feature bit has a distinct name", "[compiler]") {
    std::set<std::string> names;
    for (uint32_t bit = 0; bit < ffxdof::shaders::kFeatureCount; ++bit) {
        const char* name = ffxdof::shaders::featureName(ffxdof::shaders::Feature(1u << bit));
        REQUIRE(name != nullptr);
        names.insert(name);
    }
    CHECK(names.size() == ffxdof::shaders::kFeatureCount);
    CHECK(ffxdof::shaders::featureName(ffxdof::shaders::Feature(1u << ffxdof::shaders::kFeatureCount)) == nullptr);
    CHECK(featureNames(ffxdof::shaders::featureBit(ffxdof::shaders::Feature::Float16) |
                       ffxdof::shaders::featureBit(ffxdof::shaders::Feature::GroupNonUniform)) ==
          "Float16 GroupNonUniform");
    CHECK(featureNames(0).empty());
}
