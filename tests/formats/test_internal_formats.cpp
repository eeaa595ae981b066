// The internal images as C++ states them (sdk/src/ffx_dof_passes.h: kInternalImages, kMipCount) against
// the shaders' declarations, read back from the SPIR-V the Vulkan backend embeds (every unique blob of
// every pass, GLSL and HLSL) with the SPIRV-Cross C API. No device: label "cpu".
//  - every storage image the shaders declare is an internal image (level) or the output; its SPIR-V
//    image format is the C++ format of that image (GLSL: the layout qualifiers of
//    ffx_dof_callbacks_glsl.h; HLSL: no format, compiled with --no-storage-format, so Unknown);
//  - its binding is FFX_DOF_UAV_IMAGE_BASE + the C++ storage slot (+ the level), and a sampled
//    image's binding is FFX_DOF_SRV_BASE + the C++ sampled slot, all in set 0;
//  - every internal image, every level, is written by some pass and read by some pass;
//  - kMipCount is FFX_DOF_OPTION_MAX_MIP.
// The shader variables are matched by name (the table below), independently of their bindings.
#include "ffx_dof_passes.h"

#include "ffx_dof_common.h"  // FFX_DOF_OPTION_MAX_MIP (FFX_CPU is defined by ffx_dof_passes.h)
#include "ffx_dof_vk_shaders_glsl.h"
#if FFX_DOF_TEST_HAVE_HLSL
#include "ffx_dof_vk_shaders_hlsl.h"
#endif

#include <catch2/catch.hpp>
#include <spirv_cross_c.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace ffxdof;

static_assert(kMipCount == FFX_DOF_OPTION_MAX_MIP,
              "kMipCount (ffx_dof_passes.h) must equal FFX_DOF_OPTION_MAX_MIP (ffx_dof_common.h)");

namespace {

// A shader variable that is (one level of) an internal image, by the name the callbacks headers give it.
struct ShaderImage {
    const char* variable;
    const char* image;  // InternalImageSpec::name
    uint32_t level;
};

const ShaderImage kStorageImages[] = {
    {"ffxDofRwHalfColor", "HALF_COLOR", 0},       {"ffxDofRwHalfCoc", "HALF_COC", 0},
    {"ffxDofCoarseMip1", "COARSE_MIPS", 0},       {"ffxDofCoarseMip2", "COARSE_MIPS", 1},
    {"ffxDofCoarseMip3", "COARSE_MIPS", 2},       {"ffxDofRwTiles", "TILES", 0},
    {"ffxDofRwDilatedTiles", "DILATED_TILES", 0}, {"ffxDofRwNearColor", "NEAR_COLOR", 0},
    {"ffxDofRwFarColor", "FAR_COLOR", 0},         {"ffxDofRwLayerAlpha", "LAYER_ALPHA", 0},
};

const ShaderImage kSampledImages[] = {
    {"ffxDofHalfColor", "HALF_COLOR", 0},       {"ffxDofHalfCoc", "HALF_COC", 0},
    {"ffxDofCoarseMips", "COARSE_MIPS", 0},     {"ffxDofTiles", "TILES", 0},
    {"ffxDofDilatedTiles", "DILATED_TILES", 0}, {"ffxDofNearColor", "NEAR_COLOR", 0},
    {"ffxDofFarColor", "FAR_COLOR", 0},         {"ffxDofLayerAlpha", "LAYER_ALPHA", 0},
};

// The engine's images: not internal, bound wherever the engine's are.
const std::set<std::string> kEngineStorageImages = {"ffxDofOutput"};
const std::set<std::string> kEngineSampledImages = {"ffxDofInputColor", "ffxDofInputDepth"};

const char* const kFormatNames[] = {"R11G11B10Float", "R16Float", "R16G16B16A16Float", "R8Unorm", "R32G32Uint"};

SpvImageFormat spirvFormat(InternalFormat format) {
    switch (format) {
        case InternalFormat::R11G11B10Float:
            return SpvImageFormatR11fG11fB10f;
        case InternalFormat::R16Float:
            return SpvImageFormatR16f;
        case InternalFormat::R16G16B16A16Float:
            return SpvImageFormatRgba16f;
        case InternalFormat::R8Unorm:
            return SpvImageFormatR8;
        case InternalFormat::R32G32Uint:
            return SpvImageFormatRg32ui;
    }
    FAIL("unknown InternalFormat " << uint32_t(format));
    return SpvImageFormatUnknown;
}

// SPIR-V format names as in the specification (ImageFormat), for readable failures.
std::string spirvFormatName(SpvImageFormat format) {
    switch (format) {
        case SpvImageFormatUnknown:
            return "Unknown";
        case SpvImageFormatR11fG11fB10f:
            return "R11fG11fB10f";
        case SpvImageFormatR16f:
            return "R16f";
        case SpvImageFormatRg16f:
            return "Rg16f";
        case SpvImageFormatRgba16f:
            return "Rgba16f";
        case SpvImageFormatR8:
            return "R8";
        case SpvImageFormatRg32ui:
            return "Rg32ui";
        default:
            return "ImageFormat " + std::to_string(uint32_t(format));
    }
}

const InternalImageSpec* findSpec(const std::string& name) {
    for (const InternalImageSpec& spec : kInternalImages) {
        if (name == spec.name) return &spec;
    }
    return nullptr;
}

const ShaderImage* findShaderImage(const ShaderImage* begin, const ShaderImage* end, const std::string& variable) {
    for (const ShaderImage* image = begin; image != end; ++image) {
        if (variable == image->variable) return image;
    }
    return nullptr;
}

// One image resource of a blob, as reflected.
struct ReflectedImage {
    std::string name;
    uint32_t set = 0;
    uint32_t binding = 0;
    SpvImageFormat format = SpvImageFormatUnknown;
};

struct ReflectedBlob {
    std::vector<ReflectedImage> storage;
    std::vector<ReflectedImage> sampled;
};

std::vector<ReflectedImage> imagesOf(spvc_compiler compiler, spvc_resources resources, spvc_resource_type type) {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    REQUIRE(spvc_resources_get_resource_list_for_type(resources, type, &list, &count) == SPVC_SUCCESS);
    std::vector<ReflectedImage> images;
    for (size_t i = 0; i < count; ++i) {
        ReflectedImage image;
        image.name = list[i].name ? list[i].name : "";
        image.set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
        image.binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
        image.format = spvc_type_get_image_storage_format(spvc_compiler_get_type_handle(compiler, list[i].type_id));
        images.push_back(image);
    }
    return images;
}

ReflectedBlob reflect(const shaders::Blob& blob) {
    spvc_context context = nullptr;
    REQUIRE(spvc_context_create(&context) == SPVC_SUCCESS);
    struct Destroy {
        spvc_context context;
        ~Destroy() { spvc_context_destroy(context); }
    } destroy{context};
    spvc_parsed_ir ir = nullptr;
    spvc_compiler compiler = nullptr;
    spvc_resources resources = nullptr;
    const bool parsed = spvc_context_parse_spirv(context, blob.words, blob.wordCount, &ir) == SPVC_SUCCESS &&
                        spvc_context_create_compiler(context, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                                     &compiler) == SPVC_SUCCESS &&
                        spvc_compiler_create_shader_resources(compiler, &resources) == SPVC_SUCCESS;
    INFO(spvc_context_get_last_error_string(context));
    REQUIRE(parsed);
    ReflectedBlob reflected;
    reflected.storage = imagesOf(compiler, resources, SPVC_RESOURCE_TYPE_STORAGE_IMAGE);
    reflected.sampled = imagesOf(compiler, resources, SPVC_RESOURCE_TYPE_SEPARATE_IMAGE);
    return reflected;
}

// What the blobs of one language declare, over all passes: (image name, level) written / read.
struct Coverage {
    std::set<std::pair<std::string, uint32_t>> written;
    std::set<std::string> read;
    std::map<std::string, uint32_t> levelsDeclared;  // by image: highest storage level + 1
};

// Checks every blob of every table; `storageFormatDeclared`: GLSL declares the format of each storage
// image, HLSL (--no-storage-format) leaves it Unknown.
Coverage checkTables(const shaders::PassTable* const* tables, size_t tableCount, bool storageFormatDeclared) {
    Coverage coverage;
    REQUIRE(tableCount == kPassCount);
    for (size_t t = 0; t < tableCount; ++t) {
        const shaders::PassTable& table = *tables[t];
        for (uint32_t b = 0; b < table.blobCount; ++b) {
            CAPTURE(table.language, table.pass, b);
            const ReflectedBlob blob = reflect(table.blobs[b]);
            for (const ReflectedImage& image : blob.storage) {
                CAPTURE(image.name, image.binding);
                CHECK(image.set == 0u);
                if (kEngineStorageImages.count(image.name)) {
                    CHECK(image.binding == FFX_DOF_UAV_IMAGE_BASE + FFX_DOF_UAV_OUTPUT);
                    continue;
                }
                const ShaderImage* known =
                    findShaderImage(std::begin(kStorageImages), std::end(kStorageImages), image.name);
                if (!known) FAIL("a storage image that is neither an internal image nor the output");
                const InternalImageSpec* spec = findSpec(known->image);
                REQUIRE(spec != nullptr);
                CAPTURE(spec->name, known->level, kFormatNames[uint32_t(spec->format)]);
                CHECK(image.binding == FFX_DOF_UAV_IMAGE_BASE + spec->storageSlot + known->level);
                const std::string declared = spirvFormatName(image.format);
                if (storageFormatDeclared) {
                    CHECK(declared == spirvFormatName(spirvFormat(spec->format)));
                } else {
                    CHECK(declared == spirvFormatName(SpvImageFormatUnknown));
                }
                coverage.written.insert({spec->name, known->level});
                uint32_t& levels = coverage.levelsDeclared[spec->name];
                levels = std::max(levels, known->level + 1);
            }
            for (const ReflectedImage& image : blob.sampled) {
                CAPTURE(image.name, image.binding);
                CHECK(image.set == 0u);
                if (kEngineSampledImages.count(image.name)) continue;
                const ShaderImage* known =
                    findShaderImage(std::begin(kSampledImages), std::end(kSampledImages), image.name);
                if (!known) FAIL("a sampled image that is neither an internal image nor an engine input");
                const InternalImageSpec* spec = findSpec(known->image);
                REQUIRE(spec != nullptr);
                CAPTURE(spec->name);
                CHECK(image.binding == FFX_DOF_SRV_BASE + spec->sampledSlot);
                coverage.read.insert(spec->name);
            }
        }
    }
    return coverage;
}

void checkCoverage(const Coverage& coverage) {
    for (const InternalImageSpec& spec : kInternalImages) {
        CAPTURE(spec.name);
        const uint32_t levels = spec.levels;
        for (uint32_t level = 0; level < levels; ++level) {
            CAPTURE(level);
            CHECK(coverage.written.count({spec.name, level}) == 1u);
        }
        CHECK(coverage.read.count(spec.name) == 1u);
        // No pass writes a level the C++ side does not allocate.
        const auto declared = coverage.levelsDeclared.find(spec.name);
        if (declared != coverage.levelsDeclared.end()) CHECK(declared->second == levels);
    }
}

}  // namespace

TEST_CASE("the C++ table of internal images names each image once with its own slots", "[formats]") {
    std::set<std::string> names;
    std::set<uint32_t> storageSlots, sampledSlots;
    for (const InternalImageSpec& spec : kInternalImages) {
        CAPTURE(spec.name);
        CHECK(names.insert(spec.name).second);
        CHECK(sampledSlots.insert(spec.sampledSlot).second);
        for (uint32_t level = 0; level < spec.levels; ++level) {
            CHECK(storageSlots.insert(spec.storageSlot + level).second);
        }
        CHECK(uint32_t(spec.format) < sizeof(kFormatNames) / sizeof(kFormatNames[0]));
    }
    // The engine's slots are not among them.
    CHECK(storageSlots.count(FFX_DOF_UAV_OUTPUT) == 0u);
    CHECK(sampledSlots.count(FFX_DOF_SRV_INPUT_COLOR) == 0u);
    CHECK(sampledSlots.count(FFX_DOF_SRV_INPUT_DEPTH) == 0u);
}

TEST_CASE("GLSL storage images have the C++ format and slot of their internal image", "[formats]") {
    const Coverage coverage = checkTables(shaders::glsl::kPassTables, shaders::glsl::kPassTableCount, true);
    checkCoverage(coverage);
}

#if FFX_DOF_TEST_HAVE_HLSL
TEST_CASE("HLSL storage images have the C++ slot of their internal image and no format", "[formats]") {
    const Coverage coverage = checkTables(shaders::hlsl::kPassTables, shaders::hlsl::kPassTableCount, false);
    checkCoverage(coverage);
}
#endif

TEST_CASE("kMipCount is FFX_DOF_OPTION_MAX_MIP, the levels the shaders declare", "[formats]") {
    CHECK(kMipCount == uint32_t(FFX_DOF_OPTION_MAX_MIP));  // also a static_assert above
    const Coverage coverage = checkTables(shaders::glsl::kPassTables, shaders::glsl::kPassTableCount, true);
    CHECK(coverage.levelsDeclared.at("HALF_COLOR") == 1);
    CHECK(coverage.levelsDeclared.at("HALF_COC") == 1);
    CHECK(coverage.levelsDeclared.at("COARSE_MIPS") == kMipCount - 1);  // MIPs 1..
}
