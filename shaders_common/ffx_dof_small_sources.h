// Where small bright far sources are drawn at full resolution: the one decision the blur and the
// composite share (see docs/technique.md, "Small far sources").
//
// A far pixel whose radius is below FFX_DOF_FAR_LAYER_ONLY_RADIUS blurs itself at full resolution in
// the composite, while the background around it shows the half-res layers, where such a light is a
// disc of a texel or two: what it spreads onto that background is lost or doubled (a 1 px light at
// 2 px kept half its energy). Where a tile may hold such sources bright enough to matter, the blur
// leaves them out of its layers (ffxDofSmallSourceShare, ffxDofOwnGatherShare) and the composite draws
// them at full resolution (ffxDofGatherSmallSources). Elsewhere both passes keep the cheaper half-res
// path: the composite's full-res gather loops over 13 x 13 pixels, which made it 1.4 times as long
// over a band of small radii where it ran everywhere (docs/performance.md).
//
// Dilate decides it once per tile for both passes (ffxDofSurveyTilesAround, in their list entries), so what one
// leaves out the other draws.
#ifndef FFX_DOF_SMALL_SOURCES_H
#define FFX_DOF_SMALL_SOURCES_H

#include "ffx_dof_common.h"

// Small far sources whose largest channel is at most this (display white, in the input's units) stay
// on the half-res path: below white, what a lost or doubled share changes is a fraction of the
// surrounding level, within the half-res path's own error.
#define FFX_DOF_SMALL_SOURCE_MIN_PEAK 1.0f

// Whether a tile of (min, max) signed radius and colour peak `rangeAndPeak` (ffxDofTileRangeAndPeak) may hold far
// pixels of radius below FFX_DOF_FAR_LAYER_ONLY_RADIUS and a channel above FFX_DOF_SMALL_SOURCE_MIN_PEAK (not
// necessarily the same pixels: the test is a tile's, conservative).
FFX_DOF_INLINE FfxBoolean ffxDofTileMayHoldBrightSmallSources(FfxFloat32x3 rangeAndPeak)
{
    return rangeAndPeak.z > FFX_DOF_SMALL_SOURCE_MIN_PEAK && rangeAndPeak.x <= -FFX_DOF_IN_FOCUS_RADIUS &&
           rangeAndPeak.y > -FFX_DOF_FAR_LAYER_ONLY_RADIUS;
}

// The `k`th (0..8, row by row) of the 3 x 3 tiles around `tile`, clamped to the image.
FFX_DOF_INLINE FfxUInt32x2 ffxDofTileAround(FfxUInt32x2 tile, FfxUInt32 k, FfxUInt32x2 tileCount)
{
    return FfxUInt32x2(clamp(FfxInt32x2(tile) + FfxInt32x2(FfxInt32(k % 3u) - 1, FfxInt32(k / 3u) - 1),
                             FfxInt32x2(0, 0), FfxInt32x2(tileCount) - FfxInt32x2(1, 1)));
}

#endif  // FFX_DOF_SMALL_SOURCES_H
