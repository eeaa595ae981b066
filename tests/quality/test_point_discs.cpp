// Issue 17's disc-shape gates: a single bright far point on black at radii from 2 full-res px to the
// CoC limit of 1080p's default (0.05 of the height: 54 px), at sub-pixel positions that put it at
// every corner of the 2 x 2 quads of the half-res downsample and inside a tile, with ring merging on
// and off. The truth of a one-pixel point is a flat disc of the thin-lens radius holding the
// point's energy; each disc's radius, flatness, centre, rim and glow are held against it.
#include "quality_scenes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace ffxdof;

// One test case for every gate of the far discs: CTest runs each test case in a process of its own, and four
// of them rendered the 100 discs four times (33 s each in CI).
//
// Rim: measured at most 0.51 either way. With merging, inner rings read the point from the coarser MIP texel holding
// it, up to 0.7 half-res px off; until the rim border moved in where they meet the outermost ring
// (ffxDofWalkBorderRadius), the disc bulged 1.29 px toward that texel's centre.
// Glow: until 2026-11-30 every radius from 6 px on measured 0.08 to 0.16 of the disc's level there: the far layer is
// half-res and upsampled bilinearly, so its rim spread over one more half-res texel (2 full-res px) beyond the
// disc. Far highlights drawn at full resolution (ffx_dof_highlights.h) took it to 0 from 8 px on, and since they
// start where the layers would draw part of a pixel's own light (FFX_DOF_HIGHLIGHT_FULL_RADIUS), at 4.5 and 6 px
// too (0.036 and 0.115 until then).
TEST_CASE(
    "point discs: radius within 1 px, energy within 5%, flat with no dip at the centre, the rim within 1 px of a "
    "circle at 64 angles and no glow beyond R + 1.5 px, at every radius and offset, ring merging on and off",
    "[quality][vulkan][discs]") {
    quality::validatedDevice().clearValidationMessages();
    for (const quality::PointDiscCase& c : quality::runPointDiscCases(quality::validatedDevice())) {
        INFO(c.describe());
        CHECK(c.radiusOk());
        CHECK(c.energyOk());
        CHECK(c.flatOk());
        CHECK(c.noCentreDip());
        CHECK(c.rimOk());
        CHECK(c.glowOk());
    }
    CHECK(quality::validatedDevice().validationMessages().empty());
}

// The near field's point discs (docs/quality.md, near point discs), held to the far discs' gates. Until
// 2026-11-30 they were drawn from the half-res near layer: discs 1.3 to 1.9 px small, a glow of up to 0.14 of
// the level beyond R + 1.5 px, not flat below 8 px, and 0.81 of the light at 4.5 px. Near highlights
// (ffx_dof_highlights.h) now draw a point brighter than white at full resolution, as far ones.
TEST_CASE("near point discs: radius, energy, flatness, centre, rim and glow as the far discs'",
          "[quality][vulkan][discs]") {
    quality::validatedDevice().clearValidationMessages();
    for (const quality::PointDiscCase& c : quality::runNearPointDiscCases(quality::validatedDevice())) {
        INFO(c.describe());
        CHECK(c.radiusOk());
        CHECK(c.energyOk());
        CHECK(c.flatOk());
        CHECK(c.noCentreDip());
        CHECK(c.rimOk());
        CHECK(c.glowOk());
    }
    CHECK(quality::validatedDevice().validationMessages().empty());
}
