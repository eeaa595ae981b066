// Pass 5 of 5: composition at full resolution.
//
// One workgroup covers one tile (16 x 16 full-res px); each invocation writes a 2 x 2 quad. The pass runs
// one pipeline per class of tiles (ffx_dof_tile_classes.h), each an indirect dispatch over the tiles
// dilate listed under that class (TILE_LISTS): no workgroup runs for a tile another class composes.
//   1. A tile that is in focus and that no near-field blur reaches (class COPY) is copied (with
//      FFX_DOF_OPTION_OUTPUT_PRE_INIT not dispatched at all): exactly what the per-pixel path would do.
//   2. The group loads the 12 x 12 half-res texels around the tile (with a summary per texel that the
//      post-filter reads of each neighbour in one read) and post-filters the 10 x 10 that bilinear
//      upsampling touches, once per texel: luminance of near and far color clamped to the
//      range of the 8 neighbours (an outlier filter that keeps edges and energy),
//      3x3 average of near opacity, the opacity it adds in its neighbours' colour (ffxDofPostFilterTexel).
//   3. Per pixel: CoC from depth (32-bit); in focus and not covered by the near field -> the input,
//      bit for bit. Otherwise: near layer upsampled bilinearly (where a corner has zero opacity, the
//      pixel takes the near layer alone over what it shows without it: the rim of a near disc); far
//      layer upsampled joint-bilaterally (taps weighted by validity and by how well their CoC matches
//      the pixel's, so a sharp foreground never spills into the blurred background). Layers blended so
//      that the combined blur has the variance of the pixel's disc (ffxDofDiscVariance): the fixed 3x3
//      blur is mixed into the input by the radius, alone from
//      |radius| 0.76 half-res px (ffxDofFixedBlurBlend; left out under a near-field opacity above
//      FFX_DOF_NEAR_BLOCKS_FIXED_BLUR, where it would spread foreground color), the far layer over
//      it, alone from FFX_DOF_FAR_LAYER_ONLY_RADIUS (ffxDofFarBlend), and the near layer on top
//      (ffxDofNearLayerWeight). Between FFX_DOF_OWN_SURFACE_MIN_RADIUS and FFX_DOF_FAR_LAYER_ONLY_RADIUS the
//      pixel's own surface is instead gathered at full resolution from a 30 x 30 neighbourhood the
//      group loads once (a quad at a time: ffxDofGatherOwnSurfaceQuad), the far layer showing where it does not
//      cover the disc (near pixels too: their far layer is the background the blur extrapolates
//      behind them; a near pixel takes the layers by the square of what it leaves uncovered), and
//      handing over to the layers over the last half-res px. Only the FULL_RES and
//      LIGHTS classes gather their own surface at full resolution, and only LIGHTS draws the small sources at full
//      resolution and the highlights pass 2 took out of the layers (ffxDofHighlightsAtQuad, ffx_dof_highlights.h),
//      on the far layer; the LAYERS class's pipeline has none of these, FULL_RES's none of the lights.
// HDR range: the input color is multiplied by the frame's ffxDofColorRangeScale (from GLOBALS, written
// by pass 2) as it is read, in 32-bit, so all the work happens in the range of the half-res layers;
// a composed pixel is divided by the scale when stored (exact for the power-of-two scale unless the
// result is a denormal) and clamped to the largest finite float. Pixels that keep their input are
// stored from the input itself, bit for bit, whatever the scale.
#ifndef FFX_DOF_COMPOSITE_H
#define FFX_DOF_COMPOSITE_H

#include "ffx_dof_common.h"
#include "ffx_dof_tile_classes.h"
#include "ffx_dof_focus.h"
#include "ffx_dof_small_sources.h"
#include "ffx_dof_highlights.h"

#if defined(FFX_CPU)
FfxDofConstants ffxDofGetConstants();
FfxFloat32 ffxDofLoadInputDepth(FfxUInt32x2 pixel);
FfxFloat32x4 ffxDofLoadInputColor(FfxUInt32x2 pixel);
FfxDofFloat3 ffxDofLoadHalfColor(FfxInt32x2 texel);
FfxFloat32x2 ffxDofLoadTile(FfxUInt32x2 tile);
FfxFloat32 ffxDofLoadHalfCoc(FfxInt32x2 texel);
FfxDofFloat3 ffxDofLoadNearColor(FfxInt32x2 texel);
FfxDofFloat3 ffxDofLoadFarColor(FfxInt32x2 texel);
FfxFloat32x2 ffxDofLoadLayerAlpha(FfxInt32x2 texel);
void ffxDofStoreOutput(FfxUInt32x2 pixel, FfxFloat32x4 color);
FfxFloat32 ffxDofLoadColorScale();
#endif

// ---- Tuning constants -------------------------------------------------------------------------------

// Upper bound on the brightness gain of the outlier post-filter.
#define FFX_DOF_OUTLIER_MAX_GAIN 2.0f
// Above this near-field opacity the fixed 3x3 blur is not used (it would spread foreground color).
#define FFX_DOF_NEAR_BLOCKS_FIXED_BLUR 0.3f
// Coverage of the neighbours of a pixel by a disc of diameter 3 px centred on it (edge, corner);
// the centre is covered fully. Numerically integrated; tests/shaders recomputes them.
#define FFX_DOF_FIXED_BLUR_EDGE_WEIGHT 0.9718f
#define FFX_DOF_FIXED_BLUR_CORNER_WEIGHT 0.5454f
// Per-axis variance of that 3x3 kernel, in half-res px^2: (2 * edge + 4 * corner) / (1 + 4 * edge +
// 4 * corner) full-res px^2, divided by 4.
#define FFX_DOF_FIXED_BLUR_VARIANCE 0.1459f
// Per-axis variance, in half-res px^2, that the far layer adds to its disc: the 2x2 downsample box
// (1/12), the bilinear upsample (1/6), the kernel jitter and the half-pixel anti-aliased reach.
#define FFX_DOF_FAR_LAYER_EXTRA_VARIANCE 0.3f
// Below FFX_DOF_FAR_LAYER_ONLY_RADIUS a pixel's own surface is gathered at full resolution
// (ffxDofGatherOwnSurface): the half-res layers, upsampled, blur a disc of a few pixels by half its
// radius again and peak it (the circular gather, which ignores depth, beat them by up to 5 dB there).
// Over the last half-res pixel of radius below the limit the gather hands over to the layers.
#define FFX_DOF_OWN_SURFACE_FADE 1.0f
// Full-res pixels read around the tile: the largest own-surface disc, 2 * 3 + 0.5 rounded up.
#define FFX_DOF_OWN_SURFACE_BORDER 7
#define FFX_DOF_OWN_SURFACE_SIDE (FFX_DOF_COMPOSITE_GROUP_EXTENT + 2 * FFX_DOF_OWN_SURFACE_BORDER)

// Back from the effect's range: exact for a power-of-two scale (unless the result is a denormal),
// clamped to the largest finite float.
FFX_DOF_INLINE FfxFloat32x4 ffxDofUnscaleColor(FfxFloat32x4 color, FfxFloat32 scale)
{
    return FfxFloat32x4(min(color.x / scale, FFX_DOF_FLOAT32_MAX), min(color.y / scale, FFX_DOF_FLOAT32_MAX),
                        min(color.z / scale, FFX_DOF_FLOAT32_MAX), color.w);
}

// ---- Post-filter and composition ----------------------------------------------------------------

// Brightness factor that moves a texel of luminance `centerLuminance` into the luminance range
// [lowest, highest] of its 8 neighbours: only a texel brighter or darker than all of them (the
// undersampling's isolated hot or cold spot) changes. A texel on an edge or a disc's rim lies within
// its neighbours' range and keeps its value, so the bokeh keeps its energy; a 3x3 median, which the
// technique uses, darkened the rims of small discs (a 3 x 3 px sun lost 3% of its energy) and
// softened the near field's edges (busy-background's near field 2.4 dB below this filter). A black
// texel is left unchanged, the gain is bounded.
FFX_DOF_INLINE FfxFloat32 ffxDofOutlierGain(FfxFloat32 centerLuminance, FfxFloat32 lowestNeighbour,
                                            FfxFloat32 highestNeighbour)
{
    if (centerLuminance <= 0.0f)
        return 1.0f;
    FfxFloat32 target = clamp(centerLuminance, lowestNeighbour, highestNeighbour);
    return min(target / centerLuminance, FFX_DOF_OUTLIER_MAX_GAIN);
}

// Blend weight of the near layer from its filtered opacity: the opacity itself, so a thin near
// object's veil is as opaque as the share of the disc it covers and the near layer keeps its energy.
// The technique's cubic (smoothstep) weight made a veil of opacity 0.2 one of 0.1, hardened its
// edges and lost 5% of a near patch's energy; a quadratic toe below 0.1 (against faint stray
// coverage on in-focus surfaces) halved the veils of thin bars at large radii (docs/technique.md).
FFX_DOF_INLINE FfxFloat32 ffxDofNearLayerWeight(FfxFloat32 opacity) { return ffxDofSaturate(opacity); }

// Weight of a neighbour of the fixed 3x3 blur (offsets in -1..1).
FFX_DOF_INLINE FfxFloat32 ffxDofFixedBlurWeight(FfxInt32 dx, FfxInt32 dy)
{
    FfxInt32 taxicab = abs(dx) + abs(dy);
    return taxicab == 0 ? 1.0f : (taxicab == 1 ? FFX_DOF_FIXED_BLUR_EDGE_WEIGHT : FFX_DOF_FIXED_BLUR_CORNER_WEIGHT);
}

// Weights of the 2 x 2 half-res texels around a full-res pixel for bilinear upsampling:
// returns the fractional position (weights of the right / bottom texels) and the top-left texel.
FFX_DOF_INLINE FfxFloat32x2 ffxDofUpsamplePosition(FfxUInt32x2 fullPixel, FFX_DOF_OUT(FfxInt32x2) topLeftTexel)
{
    // Full-res pixel centre in half-res texel space, where texel i has its centre at i.
    FfxFloat32x2 position = (FfxFloat32x2(fullPixel) + FfxFloat32x2(0.5f, 0.5f)) * 0.5f - FfxFloat32x2(0.5f, 0.5f);
    FfxFloat32x2 base = floor(position);
    topLeftTexel = FfxInt32x2(base);
    return position - base;
}

// Joint-bilateral factor of a half-res tap for a full-res pixel: how well the tap's radius matches
// the pixel's. Never exactly 0, so a pixel that matches no tap falls back to plain bilinear weights.
// A far tap for a far pixel weighs at least the smaller radius over the larger, where the tap's far layer
// holds the texel's own surface (its radius from FFX_DOF_FAR_LAYER_ONLY_RADIUS, ramped in over
// FFX_DOF_OWN_SURFACE_FADE below): what far content spreads onto a place does not depend on which far
// surface the pinhole sees there, so such texels hold much the same layers. Judged against half the
// pixel's radius only (as near and in-focus pixels judge theirs), a small far light's pixels and the
// background's around it (6.5 and 16 half-res px) each rejected the other's texels, and on a bright disc's
// rim both took it from texels farther out: the dim light of docs/quality.md's light pair kept 0.912 to
// 0.936 of its energy instead of 0.921 to 0.939, busy-background's halo band 0.36 dB less. The far layer of
// a texel of smaller radius leaves out the surface the composite gathers at full resolution
// (ffxDofOwnGatherShare): background pixels that took it drew a light of 2 or 3 px at radius 0.8 twice
// (1.05 to 1.08 of its energy). Plain bilinear between far taps drew a light at radius 6 px twice too
// (1.047).
FFX_DOF_INLINE FfxFloat32 ffxDofUpsampleCocWeight(FfxFloat32 tapCoc, FfxFloat32 pixelCoc)
{
    FfxFloat32 tolerance = max(1.0f, 0.5f * abs(pixelCoc));
    FfxFloat32 weight = ffxDofSaturate(1.0f - abs(tapCoc - pixelCoc) / tolerance);
    if (tapCoc <= -FFX_DOF_IN_FOCUS_RADIUS && pixelCoc <= -FFX_DOF_IN_FOCUS_RADIUS)
    {
        FfxFloat32 tapHoldsOwnSurface =
            ffxDofSaturate(-tapCoc - FFX_DOF_FAR_LAYER_ONLY_RADIUS + FFX_DOF_OWN_SURFACE_FADE);
        weight = max(weight, tapHoldsOwnSurface * max(tapCoc, pixelCoc) / min(tapCoc, pixelCoc));
    }
    return max(weight, 1e-3f);
}

// Blend weights of the layers below the near field, from the pixel's |radius| (half-res px). The
// layers are blended so that the second moment of the combined kernel (mixing kernels adds their
// variances, weighted) matches that of the pixel's disc, |radius|^2 / 4 per axis: the fixed 3x3 blur
// (FFX_DOF_FIXED_BLUR_VARIANCE) is mixed into the input until it alone is right, then the far layer
// (the disc plus FFX_DOF_FAR_LAYER_EXTRA_VARIANCE from half-res processing) into the fixed blur.
// Any other choice blurs the small radii behind the focus too little or too much.
FFX_DOF_INLINE FfxFloat32 ffxDofDiscVariance(FfxFloat32 absCoc) { return 0.25f * absCoc * absCoc; }
FFX_DOF_INLINE FfxFloat32 ffxDofFixedBlurBlend(FfxFloat32 absCoc, FfxFloat32 nearOpacity)
{
    return nearOpacity > FFX_DOF_NEAR_BLOCKS_FIXED_BLUR
               ? 0.0f
               : ffxDofSaturate(ffxDofDiscVariance(absCoc) / FFX_DOF_FIXED_BLUR_VARIANCE);
}
FFX_DOF_INLINE FfxFloat32 ffxDofFarBlend(FfxFloat32 absCoc, FfxFloat32 farValidity)
{
    FfxFloat32 excess = ffxDofDiscVariance(absCoc) - FFX_DOF_FIXED_BLUR_VARIANCE;
    FfxFloat32 matched = excess / max(excess + FFX_DOF_FAR_LAYER_EXTRA_VARIANCE, 1e-6f);
    // From a radius of 2 the mixture's sharp remainder shows more than the excess spread: fade it out.
    return ffxDofSaturate(max(matched, absCoc - FFX_DOF_FAR_LAYER_ONLY_RADIUS + 1.0f)) * farValidity;
}

#define FFX_DOF_RAW_SIDE 12       // half-res texels loaded per side: tile + 2 each side
#define FFX_DOF_FILTERED_SIDE 10  // half-res texels filtered per side: tile + 1 each side
#if FFX_DOF_FILTERED_SIDE != FFX_DOF_GROUP_SIDE + 2 || 4 * (FFX_DOF_FILTERED_SIDE - 1) > FFX_DOF_GROUP_THREADS
#error "the filtered grid must be the group's quads' block centres and a ring of at most a texel an invocation"
#endif
#if FFX_DOF_RAW_SIDE != FFX_DOF_FILTERED_SIDE + 2 || 8 * (FFX_DOF_RAW_SIDE - 2) > 2 * FFX_DOF_GROUP_THREADS
#error "the raw grid must be the block centres' raw texels and two rings of at most two texels an invocation"
#endif

// The raw near and far colours as 16-bit floats, whatever the permutation's precision: exact, since
// NEAR_COLOR and FAR_COLOR are B10G11R11 floats (5-bit exponents like a half's, 6 or 5 mantissa bits),
// and 8 bytes instead of 12 per colour in 32-bit keep the full-resolution class's group-shared memory
// under the 16 KiB that every Vulkan device has, with the summaries below.
FFX_DOF_GROUPSHARED FfxUInt32x2 ffxDofSharedRawNear[FFX_DOF_RAW_SIDE * FFX_DOF_RAW_SIDE];
FFX_DOF_GROUPSHARED FfxUInt32x2 ffxDofSharedRawFar[FFX_DOF_RAW_SIDE * FFX_DOF_RAW_SIDE];
// Per raw texel what the post-filter reads of each of its neighbours, in one read of two words
// (ffxDofPackRawSummary): the luminance of its near and far colour, its near opacity and far validity.
FFX_DOF_GROUPSHARED FfxUInt32x2 ffxDofSharedRawSummary[FFX_DOF_RAW_SIDE * FFX_DOF_RAW_SIDE];
// The post-filtered texels, which each quad's upsample reads for 8 texels (ffxDofStoreFilteredTexel): the near colour
// with the far validity, the far colour with the radius, each as four halves in two words, and the near opacity. On
// lavapipe a group-shared read is a loop over the lanes that moves one 32-bit component at a time: five components a
// texel instead of nine (32-bit) or seven (16-bit; docs/performance.md, "Filtered texels in five words"). Validity (0
// or 1) and radius (from HALF_COC) are exact as halves, and so are the 16-bit permutations' colours; the 32-bit ones
// round theirs to 11 significant bits, as a half-float layer image between two passes would, far below the 6 and 5
// bits of the B10G11R11 layers they are filtered from.
FFX_DOF_GROUPSHARED FfxUInt32x2 ffxDofSharedNear[FFX_DOF_FILTERED_SIDE * FFX_DOF_FILTERED_SIDE];
FFX_DOF_GROUPSHARED FfxUInt32x2 ffxDofSharedFar[FFX_DOF_FILTERED_SIDE * FFX_DOF_FILTERED_SIDE];
FFX_DOF_GROUPSHARED FfxFloat32 ffxDofSharedOpacity[FFX_DOF_FILTERED_SIDE * FFX_DOF_FILTERED_SIDE];
// Per tile of the 9 around the group's (ffxDofTileAround): its highlights' floors (ffxDofLoadGivenHighlightFloors:
// ffxDofNoHighlightFloors for a tile whose pixels gave no light).
FFX_DOF_GROUPSHARED FfxUInt32 ffxDofSharedTilesAround[9];
// Which tiles of the highlights' window hold one (ffxDofTileHoldsHighlights), a bit each in window order, and
// whether any does.
FFX_DOF_GROUPSHARED FfxUInt32 ffxDofSharedHighlightTiles[FFX_DOF_HIGHLIGHT_WINDOW_WORDS];
FFX_DOF_GROUPSHARED FfxUInt32 ffxDofSharedHighlightsInReach;
// Full-res input around the tile for the own-surface gather: per pixel its scaled color and |radius|
// in full-res px as four 16-bit floats in 8 bytes, whatever the permutation's precision. The gather
// reads this array 50 to 150 times per pixel: one 8-byte read instead of a color and a radius, and a
// smaller array lets more groups share a compute unit (on an H200 the pass took 0.19 instead of
// 0.27 ms at 1080p in 16-bit, 0.26 instead of 0.48 ms in 32-bit; docs/performance.md). The color is
// at most FFX_DOF_COLOR_RANGE_LIMIT after scaling, well inside the 16-bit range. Two pixels of a row
// share an element (the even one in xy, the odd one in zw), so that the quads' gathers read two samples
// at a time: on lavapipe a group-shared read whose address differs per lane is a loop over the lanes,
// whatever its width (docs/performance.md, "Own samples two at a time").
#if (FFX_DOF_OWN_SURFACE_SIDE % 2) != 0
#error "the own-surface neighbourhood's rows must hold whole pairs of pixels"
#endif
FFX_DOF_GROUPSHARED FfxUInt32x4 ffxDofSharedOwnSamplePairs[FFX_DOF_OWN_SURFACE_SIDE * FFX_DOF_OWN_SURFACE_SIDE / 2];

// The lowest mantissa bit of the stored |radius| says whether the pixel is in the far field, which only
// ffxDofGatherSmallSources asks: a sign the own-surface gather would take abs() of per read made the
// pass about 10% slower on lavapipe, while the bit moves the radius by at most one unit in the last
// place of a half (0.004 px at 4 px).
#define FFX_DOF_OWN_SAMPLE_FAR_BIT 0x10000u

FFX_DOF_INLINE FfxUInt32x2 ffxDofPackOwnSample(FfxFloat32x3 color, FfxFloat32 radius)
{
    FfxUInt32 blueRadius = ffxDofPackHalf2(FfxFloat32x2(color.z, abs(radius)));
    blueRadius = (blueRadius & ~FFX_DOF_OWN_SAMPLE_FAR_BIT) | (radius < 0.0f ? FFX_DOF_OWN_SAMPLE_FAR_BIT : 0u);
    return FfxUInt32x2(ffxDofPackHalf2(FfxFloat32x2(color.x, color.y)), blueRadius);
}

// Color in xyz, |radius| (full-res px) in w.
FFX_DOF_INLINE FfxFloat32x4 ffxDofUnpackOwnSample(FfxUInt32x2 packed)
{
    FfxFloat32x2 redGreen = ffxDofUnpackHalf2(packed.x);
    FfxFloat32x2 blueRadius = ffxDofUnpackHalf2(packed.y);
    return FfxFloat32x4(redGreen.x, redGreen.y, blueRadius.x, blueRadius.y);
}

FFX_DOF_INLINE FfxBoolean ffxDofPackedOwnSampleIsFar(FfxUInt32x2 packed)
{
    return (packed.y & FFX_DOF_OWN_SAMPLE_FAR_BIT) != 0u;
}

// The samples of pixels 2 `pair` and 2 `pair` + 1 of the neighbourhood, one read; `odd` picks one of them.
FFX_DOF_INLINE FfxUInt32x4 ffxDofLoadOwnSamplePair(FfxUInt32 pair) { return ffxDofSharedOwnSamplePairs[pair]; }
FFX_DOF_INLINE FfxUInt32x2 ffxDofOwnSampleOfPair(FfxUInt32x4 pair, FfxBoolean odd)
{
    return odd ? FfxUInt32x2(pair.z, pair.w) : FfxUInt32x2(pair.x, pair.y);
}

FFX_DOF_INLINE void ffxDofStoreOwnSamplePair(FfxUInt32 pair, FfxUInt32x2 even, FfxUInt32x2 odd)
{
    ffxDofSharedOwnSamplePairs[pair] = FfxUInt32x4(even.x, even.y, odd.x, odd.y);
}

// One pixel's sample, its pair's other pixel left as it is: word by word, so that two invocations may store
// the two pixels of a pair.
FFX_DOF_INLINE void ffxDofStoreOwnSample(FfxUInt32 index, FfxFloat32x3 color, FfxFloat32 radius)
{
    FfxUInt32x2 packed = ffxDofPackOwnSample(color, radius);
    FfxUInt32 word = (index & 1u) * 2u;
    ffxDofSharedOwnSamplePairs[index >> 1u][word] = packed.x;
    ffxDofSharedOwnSamplePairs[index >> 1u][word + 1u] = packed.y;
}

FFX_DOF_INLINE FfxUInt32x2 ffxDofLoadPackedOwnSample(FfxUInt32 index)
{
    return ffxDofOwnSampleOfPair(ffxDofLoadOwnSamplePair(index >> 1u), (index & 1u) != 0u);
}

// Pixel `index`'s sample: color in xyz, |radius| (full-res px) in w.
FFX_DOF_INLINE FfxFloat32x4 ffxDofLoadOwnSample(FfxUInt32 index)
{
    return ffxDofUnpackOwnSample(ffxDofLoadPackedOwnSample(index));
}

FFX_DOF_INLINE FfxBoolean ffxDofOwnSampleIsFar(FfxUInt32 index)
{
    return ffxDofPackedOwnSampleIsFar(ffxDofLoadPackedOwnSample(index));
}

#if FFX_DOF_OPTION_OUTPUT_PRE_INIT
// In place the output image is the input: other workgroups write their tiles during this pass, and
// this group writes its own. So the group reads the input only for its own tile, into group-shared
// memory before any write, and takes the pixels just outside the tile (the fixed 3x3 blur's border)
// from MIP 0 of the half-res color, which nobody writes. On D3D12 the reads go through the output UAV
// (ffx_dof_callbacks_hlsl.h); on Vulkan through the sampled view of the same GENERAL-layout image.
// The difference to out of place: the fixed blur of the tile's border pixels sees half-res color
// for its outer neighbours (bilateral 2x2 averages): documented in docs/technique.md and bounded by
// the in-place test of tests/quality.
FFX_DOF_GROUPSHARED FfxFloat32x4 ffxDofSharedInput[FFX_DOF_COMPOSITE_GROUP_EXTENT * FFX_DOF_COMPOSITE_GROUP_EXTENT];
#endif

FFX_DOF_INLINE FfxInt32x2 ffxDofClampHalfTexel(FfxInt32x2 texel, FfxUInt32x2 halfSize)
{
    return clamp(texel, FfxInt32x2(0, 0), FfxInt32x2(halfSize) - FfxInt32x2(1, 1));
}

// The radius of a full-res pixel (inside the image), from the input depth.
FFX_DOF_INLINE FfxFloat32 ffxDofLoadPixelCoc(FfxUInt32x2 pixel, FfxDofConstants constants)
{
    return ffxDofCocFromDepth(ffxDofLoadInputDepth(pixel), constants.cocScale, constants.cocBias, constants.cocLimit);
}

// The radius of the full-res pixel at a point (px), the image continued by its edge pixels.
FFX_DOF_INLINE FfxFloat32 ffxDofLoadPixelCocAt(FfxFloat32x2 position, FfxDofConstants constants)
{
    return ffxDofLoadPixelCoc(FfxUInt32x2(clamp(FfxInt32x2(floor(position)), FfxInt32x2(0, 0),
                                                FfxInt32x2(constants.fullSize) - FfxInt32x2(1, 1))),
                              constants);
}

// The far depths in front of a far highlight of |radius| `highlightRadius` (half-res px) at `lightCentre` that the
// walk from the light to a quad's centre `quadCentre` (full-res px) meets (ffx_dof_highlights.h, "What lies between
// a pixel and a light"): the first two, 0 where it meets fewer. A quad's four pixels lie within 0.71 px of its
// centre, so their segments cross the same surfaces but at their very ends; each pixel tries them itself
// (ffxDofHighlightVisibilityPast), and the walk is a quad's, not a pixel's.
FFX_DOF_INLINE FfxFloat32x2 ffxDofHighlightDepthsMet(FfxFloat32x2 quadCentre, FfxFloat32x2 lightCentre,
                                                     FfxFloat32 highlightRadius, FfxDofConstants constants)
{
    FfxFloat32x2 met = FfxFloat32x2(0.0f, 0.0f);
    FfxFloat32x2 toQuad = quadCentre - lightCentre;
    FfxUInt32 steps = ffxDofHighlightWalkSteps(toQuad);
    FFX_DOF_LOOP
    for (FfxUInt32 step = 0u; step < steps; ++step)
    {
        FfxFloat32 surface =
            ffxDofLoadPixelCocAt(lightCentre + toQuad * ((FfxFloat32(step) + 0.5f) / FfxFloat32(steps)), constants);
        if (!ffxDofHighlightMayCross(surface, highlightRadius) || surface == met.x || surface == met.y)
            continue;
        if (met.x != 0.0f)
        {
            met.y = surface;
            break;
        }
        met.x = surface;
    }
    return met;
}

// How much of a far highlight of |radius| `highlightRadius` (half-res px) at `lightCentre` reaches the pixel at
// `pixelCentre` (full-res px) whose own surface has radius `pixelCoc`, past what lies in front of the light: where
// the pixel's own surface lies in front of it, as far as that surface lets it through (ffxDofHighlightBlockerPoint);
// else none where a far depth met on the way to the light (`depthsMet`, ffxDofHighlightDepthsMet) lies at its own
// crossing point on the segment from the pixel to the light, all otherwise.
FFX_DOF_INLINE FfxFloat32 ffxDofHighlightVisibilityPast(FfxFloat32x2 pixelCentre, FfxFloat32x2 lightCentre,
                                                        FfxFloat32 pixelCoc, FfxFloat32 highlightRadius,
                                                        FfxFloat32x2 depthsMet, FfxDofConstants constants)
{
    FfxFloat32x2 blocker;
    if (ffxDofHighlightBlockerPoint(pixelCentre, lightCentre, pixelCoc, highlightRadius, blocker))
        return ffxDofHighlightVisibility(ffxDofLoadPixelCocAt(blocker, constants), highlightRadius);
    FFX_DOF_UNROLL
    for (FfxUInt32 j = 0u; j < 2u; ++j)
    {
        if (depthsMet[j] == 0.0f)
            continue;
        ffxDofHighlightBlockerPoint(pixelCentre, lightCentre, depthsMet[j], highlightRadius, blocker);
        if (ffxDofHighlightCrossed(ffxDofLoadPixelCocAt(blocker, constants), depthsMet[j]))
            return 0.0f;
    }
    return 1.0f;
}

// A colour and one more value as four halves in two words (the raw colours' fourth half is 0; the filtered texels',
// ffxDofStoreFilteredTexel, holds the far validity or the radius).
FFX_DOF_INLINE FfxUInt32x2 ffxDofPackColorAnd(FfxDofFloat3 color, FfxFloat32 extra)
{
    return FfxUInt32x2(ffxDofPackHalf2(FfxFloat32x2(FfxFloat32(color.x), FfxFloat32(color.y))),
                       ffxDofPackHalf2(FfxFloat32x2(FfxFloat32(color.z), extra)));
}
FFX_DOF_INLINE FfxFloat32 ffxDofUnpackExtraOf(FfxUInt32x2 packed) { return ffxDofUnpackHalf2(packed.y).y; }

FFX_DOF_INLINE FfxUInt32x2 ffxDofPackRawColor(FfxDofFloat3 color) { return ffxDofPackColorAnd(color, 0.0f); }
FFX_DOF_INLINE FfxDofFloat3 ffxDofUnpackRawColor(FfxUInt32x2 packed)
{
    FfxFloat32x2 redGreen = ffxDofUnpackHalf2(packed.x);
    return FfxDofFloat3(FfxDofFloat(redGreen.x), FfxDofFloat(redGreen.y), FfxDofFloat(ffxDofUnpackHalf2(packed.y).x));
}

// What the post-filter reads of a raw texel (ffxDofPostFilterTexel) in two words: the luminances of its near and far
// colours as halves, and its near opacity as a float whose sign bit holds the far validity (0 or 1; the opacity is
// never negative). Two components a read instead of four (docs/performance.md, "Filtered texels in five words"). The
// opacities stay exact, as the 3 x 3 mean sums them; a luminance only sets the range that the outlier gain clamps a
// texel's luminance to (ffxDofOutlierGain), which 11 significant bits move by at most 0.05%.
FFX_DOF_INLINE FfxUInt32x2 ffxDofPackRawSummary(FfxFloat32 nearLuminance, FfxFloat32 farLuminance, FfxFloat32x2 alpha)
{
    return FfxUInt32x2(ffxDofPackHalf2(FfxFloat32x2(nearLuminance, farLuminance)),
                       ffxDofAsUInt(alpha.x) | (alpha.y > 0.0f ? 0x80000000u : 0u));
}
// (near luminance, far luminance, near opacity, far validity) of ffxDofPackRawSummary.
FFX_DOF_INLINE FfxFloat32x4 ffxDofUnpackRawSummary(FfxUInt32x2 packed)
{
    FfxFloat32x2 luminances = ffxDofUnpackHalf2(packed.x);
    return FfxFloat32x4(luminances.x, luminances.y, ffxDofAsFloat(packed.y & 0x7fffffffu),
                        (packed.y & 0x80000000u) != 0u ? 1.0f : 0.0f);
}

// A raw texel as group-shared memory holds it (ffxDofLoadRawTexel).
struct FfxDofRawTexel
{
    FfxUInt32x2 nearColor;  // ffxDofPackRawColor
    FfxUInt32x2 farColor;   // ffxDofPackRawColor
    FfxUInt32x2 summary;    // ffxDofPackRawSummary
};

// Raw texel `cell` of the group's raw grid (its top-left at half-res texel `rawOrigin`, clamped to the image): loaded
// from the layers, stored for the post-filter and returned.
FFX_DOF_INLINE FfxDofRawTexel ffxDofLoadRawTexel(FfxUInt32x2 cell, FfxInt32x2 rawOrigin, FfxUInt32x2 halfSize)
{
    FfxInt32x2 texel = ffxDofClampHalfTexel(rawOrigin + FfxInt32x2(cell), halfSize);
    FfxDofFloat3 nearColor = ffxDofLoadNearColor(texel);
    FfxDofFloat3 farColor = ffxDofLoadFarColor(texel);
    FfxDofRawTexel raw;
    raw.nearColor = ffxDofPackRawColor(nearColor);
    raw.farColor = ffxDofPackRawColor(farColor);
    raw.summary =
        ffxDofPackRawSummary(ffxDofLuminance(nearColor), ffxDofLuminance(farColor), ffxDofLoadLayerAlpha(texel));
    FfxUInt32 index = cell.y * FfxUInt32(FFX_DOF_RAW_SIDE) + cell.x;
    ffxDofSharedRawNear[index] = raw.nearColor;
    ffxDofSharedRawFar[index] = raw.farColor;
    ffxDofSharedRawSummary[index] = raw.summary;
    return raw;
}

// The raw texel a filtered texel `index` is centred on, from group-shared memory.
FFX_DOF_INLINE FfxDofRawTexel ffxDofRawCentreOf(FfxUInt32 index)
{
    FfxUInt32 centre = (index / FfxUInt32(FFX_DOF_FILTERED_SIDE) + 1u) * FfxUInt32(FFX_DOF_RAW_SIDE) +
                       index % FfxUInt32(FFX_DOF_FILTERED_SIDE) + 1u;
    FfxDofRawTexel raw;
    raw.nearColor = ffxDofSharedRawNear[centre];
    raw.farColor = ffxDofSharedRawFar[centre];
    raw.summary = ffxDofSharedRawSummary[centre];
    return raw;
}

// Cell `index` (0 to 79) of the two rings of the raw grid around its interior of 8 x 8 (ffxDofCompositeTile): the
// outer ring, then the one inside it.
FFX_DOF_INLINE FfxUInt32x2 ffxDofRawRingCell(FfxUInt32 index)
{
    FfxUInt32 outerCells = 4u * (FfxUInt32(FFX_DOF_RAW_SIDE) - 1u);
    if (index < outerCells)
        return ffxDofBorderCell(index, FfxUInt32(FFX_DOF_RAW_SIDE));
    return ffxDofBorderCell(index - outerCells, FfxUInt32(FFX_DOF_RAW_SIDE) - 2u) + FfxUInt32x2(1u, 1u);
}

// What the upsample reads of a filtered texel.
struct FfxDofFilteredTexel
{
    FfxDofFloat3 nearColor;
    FfxDofFloat3 farColor;
    FfxFloat32x2 alpha;  // near opacity, far validity
    FfxFloat32 coc;
};

// Post-filter of filtered texel `index` (raw texel (x + 1, y + 1), `centre`: ffxDofRawCentreOf(index) or the same
// from registers), its radius left 0 (ffxDofFilterTexel).
FFX_DOF_INLINE FfxDofFilteredTexel ffxDofPostFilterTexel(FfxUInt32 index, FfxDofRawTexel centre)
{
    FfxUInt32 x = index % FfxUInt32(FFX_DOF_FILTERED_SIDE);
    FfxUInt32 y = index / FfxUInt32(FFX_DOF_FILTERED_SIDE);
    FfxFloat32x4 centerSummary = ffxDofUnpackRawSummary(centre.summary);
    FfxFloat32x2 centerAlpha = FfxFloat32x2(centerSummary.z, centerSummary.w);
    FfxFloat32 nearCenterLuminance = centerSummary.x;
    FfxFloat32 farCenterLuminance = centerSummary.y;
    FfxFloat32x2 nearRange = FfxFloat32x2(FFX_DOF_FLOAT32_MAX, 0.0f);
    FfxFloat32x2 farRange = FfxFloat32x2(FFX_DOF_FLOAT32_MAX, 0.0f);
    FfxFloat32 opacitySum = 0.0f;
    // Each neighbour's opacity, for the borrowed colour below (read once: on lavapipe a group-shared read is a loop
    // over the lanes).
    FfxFloat32 opacities[9];
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 9u; ++k)
    {
        FfxUInt32 raw = (y + k / 3u) * FfxUInt32(FFX_DOF_RAW_SIDE) + x + k % 3u;
        FfxFloat32x4 summary = k == 4u ? centerSummary : ffxDofUnpackRawSummary(ffxDofSharedRawSummary[raw]);
        opacities[k] = summary.z;
        // Texels without a value take the centre's luminance so they do not widen the range; the
        // centre itself is not a neighbour.
        FfxFloat32 nearLuminance = summary.z > 0.0f && k != 4u ? summary.x : nearCenterLuminance;
        FfxFloat32 farLuminance = summary.w > 0.0f && k != 4u ? summary.y : farCenterLuminance;
        nearRange = FfxFloat32x2(min(nearRange.x, nearLuminance), max(nearRange.y, nearLuminance));
        farRange = FfxFloat32x2(min(farRange.x, farLuminance), max(farRange.y, farLuminance));
        opacitySum += summary.z;
    }
    FfxDofFloat3 centerNear = ffxDofUnpackRawColor(centre.nearColor);
    FfxDofFloat3 nearColor = centerNear;
    if (centerAlpha.x > 0.0f)
        nearColor = nearColor * FfxDofFloat(ffxDofOutlierGain(nearCenterLuminance, nearRange.x, nearRange.y));
    // The opacity the 3 x 3 mean adds to a texel is its neighbours': it takes their colour, weighed by their
    // opacity, for that share. Under the texel's own colour, the rim of a small near disc (a tiny opacity,
    // whose colour the blur makes up for its whole step of LAYER_ALPHA: ffxDofFinishGather) took the disc's
    // opacity: a near speck of 2.25 half-res px added 1.08 times what its near layer holds. The share is 0
    // where the mean does not raise the opacity, so a near object's texture keeps its sharpness; an empty
    // texel takes its neighbours' colour whole (the most opaque neighbour's before 7aea5e0).
    FfxFloat32 borrowedShare = opacitySum > 0.0f ? ffxDofSaturate(1.0f - centerAlpha.x * 9.0f / opacitySum) : 0.0f;
    if (borrowedShare > 0.0f)
    {
        FfxFloat32x3 premultiplied = FfxFloat32x3(0.0f, 0.0f, 0.0f);
        FFX_DOF_UNROLL
        for (FfxUInt32 k = 0u; k < 9u; ++k)
        {
            FfxUInt32 raw = (y + k / 3u) * FfxUInt32(FFX_DOF_RAW_SIDE) + x + k % 3u;
            FfxDofFloat3 neighbourNear = k == 4u ? centerNear : ffxDofUnpackRawColor(ffxDofSharedRawNear[raw]);
            premultiplied += ffxDofToFloat32x3(neighbourNear) * opacities[k];
        }
        nearColor =
            ffxDofToDofFloat3(ffxDofLerp(ffxDofToFloat32x3(nearColor), premultiplied / opacitySum, borrowedShare));
    }
    FfxDofFloat3 farColor = ffxDofUnpackRawColor(centre.farColor);
    if (centerAlpha.y > 0.0f)
        farColor = farColor * FfxDofFloat(ffxDofOutlierGain(farCenterLuminance, farRange.x, farRange.y));
    FfxDofFilteredTexel filtered;
    filtered.nearColor = nearColor;
    filtered.farColor = farColor;
    filtered.alpha = FfxFloat32x2(opacitySum * (1.0f / 9.0f), centerAlpha.y);
    filtered.coc = 0.0f;
    return filtered;
}

// Filtered texel `index` as the group's upsamples read it (ffxDofStoreFilteredTexel).
FFX_DOF_INLINE FfxDofFilteredTexel ffxDofLoadFilteredTexel(FfxUInt32 index)
{
    FfxUInt32x2 packedNear = ffxDofSharedNear[index];
    FfxUInt32x2 packedFar = ffxDofSharedFar[index];
    FfxDofFilteredTexel filtered;
    filtered.nearColor = ffxDofUnpackRawColor(packedNear);
    filtered.farColor = ffxDofUnpackRawColor(packedFar);
    filtered.alpha = FfxFloat32x2(ffxDofSharedOpacity[index], ffxDofUnpackExtraOf(packedNear));
    filtered.coc = ffxDofUnpackExtraOf(packedFar);
    return filtered;
}

// Stores filtered texel `index` for the group's upsamples and returns it as they read it (ffxDofLoadFilteredTexel),
// so that the invocation that filtered it upsamples from the same values.
FFX_DOF_INLINE FfxDofFilteredTexel ffxDofStoreFilteredTexel(FfxUInt32 index, FfxDofFilteredTexel filtered)
{
    FfxUInt32x2 packedNear = ffxDofPackColorAnd(filtered.nearColor, filtered.alpha.y);
    FfxUInt32x2 packedFar = ffxDofPackColorAnd(filtered.farColor, filtered.coc);
    ffxDofSharedNear[index] = packedNear;
    ffxDofSharedFar[index] = packedFar;
    ffxDofSharedOpacity[index] = filtered.alpha.x;
    filtered.nearColor = ffxDofUnpackRawColor(packedNear);
    filtered.farColor = ffxDofUnpackRawColor(packedFar);
    return filtered;
}

// ffxDofPostFilterTexel of filtered texel `index` and its radius (the filtered grid's top-left at half-res texel
// `filteredOrigin`), stored for the group's upsamples and returned as they read it (ffxDofStoreFilteredTexel).
FFX_DOF_INLINE FfxDofFilteredTexel ffxDofFilterTexel(FfxUInt32 index, FfxDofRawTexel centre, FfxInt32x2 filteredOrigin,
                                                     FfxUInt32x2 halfSize)
{
    FfxDofFilteredTexel filtered = ffxDofPostFilterTexel(index, centre);
    FfxInt32x2 texel =
        ffxDofClampHalfTexel(filteredOrigin + FfxInt32x2(FfxInt32(index % FfxUInt32(FFX_DOF_FILTERED_SIDE)),
                                                         FfxInt32(index / FfxUInt32(FFX_DOF_FILTERED_SIDE))),
                             halfSize);
    filtered.coc = ffxDofLoadHalfCoc(texel);
    return ffxDofStoreFilteredTexel(index, filtered);
}

// The input color of a full-res pixel within one pixel of the tile that holds `ownPixel` (a pixel
// of the workgroup's own tile).
#if FFX_DOF_OPTION_OUTPUT_PRE_INIT
// Returns the scaled color (the group-shared copy and MIP 0 are scaled already).
FFX_DOF_INLINE FfxFloat32x4 ffxDofCompositeInput(FfxUInt32x2 pixel, FfxUInt32x2 ownPixel, FfxFloat32 scale)
{
    FfxUInt32 extent = FfxUInt32(FFX_DOF_COMPOSITE_GROUP_EXTENT);
    FfxUInt32x2 tileOrigin = (ownPixel / extent) * extent;
    if (pixel.x >= tileOrigin.x && pixel.y >= tileOrigin.y && pixel.x < tileOrigin.x + extent &&
        pixel.y < tileOrigin.y + extent)
        return ffxDofSharedInput[(pixel.y - tileOrigin.y) * extent + pixel.x - tileOrigin.x];
    FfxDofFloat3 color = ffxDofLoadHalfColor(FfxInt32x2(pixel / 2u));
    return FfxFloat32x4(FfxFloat32(color.x), FfxFloat32(color.y), FfxFloat32(color.z), 1.0f);
}
// Whether ffxDofCompositeInput reads the input itself (not MIP 0 of the half-res colour, from which pass 2 took
// the highlights already).
FFX_DOF_INLINE FfxBoolean ffxDofCompositeInputIsFullRes(FfxUInt32x2 pixel, FfxUInt32x2 ownPixel)
{
    FfxUInt32x2 tile = pixel / FfxUInt32(FFX_DOF_COMPOSITE_GROUP_EXTENT);
    FfxUInt32x2 ownTile = ownPixel / FfxUInt32(FFX_DOF_COMPOSITE_GROUP_EXTENT);
    return tile.x == ownTile.x && tile.y == ownTile.y;
}
#else
#define ffxDofCompositeInput(pixel, ownPixel, scale) ffxDofScaleColor(ffxDofLoadInputColor(pixel), scale)
#define ffxDofCompositeInputIsFullRes(pixel, ownPixel) true
#endif

// The input colors of the 4 x 4 full-res pixels around an invocation's 2 x 2 quad (row by row,
// clamped to the image), scaled: the four fixed 3x3 blurs of the quad share them, 16 reads instead of 36.
struct FfxDofQuadNeighbourhood
{
    FfxFloat32x4 color[16];
};

FFX_DOF_INLINE FfxDofQuadNeighbourhood ffxDofLoadQuadNeighbourhood(FfxUInt32x2 quad, FfxUInt32x2 fullSize,
                                                                   FfxFloat32 scale)
{
    FfxDofQuadNeighbourhood neighbourhood;
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 16u; ++k)
    {
        FfxInt32x2 pixel = clamp(FfxInt32x2(quad) + FfxInt32x2(FfxInt32(k % 4u) - 1, FfxInt32(k / 4u) - 1),
                                 FfxInt32x2(0, 0), FfxInt32x2(fullSize) - FfxInt32x2(1, 1));
        neighbourhood.color[k] = ffxDofCompositeInput(FfxUInt32x2(pixel), quad, scale);
    }
    return neighbourhood;
}

// The quad's neighbourhood less what pass 2 took of each of its pixels for the highlights to draw
// (ffxDofPixelHighlightShare over the floors of the pixel's tile, one of the 3 x 3 in ffxDofSharedTilesAround):
// where the composite leaves the layers' rest to a pixel's input or fixed blur (a far layer partly invalid, as
// behind a near light over an in-focus wall, or a near layer not quite opaque), a light showed through as a dot of
// up to 1.6 times its disc's level at the disc's centre, or a ring of its fixed blur around it
// (docs/technique.md, "Near highlights"). Read in place, pixels outside the group's tile come from MIP 0, which
// pass 2 left them out of already.
FFX_DOF_INLINE FfxDofQuadNeighbourhood ffxDofNeighbourhoodLessHighlights(FfxDofQuadNeighbourhood neighbourhood,
                                                                         FfxUInt32x2 quad, FfxUInt32x2 groupId,
                                                                         FfxDofConstants constants, FfxFloat32 scale)
{
    FfxInt32 extent = FfxInt32(FFX_DOF_COMPOSITE_GROUP_EXTENT);
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 16u; ++k)
    {
        FfxInt32x2 pixel = clamp(FfxInt32x2(quad) + FfxInt32x2(FfxInt32(k % 4u) - 1, FfxInt32(k / 4u) - 1),
                                 FfxInt32x2(0, 0), FfxInt32x2(constants.fullSize) - FfxInt32x2(1, 1));
        if (!ffxDofCompositeInputIsFullRes(FfxUInt32x2(pixel), quad))
            continue;
        FfxInt32x2 tileAround = pixel / extent - FfxInt32x2(groupId) + FfxInt32x2(1, 1);
        FfxFloat32x3 floors = ffxDofUnpackHighlightFloors(ffxDofSharedTilesAround[tileAround.y * 3 + tileAround.x]);
        FfxFloat32 coc = ffxDofLoadPixelCoc(FfxUInt32x2(pixel), constants);
        FfxFloat32x4 color = neighbourhood.color[k];
        FfxFloat32x3 rgb = FfxFloat32x3(color.x, color.y, color.z);
        rgb *= 1.0f - ffxDofPixelHighlightShare(FfxUInt32x2(pixel), rgb, coc, floors, scale, constants.fullSize);
        neighbourhood.color[k] = FfxFloat32x4(rgb.x, rgb.y, rgb.z, color.w);
    }
    return neighbourhood;
}

// The fixed 3x3 blur of the quad's pixel `inQuad` (0..1 each way).
FFX_DOF_INLINE FfxFloat32x3 ffxDofFixedBlur(FfxDofQuadNeighbourhood neighbourhood, FfxUInt32x2 inQuad)
{
    FfxFloat32x3 sum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 weightSum = 0.0f;
    FFX_DOF_UNROLL
    for (FfxInt32 dy = -1; dy <= 1; ++dy)
    {
        FFX_DOF_UNROLL
        for (FfxInt32 dx = -1; dx <= 1; ++dx)
        {
            FfxUInt32 k = (inQuad.y + FfxUInt32(dy + 1)) * 4u + inQuad.x + FfxUInt32(dx + 1);
            FfxFloat32 weight = ffxDofFixedBlurWeight(dx, dy);
            FfxFloat32x4 color = neighbourhood.color[k];
            sum += FfxFloat32x3(color.x, color.y, color.z) * weight;
            weightSum += weight;
        }
    }
    return sum / weightSum;
}

// The pixel's own surface blurred at full resolution: every input pixel q within its disc (2 |radius|
// full-res px, + half a pixel) that reaches it by q's own radius, each weighing its reach over its
// disc's area (scatter as gather, like the blur), so a sharper neighbour never spreads beyond its own
// disc. `local`: the pixel in the group's ffxDofSharedOwn* arrays. Returns the color and, in w, the
// coverage: the summed weights over pi (1 where the surface goes on all around the disc; less at its
// edges, where the half-res layers show what lies behind). The composite gathers a quad's four pixels in
// one walk (ffxDofGatherOwnSurfaceQuad), with the same samples, weights and order.
struct FfxDofOwnDisc
{
    FfxFloat32 reachLimit;  // 2 |radius| + 0.5 full-res px
    FfxInt32 extent;        // rows and columns read each side, within the neighbourhood's border
};
FFX_DOF_INLINE FfxDofOwnDisc ffxDofMakeOwnDisc(FfxFloat32 absCoc)
{
    FfxDofOwnDisc disc;
    disc.reachLimit = 2.0f * absCoc + 0.5f;
    disc.extent = min(FfxInt32(ceil(disc.reachLimit)), FfxInt32(FFX_DOF_OWN_SURFACE_BORDER));
    return disc;
}
// Columns read each side in row `dy` of the disc (valid for |dy| <= extent).
FFX_DOF_INLINE FfxInt32 ffxDofOwnDiscRowExtent(FfxDofOwnDisc disc, FfxInt32 dy)
{
    return min(FfxInt32(sqrt(max(disc.reachLimit * disc.reachLimit - FfxFloat32(dy * dy), 0.0f))), disc.extent);
}
// What a sample of |radius| `sampleRadius` (full-res px) at (dx, dy) from the pixel weighs in its gather.
FFX_DOF_INLINE FfxFloat32 ffxDofOwnSampleWeight(FfxFloat32 sampleRadius, FfxFloat32 areaWeight, FfxInt32 dx,
                                                FfxInt32 dy)
{
    return ffxDofReach(sampleRadius, sqrt(FfxFloat32(dx * dx + dy * dy))) * areaWeight;
}
FFX_DOF_INLINE FfxFloat32x4 ffxDofFinishOwnGather(FfxFloat32x3 sum, FfxFloat32 weightSum)
{
    return FfxFloat32x4(sum / weightSum, ffxDofSaturate(weightSum * (1.0f / FFX_DOF_PI)));
}
FFX_DOF_INLINE FfxFloat32x4 ffxDofGatherOwnSurface(FfxInt32x2 local, FfxFloat32 absCoc)
{
    FfxDofOwnDisc disc = ffxDofMakeOwnDisc(absCoc);
    FfxFloat32x3 sum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 weightSum = 0.0f;
    FFX_DOF_LOOP
    for (FfxInt32 dy = -disc.extent; dy <= disc.extent; ++dy)
    {
        FfxInt32 rowExtent = ffxDofOwnDiscRowExtent(disc, dy);
        FfxInt32 row = (local.y + dy) * FfxInt32(FFX_DOF_OWN_SURFACE_SIDE) + local.x;
        FFX_DOF_LOOP
        for (FfxInt32 dx = -rowExtent; dx <= rowExtent; ++dx)
        {
            FfxFloat32x4 colorRadius = ffxDofLoadOwnSample(FfxUInt32(row + dx));
            FfxFloat32 weight = ffxDofOwnSampleWeight(colorRadius.w, ffxDofRoundAreaWeight(colorRadius.w), dx, dy);
            sum += FfxFloat32x3(colorRadius.x, colorRadius.y, colorRadius.z) * weight;
            weightSum += weight;
        }
    }
    // The pixel itself always weighs (reach 1 at distance 0), so weightSum > 0.
    return ffxDofFinishOwnGather(sum, weightSum);
}

// The own-surface gathers of a quad's four pixels (0: top-left, 1: top-right, 2: bottom-left, 3:
// bottom-right; `topLeft` in the ffxDofSharedOwn* arrays) in one walk over the union of their discs: each
// sample is read from group-shared memory once for the four instead of once per pixel whose disc holds it
// (on lavapipe a group-shared read is a loop over the lanes; the composite took 0.9 times as long:
// docs/performance.md, "The own-surface gather a quad at a time"). A pixel's sums take the samples of its own
// disc, in its own walk's order, so each result is ffxDofGatherOwnSurface's to the bit. `gathers`: which
// pixels gather (the others' results are undefined).
struct FfxDofQuadGathers
{
    FfxFloat32x4 gathered[4];
};
FFX_DOF_INLINE FfxDofQuadGathers ffxDofGatherOwnSurfaceQuad(FfxInt32x2 topLeft, FfxFloat32x4 absCocs, FfxUInt32 gathers)
{
    FfxDofOwnDisc discs[4];
    FfxFloat32x3 sums[4];
    FfxFloat32 weightSums[4];
    FfxInt32 extent = -1;  // of the union, around the top-left pixel (one more to the right and below)
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
    {
        discs[k] = ffxDofMakeOwnDisc(absCocs[k]);
        // A pixel that does not gather reads no row (|dy| <= -1 never holds).
        if ((gathers & (1u << k)) == 0u)
            discs[k].extent = -1;
        extent = max(extent, discs[k].extent);
        sums[k] = FfxFloat32x3(0.0f, 0.0f, 0.0f);
        weightSums[k] = 0.0f;
    }
    FFX_DOF_LOOP
    for (FfxInt32 y = -extent; y <= extent + 1; ++y)
    {
        // The union's columns in this row, and each pixel's own.
        FfxInt32 rowExtents[4];
        FfxInt32 first = 1;
        FfxInt32 last = 0;
        FFX_DOF_UNROLL
        for (FfxUInt32 k = 0u; k < 4u; ++k)
        {
            FfxInt32 dy = y - FfxInt32(k >> 1u);
            rowExtents[k] = abs(dy) <= discs[k].extent ? ffxDofOwnDiscRowExtent(discs[k], dy) : -1;
            if (rowExtents[k] >= 0)
            {
                first = min(first, FfxInt32(k & 1u) - rowExtents[k]);
                last = max(last, FfxInt32(k & 1u) + rowExtents[k]);
            }
        }
        FfxInt32 row = (topLeft.y + y) * FfxInt32(FFX_DOF_OWN_SURFACE_SIDE) + topLeft.x;
        // The row's samples two at a time: a pair that also holds a sample beyond the union's columns
        // weighs it 0 for every pixel, so the sums are the same to the bit.
        FfxInt32 lastPair = first <= last ? (row + last) >> 1 : -1;
        FFX_DOF_LOOP
        for (FfxInt32 pair = (row + first) >> 1; pair <= lastPair; ++pair)
        {
            FfxUInt32x4 packedPair = ffxDofLoadOwnSamplePair(FfxUInt32(pair));
            FFX_DOF_UNROLL
            for (FfxUInt32 odd = 0u; odd < 2u; ++odd)
            {
                FfxInt32 x = 2 * pair + FfxInt32(odd) - row;
                FfxFloat32x4 colorRadius = ffxDofUnpackOwnSample(ffxDofOwnSampleOfPair(packedPair, odd != 0u));
                FfxFloat32x3 color = FfxFloat32x3(colorRadius.x, colorRadius.y, colorRadius.z);
                FfxFloat32 areaWeight = ffxDofRoundAreaWeight(colorRadius.w);
                FFX_DOF_UNROLL
                for (FfxUInt32 k = 0u; k < 4u; ++k)
                {
                    FfxInt32 dx = x - FfxInt32(k & 1u);
                    FfxInt32 dy = y - FfxInt32(k >> 1u);
                    FfxFloat32 weight =
                        abs(dx) <= rowExtents[k] ? ffxDofOwnSampleWeight(colorRadius.w, areaWeight, dx, dy) : 0.0f;
                    sums[k] += color * weight;
                    weightSums[k] += weight;
                }
            }
        }
    }
    FfxDofQuadGathers result;
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
        result.gathered[k] = ffxDofFinishOwnGather(sums[k], max(weightSums[k], 1e-30f));
    return result;
}

// The far pixels of small radius in front of a far pixel of |radius| `absCoc` (half-res px) that reach
// it, at full resolution (scatter as gather, as ffxDofGatherOwnSurface): each weighs its reach over its
// disc's area times its ffxDofSmallSourceShare, the share the blur leaves out of the half-res layers.
// Returns their color and, in w, their coverage (their reach summed over the disc's area on the pixel
// grid, ffxDofPixelDiscArea), to be composed over the far layer. Sources reach at most
// 2 FFX_DOF_FAR_LAYER_ONLY_RADIUS + 0.5 full-res px, within the border. The composite gathers a quad's
// four pixels in one walk (ffxDofGatherSmallSourcesQuad), with the same samples, weights and order.
#define FFX_DOF_SMALL_SOURCE_EXTENT FfxInt32(2.0f * FFX_DOF_FAR_LAYER_ONLY_RADIUS)
// A sample's share for a pixel of |radius| `absCoc`: far sources only, judged in half-res px.
FFX_DOF_INLINE FfxFloat32 ffxDofSmallSourceSampleShare(FfxBoolean far, FfxFloat32 sourceAbs, FfxFloat32 absCoc)
{
    return far && sourceAbs >= FFX_DOF_IN_FOCUS_RADIUS
               ? ffxDofSmallSourceShare(sourceAbs, absCoc) * ffxDofFarNearerShare(sourceAbs, absCoc)
               : 0.0f;
}
FFX_DOF_INLINE FfxFloat32x4 ffxDofFinishSmallSources(FfxFloat32x3 sum, FfxFloat32 weightSum, FfxFloat32 radiusSum)
{
    if (weightSum <= 0.0f)
        return FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
    // The weights sum the sources' coverage in units of pi radius^2; the grid's disc is
    // ffxDofPixelDiscArea, evaluated at the sources' mean radius (one radius for one light).
    FfxFloat32 radius = radiusSum / weightSum;
    return FfxFloat32x4(sum / weightSum, ffxDofSaturate(weightSum * radius * radius / ffxDofPixelDiscArea(radius)));
}
FFX_DOF_INLINE FfxFloat32x4 ffxDofGatherSmallSources(FfxInt32x2 local, FfxFloat32 absCoc)
{
    FfxInt32 extent = FFX_DOF_SMALL_SOURCE_EXTENT;
    FfxFloat32x3 sum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 weightSum = 0.0f;
    FfxFloat32 radiusSum = 0.0f;
    FFX_DOF_LOOP
    for (FfxInt32 dy = -extent; dy <= extent; ++dy)
    {
        FfxInt32 row = (local.y + dy) * FfxInt32(FFX_DOF_OWN_SURFACE_SIDE) + local.x;
        FFX_DOF_LOOP
        for (FfxInt32 dx = -extent; dx <= extent; ++dx)
        {
            FfxFloat32x4 colorRadius = ffxDofLoadOwnSample(FfxUInt32(row + dx));
            FfxFloat32 sourceAbs = colorRadius.w * 0.5f;
            FfxFloat32 share =
                ffxDofSmallSourceSampleShare(ffxDofOwnSampleIsFar(FfxUInt32(row + dx)), sourceAbs, absCoc);
            FfxFloat32 weight = ffxDofReach(2.0f * sourceAbs, sqrt(FfxFloat32(dx * dx + dy * dy))) *
                                ffxDofRoundAreaWeight(2.0f * sourceAbs) * share;
            sum += FfxFloat32x3(colorRadius.x, colorRadius.y, colorRadius.z) * weight;
            weightSum += weight;
            radiusSum += colorRadius.w * weight;
        }
    }
    return ffxDofFinishSmallSources(sum, weightSum, radiusSum);
}

// ffxDofGatherSmallSources of a quad's four pixels in one walk over the union of their squares, as
// ffxDofGatherOwnSurfaceQuad: each result is the per-pixel gather's to the bit. `gathers`: which pixels gather
// (the others' results are zero).
FFX_DOF_INLINE FfxDofQuadGathers ffxDofGatherSmallSourcesQuad(FfxInt32x2 topLeft, FfxFloat32x4 absCocs,
                                                              FfxUInt32 gathers)
{
    FfxInt32 extent = FFX_DOF_SMALL_SOURCE_EXTENT;
    FfxFloat32x3 sums[4];
    FfxFloat32 weightSums[4];
    FfxFloat32 radiusSums[4];
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
    {
        sums[k] = FfxFloat32x3(0.0f, 0.0f, 0.0f);
        weightSums[k] = 0.0f;
        radiusSums[k] = 0.0f;
    }
    FFX_DOF_LOOP
    for (FfxInt32 y = -extent; y <= extent + 1; ++y)
    {
        FfxInt32 row = (topLeft.y + y) * FfxInt32(FFX_DOF_OWN_SURFACE_SIDE) + topLeft.x;
        // Two samples a read, as ffxDofGatherOwnSurfaceQuad's: one beyond the square weighs 0.
        FFX_DOF_LOOP
        for (FfxInt32 pair = (row - extent) >> 1; pair <= (row + extent + 1) >> 1; ++pair)
        {
            FfxUInt32x4 packedPair = ffxDofLoadOwnSamplePair(FfxUInt32(pair));
            FFX_DOF_UNROLL
            for (FfxUInt32 odd = 0u; odd < 2u; ++odd)
            {
                FfxInt32 x = 2 * pair + FfxInt32(odd) - row;
                FfxUInt32x2 packed = ffxDofOwnSampleOfPair(packedPair, odd != 0u);
                FfxFloat32x4 colorRadius = ffxDofUnpackOwnSample(packed);
                FfxFloat32x3 color = FfxFloat32x3(colorRadius.x, colorRadius.y, colorRadius.z);
                FfxBoolean far = ffxDofPackedOwnSampleIsFar(packed);
                FfxFloat32 sourceAbs = colorRadius.w * 0.5f;
                FfxFloat32 areaWeight = ffxDofRoundAreaWeight(2.0f * sourceAbs);
                FFX_DOF_UNROLL
                for (FfxUInt32 k = 0u; k < 4u; ++k)
                {
                    FfxInt32 dx = x - FfxInt32(k & 1u);
                    FfxInt32 dy = y - FfxInt32(k >> 1u);
                    FfxBoolean inside = (gathers & (1u << k)) != 0u && abs(dx) <= extent && abs(dy) <= extent;
                    FfxFloat32 share = inside ? ffxDofSmallSourceSampleShare(far, sourceAbs, absCocs[k]) : 0.0f;
                    FfxFloat32 weight =
                        ffxDofReach(2.0f * sourceAbs, sqrt(FfxFloat32(dx * dx + dy * dy))) * areaWeight * share;
                    sums[k] += color * weight;
                    weightSums[k] += weight;
                    radiusSums[k] += colorRadius.w * weight;
                }
            }
        }
    }
    FfxDofQuadGathers result;
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
        result.gathered[k] = ffxDofFinishSmallSources(sums[k], weightSums[k], radiusSums[k]);
    return result;
}

// Share of the half-res layers in a pixel whose own surface is gathered at full resolution: 0 up to
// the last FFX_DOF_OWN_SURFACE_FADE half-res px below FFX_DOF_FAR_LAYER_ONLY_RADIUS, 1 from there.
FFX_DOF_INLINE FfxFloat32 ffxDofOwnSurfaceLayerShare(FfxFloat32 absCoc)
{
    return ffxDofSaturate((absCoc - FFX_DOF_FAR_LAYER_ONLY_RADIUS + FFX_DOF_OWN_SURFACE_FADE) *
                          (1.0f / FFX_DOF_OWN_SURFACE_FADE));
}

// Whether a far pixel of radius `coc` (half-res px) draws the small sources in front of it at full resolution
// (where its far layer is valid).
FFX_DOF_INLINE FfxBoolean ffxDofPixelGathersSmallSources(FfxBoolean smallSourceTile, FfxFloat32 coc)
{
    return smallSourceTile && coc <= -FFX_DOF_IN_FOCUS_RADIUS && abs(coc) > FFX_DOF_FAR_LAYER_ONLY_RADIUS - 1.0f;
}

// Whether a pixel of |radius| `absCoc` (half-res px) takes its own surface gathered at full resolution.
FFX_DOF_INLINE FfxBoolean ffxDofPixelGathersOwnSurface(FfxBoolean ownSurfaceTile, FfxFloat32 absCoc)
{
    return ownSurfaceTile && absCoc >= FFX_DOF_OWN_SURFACE_MIN_RADIUS && absCoc < FFX_DOF_FAR_LAYER_ONLY_RADIUS;
}

// ---- Far highlights ----------------------------------------------------------------------------------

// Whether `tile` holds a highlight (in any of its quadrants' slots): its pixels gave light.
FFX_DOF_INLINE FfxBoolean ffxDofTileHoldsHighlights(FfxUInt32x2 tile, FfxUInt32x2 tileCount)
{
    return ffxDofHighlightFloorsGaveLight(ffxDofLoadHighlightWord(ffxDofHighlightFloorWord(tile, tileCount)));
}

// The window of tiles whose highlights may reach a pixel of `tile` (ffxDofHighlightTileRange), clipped to the
// image: first..last inclusive.
FFX_DOF_INLINE void ffxDofHighlightWindow(FfxUInt32x2 tile, FfxDofConstants constants, FFX_DOF_OUT(FfxInt32x2) first,
                                          FFX_DOF_OUT(FfxInt32x2) last)
{
    ffxDofTileWindow(FfxInt32x2(tile), ffxDofHighlightTileRange(constants.cocLimit, ffxDofApertureExtent(constants)),
                     constants.tileCount, first, last);
}

// What the highlights of the tiles in the window add to a quad's four pixels (0: top-left .. 3: bottom-right;
// `quad` its top-left pixel, `cocs` their radii): far ones to their far layers, each as far as what lies in front
// does not hide it (ffxDofHighlightVisibilityPast), near ones over everything (nothing the pinhole image shows lies
// in front of a near light but a nearer surface, which it would show instead). Tiles in the window's order, slots
// in theirs: the same sum whatever the order the groups ran in.
struct FfxDofQuadHighlights
{
    FfxFloat32x3 added[4];
    FfxFloat32x3 nearAdded[4];
};
FFX_DOF_INLINE FfxDofQuadHighlights ffxDofNoQuadHighlights()
{
    FfxDofQuadHighlights none;
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
    {
        none.added[k] = FfxFloat32x3(0.0f, 0.0f, 0.0f);
        none.nearAdded[k] = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    }
    return none;
}
FFX_DOF_INLINE FfxDofQuadHighlights ffxDofHighlightsAtQuad(FfxUInt32x2 tile, FfxUInt32x2 quad, FfxFloat32x4 cocs,
                                                           FfxDofConstants constants)
{
    FfxDofQuadHighlights result = ffxDofNoQuadHighlights();
    // The aperture at the quad's centre (half-res px): the cat's eye changes over a frame, not over a quad.
    FfxDofPixelAperture aperture = ffxDofMakeAperture(constants, (FfxFloat32x2(quad) + FfxFloat32x2(1.0f, 1.0f)) * 0.5f,
                                                      FfxFloat32x2(constants.halfSize));
    FfxInt32x2 first;
    FfxInt32x2 last;
    ffxDofHighlightWindow(tile, constants, first, last);
    FfxUInt32 width = FfxUInt32(last.x - first.x + 1);
    FfxUInt32 words = (width * FfxUInt32(last.y - first.y + 1) + 31u) / 32u;
    FfxFloat32 extent = ffxDofApertureExtent(constants);
    FfxFloat32x2 quadCentre = FfxFloat32x2(quad) + FfxFloat32x2(1.0f, 1.0f);
    // Only the tiles that hold a highlight (ffxDofSharedHighlightTiles), in window order.
    FFX_DOF_LOOP
    for (FfxUInt32 w = 0u; w < words; ++w)
    {
        FfxUInt32 bits = ffxDofSharedHighlightTiles[w];
        FFX_DOF_LOOP
        while (bits != 0u)
        {
            FfxUInt32 index = w * 32u + ffxDofFirstBitLow(bits);
            bits &= bits - 1u;
            FfxUInt32x2 source = FfxUInt32x2(first) + FfxUInt32x2(index % width, index / width);
            FfxUInt32 word = ffxDofHighlightWord(source, 0u, constants.tileCount);
            FfxFloat32x2 origin = FfxFloat32x2(source * 2u * FfxUInt32(FFX_DOF_TILE_SIZE));
            FFX_DOF_LOOP
            for (FfxUInt32 slot = 0u; slot < FfxUInt32(FFX_DOF_HIGHLIGHT_SLOTS); ++slot)
            {
                FfxUInt32 slotEnergy = ffxDofLoadHighlightWord(word);
                word += FfxUInt32(FFX_DOF_HIGHLIGHT_WORDS);
                if (slotEnergy == 0u)
                    continue;
                FfxDofHighlight highlight = ffxDofUnpackHighlight(
                    FfxUInt32x3(slotEnergy, ffxDofLoadHighlightWord(word - 2u), ffxDofLoadHighlightWord(word - 1u)));
                // The quad's pixels lie within 0.71 px of its centre, and each disc within the axis's length of
                // the highlight's place.
                if (length(quadCentre - origin - highlight.position) >
                    ffxDofHighlightReach(highlight.radius, extent) + 0.71f + length(highlight.axis))
                    continue;
                FfxUInt32 discs = ffxDofHighlightDiscCount(highlight);
                highlight.energy *= 1.0f / FfxFloat32(discs);
                FFX_DOF_LOOP
                for (FfxUInt32 disc = 0u; disc < discs; ++disc)
                {
                    FfxFloat32x2 centre = origin + ffxDofHighlightDiscCentre(highlight, disc);
                    FfxFloat32x2 depthsMet =
                        highlight.near ? FfxFloat32x2(0.0f, 0.0f)
                                       : ffxDofHighlightDepthsMet(quadCentre, centre, highlight.radius, constants);
                    FFX_DOF_UNROLL
                    for (FfxUInt32 k = 0u; k < 4u; ++k)
                    {
                        FfxFloat32x2 pixelCentre =
                            FfxFloat32x2(quad + FfxUInt32x2(k & 1u, k >> 1u)) + FfxFloat32x2(0.5f, 0.5f);
                        FfxFloat32x3 added = ffxDofHighlightAt(highlight, pixelCentre - centre, aperture);
                        if (highlight.near)
                        {
                            result.nearAdded[k] += added;
                            continue;
                        }
                        // Outside its disc a light adds nothing, and nothing need be asked of what hides it.
                        if (max(added.x, max(added.y, added.z)) > 0.0f)
                            result.added[k] +=
                                added * ffxDofHighlightVisibilityPast(pixelCentre, centre, cocs[k], highlight.radius,
                                                                      depthsMet, constants);
                    }
                }
            }
        }
    }
    return result;
}

// The filtered half-res texels around a full-res pixel (top-left, top-right, bottom-left, bottom-right), as
// its upsampling reads them: post-filtered near and far colour, (near opacity, far validity) and radius.
struct FfxDofUpsampleTaps
{
    FfxFloat32x2 alpha[4];
    FfxDofFloat3 nearColor[4];
    FfxDofFloat3 farColor[4];
    FfxFloat32 coc[4];
};

// The composed color of one full-res pixel of radius `coc` whose input is `color` and fixed 3x3 blur
// `fixedBlur`, upsampled from `taps` with the bilinear `fraction` (ffxDofUpsamplePosition). `ownSurfaceTile`
// and `smallSourceTile`: whether the group loaded the full-res neighbourhood for either gather
// (ffxDofTileGathersOwnSurface, ffxDofTileMayHoldBrightSmallSources); `ownGather` and `smallSources`: the
// pixel's gathers (ffxDofGatherOwnSurfaceQuad, ffxDofGatherSmallSourcesQuad), used where
// ffxDofPixelGathersOwnSurface and ffxDofPixelGathersSmallSources say; `highlights` and `nearHighlights` what
// the far and near highlights add to it (ffxDofHighlightsAtQuad). Returns false (and leaves `color` alone) when
// the pixel keeps its input value.
FFX_DOF_INLINE FfxBoolean ffxDofComposePixel(FfxDofUpsampleTaps taps, FfxFloat32x2 fraction, FfxFloat32 coc,
                                             FfxFloat32x3 fixedBlur, FfxBoolean ownSurfaceTile, FfxFloat32x4 ownGather,
                                             FfxBoolean smallSourceTile, FfxFloat32x4 smallSources,
                                             FfxFloat32x3 highlights, FfxFloat32x3 nearHighlights,
                                             FFX_DOF_INOUT(FfxFloat32x4) color)
{
    FfxFloat32 bilinear[4];
    bilinear[0] = (1.0f - fraction.x) * (1.0f - fraction.y);
    bilinear[1] = fraction.x * (1.0f - fraction.y);
    bilinear[2] = (1.0f - fraction.x) * fraction.y;
    bilinear[3] = fraction.x * fraction.y;

    FfxFloat32 nearOpacity = 0.0f;
    // The near colour of the taps the near field covers, and their bilinear weight (1 where it covers all four).
    FfxFloat32x3 nearColor = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 coveredWeight = 0.0f;
    FfxBoolean nearValid = true;
    FfxFloat32x3 farSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 farWeight = 0.0f;
    FfxFloat32 farTotal = 0.0f;
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
    {
        FfxFloat32x2 alpha = taps.alpha[k];
        FfxFloat32 coveredTap = alpha.x > 0.0f ? bilinear[k] : 0.0f;
        nearValid = nearValid && alpha.x > 0.0f;
        nearOpacity += alpha.x * bilinear[k];
        nearColor += ffxDofToFloat32x3(taps.nearColor[k]) * coveredTap;
        coveredWeight += coveredTap;
        FfxFloat32 tapWeight = bilinear[k] * ffxDofUpsampleCocWeight(taps.coc[k], coc);
        farSum += ffxDofToFloat32x3(taps.farColor[k]) * (tapWeight * alpha.y);
        farWeight += tapWeight * alpha.y;
        farTotal += tapWeight;
    }
    // The near layer's rim: a pixel whose bilinear footprint holds a texel the near field does not cover takes
    // only the near layer over what it would show without it. Composed in full there (its own blur and the far
    // layer mixed in by its radius), in-focus pixels around stray near coverage changed by up to 23/255 (the
    // floor scene); left without the near layer, a small near disc lost its rim: a 1 px near light at radius
    // 8 px kept 0.93 of its energy, 0.97 to 0.99 now (docs/quality.md, near lights). Its colour is that of the
    // taps the near field covers: the others hold none, and mixed in (before 7aea5e0) they darkened the rim
    // twice, in colour and in opacity (a near speck of 1 half-res px added 0.80 times what its near layer holds).
    FfxFloat32 rimOpacity = nearValid ? 0.0f : nearOpacity;
    if (!nearValid)
    {
        nearOpacity = 0.0f;
        if (coveredWeight > 0.0f)
            nearColor /= coveredWeight;
    }
    FfxFloat32 absCoc = abs(coc);
    // Near highlights go over everything the pixel shows, its input included.
    FfxBoolean nearLights = nearHighlights.x > 0.0f || nearHighlights.y > 0.0f || nearHighlights.z > 0.0f;
    if (absCoc < FFX_DOF_IN_FOCUS_RADIUS && nearOpacity <= 0.0f)
    {
        if (rimOpacity <= 0.0f && !nearLights)
            return false;
        FfxFloat32x3 veiled =
            ffxDofLerp(FfxFloat32x3(color.x, color.y, color.z), nearColor, ffxDofNearLayerWeight(rimOpacity)) +
            nearHighlights;
        color = FfxFloat32x4(veiled.x, veiled.y, veiled.z, color.w);
        return true;
    }

    FfxFloat32x3 result = FfxFloat32x3(color.x, color.y, color.z);
    // A pixel of the near field is its own foreground: the fixed blur may spread its color, and the
    // half-res layers (background through the near layer) replace its own small blur only as far as
    // the variance match of its radius asks (ffxDofFarBlend), like a far-field pixel's.
    FfxBoolean ownNear = coc >= FFX_DOF_NEAR_THRESHOLD;
    // Radii below FFX_DOF_FAR_LAYER_ONLY_RADIUS: the own surface gathered at full resolution, the half-res
    // layers where it does not cover the disc and over the fade; elsewhere (or in tiles the test of the
    // group left out) the input, the fixed 3x3 blur and the layers mixed by their variance.
    FfxBoolean gatherOwn = ffxDofPixelGathersOwnSurface(ownSurfaceTile, absCoc);
    FfxFloat32 layerShare = ffxDofFarBlend(absCoc, 1.0f);
    FfxFloat32 ownCoverage = 1.0f;
    if (gatherOwn)
    {
        result = FfxFloat32x3(ownGather.x, ownGather.y, ownGather.z);
        ownCoverage = ownGather.w;
        layerShare = ffxDofOwnSurfaceLayerShare(absCoc);
    }
    else
    {
        FfxFloat32 fixedBlurBlend = ffxDofFixedBlurBlend(absCoc, ownNear ? 0.0f : nearOpacity);
        if (fixedBlurBlend > 0.0f)
            result = ffxDofLerp(result, fixedBlur, fixedBlurBlend);
    }
    FfxFloat32x3 ownBlur = result;
    if (farWeight > 0.0f)
    {
        FfxFloat32 farValidity = farWeight / farTotal;
        // A near pixel's own surface, too, shows what lies behind it where it does not cover its disc
        // (within its radius of its silhouette): kept opaque there, the rim of a small near object was
        // as solid as its middle (floor's near field 0.79 dB lower, docs/quality.md).
        if (ownNear && gatherOwn)
            ownBlur = ffxDofLerp(ownBlur, farSum / farWeight, (1.0f - ownCoverage) * farValidity);
        FfxFloat32 farShare =
            gatherOwn ? max(layerShare, 1.0f - ownCoverage) * farValidity : ffxDofFarBlend(absCoc, farValidity);
        FfxFloat32x3 farColor = farSum / farWeight;
        // Small far sources in front of the pixel, which the blur left out of the layers it shows.
        if (ffxDofPixelGathersSmallSources(smallSourceTile, coc))
            farColor =
                ffxDofLerp(farColor, FfxFloat32x3(smallSources.x, smallSources.y, smallSources.z), smallSources.w);
        // Far highlights the layers left out (ffxDofHighlightsAtQuad), on top of what lies behind them: in full
        // over a far pixel, whose own-surface gather left them out too (ffxDofPixelHighlightShare); over a near
        // pixel, in the far layer its own blur and near layer cover.
        if (ownNear)
            farColor += highlights;
        result = ffxDofLerp(result, farColor, ownNear ? farValidity : farShare);
        if (!ownNear)
            result += highlights * farValidity;
    }
    result = ffxDofLerp(result, nearColor, ffxDofNearLayerWeight(nearOpacity + rimOpacity));
    // A near pixel whose own surface covers little of its disc is mostly what the layers show around it: an
    // isolated near speck's own gather drew its light at full resolution (0.080 of it at radius 1 half-res px)
    // where the near layer, which keeps that light in the pixels around, holds 0.028 there (1.052 of the light
    // in all). The layers' share grows with the square of what the surface leaves uncovered, so that a
    // surface's rim (about half covered) keeps mostly its own gather: with the share linear, floor's near
    // field lost 0.03 dB and busy-background's 0.04 (docs/technique.md, "Near specks keep their light").
    // Where the pixel gathers no own surface its coverage is 1 and the share is layerShare alone.
    FfxFloat32 uncovered = 1.0f - ownCoverage;
    if (ownNear)
        result = ffxDofLerp(ownBlur, result, max(layerShare, uncovered * uncovered));
    result += nearHighlights;
    color = FfxFloat32x4(result.x, result.y, result.z, color.w);
    return true;
}

// Pixel `index` of the own-surface neighbourhood (its top-left pixel at `origin`, clamped to the image), packed
// for the gathers (ffxDofPackOwnSample): its scaled input and radius, less what pass 2 took of its light where
// `highlightsAround` (the gathers draw what pass 2 left of the pixel's light; the highlights draw the rest).
FFX_DOF_INLINE FfxUInt32x2 ffxDofOwnNeighbourhoodSample(FfxUInt32 index, FfxInt32x2 origin, FfxUInt32x2 groupId,
                                                        FfxBoolean highlightsAround, FfxFloat32 scale,
                                                        FfxDofConstants constants)
{
    FfxInt32x2 pixel = clamp(origin + FfxInt32x2(FfxInt32(index % FfxUInt32(FFX_DOF_OWN_SURFACE_SIDE)),
                                                 FfxInt32(index / FfxUInt32(FFX_DOF_OWN_SURFACE_SIDE))),
                             FfxInt32x2(0, 0), FfxInt32x2(constants.fullSize) - FfxInt32x2(1, 1));
    FfxFloat32x4 inputColor =
        ffxDofCompositeInput(FfxUInt32x2(pixel), groupId * FfxUInt32(FFX_DOF_COMPOSITE_GROUP_EXTENT), scale);
    FfxFloat32x3 sampleColor = FfxFloat32x3(inputColor.x, inputColor.y, inputColor.z);
    FfxFloat32 sampleCoc = ffxDofLoadPixelCoc(FfxUInt32x2(pixel), constants);
    if (highlightsAround &&
        ffxDofCompositeInputIsFullRes(FfxUInt32x2(pixel), groupId * FfxUInt32(FFX_DOF_COMPOSITE_GROUP_EXTENT)))
    {
        FfxInt32x2 tileAround =
            pixel / FfxInt32(FFX_DOF_COMPOSITE_GROUP_EXTENT) - FfxInt32x2(groupId) + FfxInt32x2(1, 1);
        FfxFloat32x3 tileFloors = ffxDofUnpackHighlightFloors(ffxDofSharedTilesAround[tileAround.y * 3 + tileAround.x]);
        sampleColor *= 1.0f - ffxDofPixelHighlightShare(FfxUInt32x2(pixel), sampleColor, sampleCoc, tileFloors, scale,
                                                        constants.fullSize);
    }
    return ffxDofPackOwnSample(sampleColor, 2.0f * sampleCoc);
}

// Composes the tile of the list entry `listedTile` (ffxDofPackListedTile) by the work of `compositeClass`
// (FFX_DOF_COMPOSITE_CLASS_*): the class dilate chose for it, or one holding more work (the CPU tests compare them).
FFX_DOF_INLINE void ffxDofCompositeTile(FfxUInt32 listedTile, FfxUInt32 localIndex, FfxUInt32 compositeClass)
{
    FfxDofConstants constants = ffxDofGetFocusedConstants();
    FfxUInt32x2 groupId = ffxDofUnpackListedTile(listedTile);
    FfxUInt32 extent = FfxUInt32(FFX_DOF_COMPOSITE_GROUP_EXTENT);
    FfxUInt32x2 quad = groupId * extent + ffxDofLocalCoord(localIndex) * 2u;
    if (compositeClass == FfxUInt32(FFX_DOF_COMPOSITE_CLASS_COPY))
    {
        // In focus, and no near field reaches the tile (ffxDofTileKeepsInput). In place there is nothing to
        // do, and the core dispatches no copy.
#if !FFX_DOF_OPTION_OUTPUT_PRE_INIT
        FFX_DOF_UNROLL
        for (FfxUInt32 k = 0u; k < 4u; ++k)
        {
            FfxUInt32x2 pixel = quad + FfxUInt32x2(k & 1u, k >> 1u);
            if (pixel.x < constants.fullSize.x && pixel.y < constants.fullSize.y)
                ffxDofStoreOutput(pixel, ffxDofLoadInputColor(pixel));
        }
#endif
        return;
    }
    // FULL_RES and LIGHTS tiles gather at full resolution; only LIGHTS tiles draw lights there
    // (ffxDofCompositeTileClass).
    FfxBoolean lightsTile = compositeClass == FfxUInt32(FFX_DOF_COMPOSITE_CLASS_LIGHTS);
    FfxBoolean fullResTile = lightsTile || compositeClass == FfxUInt32(FFX_DOF_COMPOSITE_CLASS_FULL_RES);
    FfxFloat32 scale = ffxDofLoadColorScale();
    FfxFloat32x2 tile = ffxDofLoadTile(groupId);

#if FFX_DOF_OPTION_OUTPUT_PRE_INIT
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
    {
        FfxUInt32x2 pixel = quad + FfxUInt32x2(k & 1u, k >> 1u);
        if (pixel.x < constants.fullSize.x && pixel.y < constants.fullSize.y)
            ffxDofSharedInput[(pixel.y - groupId.y * extent) * extent + pixel.x - groupId.x * extent] =
                ffxDofScaleColor(ffxDofLoadInputColor(pixel), scale);
    }
#endif
    if (localIndex == 0u)
        ffxDofSharedHighlightsInReach = 0u;
    if (localIndex < FfxUInt32(FFX_DOF_HIGHLIGHT_WINDOW_WORDS))
        ffxDofSharedHighlightTiles[localIndex] = 0u;
    if (lightsTile && localIndex < 9u)
    {
        FfxUInt32x2 around = ffxDofTileAround(groupId, localIndex, constants.tileCount);
        FfxFloat32x3 rangeAndPeak = ffxDofTileRangeAndPeak(around, constants.tileCount);
        ffxDofSharedTilesAround[localIndex] = ffxDofLoadGivenHighlightFloors(around, rangeAndPeak, constants.tileCount);
    }
    FfxInt32x2 tileOrigin = FfxInt32x2(groupId * FfxUInt32(FFX_DOF_TILE_SIZE));
    // Each invocation loads the raw texel its quad's block centre is filtered from (the raw grid's interior, one texel
    // an invocation) and keeps it for that post-filter below, then the two rings around the interior: three
    // group-shared reads of two words fewer an invocation.
    FfxInt32x2 rawOrigin = tileOrigin - FfxInt32x2(2, 2);
    FfxUInt32x2 quadTexel = ffxDofLocalCoord(localIndex);
    FfxDofRawTexel blockCentreRaw = ffxDofLoadRawTexel(quadTexel + FfxUInt32x2(2u, 2u), rawOrigin, constants.halfSize);
    for (FfxUInt32 index = localIndex; index < FfxUInt32(FFX_DOF_RAW_SIDE * FFX_DOF_RAW_SIDE - FFX_DOF_GROUP_THREADS);
         index += FfxUInt32(FFX_DOF_GROUP_THREADS))
        ffxDofLoadRawTexel(ffxDofRawRingCell(index), rawOrigin, constants.halfSize);
    ffxDofGroupBarrier();
    // The full-res neighbourhood of the own-surface gather, after the barrier above: in place, the
    // input of the group's own tile is read from group-shared memory (ffxDofCompositeInput).
    FfxBoolean ownSurfaceTile = fullResTile && ffxDofTileGathersOwnSurface(tile);
    // Whether a pixel of the full-res neighbourhood may have given light to the highlights (the same for the
    // whole group: its pixels skip the share where none does).
    FfxBoolean highlightsAround = false;
    if (lightsTile)
    {
        FFX_DOF_UNROLL
        for (FfxUInt32 k = 0u; k < 9u; ++k)
            highlightsAround = highlightsAround || ffxDofSharedTilesAround[k] != ffxDofNoHighlightFloors();
    }
    // Dilate's survey of the same 9 tiles (ffxDofSurveyTilesAround), which chose the class.
    FfxBoolean smallSourceTile =
        lightsTile && (ffxDofListedTileFlags(listedTile) & FfxUInt32(FFX_DOF_LISTED_TILE_SMALL_SOURCES)) != 0u;
    // Which tiles in the highlights' window hold one, a tile an invocation (known after the next barrier).
    if (lightsTile)
    {
        FfxInt32x2 first;
        FfxInt32x2 last;
        ffxDofHighlightWindow(groupId, constants, first, last);
        FfxUInt32 width = FfxUInt32(last.x - first.x + 1);
        FfxUInt32 windowTiles = width * FfxUInt32(last.y - first.y + 1);
        FFX_DOF_LOOP
        for (FfxUInt32 index = localIndex; index < windowTiles; index += FfxUInt32(FFX_DOF_GROUP_THREADS))
        {
            if (ffxDofTileHoldsHighlights(FfxUInt32x2(first) + FfxUInt32x2(index % width, index / width),
                                          constants.tileCount))
            {
                ffxDofGroupAtomicOr(ffxDofSharedHighlightTiles[index >> 5u], 1u << (index & 31u));
                ffxDofGroupAtomicOr(ffxDofSharedHighlightsInReach, 1u);
            }
        }
    }
    FfxInt32x2 ownSurfaceOrigin =
        FfxInt32x2(groupId * extent) - FfxInt32x2(FFX_DOF_OWN_SURFACE_BORDER, FFX_DOF_OWN_SURFACE_BORDER);
    if (ownSurfaceTile || smallSourceTile)
    {
        for (FfxUInt32 pair = localIndex; pair < FfxUInt32(FFX_DOF_OWN_SURFACE_SIDE * FFX_DOF_OWN_SURFACE_SIDE / 2);
             pair += FfxUInt32(FFX_DOF_GROUP_THREADS))
            ffxDofStoreOwnSamplePair(
                pair,
                ffxDofOwnNeighbourhoodSample(2u * pair, ownSurfaceOrigin, groupId, highlightsAround, scale, constants),
                ffxDofOwnNeighbourhoodSample(2u * pair + 1u, ownSurfaceOrigin, groupId, highlightsAround, scale,
                                             constants));
    }
    // Each invocation filters the centre texel of its quad's upsample block first (the grid's interior, one texel an
    // invocation), which its upsample then takes from registers, then the ring around the interior (the first
    // 4 (FFX_DOF_FILTERED_SIDE - 1) invocations): one group-shared read of 9 fewer per quad.
    FfxInt32x2 filteredOrigin = tileOrigin - FfxInt32x2(1, 1);
    FfxUInt32 blockIndex = quadTexel.y * FfxUInt32(FFX_DOF_FILTERED_SIDE) + quadTexel.x;
    FfxDofFilteredTexel blockCentre = ffxDofFilterTexel(blockIndex + FfxUInt32(FFX_DOF_FILTERED_SIDE) + 1u,
                                                        blockCentreRaw, filteredOrigin, constants.halfSize);
    if (localIndex < 4u * (FfxUInt32(FFX_DOF_FILTERED_SIDE) - 1u))
    {
        FfxUInt32x2 ringCell = ffxDofBorderCell(localIndex, FfxUInt32(FFX_DOF_FILTERED_SIDE));
        FfxUInt32 ringIndex = ringCell.y * FfxUInt32(FFX_DOF_FILTERED_SIDE) + ringCell.x;
        ffxDofFilterTexel(ringIndex, ffxDofRawCentreOf(ringIndex), filteredOrigin, constants.halfSize);
    }
    ffxDofGroupBarrier();

    // The quad's four fixed 3x3 blurs and input colours, taken from its 4 x 4 neighbourhood before the
    // pixels are composed, so that 28 values stay live through the (unrolled) composition instead of the
    // neighbourhood's 64: on lavapipe the pass took 0.8 times as long (docs/performance.md, "Issue 17's
    // speed gate"). Each blur is computed whether its pixel uses it or not: 36 multiply-adds per quad.
    FfxFloat32x3 fixedBlurs[4];
    FfxFloat32x4 inputColors[4];
    {
        FfxDofQuadNeighbourhood neighbourhood = ffxDofLoadQuadNeighbourhood(quad, constants.fullSize, scale);
        if (lightsTile && highlightsAround)
            neighbourhood = ffxDofNeighbourhoodLessHighlights(neighbourhood, quad, groupId, constants, scale);
        FFX_DOF_UNROLL
        for (FfxUInt32 k = 0u; k < 4u; ++k)
        {
            FfxUInt32x2 inQuad = FfxUInt32x2(k & 1u, k >> 1u);
            fixedBlurs[k] = ffxDofFixedBlur(neighbourhood, inQuad);
            inputColors[k] = neighbourhood.color[(inQuad.y + 1u) * 4u + inQuad.x + 1u];
        }
    }
    // The quad's four pixels upsample from the 3 x 3 filtered texels from the top-left neighbour of the
    // quad's own half-res texel (filtered index = its local texel, the filtered side starting one texel
    // before the tile): an even pixel reads its 2 x 2 from block offset 0 with fraction 0.75, an odd one
    // from offset 1 with 0.25 (ffxDofUpsamplePosition), per axis. Each texel is read once for the quad
    // instead of once per pixel that reads it, the centre from registers: 32 group-shared reads instead of 64.
    FfxFloat32x2 blockAlpha[9];
    FfxDofFloat3 blockNear[9];
    FfxDofFloat3 blockFar[9];
    FfxFloat32 blockCoc[9];
    FFX_DOF_UNROLL
    for (FfxUInt32 b = 0u; b < 9u; ++b)
    {
        FfxUInt32 index = blockIndex + (b / 3u) * FfxUInt32(FFX_DOF_FILTERED_SIDE) + b % 3u;
        if (b == 4u)
        {
            blockAlpha[b] = blockCentre.alpha;
            blockNear[b] = blockCentre.nearColor;
            blockFar[b] = blockCentre.farColor;
            blockCoc[b] = blockCentre.coc;
            continue;
        }
        FfxDofFilteredTexel filtered = ffxDofLoadFilteredTexel(index);
        blockAlpha[b] = filtered.alpha;
        blockNear[b] = filtered.nearColor;
        blockFar[b] = filtered.farColor;
        blockCoc[b] = filtered.coc;
    }
    // The quad's radii, and the own-surface gathers of those of its pixels that take one, in one walk.
    FfxFloat32x4 cocs = FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
    FfxUInt32 ownGathers = 0u;
    FfxUInt32 smallGathers = 0u;
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
    {
        FfxUInt32x2 pixel = quad + FfxUInt32x2(k & 1u, k >> 1u);
        cocs[k] = ffxDofLoadPixelCoc(min(pixel, constants.fullSize - FfxUInt32x2(1u, 1u)), constants);
        FfxBoolean inside = pixel.x < constants.fullSize.x && pixel.y < constants.fullSize.y;
        if (inside && ffxDofPixelGathersOwnSurface(ownSurfaceTile, abs(cocs[k])))
            ownGathers |= 1u << k;
        if (inside && ffxDofPixelGathersSmallSources(smallSourceTile, cocs[k]))
            smallGathers |= 1u << k;
    }
    FfxDofQuadHighlights highlights = ffxDofNoQuadHighlights();
    if (lightsTile && ffxDofSharedHighlightsInReach != 0u)
        highlights = ffxDofHighlightsAtQuad(groupId, quad, cocs, constants);
    FfxDofQuadGathers own;
    FfxDofQuadGathers small;
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
    {
        own.gathered[k] = FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
        small.gathered[k] = FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
    }
    FfxInt32x2 quadInNeighbourhood = FfxInt32x2(quad) - ownSurfaceOrigin;
    if (ownGathers != 0u)
        own = ffxDofGatherOwnSurfaceQuad(quadInNeighbourhood, abs(cocs), ownGathers);
    // Also for a pixel whose far layer turns out empty (it then ignores them): rare, and the walk is the quad's.
    if (smallGathers != 0u)
        small = ffxDofGatherSmallSourcesQuad(quadInNeighbourhood, abs(cocs), smallGathers);
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 4u; ++k)
    {
        FfxUInt32x2 inQuad = FfxUInt32x2(k & 1u, k >> 1u);
        FfxUInt32x2 pixel = quad + inQuad;
        if (pixel.x >= constants.fullSize.x || pixel.y >= constants.fullSize.y)
            continue;
        FfxInt32x2 topLeft;
        FfxFloat32x2 fraction = ffxDofUpsamplePosition(pixel, topLeft);
        FfxDofUpsampleTaps taps;
        FFX_DOF_UNROLL
        for (FfxUInt32 t = 0u; t < 4u; ++t)
        {
            FfxUInt32 b = (inQuad.y + t / 2u) * 3u + inQuad.x + t % 2u;
            taps.alpha[t] = blockAlpha[b];
            taps.nearColor[t] = blockNear[b];
            taps.farColor[t] = blockFar[b];
            taps.coc[t] = blockCoc[b];
        }
        FfxFloat32x4 color = inputColors[k];
#if FFX_DOF_OPTION_OUTPUT_PRE_INIT
        if (ffxDofComposePixel(taps, fraction, cocs[k], fixedBlurs[k], ownSurfaceTile, own.gathered[k], smallSourceTile,
                               small.gathered[k], highlights.added[k], highlights.nearAdded[k], color))
            ffxDofStoreOutput(pixel, ffxDofUnscaleColor(color, scale));
#else
        if (ffxDofComposePixel(taps, fraction, cocs[k], fixedBlurs[k], ownSurfaceTile, own.gathered[k], smallSourceTile,
                               small.gathered[k], highlights.added[k], highlights.nearAdded[k], color))
            ffxDofStoreOutput(pixel, ffxDofUnscaleColor(color, scale));
        else
            ffxDofStoreOutput(pixel, ffxDofLoadInputColor(pixel));
#endif
    }
}

// Composes tile `listIndex` of the list of `compositeClass` (FFX_DOF_COMPOSITE_CLASS_*, which dilate chose
// for it). The class is the pipeline's constant (FFX_DOF_OPTION_COMPOSITE_CLASS), so each pipeline holds only
// its class's work: the copy, or the layers, or the layers and the own-surface gather, or those and the lights.
FFX_DOF_INLINE void ffxDofComposite(FfxUInt32 compositeClass, FfxUInt32 listIndex, FfxUInt32 localIndex)
{
    FfxUInt32x2 tileCount = ffxDofGetConstants().tileCount;
    ffxDofCompositeTile(ffxDofListedTileWord(FfxUInt32(FFX_DOF_COMPOSITE_TILE_LIST_FIRST) + compositeClass, listIndex,
                                             tileCount.x * tileCount.y),
                        localIndex, compositeClass);
}

#endif  // FFX_DOF_COMPOSITE_H
