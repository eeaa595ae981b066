// With FFX_DOF_VK_USE_HLSL_SHADERS the backend must create its pipelines from the HLSL-compiled
// blobs, and from the permutation the context's options call for. The test hands the backend a
// vkGetDeviceProcAddr that wraps vkCreateShaderModule, records the SPIR-V of every module the
// context creates, and compares it word for word with the blob the embedded tables give for the
// expected key. Without this check, a backend that ignored the flag would make the HLSL-vs-GLSL
// comparison pass trivially (GLSL against itself).
#include "hlsl_test_support.h"

#include "ffx_dof_pass_list.h"
#include "ffx_dof_vk_shaders_glsl.h"
#include "ffx_dof_vk_shaders_hlsl.h"

#include <algorithm>
#include <cstring>
#include <vector>

using namespace ffxdof;
using namespace ffxdof::hlsltest;

namespace {

// The wrapper is a plain function pointer, so what it records lives at namespace scope (one test
// thread; cleared before each context).
std::vector<std::vector<uint32_t>> recordedModules;
PFN_vkCreateShaderModule realCreateShaderModule = nullptr;

VKAPI_ATTR VkResult VKAPI_CALL recordingCreateShaderModule(VkDevice device, const VkShaderModuleCreateInfo* info,
                                                           const VkAllocationCallbacks* allocator,
                                                           VkShaderModule* module) {
    const uint32_t* words = info->pCode;
    recordedModules.emplace_back(words, words + info->codeSize / sizeof(uint32_t));
    return realCreateShaderModule(device, info, allocator, module);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL recordingGetDeviceProcAddr(VkDevice device, const char* name) {
    if (std::strcmp(name, "vkCreateShaderModule") == 0) {
        realCreateShaderModule = reinterpret_cast<PFN_vkCreateShaderModule>(vkGetDeviceProcAddr(device, name));
        return reinterpret_cast<PFN_vkVoidFunction>(&recordingCreateShaderModule);
    }
    return vkGetDeviceProcAddr(device, name);
}

struct Options {
    bool hlsl, half, reversedDepth, ringMerge, inPlace, apertureShapes;
};

const shaders::PassTable* tableFor(bool hlsl, const char* pass) {
    return hlsl ? shaders::hlsl::findPassTable(pass) : shaders::glsl::findPassTable(pass);
}

// One pipeline of a pass: its aperture axis value and its tile class (0 for a pass without the axis).
struct Variant {
    uint32_t aperture = 0;
    uint32_t tileClass = 0;
};

// The aperture values a context of `options` makes blurs of: 0 without shapes; with them, every value of
// the axis's per-dispatch list (kAxisDispatchValues from the permutations JSON).
std::vector<uint32_t> apertureValues(const Options& options) {
    if (!options.apertureShapes) return {0u};
    for (uint32_t a = 0; a < kAxisCount; ++a) {
        const AxisDispatchValues& perDispatch = kAxisDispatchValues[a];
        if (std::strcmp(kAxisMacros[a], "FFX_DOF_OPTION_APERTURE_SHAPES") == 0 && perDispatch.count > 0)
            return std::vector<uint32_t>(perDispatch.values, perDispatch.values + perDispatch.count);
    }
    return {1u};
}

// The pipelines a context of `options` makes of `pass`: the blur one per aperture value and tile class,
// the composite one per tile class (in place none for the copy), the others one.
std::vector<Variant> variantsOf(const char* pass, const Options& options) {
    std::vector<Variant> variants;
    if (std::strcmp(pass, "composite") == 0) {
        for (uint32_t tileClass = 0; tileClass < FFX_DOF_COMPOSITE_CLASS_COUNT; ++tileClass) {
            if (!(options.inPlace && tileClass == FFX_DOF_COMPOSITE_CLASS_COPY)) variants.push_back({0u, tileClass});
        }
    } else if (std::strcmp(pass, "blur") == 0) {
        for (uint32_t aperture : apertureValues(options))
            for (uint32_t tileClass = 0; tileClass < FFX_DOF_BLUR_CLASS_COUNT; ++tileClass)
                variants.push_back({aperture, tileClass});
    } else {
        variants.push_back({});
    }
    return variants;
}

// The blob the options call for: each axis the table has gets the options' value, and the aperture axis
// and the tile class the variant's.
const shaders::Blob& expectedBlob(const shaders::PassTable& table, const Options& options, const Variant& variant) {
    std::vector<shaders::Define> key;
    for (uint32_t a = 0; a < table.axisCount; ++a) {
        const std::string macro = table.axes[a].macro;
        uint32_t value = 0;
        if (macro == "FFX_HALF")
            value = options.half;
        else if (macro == "FFX_DOF_OPTION_REVERSE_DEPTH")
            value = options.reversedDepth;
        else if (macro == "FFX_DOF_OPTION_DISABLE_RING_MERGE")
            value = options.ringMerge ? 0 : 1;
        else if (macro == "FFX_DOF_OPTION_OUTPUT_PRE_INIT")
            value = options.inPlace;
        else if (macro == "FFX_DOF_OPTION_APERTURE_SHAPES")
            value = variant.aperture;
        else if (macro == "FFX_DOF_OPTION_COMPOSITE_CLASS" || macro == "FFX_DOF_OPTION_BLUR_CLASS")
            value = variant.tileClass;
        else if (macro != "FFX_DOF_OPTION_WAVE64")
            FAIL("axis " << macro << " is unknown to this test");
        key.emplace_back(macro, value);
    }
    std::string error;
    const shaders::Blob* blob = shaders::findPermutation(table, key, &error);
    INFO(error);
    REQUIRE(blob != nullptr);
    return *blob;
}

bool sameWords(const std::vector<uint32_t>& words, const shaders::Blob& blob) {
    return words.size() == blob.wordCount && std::memcmp(words.data(), blob.words, blob.wordCount * 4) == 0;
}

}  // namespace

TEST_CASE("the backend creates its pipelines from the blobs of the chosen language and permutation", "[vulkan][hlsl]") {
    vkrun::Device& device = validatedDevice();
    REQUIRE(device.features().shaderFloat16);
    REQUIRE(device.features().storageBuffer16BitAccess);
    // One backend per language and precision, and with it a context for each of the other 16 option sets: the
    // backend compiles each blob once for all its contexts (docs/api.md), so each context records the modules of
    // the blobs no earlier context of the backend needed, and the backend's modules are the union of its
    // contexts' blobs, each exactly once.
    for (uint32_t backendBits = 0; backendBits < 4; ++backendBits) {
        const bool hlsl = (backendBits & 1) != 0, half = (backendBits & 2) != 0;
        CAPTURE(hlsl, half);
        uint32_t backendFlags = FFX_DOF_VK_DISABLE_WAVE64;
        if (hlsl) backendFlags |= FFX_DOF_VK_USE_HLSL_SHADERS;
        if (!half) backendFlags |= FFX_DOF_VK_DISABLE_FLOAT16;
        FfxDofBackendDescriptionVK description = device.backendDescription(backendFlags);
        description.vkGetDeviceProcAddr = &recordingGetDeviceProcAddr;
        FfxDofBackend backend = nullptr;
        REQUIRE(ffxDofBackendCreateVK(&description, &backend) == FFX_DOF_OK);
        std::vector<const shaders::Blob*> compiled;  // by this backend so far, each once
        for (uint32_t contextBits = 0; contextBits < 16; ++contextBits) {
            const Options options{hlsl,
                                  half,
                                  (contextBits & 1) != 0,
                                  (contextBits & 2) != 0,
                                  (contextBits & 4) != 0,
                                  (contextBits & 8) != 0};
            CAPTURE(options.reversedDepth, options.ringMerge, options.inPlace, options.apertureShapes);
            FfxDofContextDescription contextInfo{};
            contextInfo.quality = 4;
            contextInfo.resolution = {67, 41};
            contextInfo.cocLimitFactor = 0.05f;
            contextInfo.flags = contextFlags(options.reversedDepth, options.ringMerge) |
                                (options.inPlace ? uint32_t(FFX_DOF_OUTPUT_PRE_INIT) : 0u) |
                                (options.apertureShapes ? uint32_t(FFX_DOF_ENABLE_APERTURE_SHAPES) : 0u);
            contextInfo.backendInterface = backend;
            recordedModules.clear();
            FfxDofContext context = nullptr;
            const FfxDofErrorCode created = ffxDofContextCreate(&context, &contextInfo);
            INFO(ffxDofGetLastErrorMessage());
            CHECK(created == FFX_DOF_OK);
            ffxDofContextDestroy(&context);

            // The context's blobs: one per pass, but a blur per tile list, twice in a shaped context (the general
            // and the compact aperture's, chosen per dispatch), and a composite per tile list. Those the backend
            // had not compiled yet are the ones it must compile now.
            std::vector<const shaders::Blob*> expected;
            for (uint32_t t = 0; t < shaders::glsl::kPassTableCount; ++t) {
                const shaders::PassTable* own = tableFor(hlsl, shaders::glsl::kPassTables[t]->pass);
                REQUIRE(own != nullptr);
                for (const Variant& variant : variantsOf(own->pass, options)) {
                    const shaders::Blob* blob = &expectedBlob(*own, options, variant);
                    if (std::find(compiled.begin(), compiled.end(), blob) == compiled.end()) expected.push_back(blob);
                }
            }
            if (options.apertureShapes) CHECK(apertureValues(options).size() >= 2);
            REQUIRE(recordedModules.size() == expected.size());
            for (const std::vector<uint32_t>& module : recordedModules) {
                bool matched = false;
                for (auto blob = expected.begin(); blob != expected.end() && !matched; ++blob) {
                    if (sameWords(module, **blob)) {
                        matched = true;
                        compiled.push_back(*blob);
                        expected.erase(blob);  // each expected blob once
                        break;
                    }
                }
                CHECK(matched);
                for (uint32_t t = 0; t < shaders::glsl::kPassTableCount; ++t) {
                    const shaders::PassTable* other = tableFor(!hlsl, shaders::glsl::kPassTables[t]->pass);
                    REQUIRE(other != nullptr);
                    INFO("pass " << other->pass);
                    for (uint32_t b = 0; b < other->blobCount; ++b) CHECK_FALSE(sameWords(module, other->blobs[b]));
                }
            }
            CHECK(expected.empty());
        }
        ffxDofBackendDestroy(backend);
        requireNoValidationMessages(device, hlsl ? "HLSL pipelines" : "GLSL pipelines");
    }
}
