// Pure functions shared by the five passes of ffx-dof (no bindings, no accessors). Every function
// here is unit-tested on the CPU (tests/shaders/ffx_dof_common_tests.cpp).
//
// Units: a CoC radius is in half-resolution pixels and signed: positive in the near field (in
// front of the focus plane), negative in the far field. Distances are in half-resolution pixels.
#ifndef FFX_DOF_COMMON_H
#define FFX_DOF_COMMON_H

#include "ffx_dof_portability.h"
#include "ffx_dof_constants.h"
#include "ffx_dof_resources.h"

// ---- Options (every one can be overridden with -D; the permutation axes are listed in
// ffx_dof_permutations.json) --------------------------------------------------------------------

// Compile-time upper bound on kernel rings; the runtime bound is FfxDofConstants::maxRings.
#ifndef FFX_DOF_OPTION_MAX_RINGS
#define FFX_DOF_OPTION_MAX_RINGS 32
#endif
// Number of MIP levels of COLOR_MIPS / COC_MIPS that exist and may be sampled (1..4: a tile of
// 8 x 8 half-res px reduces to 1 x 1 at level 3 inside one workgroup).
#ifndef FFX_DOF_OPTION_MAX_MIP
#define FFX_DOF_OPTION_MAX_MIP 4
#endif
#if FFX_DOF_OPTION_MAX_MIP < 1 || FFX_DOF_OPTION_MAX_MIP > 4
#error "FFX_DOF_OPTION_MAX_MIP must be 1..4"
#endif
// 1: never merge inner kernel rings in flat far-field tiles (FFX_DOF_DISABLE_RING_MERGE).
#ifndef FFX_DOF_OPTION_DISABLE_RING_MERGE
#define FFX_DOF_OPTION_DISABLE_RING_MERGE 0
#endif
// log2 of the number of rings merged into one in flat far-field tiles (0: never merge).
#if FFX_DOF_OPTION_DISABLE_RING_MERGE
#define FFX_DOF_RING_MERGE_LOG 0
#else
#define FFX_DOF_RING_MERGE_LOG 1
#endif
// 1: the depth buffer is inverted (near plane at 1).
#ifndef FFX_DOF_OPTION_REVERSE_DEPTH
#define FFX_DOF_OPTION_REVERSE_DEPTH 0
#endif
// 1: the output already holds the input; only changed pixels are written.
#ifndef FFX_DOF_OPTION_OUTPUT_PRE_INIT
#define FFX_DOF_OPTION_OUTPUT_PRE_INIT 0
#endif

// ---- Tuning constants -------------------------------------------------------------------------

// Below this |radius| a pixel is in focus: half-resolution blur cannot represent it.
#define FFX_DOF_IN_FOCUS_RADIUS 0.5f
// Radii at or above this are near-field samples (scatter as a layer in front).
#define FFX_DOF_NEAR_THRESHOLD 0.5f
// Extra half-res px a tile's radius is granted during dilation: soft sample reach (0.5), the
// sub-pixel kernel jitter (< 0.36) and the composite's 3x3 filter plus bilinear footprint (2).
#define FFX_DOF_DILATE_MARGIN 3.0f
// Amplitude of the random kernel origin: +-half of this, in half-res px.
#define FFX_DOF_JITTER_AMPLITUDE 0.5f
// Upper bound on the brightness gain of the median post-filter.
#define FFX_DOF_MEDIAN_MAX_GAIN 2.0f
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
// From this |radius| (half-res px) on, the far layer alone makes the pixel.
#define FFX_DOF_FAR_LAYER_ONLY_RADIUS 3.0f
// Ring merging: where every radius on a texel's outermost ring is within FLAT of its own radius
// (half-res px), inner rings are merged; from NOT_FLAT on they are not; in between both are mixed.
#define FFX_DOF_RING_MERGE_FLAT_SPREAD 0.5f
#define FFX_DOF_RING_MERGE_NOT_FLAT_SPREAD 1.0f
// A blur tile whose kernels read only radii within this of each other (half-res px) takes the
// equal-weight path, where every sample weighs what the texel's own radius gives. Small: bright
// highlights a fraction of a pixel nearer than their background must keep their own radius
// (0.5 cost the far-highlights scene 0.29 dB, 0.1 nothing; docs/technique.md).
#define FFX_DOF_EQUAL_WEIGHT_SPREAD 0.1f
// Far-field samples up to this much farther than the texel itself (|radius| larger, half-res px) are
// its own surface (front layer), so that a receding surface is not split into layers; the share then
// falls to 0 over one more pixel (ffxDofFarFrontShare).
#define FFX_DOF_FAR_FRONT_TOLERANCE 0.5f

// Tile classes of the blur pass (ffxDofClassifyTile), cheapest first.
#define FFX_DOF_TILE_CLASS_COPY 0u       // every kernel is in focus: the texel is the far layer
#define FFX_DOF_TILE_CLASS_EQUAL 1u      // all radii read are within FFX_DOF_EQUAL_WEIGHT_SPREAD
#define FFX_DOF_TILE_CLASS_FAR_ONLY 2u   // no near-field radius reaches the tile
#define FFX_DOF_TILE_CLASS_NEAR_ONLY 3u  // every radius read is near-field: no far buckets, no fill
#define FFX_DOF_TILE_CLASS_MIXED 4u      // near and far field, hole filling

// ---- CoC ----------------------------------------------------------------------------------------

// Signed CoC radius of a depth value, always in 32-bit: rounding depth to 16 bits first would move
// in-focus pixels next to the near plane out of focus.
FFX_DOF_INLINE FfxFloat32 ffxDofCocFromDepth(FfxFloat32 depth, FfxFloat32 cocScale, FfxFloat32 cocBias,
                                             FfxFloat32 cocLimit)
{
    return clamp(depth * cocScale + cocBias, -cocLimit, cocLimit);
}

// The depth (of two) that is nearer the camera: the smaller one unless the depth buffer is inverted.
FFX_DOF_INLINE FfxFloat32 ffxDofNearerDepth(FfxFloat32 a, FfxFloat32 b)
{
#if FFX_DOF_OPTION_REVERSE_DEPTH
    return max(a, b);
#else
    return min(a, b);
#endif
}
FFX_DOF_INLINE FfxFloat32 ffxDofFartherDepth(FfxFloat32 a, FfxFloat32 b)
{
#if FFX_DOF_OPTION_REVERSE_DEPTH
    return min(a, b);
#else
    return max(a, b);
#endif
}

// ---- Bilateral downsampling ----------------------------------------------------------------------

FFX_DOF_INLINE FfxFloat32 ffxDofLuminance(FfxDofFloat3 color)
{
    return FfxFloat32(color.x) * 0.2126f + FfxFloat32(color.y) * 0.7152f + FfxFloat32(color.z) * 0.0722f;
}

// Weight of a pixel of a 2x2 quad relative to the quad's top-left pixel: 1 for equal radii, falling
// linearly to 0 at a difference of one pixel of radius.
FFX_DOF_INLINE FfxFloat32 ffxDofBilateralWeight(FfxFloat32 referenceCoc, FfxFloat32 coc)
{
    return ffxDofSaturate(1.0f - abs(coc - referenceCoc));
}

// The reference radius of a 2x2 quad: the one closest to the quad's mean (the same whichever pixel
// of the quad it is; the top-left pixel as reference made an isolated pixel of another radius gain
// energy at one position of the quad and lose it at the others).
FFX_DOF_INLINE FfxFloat32 ffxDofQuadReferenceCoc(FfxFloat32 coc0, FfxFloat32 coc1, FfxFloat32 coc2, FfxFloat32 coc3)
{
    FfxFloat32 mean = (coc0 + coc1 + coc2 + coc3) * 0.25f;
    FfxFloat32 reference = coc0;
    if (abs(coc1 - mean) < abs(reference - mean))
        reference = coc1;
    if (abs(coc2 - mean) < abs(reference - mean))
        reference = coc2;
    if (abs(coc3 - mean) < abs(reference - mean))
        reference = coc3;
    return reference;
}

// Weight of a quad pixel of radius `coc`: 1 for all while every radius of the quad is within one
// pixel of every other (the plain average: every pixel's energy stays in the texel), the bilateral
// weight relative to the reference once the quad's range of radii exceeds 1.25 px, mixed in between
// so that the texel changes continuously with the radii.
FFX_DOF_INLINE FfxFloat32 ffxDofQuadWeight(FfxFloat32 referenceCoc, FfxFloat32 cocRange, FfxFloat32 coc)
{
    return max(ffxDofBilateralWeight(referenceCoc, coc), ffxDofSaturate((1.25f - cocRange) * 4.0f));
}

// Luminance of the quad's reference pixel (the first whose radius is the reference).
FFX_DOF_INLINE FfxFloat32 ffxDofQuadReferenceLuminance(FfxFloat32 reference, FfxFloat32 coc0, FfxFloat32 coc1,
                                                       FfxFloat32 coc2, FfxDofFloat3 color0, FfxDofFloat3 color1,
                                                       FfxDofFloat3 color2, FfxDofFloat3 color3)
{
    if (coc0 == reference)
        return ffxDofLuminance(color0);
    if (coc1 == reference)
        return ffxDofLuminance(color1);
    if (coc2 == reference)
        return ffxDofLuminance(color2);
    return ffxDofLuminance(color3);
}

// Keeps the energy of small lights through the bilateral reduction, which would drop the pixels of
// another radius than the quad's reference:
// - a pixel far brighter than the reference pixel is kept whatever its radius (weight 1 from 4 times
//   the reference's luminance, none below 2 times): a small light among pixels of another radius
//   would otherwise vanish from the half-resolution image and every MIP above it. Its radius then
//   dominates the texel's (radii are averaged with luminance weights), so it spreads with its disc;
// - where the reference is itself such a light in the far field, the far darker pixels behind it are
//   kept as well (same ratios): dropped, the light's color would fill the whole texel, and a light of
//   a few texels would gain up to a third of its energy at every MIP level.
FFX_DOF_INLINE FfxFloat32 ffxDofLightKeep(FfxDofFloat3 color, FfxFloat32 coc, FfxFloat32 referenceCoc,
                                          FfxFloat32 referenceLuminance)
{
    // Only within the far field: a near-field pixel in a far texel, or the reverse,
    // would move the texel's radius across the layers.
    if (coc >= FFX_DOF_NEAR_THRESHOLD || referenceCoc >= FFX_DOF_NEAR_THRESHOLD)
        return 0.0f;
    FfxFloat32 luminance = ffxDofLuminance(color);
    // An in-focus pixel is drawn from the full-resolution input: kept in a blurred texel, it would
    // only spread its color into the background.
    FfxFloat32 brighter = ffxDofSaturate(luminance / (2.0f * referenceLuminance + 1e-4f) - 1.0f) *
                          ffxDofSaturate(-coc - FFX_DOF_IN_FOCUS_RADIUS);
    FfxFloat32 darkerBehind = ffxDofSaturate(referenceLuminance / (2.0f * luminance + 1e-4f) - 1.0f) *
                              ffxDofSaturate(referenceCoc - coc) *
                              ffxDofSaturate(-referenceCoc - FFX_DOF_IN_FOCUS_RADIUS);
    return max(brighter, darkerBehind);
}

// Reduces a 2x2 quad (0: top-left, 1: top-right, 2: bottom-left, 3: bottom-right). The same kernel
// makes every MIP level. The radius is averaged with the color's luminance as an extra weight: the
// texel's light spreads with the radius of the pixels it comes from (a bright point keeps its own
// radius among darker pixels of a slightly different one).
FFX_DOF_INLINE void ffxDofBilateralReduce(FfxDofFloat3 color0, FfxDofFloat3 color1, FfxDofFloat3 color2,
                                          FfxDofFloat3 color3, FfxFloat32 coc0, FfxFloat32 coc1, FfxFloat32 coc2,
                                          FfxFloat32 coc3, FFX_DOF_OUT(FfxDofFloat3) color, FFX_DOF_OUT(FfxFloat32) coc)
{
    FfxFloat32 reference = ffxDofQuadReferenceCoc(coc0, coc1, coc2, coc3);
    FfxFloat32 range = max(max(coc0, coc1), max(coc2, coc3)) - min(min(coc0, coc1), min(coc2, coc3));
    FfxFloat32 referenceLight =
        ffxDofQuadReferenceLuminance(reference, coc0, coc1, coc2, color0, color1, color2, color3);
    FfxFloat32 weight0 =
        max(ffxDofQuadWeight(reference, range, coc0), ffxDofLightKeep(color0, coc0, reference, referenceLight));
    FfxFloat32 weight1 =
        max(ffxDofQuadWeight(reference, range, coc1), ffxDofLightKeep(color1, coc1, reference, referenceLight));
    FfxFloat32 weight2 =
        max(ffxDofQuadWeight(reference, range, coc2), ffxDofLightKeep(color2, coc2, reference, referenceLight));
    FfxFloat32 weight3 =
        max(ffxDofQuadWeight(reference, range, coc3), ffxDofLightKeep(color3, coc3, reference, referenceLight));
    FfxFloat32 normalization = 1.0f / (weight0 + weight1 + weight2 + weight3);  // the reference weighs 1
    color = (color0 * FfxDofFloat(weight0) + color1 * FfxDofFloat(weight1) + color2 * FfxDofFloat(weight2) +
             color3 * FfxDofFloat(weight3)) *
            FfxDofFloat(normalization);
    // A small floor keeps black quads at the plain weighted mean.
    FfxFloat32 light0 = weight0 * (ffxDofLuminance(color0) + 1e-3f);
    FfxFloat32 light1 = weight1 * (ffxDofLuminance(color1) + 1e-3f);
    FfxFloat32 light2 = weight2 * (ffxDofLuminance(color2) + 1e-3f);
    FfxFloat32 light3 = weight3 * (ffxDofLuminance(color3) + 1e-3f);
    coc = (coc0 * light0 + coc1 * light1 + coc2 * light2 + coc3 * light3) / (light0 + light1 + light2 + light3);
}

// ---- Storage ------------------------------------------------------------------------------------

// Rounds a non-negative float to nearest with `mantissaBits` bits of mantissa. The packed float
// formats of the half-res color images (B10G11R11: 6, 6 and 5 bits) may be written by truncation
// (lavapipe does), which darkens every stored color by half a unit in the last place on average, a
// bias that adds up over the two stores a blurred pixel goes through; rounding first makes the
// store exact whichever rounding the device uses.
FFX_DOF_INLINE FfxFloat32 ffxDofRoundMantissa(FfxFloat32 value, FfxUInt32 mantissaBits)
{
    FfxUInt32 dropped = 23u - mantissaBits;
    FfxUInt32 bits = ffxDofAsUInt(max(value, 0.0f)) + (1u << (dropped - 1u));
    return ffxDofAsFloat(bits & ~((1u << dropped) - 1u));
}
FFX_DOF_INLINE FfxDofFloat3 ffxDofRoundForPackedColor(FfxDofFloat3 color)
{
    return FfxDofFloat3(FfxDofFloat(ffxDofRoundMantissa(FfxFloat32(color.x), 6u)),
                        FfxDofFloat(ffxDofRoundMantissa(FfxFloat32(color.y), 6u)),
                        FfxDofFloat(ffxDofRoundMantissa(FfxFloat32(color.z), 5u)));
}

// ---- HDR range ---------------------------------------------------------------------------------

// The internal colour images are B10G11R11 float (largest finite value 65024) and the 16-bit
// permutation computes colour in half (65504); weighted sums (the bilateral reduction's 4 taps, the
// composite's fixed 3x3 blur) reach several times a pixel's value. A frame whose largest finite
// colour channel (its colour peak, reduced by pass 1 into GLOBALS) exceeds this limit is scaled by
// ffxDofColorRangeScale on the way in (passes 2 and 5) and back on the way out (pass 5). A power of
// two, so that scaling is exact.
#define FFX_DOF_COLOR_RANGE_LIMIT 4096.0f
#define FFX_DOF_COLOR_RANGE_LIMIT_LOG2 12
// The largest finite 32-bit float and the largest finite half.
#define FFX_DOF_FLOAT32_MAX 3.402823466e38f
#define FFX_DOF_FLOAT16_MAX 65504.0f

// `value` when it is finite and not negative (so it can be a colour peak), else 0 (NaN, inf and
// negative channels never set the peak: they are left as they are, as before).
FFX_DOF_INLINE FfxFloat32 ffxDofPeakCandidate(FfxFloat32 value)
{
    return (value >= 0.0f && value <= FFX_DOF_FLOAT32_MAX) ? value : 0.0f;
}
// The largest finite, non-negative channel of an RGB(A) colour (alpha ignored), else 0.
FFX_DOF_INLINE FfxFloat32 ffxDofColorPeak(FfxFloat32x4 color)
{
    return max(max(ffxDofPeakCandidate(color.x), ffxDofPeakCandidate(color.y)), ffxDofPeakCandidate(color.z));
}

// The factor the frame's colour is multiplied by inside the effect: 1 when `peak` (the largest finite
// colour channel of the frame) is at most FFX_DOF_COLOR_RANGE_LIMIT, else the largest power of two
// 2^-k with peak * 2^-k <= FFX_DOF_COLOR_RANGE_LIMIT (for any finite peak, k <= 116: a normal float).
FFX_DOF_INLINE FfxFloat32 ffxDofColorRangeScale(FfxFloat32 peak)
{
    if (!(peak > FFX_DOF_COLOR_RANGE_LIMIT))
        return 1.0f;
    FfxUInt32 bits = ffxDofAsUInt(min(peak, FFX_DOF_FLOAT32_MAX));
    // peak is in [2^exponent, 2^(exponent + 1)); an exact power of two needs one step less.
    FfxInt32 exponent = FfxInt32((bits >> 23u) & 0xffu) - 127;
    FfxInt32 k = exponent - FFX_DOF_COLOR_RANGE_LIMIT_LOG2 + ((bits & 0x7fffffu) != 0u ? 1 : 0);
    return ffxDofAsFloat(FfxUInt32(127 - k) << 23u);
}

// A 32-bit colour channel scaled into the effect's range, clamped so that its conversion to half (or
// to B10G11R11) cannot give inf. Values the clamp does not touch are unchanged.
FFX_DOF_INLINE FfxFloat32 ffxDofScaleChannel(FfxFloat32 value, FfxFloat32 scale)
{
    return min(value * scale, FFX_DOF_FLOAT16_MAX);
}
FFX_DOF_INLINE FfxFloat32x4 ffxDofScaleColor(FfxFloat32x4 color, FfxFloat32 scale)
{
    return FfxFloat32x4(ffxDofScaleChannel(color.x, scale), ffxDofScaleChannel(color.y, scale),
                        ffxDofScaleChannel(color.z, scale), color.w);
}
// Back from the effect's range: exact for a power-of-two scale (unless the result is a denormal),
// clamped to the largest finite float.
FFX_DOF_INLINE FfxFloat32x4 ffxDofUnscaleColor(FfxFloat32x4 color, FfxFloat32 scale)
{
    return FfxFloat32x4(min(color.x / scale, FFX_DOF_FLOAT32_MAX), min(color.y / scale, FFX_DOF_FLOAT32_MAX),
                        min(color.z / scale, FFX_DOF_FLOAT32_MAX), color.w);
}

// ---- Workgroup and tile arithmetic --------------------------------------------------------------

// Position of an invocation in its 8 x 8 workgroup.
FFX_DOF_INLINE FfxUInt32x2 ffxDofLocalCoord(FfxUInt32 localIndex)
{
    return FfxUInt32x2(localIndex % 8u, localIndex / 8u);
}

// Size of MIP level `mip` of an image whose level 0 is `size` (the Vulkan/D3D rule).
FFX_DOF_INLINE FfxUInt32x2 ffxDofMipSize(FfxUInt32x2 size, FfxUInt32 mip)
{
    return max(FfxUInt32x2(size.x >> mip, size.y >> mip), FfxUInt32x2(1u, 1u));
}

// Shortest distance, in half-res px, between a pixel centre of the central tile and a pixel centre
// of the tile `tileOffset` tiles away.
FFX_DOF_INLINE FfxFloat32 ffxDofTileGapDistance(FfxInt32x2 tileOffset)
{
    FfxFloat32 tileSize = FfxFloat32(FFX_DOF_TILE_SIZE);
    FfxFloat32 gapX = max(FfxFloat32(abs(tileOffset.x)) * tileSize - (tileSize - 1.0f), 0.0f);
    FfxFloat32 gapY = max(FfxFloat32(abs(tileOffset.y)) * tileSize - (tileSize - 1.0f), 0.0f);
    return sqrt(gapX * gapX + gapY * gapY);
}

// Whether a tile whose largest spreading radius is `radius` can affect any pixel `distance` away
// (ffxDofTileGapDistance), including everything the later passes derive from that pixel.
FFX_DOF_INLINE FfxBoolean ffxDofTileReaches(FfxFloat32 radius, FfxFloat32 distance)
{
    return radius > 0.0f && radius + FFX_DOF_DILATE_MARGIN > distance;
}

// Number of tiles to look at on each side of the central tile during dilation.
FFX_DOF_INLINE FfxInt32 ffxDofDilateTileRange(FfxFloat32 globalMaxRadius)
{
    return FfxInt32(ceil((globalMaxRadius + FFX_DOF_DILATE_MARGIN) / FfxFloat32(FFX_DOF_TILE_SIZE)));
}

// Largest kernel radius of any texel of a tile whose dilated (far, near) range is `farNear`: a texel's
// kernel is max(dilated near radius, |own radius|), and its own radius is within the range.
FFX_DOF_INLINE FfxFloat32 ffxDofTileKernelRadius(FfxFloat32x2 farNear) { return max(max(farNear.y, -farNear.x), 0.0f); }

// Distance (half-res px, from texel centre to texel centre) within which the blur kernels of a tile
// whose largest kernel radius is `kernelRadius` can read a texel or a MIP texel covering it: the
// radius, the sub-pixel origin (FFX_DOF_DILATE_MARGIN covers it), and two ring spacings for the
// extent of the MIP texels read (ffxDofMipForSpacing's texels are at most 1.41 spacings wide, a
// merged ring's 2.83: half a diagonal is at most 2 spacings).
FFX_DOF_INLINE FfxFloat32 ffxDofKernelFootprintRadius(FfxFloat32 kernelRadius, FfxUInt32 maxRings)
{
    FfxFloat32 rings = FfxFloat32(clamp(maxRings, 1u, FfxUInt32(FFX_DOF_OPTION_MAX_RINGS)));
    return kernelRadius + FFX_DOF_DILATE_MARGIN + 2.0f * max(kernelRadius / rings, 1.0f);
}

// Blur path of a tile from its DILATED_TILES texel (far, near, footprint min, footprint max).
// Per tile, never per texel, so that a workgroup runs one path; every path gives what the mixed
// path would give on that tile (the equal-weight path up to radii within the spread), so the
// choice never shows as a tile border.
FFX_DOF_INLINE FfxUInt32 ffxDofClassifyTile(FfxFloat32x4 dilated)
{
    if (ffxDofTileKernelRadius(FfxFloat32x2(dilated.x, dilated.y)) < FFX_DOF_IN_FOCUS_RADIUS)
        return FFX_DOF_TILE_CLASS_COPY;
    FfxBoolean allNear = dilated.z >= FFX_DOF_NEAR_THRESHOLD;
    FfxBoolean allFar = dilated.w < FFX_DOF_NEAR_THRESHOLD;
    if ((allNear || allFar) && dilated.w - dilated.z <= FFX_DOF_EQUAL_WEIGHT_SPREAD)
        return FFX_DOF_TILE_CLASS_EQUAL;
    if (dilated.y < FFX_DOF_NEAR_THRESHOLD)
        return FFX_DOF_TILE_CLASS_FAR_ONLY;
    if (allNear)
        return FFX_DOF_TILE_CLASS_NEAR_ONLY;
    return FFX_DOF_TILE_CLASS_MIXED;
}

// ---- Kernel shape: the only function that knows it is circular ---------------------------------

// Half the width of the kernel's row `dy` from its centre, for a kernel of `radius` (same units): a
// texel is in the kernel when its centre lies less than this far from the centre horizontally.
// Another bokeh shape replaces this function (the row of a convex polygon is one interval too).
FFX_DOF_INLINE FfxFloat32 ffxDofKernelRowHalfWidth(FfxFloat32 radius, FfxFloat32 dy)
{
    return sqrt(max(radius * radius - dy * dy, 0.0f));
}

// ---- Kernel walk: every texel of a ring read once -----------------------------------------------
//
// Ring k of a kernel whose rings are s apart holds the texels whose centres lie at [(k - 1/2) s,
// (k + 1/2) s) from the kernel origin (ring 0: [0, s / 2)), and the blur reads each of them once,
// walking rows. (Points on a circle read from the nearest texel hit a one-texel source 0, 1 or 2
// times depending on the output texel: a dotted disc, issue 6.)

// The texels (first, last) of a row or column whose centres lie less than `halfWidth` from `center`;
// in texels, texel i spanning [i, i + 1). first > last when there are none. Strict on both sides,
// so two rings that share a border share no texel and miss none.
FFX_DOF_INLINE FfxFloat32x2 ffxDofTexelSpan(FfxFloat32 center, FfxFloat32 halfWidth)
{
    return FfxFloat32x2(floor(center - 0.5f - halfWidth) + 1.0f, ceil(center - 0.5f + halfWidth) - 1.0f);
}

// Inner radius of ring `ring` for rings `spacing` apart; the outer radius of ring k is the inner
// radius of ring k + 1, the same expression, so that the rings tile the kernel exactly.
FFX_DOF_INLINE FfxFloat32 ffxDofRingInnerRadius(FfxUInt32 ring, FfxFloat32 spacing)
{
    return max(FfxFloat32(ring) - 0.5f, 0.0f) * spacing;
}

// The texels whose centres lie at [innerRadius, outerRadius) from `origin` (all in texels of one
// MIP level), walked row by row: what does not change during the walk ...
// Each border may be judged at a coarser MIP than the walk's (a block of `innerBlock` / `outerBlock`
// texels per side, a power of two; 1: the walk's own texels): where a walk meets a walk of a coarser
// MIP, both judge their common border by the coarse texels' centres, so a texel of the finer level
// is read once, by one of them. Judged by each side's own centres, a one-texel source next to the
// border was read twice or not at all: a notched, soft rim and a dip at the centre of a single
// point's disc, and a small light losing or gaining energy (issue 17).
// One border of an annulus, judged in blocks of `block` texels: what a row's span needs, computed
// once per walk (the span of the next row is computed at every step of the walk).
struct FfxDofAnnulusBorder
{
    FfxFloat32 block;          // texels per block side (a power of two)
    FfxFloat32 scale;          // 1 / block
    FfxFloat32 radiusSquared;  // in blocks^2
    FfxFloat32 spanCenter;     // origin.x in blocks, less half a block (ffxDofTexelSpan's centre - 0.5)
    FfxFloat32 rowOffset;      // half a block less origin.y, in blocks
};
struct FfxDofAnnulus
{
    FfxFloat32x2 origin;
    FfxDofAnnulusBorder inner;
    FfxDofAnnulusBorder outer;
    FfxFloat32 firstRow;
    FfxFloat32 lastRow;
};
// ... and the walk's position.
struct FfxDofAnnulusWalk
{
    FfxFloat32x2 texel;    // the current position, a texel of the annulus while texel.x <= rowLast
    FfxFloat32 rowLast;    // last texel of the current row
    FfxFloat32 holeFirst;  // first texel of the row inside the inner radius
    FfxFloat32 holeEnd;    // first texel after them (holeFirst when the row has none)
};

// A border of `radius` around `origin` judged in blocks of `block` texels. The block figures are the
// ones the coarse walk computes for itself (scaling by a power of two is exact), so the two walks
// agree to the bit on every block.
FFX_DOF_INLINE FfxDofAnnulusBorder ffxDofMakeAnnulusBorder(FfxFloat32x2 origin, FfxFloat32 radius, FfxFloat32 block)
{
    FfxDofAnnulusBorder border;
    border.block = block;
    border.scale = 1.0f / block;
    FfxFloat32 blockRadius = radius * border.scale;
    border.radiusSquared = blockRadius * blockRadius;
    border.spanCenter = origin.x * border.scale - 0.5f;
    border.rowOffset = 0.5f - origin.y * border.scale;
    return border;
}

// The texels (first, last) of row `y` whose block has its centre less than the border's radius from
// the origin: ffxDofTexelSpan of the block row, widened to whole blocks (with block 1, the texels of
// the row whose centres are inside). first > last when there are none.
FFX_DOF_INLINE FfxFloat32x2 ffxDofBorderSpan(FfxDofAnnulusBorder border, FfxFloat32 y)
{
    FfxFloat32 dy = floor(y * border.scale) + border.rowOffset;
    FfxFloat32 halfWidth = sqrt(max(border.radiusSquared - dy * dy, 0.0f));
    FfxFloat32 first = floor(border.spanCenter - halfWidth) + 1.0f;
    FfxFloat32 last = ceil(border.spanCenter + halfWidth) - 1.0f;
    return FfxFloat32x2(first * border.block, last * border.block + border.block - 1.0f);
}

FFX_DOF_INLINE FfxDofAnnulus ffxDofMakeAnnulus(FfxFloat32x2 origin, FfxFloat32 innerRadius, FfxFloat32 outerRadius,
                                               FfxFloat32 innerBlock, FfxFloat32 outerBlock)
{
    FfxDofAnnulus annulus;
    annulus.origin = origin;
    annulus.inner = ffxDofMakeAnnulusBorder(origin, innerRadius, innerBlock);
    annulus.outer = ffxDofMakeAnnulusBorder(origin, outerRadius, outerBlock);
    FfxFloat32x2 rows = ffxDofTexelSpan(origin.y * annulus.outer.scale, outerRadius * annulus.outer.scale);
    annulus.firstRow = rows.x * outerBlock;
    annulus.lastRow = rows.y * outerBlock + outerBlock - 1.0f;
    return annulus;
}

// Row `y` of the annulus, positioned on its first texel (past its last one when it has none).
FFX_DOF_INLINE FfxDofAnnulusWalk ffxDofAnnulusRow(FfxDofAnnulus annulus, FfxFloat32 y)
{
    FfxFloat32x2 row = ffxDofBorderSpan(annulus.outer, y);
    FfxFloat32x2 hole = ffxDofBorderSpan(annulus.inner, y);
    FfxDofAnnulusWalk walk;
    walk.rowLast = row.y;
    walk.holeFirst = hole.x;
    // An empty hole (first > last, by 2 where the origin lies exactly on a texel centre) must not
    // send the walk backwards.
    walk.holeEnd = max(hole.y + 1.0f, hole.x);
    // Judged in blocks of different sizes, the hole may begin before the row does.
    walk.texel = FfxFloat32x2(row.x >= walk.holeFirst && row.x < walk.holeEnd ? walk.holeEnd : row.x, y);
    return walk;
}

FFX_DOF_INLINE FfxDofAnnulusWalk ffxDofAnnulusBegin(FfxDofAnnulus annulus)
{
    return ffxDofAnnulusRow(annulus, annulus.firstRow);
}

// Whether the walk has rows left. Its position may still be no texel: a row at the top or bottom,
// or a row of a thin annulus, can be empty, and a walk step finds one row, never loops over rows
// (ffxDofAnnulusValid says).
FFX_DOF_INLINE FfxBoolean ffxDofAnnulusRowsLeft(FfxDofAnnulus annulus, FfxDofAnnulusWalk walk)
{
    return walk.texel.y <= annulus.lastRow;
}
FFX_DOF_INLINE FfxBoolean ffxDofAnnulusValid(FfxDofAnnulusWalk walk) { return walk.texel.x <= walk.rowLast; }

// One step: the next texel of the row, else the first of the next row. Straight-line, the next row
// computed and selected: a loop over empty rows (or a branch, on devices that run both sides of
// every branch in lock step, like lavapipe) cost more than the row itself.
FFX_DOF_INLINE FfxDofAnnulusWalk ffxDofAnnulusNext(FfxDofAnnulus annulus, FfxDofAnnulusWalk walk)
{
    FfxFloat32 x = walk.texel.x + 1.0f;
    walk.texel.x = x == walk.holeFirst ? walk.holeEnd : x;
    FfxDofAnnulusWalk next = ffxDofAnnulusRow(annulus, walk.texel.y + 1.0f);
    return walk.texel.x > walk.rowLast ? next : walk;
}

// ---- Kernel size --------------------------------------------------------------------------------

// Rings for a kernel of `radius`: none below the in-focus radius (the pixel is copied), else one per
// pixel of radius, at most the quality setting and FFX_DOF_OPTION_MAX_RINGS.
FFX_DOF_INLINE FfxUInt32 ffxDofRingCount(FfxFloat32 radius, FfxUInt32 maxRings)
{
    if (radius < FFX_DOF_IN_FOCUS_RADIUS)
        return 0u;
    FfxUInt32 limit = clamp(maxRings, 1u, FfxUInt32(FFX_DOF_OPTION_MAX_RINGS));
    return min(FfxUInt32(ceil(radius)), limit);
}

// MIP level to read when rings are `spacing` half-res px apart: the level whose texel size is nearest
// the spacing in log2, so the spacing is 0.71 to 1.41 texels (from 0.5 at level 0). The blur reads
// every texel of its kernel, pi ((rings + 1/2) s / texel)^2 of them, where 6k points per ring cost
// 3 rings^2: rounding the level keeps the two about equal (pi E[(s / texel)^2] = 3.4 for a
// log-uniform spacing); the finest level no larger than the spacing cost up to 4 times as much.
FFX_DOF_INLINE FfxFloat32 ffxDofMipForSpacing(FfxFloat32 spacing)
{
    return clamp(floor(log2(max(spacing, 1.0f)) + 0.5f), 0.0f, FfxFloat32(FFX_DOF_OPTION_MAX_MIP - 1));
}

// Random sub-pixel kernel origin for one pixel and frame, in half-res px.
FFX_DOF_INLINE FfxUInt32 ffxDofHash(FfxUInt32 x)
{
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}
FFX_DOF_INLINE FfxFloat32x2 ffxDofKernelJitter(FfxUInt32x2 pixel, FfxUInt32 frameIndex)
{
    FfxUInt32 h = ffxDofHash(pixel.x ^ ffxDofHash(pixel.y ^ ffxDofHash(frameIndex)));
    FfxFloat32x2 unit = FfxFloat32x2(FfxFloat32(h & 0xffffu), FfxFloat32(h >> 16u)) * (1.0f / 65536.0f);
    return (unit - FfxFloat32x2(0.5f, 0.5f)) * FFX_DOF_JITTER_AMPLITUDE;
}

// ---- Gathering ----------------------------------------------------------------------------------

// How much of the merged-ring path a texel takes (0: all rings at full resolution, 1: merged), from
// the largest difference between its own radius and those on its outermost ring. Continuous, so
// the result changes smoothly where the radii stop being flat.
FFX_DOF_INLINE FfxFloat32 ffxDofRingMergeAmount(FfxFloat32 cocSpread)
{
    return ffxDofSaturate((FFX_DOF_RING_MERGE_NOT_FLAT_SPREAD - cocSpread) /
                          (FFX_DOF_RING_MERGE_NOT_FLAT_SPREAD - FFX_DOF_RING_MERGE_FLAT_SPREAD));
}

// How much a sample of |radius| reaches a pixel `distance` away (scatter-as-gather), with half a
// pixel of anti-aliasing.
FFX_DOF_INLINE FfxFloat32 ffxDofReach(FfxFloat32 absRadius, FfxFloat32 distance)
{
    return ffxDofSaturate(absRadius - distance + 0.5f);
}

// A sample spreads its energy over its disc: weight proportional to the inverse disc area,
// normalized so that a radius of half a pixel or less weighs 4.
FFX_DOF_INLINE FfxFloat32 ffxDofAreaWeight(FfxFloat32 absRadius) { return 1.0f / max(absRadius * absRadius, 0.25f); }

// A weighted sum of far-field samples.
struct FfxDofBucket
{
    FfxFloat32x3 color;  // sum of color * weight (32-bit: hundreds of HDR samples overflow 16 bits)
    FfxFloat32 weight;   // sum of reach * area weight * texel area
};

FFX_DOF_INLINE FfxDofBucket ffxDofEmptyBucket()
{
    FfxDofBucket bucket;
    bucket.color = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    bucket.weight = 0.0f;
    return bucket;
}

// How much of a far-field sample of |radius| `absRadius` belongs to the front layer of a texel whose
// own far-field |radius| is `centerAbsRadius`: 1 up to FFX_DOF_FAR_FRONT_TOLERANCE beyond the texel's
// own radius (the texel's surface and everything nearer the camera), falling to 0 one pixel of radius
// farther (the background, seen only where the front layer leaves gaps). A texel in the near field has
// no front layer: every far-field sample is background to it.
FFX_DOF_INLINE FfxFloat32 ffxDofFarFrontShare(FfxFloat32 absRadius, FfxFloat32 centerAbsRadius)
{
    return ffxDofSaturate(centerAbsRadius + FFX_DOF_FAR_FRONT_TOLERANCE + 1.0f - absRadius);
}

// Far-field color of a texel from its two layers, composed front to back. Every far sample spreads its
// light over its own disc, so the front layer's summed weights over pi are the share of the texel it
// covers (a solid surface of any radius sums to pi: opacity 1); the background shows through the rest.
// Without this, the ring occlusion of the technique let a small light nearer than its background
// occlude the whole kernel at its own position: its centre kept the input's brightness on top of its
// disc. Returns false when neither layer has weight (no far-field sample reaches the texel).
FFX_DOF_INLINE FfxBoolean ffxDofComposeFarLayers(FfxDofBucket front, FfxDofBucket back, FFX_DOF_OUT(FfxFloat32x3) color)
{
    color = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    if (front.weight <= 0.0f && back.weight <= 0.0f)
        return false;
    if (back.weight <= 0.0f)
    {
        color = front.color / front.weight;
        return true;
    }
    FfxFloat32 frontOpacity = ffxDofSaturate(front.weight * (1.0f / 3.14159265359f));
    FfxFloat32x3 frontColor = front.weight > 0.0f ? front.color / front.weight : FfxFloat32x3(0.0f, 0.0f, 0.0f);
    color = frontColor * frontOpacity + (back.color / back.weight) * (1.0f - frontOpacity);
    return true;
}

// Near-field opacity from the weights of the near samples that reach the pixel (scatter as gather).
// A sample weighs reach * ffxDofAreaWeight(radius) * the area of the texel read (4^mip half-res
// px^2), so the sum is the area the near field covers in the kernel over its discs' areas / pi: a
// solid near region of the kernel's radius R sums to pi R^2 / R^2 = pi, opacity 1.
FFX_DOF_INLINE FfxFloat32 ffxDofNearOpacity(FfxFloat32 nearWeight)
{
    return ffxDofSaturate(nearWeight * (1.0f / 3.14159265359f));
}

// ---- Post-filter and composition ----------------------------------------------------------------

// Median of nine values by a 19-exchange selection network.
FFX_DOF_INLINE void ffxDofSort2(FFX_DOF_INOUT(FfxFloat32) a, FFX_DOF_INOUT(FfxFloat32) b)
{
    FfxFloat32 lo = min(a, b);
    b = max(a, b);
    a = lo;
}
FFX_DOF_INLINE FfxFloat32 ffxDofMedian9(FfxFloat32 p0, FfxFloat32 p1, FfxFloat32 p2, FfxFloat32 p3, FfxFloat32 p4,
                                        FfxFloat32 p5, FfxFloat32 p6, FfxFloat32 p7, FfxFloat32 p8)
{
    ffxDofSort2(p1, p2);
    ffxDofSort2(p4, p5);
    ffxDofSort2(p7, p8);
    ffxDofSort2(p0, p1);
    ffxDofSort2(p3, p4);
    ffxDofSort2(p6, p7);
    ffxDofSort2(p1, p2);
    ffxDofSort2(p4, p5);
    ffxDofSort2(p7, p8);
    p3 = max(p0, p3);
    p5 = min(p5, p8);
    ffxDofSort2(p4, p7);
    p6 = max(p3, p6);
    p4 = max(p1, p4);
    p2 = min(p2, p5);
    p4 = min(p4, p7);
    ffxDofSort2(p4, p2);
    p4 = max(p6, p4);
    return min(p4, p2);
}

// Brightness factor that moves a pixel of luminance `centerLuminance` to the median of its
// neighbourhood; a zero median or a black pixel leaves it unchanged, the gain is bounded.
FFX_DOF_INLINE FfxFloat32 ffxDofMedianGain(FfxFloat32 centerLuminance, FfxFloat32 medianLuminance)
{
    if (medianLuminance <= 0.0f || centerLuminance <= 0.0f)
        return 1.0f;
    return min(medianLuminance / centerLuminance, FFX_DOF_MEDIAN_MAX_GAIN);
}

// Blend weight from a filtered opacity: flat at 0 and 1 so that the layer edges do not bleed.
FFX_DOF_INLINE FfxFloat32 ffxDofCubicWeight(FfxFloat32 opacity)
{
    FfxFloat32 a = ffxDofSaturate(opacity);
    return a * a * (3.0f - 2.0f * a);
}

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
// the pixel's, relative to the pixel's own radius. Never exactly 0, so a pixel that matches no tap
// falls back to plain bilinear weights.
FFX_DOF_INLINE FfxFloat32 ffxDofUpsampleCocWeight(FfxFloat32 tapCoc, FfxFloat32 pixelCoc)
{
    FfxFloat32 tolerance = max(1.0f, 0.5f * abs(pixelCoc));
    return max(ffxDofSaturate(1.0f - abs(tapCoc - pixelCoc) / tolerance), 1e-3f);
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

// sRGB encoding for outputs written through a UNORM view of an sRGB image.
FFX_DOF_INLINE FfxFloat32 ffxDofLinearToSrgb(FfxFloat32 x)
{
    FfxFloat32 c = ffxDofSaturate(x);
    return c <= 0.0031308f ? c * 12.92f : 1.055f * pow(c, 1.0f / 2.4f) - 0.055f;
}

// sRGB decoding, for an in-place input read back through a UNORM view of an sRGB image.
FFX_DOF_INLINE FfxFloat32 ffxDofSrgbToLinear(FfxFloat32 x)
{
    return x <= 0.04045f ? x / 12.92f : pow((x + 0.055f) / 1.055f, 2.4f);
}

#endif  // FFX_DOF_COMMON_H
