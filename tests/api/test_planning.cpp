// Dispatch planning: constants and workgroup counts for awkward sizes (rounding must be symmetric and
// cover every pixel, tile and half-resolution texel exactly once).
#include "ffx_dof_context.h"

#include <catch2/catch.hpp>

using namespace ffxdof;

namespace {

DispatchPlan plan(uint32_t width, uint32_t height, uint32_t flags = 0, float cocLimitFactor = 0.05f) {
    ContextConfig config;
    config.resolution = {width, height};
    config.flags = flags;
    config.quality = 10;
    config.cocLimitFactor = cocLimitFactor;
    FfxDofDispatchDescription dispatch{};
    dispatch.cocScale = -3.0f;
    dispatch.cocBias = 2.0f;
    return planDispatch(config, dispatch, 7);
}

uint32_t ceilDiv(uint32_t a, uint32_t b) { return (a + b - 1) / b; }

}  // namespace

TEST_CASE("half resolution and tile counts round up in both directions") {
    const auto [width, height] = GENERATE(table<uint32_t, uint32_t>(
        {{1, 1}, {7, 5}, {16, 16}, {17, 15}, {641, 479}, {1920, 1080}, {4096, 2160}, {16384, 3}}));
    const DispatchPlan p = plan(width, height);
    const FfxDofConstants& c = p.constants;
    CHECK(c.fullSize.x == width);
    CHECK(c.fullSize.y == height);
    CHECK(c.halfSize.x == (width + 1) / 2);
    CHECK(c.halfSize.y == (height + 1) / 2);
    CHECK(c.tileCount.x == ceilDiv(c.halfSize.x, FFX_DOF_TILE_SIZE));
    CHECK(c.tileCount.y == ceilDiv(c.halfSize.y, FFX_DOF_TILE_SIZE));
    CHECK(c.halfTexelSize.x == Approx(1.0 / c.halfSize.x));
    CHECK(c.fullTexelSize.y == Approx(1.0 / height));

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
        const PassGrid grid = p.passes[uint32_t(pass.pass)];
        CHECK(grid.x * pass.extent >= pass.domainWidth);
        CHECK(grid.y * pass.extent >= pass.domainHeight);
        CHECK((grid.x - 1) * pass.extent < pass.domainWidth);
        CHECK((grid.y - 1) * pass.extent < pass.domainHeight);
        CHECK(grid.z == 1);
    }
}

TEST_CASE("the CoC limit is the factor times the height, in half-resolution pixels") {
    CHECK(plan(1920, 1080, 0, 0.05f).constants.cocLimit == Approx(27.0f));
    CHECK(plan(1920, 1080, 0, 0.01f).constants.cocLimit == Approx(5.4f));
    CHECK(plan(1920, 1080, 0, 0.0f).constants.cocLimit == 0.0f);
}

TEST_CASE("flags select the permutation options") {
    CHECK(plan(64, 64).options.reverseDepth == 0);
    CHECK(plan(64, 64).options.ringMergeLog == 1);
    CHECK(plan(64, 64).options.combineInPlace == 0);
    CHECK(plan(64, 64, FFX_DOF_REVERSE_DEPTH).options.reverseDepth == 1);
    CHECK(plan(64, 64, FFX_DOF_DISABLE_RING_MERGE).options.ringMergeLog == 0);
    CHECK(plan(64, 64, FFX_DOF_OUTPUT_PRE_INIT).options.combineInPlace == 1);
}

TEST_CASE("per-frame values are copied into the constants") {
    const DispatchPlan p = plan(64, 64);
    CHECK(p.constants.cocScale == -3.0f);
    CHECK(p.constants.cocBias == 2.0f);
    CHECK(p.constants.maxRings == 10);
    CHECK(p.constants.frameIndex == 7);
    CHECK(p.constants.outputFlags == 0);
}
