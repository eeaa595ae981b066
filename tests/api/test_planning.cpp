// Planning: the context plan (permutations, image sizes, slot map, each pass's reads and writes from
// the real GLSL tables' reflection) and the per-dispatch constants and workgroup counts for awkward
// sizes (rounding must be symmetric and cover every pixel, tile and half-resolution texel exactly once).
#include "fake_backend.h"
#include "ffx_dof_aperture.h"
#include "ffx_dof_plan.h"
#include "ffx_dof_readback_ring.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace ffxdof;

namespace {

ContextPlan contextPlan(uint32_t width, uint32_t height, uint32_t flags = 0, float cocLimitFactor = 0.05f,
                        bool half = false) {
    ContextConfig config;
    config.resolution = {width, height};
    config.flags = flags;
    config.quality = 10;
    config.cocLimitFactor = cocLimitFactor;
    ContextPlan plan;
    REQUIRE(buildContextPlan(config, testing::glslCapabilities(half), &plan) == FFX_DOF_OK);
    return plan;
}

struct Planned {
    ContextPlan context;
    DispatchPlan dispatch;
};

Planned plan(uint32_t width, uint32_t height, uint32_t flags = 0, float cocLimitFactor = 0.05f) {
    Planned planned{contextPlan(width, height, flags, cocLimitFactor), {}};
    FfxDofDispatchDescription dispatch{};
    dispatch.cocScale = -3.0f;
    dispatch.cocBias = 2.0f;
    planned.dispatch = planDispatch(planned.context, dispatch, 7);
    return planned;
}

uint32_t ceilDiv(uint32_t a, uint32_t b) { return (a + b - 1) / b; }

}  // namespace

TEST_CASE("half resolution and tile counts round up in both directions") {
    const auto [width, height] = GENERATE(table<uint32_t, uint32_t>(
        {{1, 1}, {7, 5}, {16, 16}, {17, 15}, {641, 479}, {1920, 1080}, {4096, 2160}, {16384, 3}}));
    const Planned p = plan(width, height);
    const FfxDofConstants& c = p.dispatch.constants;
    CHECK(c.fullSize.x == width);
    CHECK(c.fullSize.y == height);
    CHECK(c.halfSize.x == (width + 1) / 2);
    CHECK(c.halfSize.y == (height + 1) / 2);
    CHECK(c.tileCount.x == ceilDiv(c.halfSize.x, FFX_DOF_TILE_SIZE));
    CHECK(c.tileCount.y == ceilDiv(c.halfSize.y, FFX_DOF_TILE_SIZE));
    CHECK(c.bladeCount == 0);  // round
    CHECK(c.anamorphicRatio == 1.0f);
    CHECK(c.apertureAreaScale == 1.0f);
    CHECK(c.catEye == 0.0f);

    // Every pass covers its whole domain, and no group lies entirely outside it.
    const struct {
        Pass pass;
        uint32_t domainWidth, domainHeight, extent;
    } passes[] = {
        {Pass::DownsampleDepth, width, height, FFX_DOF_DOWNSAMPLE_DEPTH_GROUP_EXTENT},
        {Pass::DownsampleColor, width, height, FFX_DOF_DOWNSAMPLE_COLOR_GROUP_EXTENT},
        {Pass::Dilate, c.tileCount.x, c.tileCount.y, FFX_DOF_DILATE_GROUP_EXTENT},
        {Pass::Blur, c.halfSize.x, c.halfSize.y, FFX_DOF_BLUR_GROUP_EXTENT},
        {Pass::Composite, width, height, FFX_DOF_COMPOSITE_GROUP_EXTENT},
    };
    for (const auto& pass : passes) {
        INFO("pass " << kPassNames[uint32_t(pass.pass)] << " at " << width << "x" << height);
        const PassGrid grid = p.context.passes[uint32_t(pass.pass)].groups;
        CHECK(grid.x * pass.extent >= pass.domainWidth);
        CHECK(grid.y * pass.extent >= pass.domainHeight);
        CHECK((grid.x - 1) * pass.extent < pass.domainWidth);
        CHECK((grid.y - 1) * pass.extent < pass.domainHeight);
        CHECK(grid.z == 1);
    }
}

TEST_CASE("the CoC limit is the factor times the height, in half-resolution pixels") {
    CHECK(plan(1920, 1080, 0, 0.05f).dispatch.constants.cocLimit == Approx(27.0f));
    CHECK(plan(1920, 1080, 0, 0.01f).dispatch.constants.cocLimit == Approx(5.4f));
    CHECK(plan(1920, 1080, 0, 0.0f).dispatch.constants.cocLimit == 0.0f);
}

TEST_CASE("flags select the permutation axes of the same name and sense") {
    CHECK(contextPlan(64, 64).axes.reverseDepth == 0);
    CHECK(contextPlan(64, 64).axes.disableRingMerge == 0);
    CHECK(contextPlan(64, 64).axes.outputPreInit == 0);
    CHECK(contextPlan(64, 64, FFX_DOF_REVERSE_DEPTH).axes.reverseDepth == 1);
    CHECK(contextPlan(64, 64, FFX_DOF_DISABLE_RING_MERGE).axes.disableRingMerge == 1);
    CHECK(contextPlan(64, 64, FFX_DOF_OUTPUT_PRE_INIT).axes.outputPreInit == 1);
    CHECK(contextPlan(64, 64, 0, 0.05f, true).axes.half == 1);
}

TEST_CASE("each pass runs the permutation of the context's axes") {
    const uint32_t flags =
        GENERATE(0u, uint32_t(FFX_DOF_REVERSE_DEPTH | FFX_DOF_DISABLE_RING_MERGE), uint32_t(FFX_DOF_OUTPUT_PRE_INIT));
    const bool half = GENERATE(false, true);
    const ContextPlan plan = contextPlan(64, 48, flags, 0.05f, half);
    std::vector<uint32_t> allLists;
    for (uint32_t p = 0; p < kPassCount; ++p) {
        const PlannedPass& pass = plan.passes[p];
        INFO("pass " << kPassNames[p]);
        REQUIRE(pass.table != nullptr);
        CHECK(std::string(pass.table->pass) == kPassNames[p]);
        // Without FFX_DOF_ENABLE_APERTURE_SHAPES no axis varies per dispatch; the blur and the composite run
        // one pipeline per tile list (in place the composite none for the copy class, which has nothing to do
        // there).
        const bool inPlace = (flags & FFX_DOF_OUTPUT_PRE_INIT) != 0;
        const bool composite = Pass(p) == Pass::Composite;
        const bool blur = Pass(p) == Pass::Blur;
        std::vector<uint32_t> classes{0};
        uint32_t firstList = 0;
        if (composite) {
            classes = inPlace ? std::vector<uint32_t>{FFX_DOF_COMPOSITE_CLASS_LAYERS, FFX_DOF_COMPOSITE_CLASS_FULL_RES,
                                                      FFX_DOF_COMPOSITE_CLASS_LIGHTS}
                              : std::vector<uint32_t>{FFX_DOF_COMPOSITE_CLASS_COPY, FFX_DOF_COMPOSITE_CLASS_LAYERS,
                                                      FFX_DOF_COMPOSITE_CLASS_FULL_RES, FFX_DOF_COMPOSITE_CLASS_LIGHTS};
            firstList = FFX_DOF_COMPOSITE_TILE_LIST_FIRST;
        } else if (blur) {
            classes = {FFX_DOF_BLUR_CLASS_COPY,     FFX_DOF_BLUR_CLASS_EQUAL_FAR, FFX_DOF_BLUR_CLASS_EQUAL_NEAR,
                       FFX_DOF_BLUR_CLASS_FAR_ONLY, FFX_DOF_BLUR_CLASS_NEAR_ONLY, FFX_DOF_BLUR_CLASS_MIXED};
            firstList = FFX_DOF_BLUR_TILE_LIST_FIRST;
        }
        CHECK(pass.perTileList == (composite || blur));
        REQUIRE(pass.variantCount == classes.size());
        CHECK(pass.tileListVariants == pass.variantCount);
        std::vector<uint32_t> lists;
        for (uint32_t v = 0; v < pass.variantCount; ++v) {
            const PassVariant& variant = pass.variants[v];
            CHECK(variant.dispatchValue == 0);
            if (composite || blur) {
                CHECK(variant.tileListValue == classes[v]);
                CHECK(variant.tileList == firstList + classes[v]);
                lists.push_back(variant.tileList);
            }
            for (const shaders::Define& define : shaders::permutationDefines(*pass.table, variant.permutationIndex)) {
                uint32_t expected = 99;
                for (uint32_t a = 0; a < kAxisCount; ++a) {
                    if (define.first == kAxisMacros[a])
                        expected = kAxisRunsPerTileList[a] ? variant.tileListValue : axisValue(plan.axes, Axis(a));
                }
                CHECK(define.second == expected);
            }
            CHECK(variant.blob == &pass.table->blobs[pass.table->permutationToBlob[variant.permutationIndex]]);
        }
        // Each list is dispatched by one pass at most, and lies within TILE_LIST_ARGS.
        for (uint32_t list : lists) {
            CHECK(list < FFX_DOF_TILE_LIST_COUNT);
            CHECK(std::count(allLists.begin(), allLists.end(), list) == 0);
        }
        allLists.insert(allLists.end(), lists.begin(), lists.end());
        // Dispatched indirectly from TILE_LIST_ARGS, which it does not bind.
        CHECK(pass.indirect == (composite || blur ? resourceBit(Resource::TileListArgs) : 0u));
    }
    // The plan sums the indirect reads once, for the backends' barriers.
    CHECK(plan.indirect == resourceBit(Resource::TileListArgs));
}

namespace {

// The value of `macro` in the permutation a pass's variant runs (99 when the key lacks it).
uint32_t variantAxisValue(const PlannedPass& pass, uint32_t variant, const char* macro) {
    for (const shaders::Define& define :
         shaders::permutationDefines(*pass.table, pass.variants[variant].permutationIndex))
        if (define.first == macro) return define.second;
    return 99;
}

// The FFX_DOF_OPTION_APERTURE_SHAPES value the blur of a dispatch with this aperture runs.
uint32_t blurApertureShapes(const ContextPlan& context, const FfxDofAperture* aperture) {
    FfxDofDispatchDescription dispatch{};
    dispatch.cocScale = -3.0f;
    dispatch.cocBias = 2.0f;
    dispatch.pAperture = aperture;
    const DispatchPlan planned = planDispatch(context, dispatch, 0);
    const PlannedPass& blur = context.passes[uint32_t(Pass::Blur)];
    return variantAxisValue(blur, planned.variants[uint32_t(Pass::Blur)], "FFX_DOF_OPTION_APERTURE_SHAPES");
}

}  // namespace

TEST_CASE("a shaped context runs the compact blur where the dispatch's aperture allows, the general one elsewhere") {
    const bool ringMerge = GENERATE(false, true);
    const ContextPlan context =
        contextPlan(64, 48, FFX_DOF_ENABLE_APERTURE_SHAPES | (ringMerge ? 0u : uint32_t(FFX_DOF_DISABLE_RING_MERGE)));
    const PlannedPass& blur = context.passes[uint32_t(Pass::Blur)];
    // A group of one pipeline per tile list for each aperture value, the lists innermost.
    const uint32_t lists = FFX_DOF_BLUR_CLASS_COUNT;
    REQUIRE(blur.tileListVariants == lists);
    REQUIRE(blur.variantCount == 2 * lists);
    // Every variant keeps the context's other axes; a group differs from the other in the aperture axis alone.
    for (uint32_t v = 0; v < blur.variantCount; ++v) {
        CHECK(variantAxisValue(blur, v, "FFX_DOF_OPTION_DISABLE_RING_MERGE") == (ringMerge ? 0u : 1u));
        CHECK(variantAxisValue(blur, v, "FFX_DOF_OPTION_APERTURE_SHAPES") == blur.variants[v].dispatchValue);
        CHECK(variantAxisValue(blur, v, "FFX_DOF_OPTION_BLUR_CLASS") == v % lists);
        CHECK(blur.variants[v].dispatchValue == blur.variants[v - v % lists].dispatchValue);
        CHECK(blur.variants[v].tileList == FFX_DOF_BLUR_TILE_LIST_FIRST + v % lists);
    }
    CHECK(blur.variants[0].dispatchValue != blur.variants[lists].dispatchValue);
    CHECK(blur.variants[0].blob != blur.variants[lists].blob);
    for (uint32_t p = 0; p < kPassCount; ++p)
        CHECK(context.passes[p].variantCount ==
              (Pass(p) == Pass::Blur ? 2u * lists
                                     : (Pass(p) == Pass::Composite ? uint32_t(FFX_DOF_COMPOSITE_CLASS_COUNT) : 1u)));

    const uint32_t compact = FFX_DOF_APERTURE_SHAPES_COMPACT;
    const uint32_t any = FFX_DOF_APERTURE_SHAPES_ANY;
    CHECK(blurApertureShapes(context, nullptr) == compact);
    const FfxDofAperture anamorphic{0, 0.0f, 0.0f, 1.5f, 0.0f};
    CHECK(blurApertureShapes(context, &anamorphic) == compact);
    // Blades whose polygon folds to at most two sides: 3, 4 and 6 (and 0).
    for (uint32_t blades = 3; blades <= FFX_DOF_MAX_APERTURE_BLADES; ++blades) {
        INFO(blades << " blades");
        const FfxDofAperture bladed{blades, 0.3f, 0.2f, 1.0f, 0.0f};
        const bool fits = blades == 3 || blades == 4 || blades == 6;
        CHECK(blurApertureShapes(context, &bladed) == (fits ? compact : any));
        // Any cat's eye takes the general blur, whatever the blades.
        const FfxDofAperture catEye{blades, 0.3f, 0.2f, 1.0f, 0.01f};
        CHECK(blurApertureShapes(context, &catEye) == any);
    }
    // Fully round blades are no blades.
    const FfxDofAperture roundBlades{9, 0.0f, 1.0f, 1.0f, 0.0f};
    CHECK(blurApertureShapes(context, &roundBlades) == compact);

    // A context without the flag has one blur, the circle's, for every dispatch.
    const ContextPlan round = contextPlan(64, 48);
    CHECK(blurApertureShapes(round, nullptr) == 0u);
}

TEST_CASE("the passes' reflected reads and writes form the pipeline's data flow") {
    const uint32_t flags = GENERATE(0u, uint32_t(FFX_DOF_OUTPUT_PRE_INIT));
    const ContextPlan plan = contextPlan(640, 360, flags);
    // Every internal resource a pass reads was written by an earlier pass; the inputs are only read
    // and the output only written (and read in place); the last pass writes the output.
    ResourceSet written = 0;
    for (uint32_t p = 0; p < kPassCount; ++p) {
        const PlannedPass& pass = plan.passes[p];
        INFO("pass " << kPassNames[p]);
        const ResourceSet engineInputs = resourceBit(Resource::InputColor) | resourceBit(Resource::InputDepth);
        CHECK((pass.reads & ~engineInputs & ~written) == 0);
        CHECK((pass.indirect & ~written) == 0);  // dispatch arguments an earlier pass wrote
        CHECK((pass.writes & engineInputs) == 0);
        written |= pass.writes;
    }
    CHECK(plan.passes[uint32_t(Pass::Composite)].writes & resourceBit(Resource::Output));
    CHECK(plan.passes[uint32_t(Pass::DownsampleDepth)].reads & resourceBit(Resource::InputDepth));
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        INFO(kInternalImages[i].name);
        CHECK(written & resourceBit(internalImageResource(i)));
    }
}

TEST_CASE("the slot map binds each MIP slot to its level, the missing levels of a small image to its last") {
    const ContextPlan plan = contextPlan(7, 5);  // half 4x3: its chain has 3 levels, 2 of them coarse
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        const InternalImageSpec& spec = kInternalImages[i];
        const PlannedImage& image = plan.images[i];
        INFO(spec.name);
        CHECK(plan.sampledSlots[spec.sampledSlot].resource == internalImageResource(i));
        CHECK(plan.sampledSlots[spec.sampledSlot].mipCount == image.mipLevels);
        if (spec.levels == 1) continue;
        // COARSE_MIPS, from MIP 1 (2x1), has 2 of its 3 levels.
        REQUIRE(spec.extent == ImageExtent::Quarter);
        const uint32_t levels = 2u;
        CHECK(image.mipLevels == levels);
        for (uint32_t level = 0; level < spec.levels; ++level) {
            const SlotTarget& target = plan.storageImageSlots[spec.storageSlot + level];
            CHECK(target.resource == internalImageResource(i));
            CHECK(target.firstMip == std::min(level, levels - 1));
        }
    }
    CHECK(plan.sampledSlots[FFX_DOF_SRV_INPUT_COLOR].resource == Resource::InputColor);
    CHECK(plan.storageImageSlots[FFX_DOF_UAV_OUTPUT].resource == Resource::Output);
}

TEST_CASE("the storage buffer slots map to their buffers, sized by the tile count") {
    const ContextPlan plan = contextPlan(1920, 1080);  // tiles 120 x 68
    CHECK(plan.storageBufferSlots[FFX_DOF_UAV_BUFFER_GLOBALS].resource == Resource::Globals);
    CHECK(plan.storageBufferSlots[FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS].resource == Resource::TileListArgs);
    CHECK(plan.storageBufferSlots[FFX_DOF_UAV_BUFFER_TILE_LISTS].resource == Resource::TileLists);
    CHECK(plan.storageBufferSlots[FFX_DOF_UAV_BUFFER_HIGHLIGHTS].resource == Resource::Highlights);
    CHECK(kStorageBufferSlotCount == 4);
    // The byte counts of docs/technique.md's table of internal resources.
    CHECK(plan.tileListsBytes == 163200u);
    CHECK(plan.highlightsBytes == 456960u);
    // The smallest context still has one tile of highlights: four slots of three words, the floor and the peak.
    CHECK(contextPlan(1, 1).highlightsBytes == 56u);
}

TEST_CASE("the internal resources at 1080p hold the bytes of docs/technique.md's table, within the 10 MB budget") {
    ContextConfig config;
    config.resolution = {1920, 1080};
    config.quality = 10;
    config.cocLimitFactor = 0.05f;
    // The table's total (its Python command); a backend reports at least this (the Vulkan tests check it on the
    // device, and the budget where the device lays images out linearly).
    CHECK(internalResourceBytes(config) == 9887248u);
    CHECK(internalResourceBytes(config) <= 10u * 1000u * 1000u);
    // Neither the quality nor the CoC limit sizes anything.
    config.quality = 32;
    config.cocLimitFactor = 0.3f;
    CHECK(internalResourceBytes(config) == 9887248u);
    // A 1 x 1 context: a texel of each image at each of its levels (one), one tile of lists and highlights.
    config.resolution = {1, 1};
    CHECK(internalResourceBytes(config) == 4u + 2u + 8u + 8u + 8u + 4u + 4u + 1u + kGlobalsBufferBytes +
                                               kTileListArgsBytes + tileListsWordCount(1, 1) * 4u +
                                               highlightsWordCount(1, 1) * 4u);
}

TEST_CASE("a backend without a pass's shaders, or without its permutation, cannot make a context") {
    ContextConfig config;
    config.resolution = {64, 64};
    config.quality = 4;
    BackendCapabilities capabilities = testing::glslCapabilities();
    capabilities.tables[uint32_t(Pass::Blur)] = nullptr;
    ContextPlan plan;
    CHECK(buildContextPlan(config, capabilities, &plan) == FFX_DOF_ERROR_UNSUPPORTED);
    CHECK(std::string(ffxDofGetLastErrorMessage()).find("blur") != std::string::npos);

    // A table of another pass has other axes: the key of this pass is not in it.
    capabilities = testing::glslCapabilities();
    capabilities.tables[uint32_t(Pass::DownsampleColor)] = capabilities.tables[uint32_t(Pass::DownsampleDepth)];
    CHECK(buildContextPlan(config, capabilities, &plan) == FFX_DOF_ERROR_UNSUPPORTED);
    CHECK(std::string(ffxDofGetLastErrorMessage()).find("downsample_color") != std::string::npos);
}

TEST_CASE("per-frame values are copied into the constants") {
    const DispatchPlan p = plan(64, 64).dispatch;
    CHECK(p.constants.cocScale == -3.0f);
    CHECK(p.constants.cocBias == 2.0f);
    CHECK(p.constants.maxRings == 10);
    CHECK(p.constants.frameIndex == 7);
    CHECK(p.constants.outputFlags == 0);
}

TEST_CASE("the autofocus readback ring answers for the dispatches it keeps") {
    AutofocusReadbackRing ring(2);  // maxFramesInFlight 2: 3 slots
    REQUIRE(ring.slotCount() == 3);
    float values[3] = {};
    float distance = 0.0f;
    CHECK(ring.read(0, values, &distance) == FFX_DOF_ERROR_INVALID_ARGUMENT);  // nothing recorded yet

    values[ring.record(true)] = -2.0f;   // dispatch 0
    values[ring.record(false)] = 99.0f;  // dispatch 1: no autofocus, its slot holds nothing
    values[ring.record(true)] = -4.0f;   // dispatch 2
    REQUIRE(ring.read(0, values, &distance) == FFX_DOF_OK);
    CHECK(distance == 4.0f);  // positive, whatever the sign of view z
    CHECK(ring.read(1, values, &distance) == FFX_DOF_ERROR_INVALID_ARGUMENT);
    CHECK(std::string(ffxDofGetLastErrorMessage()).find("did not run autofocus") != std::string::npos);
    REQUIRE(ring.read(2, values, &distance) == FFX_DOF_OK);
    CHECK(distance == 2.0f);
    CHECK(ring.read(3, values, &distance) == FFX_DOF_ERROR_INVALID_ARGUMENT);  // further than kept

    // Dispatch 3 reuses dispatch 0's slot: dispatch 0 is no longer there.
    values[ring.record(true)] = -8.0f;
    REQUIRE(ring.read(0, values, &distance) == FFX_DOF_OK);
    CHECK(distance == 8.0f);
    REQUIRE(ring.read(1, values, &distance) == FFX_DOF_OK);
    CHECK(distance == 4.0f);
}

TEST_CASE("the aperture's constants: the round one is the default, shapes set theirs") {
    const Planned round = plan(64, 64);
    FfxDofDispatchDescription dispatch{};
    dispatch.cocScale = -3.0f;
    dispatch.cocBias = 2.0f;
    const FfxDofAperture explicitRound{0, 1.0f, 0.5f, 1.0f, 0.0f};
    dispatch.pAperture = &explicitRound;
    const DispatchPlan same = planDispatch(round.context, dispatch, 7);
    CHECK(std::memcmp(&same.constants, &round.dispatch.constants, sizeof(FfxDofConstants)) == 0);

    // A hexagon turned 30 degrees, half round, 1.5 times taller than wide, with cat's eye.
    const float rotation = 0.5235988f;
    const FfxDofAperture hexagon{6, rotation, 0.5f, 1.5f, 0.25f};
    dispatch.pAperture = &hexagon;
    const FfxDofConstants c = planDispatch(round.context, dispatch, 7).constants;
    const double polygonInradius = std::cos(3.14159265358979 / 6.0);
    const double inradius = polygonInradius + 0.5 * (1.0 - polygonInradius);
    CHECK(c.bladeCount == 6u);
    CHECK(c.bladeNormal.x == Approx(std::cos(rotation) / inradius));
    CHECK(c.bladeNormal.y == Approx(std::sin(rotation) / inradius));
    CHECK(c.anamorphicRatio == 1.5f);
    CHECK(c.catEye == 0.25f);
    // pi over the shape's area (the circle less six segments beyond the sides), times the ratio.
    const double segment = std::acos(inradius) - inradius * std::sqrt(1.0 - inradius * inradius);
    CHECK(c.apertureAreaScale == Approx(3.14159265358979 / (3.14159265358979 - 6.0 * segment) * 1.5));
    // Fully round blades are the circle: no blade loop.
    const FfxDofAperture roundBlades{6, rotation, 1.0f, 1.0f, 0.0f};
    dispatch.pAperture = &roundBlades;
    CHECK(planDispatch(round.context, dispatch, 7).constants.bladeCount == 0u);
}
