// Pure functions and constants that several of the five passes of ffx-dof share (no bindings, no
// accessors); what one pass alone needs lives in that pass's header, next to its use. Unit-tested on
// the CPU with the pass headers' functions (tests/shaders/ffx_dof_common_tests.cpp).
//
// Units: a CoC radius is in half-resolution pixels and signed: positive in the near field (in
// front of the focus plane), negative in the far field. Distances are in half-resolution pixels.
#ifndef FFX_DOF_COMMON_H
#define FFX_DOF_COMMON_H

#include "ffx_dof_portability.h"
#include "ffx_dof_constants.h"
#include "ffx_dof_resources.h"
#include "ffx_dof_aperture.h"

// ---- Options (every one can be overridden with -D; the permutation axes are listed in
// ffx_dof_permutations.json) --------------------------------------------------------------------

// Compile-time upper bound on kernel rings; the runtime bound is FfxDofConstants::maxRings.
#ifndef FFX_DOF_OPTION_MAX_RINGS
#define FFX_DOF_OPTION_MAX_RINGS 32
#endif
// Number of MIP levels of the half-res colour and radius that exist and may be sampled: MIP 0
// (HALF_COLOR, HALF_COC) and MIPs 1 .. MAX_MIP - 1 (COARSE_MIPS); 1..4: a tile of 8 x 8 half-res px
// reduces to 1 x 1 at level 3 inside one workgroup.
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
// Not 0: the blur draws shaped apertures (FFX_DOF_ENABLE_APERTURE_SHAPES), any of them (1) or those whose
// gauge is compact (2, ffx_dof_aperture.h), the core choosing per dispatch; 0: the circle's code alone.
#ifndef FFX_DOF_OPTION_APERTURE_SHAPES
#define FFX_DOF_OPTION_APERTURE_SHAPES 0
#endif
// 1: the depth buffer is inverted (near plane at 1).
#ifndef FFX_DOF_OPTION_REVERSE_DEPTH
#define FFX_DOF_OPTION_REVERSE_DEPTH 0
#endif
// 1: the output already holds the input; only changed pixels are written.
#ifndef FFX_DOF_OPTION_OUTPUT_PRE_INIT
#define FFX_DOF_OPTION_OUTPUT_PRE_INIT 0
#endif
// The class of tiles (FFX_DOF_BLUR_CLASS_*) a blur pipeline blurs, from its tile list.
#ifndef FFX_DOF_OPTION_BLUR_CLASS
#define FFX_DOF_OPTION_BLUR_CLASS FFX_DOF_BLUR_CLASS_MIXED
#endif
// The class of tiles (FFX_DOF_COMPOSITE_CLASS_*) a composite pipeline composes, from its tile list.
#ifndef FFX_DOF_OPTION_COMPOSITE_CLASS
#define FFX_DOF_OPTION_COMPOSITE_CLASS FFX_DOF_COMPOSITE_CLASS_LIGHTS
#endif

// ---- Tuning constants -------------------------------------------------------------------------

// Below this |radius| a pixel is in focus: half-resolution blur cannot represent it.
#define FFX_DOF_IN_FOCUS_RADIUS 0.5f
// Radii at or above this are near-field samples (scatter as a layer in front).
#define FFX_DOF_NEAR_THRESHOLD 0.5f

// Far-field samples up to this much farther than the texel itself (|radius| larger, half-res px) are
// its own surface (front layer), so that a receding surface is not split into layers; the share then
// falls to 0 over one more pixel (ffxDofFarFrontShare).
#define FFX_DOF_FAR_FRONT_TOLERANCE 0.5f
// From this |radius| (half-res px) on, the composite shows the half-res layers alone; below it a pixel's
// own surface is gathered at full resolution (ffx_dof_composite.h).
#define FFX_DOF_FAR_LAYER_ONLY_RADIUS 3.0f
// Below this |radius| (half-res px; 2 full-res px) the fixed 3x3 blur, a disc of 1.5 px, mixed into the
// input by variance is the right size already: the gather starts here (from 0.5 instead: the same
// figures within 0.15 dB, and more tiles loading the full-res neighbourhood).
#define FFX_DOF_OWN_SURFACE_MIN_RADIUS 1.0f

// ---- CoC ----------------------------------------------------------------------------------------

// How much a sample of |radius| reaches a pixel `distance` away (scatter-as-gather), with half a
// pixel of anti-aliasing: the blur's gather at half resolution and the composite's own-surface gather
// at full resolution (both in their own pixels).
FFX_DOF_INLINE FfxFloat32 ffxDofReach(FfxFloat32 absRadius, FfxFloat32 distance)
{
    return ffxDofSaturate(absRadius - distance + 0.5f);
}

// The area of a disc of `radius` drawn by ffxDofReach on the grid of its own pixels (full-res px in the
// composite, half-res texels in the blur), centred on one: the sum of its reach over the pixel centres.
// pi radius^2 (ffxDofRoundAreaWeight's) misses it by up to 27% at half a pixel, 9% from 1 px, 5% from
// 1.5 px (2 px: 13.11 against 12.57) and 1.8% from 3 px: a small disc drawn with weights of 1 / radius^2
// adds that much more light than it has.
FFX_DOF_INLINE FfxFloat32 ffxDofPixelDiscArea(FfxFloat32 radius)
{
    FfxInt32 extent = FfxInt32(ceil(radius + 0.5f));
    FfxFloat32 area = 0.0f;
    // One quadrant, the axes counted twice and the others four times.
    FFX_DOF_LOOP
    for (FfxInt32 y = 0; y <= extent; ++y)
    {
        FFX_DOF_LOOP
        for (FfxInt32 x = 0; x <= extent; ++x)
            area +=
                ffxDofReach(radius, sqrt(FfxFloat32(x * x + y * y))) * (x == 0 ? 1.0f : 2.0f) * (y == 0 ? 1.0f : 2.0f);
    }
    return area;
}

// ---- Far-field layers (the blur's and the composite's) ----------------------------------------------

// How much of a far-field sample of |radius| `absRadius` belongs to the front layer of a texel whose
// own far-field |radius| is `centerAbsRadius`: 1 up to FFX_DOF_FAR_FRONT_TOLERANCE beyond the texel's
// own radius (the texel's surface and everything nearer the camera), falling to 0 one pixel of radius
// farther (the background, seen only where the front layer leaves gaps). A texel in the near field has
// no front layer: every far-field sample is background to it.
FFX_DOF_INLINE FfxFloat32 ffxDofFarFrontShare(FfxFloat32 absRadius, FfxFloat32 centerAbsRadius)
{
    return ffxDofSaturate(centerAbsRadius + FFX_DOF_FAR_FRONT_TOLERANCE + 1.0f - absRadius);
}

// How much of a far-field sample belongs to the layer in front of the texel's own surface: 1 from
// FFX_DOF_FAR_FRONT_TOLERANCE + 1 px of radius nearer than the texel's own, 0 from
// FFX_DOF_FAR_FRONT_TOLERANCE nearer (the mirror of ffxDofFarFrontShare). A small light in front of a
// farther background covers part of the background's texels: composed over them by its coverage
// instead of normalised with them, it keeps its energy (normalised, a light of a few texels at a
// radius of 3 px lost up to a fifth of it to the background's weights).
FFX_DOF_INLINE FfxFloat32 ffxDofFarNearerShare(FfxFloat32 absRadius, FfxFloat32 centerAbsRadius)
{
    return ffxDofSaturate(centerAbsRadius - FFX_DOF_FAR_FRONT_TOLERANCE - absRadius);
}

// The share of a far sample of |radius| `absRadius` (half-res px) in front of a receiver of |radius|
// `receiverAbsRadius` that the composite draws at full resolution (ffxDofGatherSmallSources) instead of
// the blur at half resolution: sources below FFX_DOF_FAR_LAYER_ONLY_RADIUS (their own pixels are blurred
// at full resolution) on receivers that show the half-res layers (from FFX_DOF_FAR_LAYER_ONLY_RADIUS, over
// the last px below it as the composite hands over). At half resolution such a light's disc is a texel or
// two, and what its own pixels' full-resolution blur spread onto the background was lost: a 1 px light at
// 2 px kept half its energy (docs/quality.md, small lights).
FFX_DOF_INLINE FfxFloat32 ffxDofSmallSourceShare(FfxFloat32 absRadius, FfxFloat32 receiverAbsRadius)
{
    return ffxDofSaturate(FFX_DOF_FAR_LAYER_ONLY_RADIUS - absRadius) *
           ffxDofSaturate(receiverAbsRadius - FFX_DOF_FAR_LAYER_ONLY_RADIUS + 1.0f);
}

// How much of a far texel of signed radius `coc` (half-res px) the composite draws from its own pixels
// gathered at full resolution rather than from the far layer: 1 from a radius of 1 (where the composite's
// own-surface gather starts) to 2, falling to 0 at FFX_DOF_FAR_LAYER_ONLY_RADIUS as the composite hands
// over to the layers. The blur leaves that share of the texel's own surface out of its far layer: counted
// in both, a small light's own pixels showed it twice (a 1 px light at 4 px added 1.2 to 1.3 times its
// energy once the background around it drew it at full resolution; docs/quality.md, small lights).
FFX_DOF_INLINE FfxFloat32 ffxDofOwnGatherShare(FfxFloat32 coc)
{
    return coc <= -FFX_DOF_OWN_SURFACE_MIN_RADIUS ? ffxDofSaturate(FFX_DOF_FAR_LAYER_ONLY_RADIUS - abs(coc)) : 0.0f;
}

// Signed CoC radius of a depth value, always in 32-bit: rounding depth to 16 bits first would move
// in-focus pixels next to the near plane out of focus.
FFX_DOF_INLINE FfxFloat32 ffxDofCocFromDepth(FfxFloat32 depth, FfxFloat32 cocScale, FfxFloat32 cocBias,
                                             FfxFloat32 cocLimit)
{
    return clamp(depth * cocScale + cocBias, -cocLimit, cocLimit);
}

// ---- Tiles ------------------------------------------------------------------------------------------

// The tiles within `range` tiles of `center` each way, clipped to the image: first..last inclusive.
FFX_DOF_INLINE void ffxDofTileWindow(FfxInt32x2 center, FfxInt32 range, FfxUInt32x2 tileCount,
                                     FFX_DOF_OUT(FfxInt32x2) first, FFX_DOF_OUT(FfxInt32x2) last)
{
    first = max(center - FfxInt32x2(range, range), FfxInt32x2(0, 0));
    last = min(center + FfxInt32x2(range, range), FfxInt32x2(tileCount) - FfxInt32x2(1, 1));
}

// ---- Colour -----------------------------------------------------------------------------------------

// Rec. 709 luminance: the brightness that weighs a quad pixel's radius in the bilateral reduction
// (pass 2), that tells a highlight in the blur (pass 4) and that the outlier post-filter clamps
// (pass 5). The 32-bit form is for values already in 32-bit (the blur's samples).
FFX_DOF_INLINE FfxFloat32 ffxDofLuminance32(FfxFloat32x3 color)
{
    return color.x * 0.2126f + color.y * 0.7152f + color.z * 0.0722f;
}
FFX_DOF_INLINE FfxFloat32 ffxDofLuminance(FfxDofFloat3 color) { return ffxDofLuminance32(ffxDofToFloat32x3(color)); }

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
FFX_DOF_INLINE FfxFloat32x3 ffxDofRoundForPackedColor32(FfxFloat32x3 color)
{
    return FfxFloat32x3(ffxDofRoundMantissa(color.x, 6u), ffxDofRoundMantissa(color.y, 6u),
                        ffxDofRoundMantissa(color.z, 5u));
}
FFX_DOF_INLINE FfxDofFloat3 ffxDofRoundForPackedColor(FfxDofFloat3 color)
{
    return ffxDofToDofFloat3(ffxDofRoundForPackedColor32(ffxDofToFloat32x3(color)));
}

// A texel of COARSE_MIPS (MIPs 1 to 3 of the half-res colour and radius): everything the blur reads of
// a coarse sample in one 64-bit fetch (x: its colour as B10G11R11 float bits; y: its radius as a half
// in bits 0..15, a near radius with its coverage in the four lowest mantissa bits (ffxDofPackCoarseNearCoverage),
// its light offset as two snorm8 in bits 16..31, twice the offset in its own texels).
// On lavapipe every fetch of the blur's sample loop costs about as much as the rest of the sample: a
// sample read from three images (colour, radius, light offset) made the blur up to 1.35 times as long
// as one read from two (docs/performance.md, "Coarse texels in one fetch").
// A B10G11R11 float is a half with its sign and low mantissa bits dropped, so the packing goes through
// the half conversion: exact for the colours ffxDofRoundForPackedColor gives, rounded to nearest
// otherwise, and clamped to the format's largest finite value (65024).
FFX_DOF_INLINE FfxUInt32 ffxDofPackR11G11B10(FfxFloat32x3 color)
{
    FfxFloat32x3 clamped = clamp(color, FfxFloat32x3(0.0f, 0.0f, 0.0f), FfxFloat32x3(65024.0f, 65024.0f, 65024.0f));
    FfxUInt32 redGreen = ffxDofPackHalf2(FfxFloat32x2(clamped.x, clamped.y));
    FfxUInt32 blue = ffxDofPackHalf2(FfxFloat32x2(clamped.z, 0.0f));
    // Sign bits dropped (a -0 from the clamp); a NaN becomes the largest finite value.
    FfxUInt32 red = min(((redGreen & 0x7fffu) + 0x8u) >> 4u, 0x7bfu);
    FfxUInt32 green = min((((redGreen >> 16u) & 0x7fffu) + 0x8u) >> 4u, 0x7bfu);
    blue = min(((blue & 0x7fffu) + 0x10u) >> 5u, 0x3dfu);
    return red | (green << 11u) | (blue << 22u);
}
FFX_DOF_INLINE FfxFloat32x3 ffxDofUnpackR11G11B10(FfxUInt32 bits)
{
    FfxFloat32x2 redGreen = ffxDofUnpackHalf2(((bits & 0x7ffu) << 4u) | (((bits >> 11u) & 0x7ffu) << 20u));
    FfxFloat32 blue = ffxDofUnpackHalf2((bits >> 22u) << 5u).x;
    return FfxFloat32x3(redGreen.x, redGreen.y, blue);
}

// A value in [-1, 1] as a snorm8 (round to nearest, as the UNORM/SNORM conversions of the APIs), in
// the low byte; and back from the byte at bit `shift`.
FFX_DOF_INLINE FfxUInt32 ffxDofPackSnorm8(FfxFloat32 value)
{
    return FfxUInt32(FfxInt32(floor(clamp(value, -1.0f, 1.0f) * 127.0f + 0.5f))) & 0xffu;
}
FFX_DOF_INLINE FfxFloat32 ffxDofUnpackSnorm8(FfxUInt32 bits, FfxUInt32 shift)
{
    FfxInt32 value = FfxInt32(bits << (24u - shift)) >> 24;
    return max(FfxFloat32(value) * (1.0f / 127.0f), -1.0f);
}

FFX_DOF_INLINE FfxUInt32x2 ffxDofPackCoarseTexel(FfxFloat32x3 color, FfxFloat32 coc, FfxFloat32x2 lightOffset)
{
    FfxUInt32 cocBits = ffxDofPackHalf2(FfxFloat32x2(coc, 0.0f)) & 0xffffu;
    FfxUInt32 offsetBits = ffxDofPackSnorm8(lightOffset.x * 2.0f) | (ffxDofPackSnorm8(lightOffset.y * 2.0f) << 8u);
    return FfxUInt32x2(ffxDofPackR11G11B10(color), cocBits | (offsetBits << 16u));
}
FFX_DOF_INLINE FfxFloat32x3 ffxDofCoarseTexelColor(FfxUInt32x2 texel) { return ffxDofUnpackR11G11B10(texel.x); }
FFX_DOF_INLINE FfxFloat32 ffxDofCoarseTexelCoc(FfxUInt32x2 texel) { return ffxDofUnpackHalf2(texel.y & 0xffffu).x; }
// Where in the texel its light lies, in its own texels from its centre (ffxDofReduceLightOffset).
FFX_DOF_INLINE FfxFloat32x2 ffxDofCoarseTexelLightOffset(FfxUInt32x2 texel)
{
    return FfxFloat32x2(ffxDofUnpackSnorm8(texel.y, 16u), ffxDofUnpackSnorm8(texel.y, 24u)) * 0.5f;
}

// A signed radius rounded to nearest as a half (10 mantissa bits), so that its R16 float store is exact
// whichever rounding the device uses: lavapipe truncates toward zero, and that bias of less than a unit
// in the last place changed which rings merge beside a bright light (docs/technique.md, "Coarse texels
// in one fetch"). Radii below the half's normal range are in focus anyway.
FFX_DOF_INLINE FfxFloat32 ffxDofRoundForHalfCoc(FfxFloat32 coc)
{
    FfxFloat32 rounded = ffxDofRoundMantissa(abs(coc), 10u);
    return coc < 0.0f ? -rounded : rounded;
}

// ---- Near coverage ------------------------------------------------------------------------------------
//
// A half-res texel holds one radius, and the bilateral reduction keeps the pixels of a quad's reference
// radius (ffxDofBilateralReduce): a quad of near pixels and pixels behind the near field was a near texel or
// not, whole. A bar of 1 px across took its quad's whole texel, 2 px of opacity, or vanished, depending on its
// column (docs/quality.md, thin near bars). Such a quad's MIP-0 texel is now its near pixels alone
// (ffxDofReduceNearQuad) with their share of the quad, its coverage, in the two lowest mantissa bits of the
// texel's radius in HALF_COC (a half: near radii keep 8 mantissa bits, 0.4%); the blur weighs the texel's near
// samples by it. The coarse MIPs reduce such texels the same way, with the coverage in sixteenths
// (ffxDofPackCoarseNearCoverage).

// Quads whose nearest pixel has a smaller radius (half-res px) keep the bilateral reduction: from every near
// radius (0.5) the floor scene's near field lost 0.32 dB more, busy-background 0.03 dB, and no bar gained. From
// 2 until 2026-11-30: the bilateral reduction weighs a pixel 1.25 px or more from the quad's reference radius by 0,
// so a near pixel of radius 1.25 to 2 in a quad of in-focus or far pixels vanished from every layer (an isolated
// one over an in-focus wall kept 3 to 5% of its light: a speck of dust, a snowflake). From 1: 1.00 to 1.15 of it;
// floor's near field 34.85 -> 34.53 dB, its in-focus pixels 32.50 -> 32.66 and halo band 32.22 -> 32.31, the
// scene 34.82 as before (docs/quality.md, near specks).
#define FFX_DOF_NEAR_COVERAGE_MIN_RADIUS 1.0f
// How much smaller (half-res px) the radius of a partly covered near texel is than its pixels': they lie up
// to 0.35 half-res px from its centre, and its disc must stay within theirs through the composite's
// upsampling (with 0.25 the floor scene's in-focus pixels changed by 12/255 beyond every near radius).
#define FFX_DOF_NEAR_COVERAGE_INSET 0.5f
#define FFX_DOF_NEAR_COVERAGE_SHIFT 13u  // the half's two lowest mantissa bits, in a float's

// A near radius rounded to a half (ffxDofRoundForHalfCoc) with `coverage` (1/4 to 1, in quarters) in its two
// lowest mantissa bits, still a half (its R16 float store keeps them). Other radii are returned as they are.
FFX_DOF_INLINE FfxFloat32 ffxDofPackNearCoverage(FfxFloat32 coc, FfxFloat32 coverage)
{
    if (coc < FFX_DOF_NEAR_THRESHOLD)
        return coc;
    FfxUInt32 quarters = FfxUInt32(clamp(floor(coverage * 4.0f + 0.5f), 1.0f, 4.0f));
    FfxUInt32 mask = 3u << FFX_DOF_NEAR_COVERAGE_SHIFT;
    return ffxDofAsFloat((ffxDofAsUInt(coc) & ~mask) | ((quarters - 1u) << FFX_DOF_NEAR_COVERAGE_SHIFT));
}

// The coverage of a near radius read from HALF_COC (ffxDofPackNearCoverage).
FFX_DOF_INLINE FfxFloat32 ffxDofNearCoverage(FfxFloat32 coc)
{
    return FfxFloat32(((ffxDofAsUInt(coc) >> FFX_DOF_NEAR_COVERAGE_SHIFT) & 3u) + 1u) * 0.25f;
}

// The coarse MIPs carry a near texel's coverage too, in sixteenths (a bar of 1 px covers a sixteenth of a
// MIP-3 texel), in the four lowest mantissa bits of the radius's half in COARSE_MIPS (ffxDofPackCoarseTexel):
// near radii there keep 6 mantissa bits (1.6%). A bar of 1 or 2 px read by the inner rings at radius 40 filled
// its coarse texel or vanished there (docs/quality.md, thin near bars).
#define FFX_DOF_COARSE_COVERAGE_STEPS 16u

// A near radius rounded to nearest at 6 mantissa bits with `coverage` (1/16 to 1) in the 4 below, an exact half.
FFX_DOF_INLINE FfxFloat32 ffxDofPackCoarseNearCoverage(FfxFloat32 coc, FfxFloat32 coverage)
{
    if (coc < FFX_DOF_NEAR_THRESHOLD)
        return coc;
    FfxFloat32 steps = FfxFloat32(FFX_DOF_COARSE_COVERAGE_STEPS);
    FfxUInt32 level = FfxUInt32(clamp(floor(coverage * steps + 0.5f), 1.0f, steps));
    FfxUInt32 mask = (FFX_DOF_COARSE_COVERAGE_STEPS - 1u) << FFX_DOF_NEAR_COVERAGE_SHIFT;
    FfxUInt32 rounded = ffxDofAsUInt(ffxDofRoundMantissa(coc, 6u));
    return ffxDofAsFloat((rounded & ~mask) | ((level - 1u) << FFX_DOF_NEAR_COVERAGE_SHIFT));
}

// The coverage of a near radius read from COARSE_MIPS (ffxDofPackCoarseNearCoverage).
FFX_DOF_INLINE FfxFloat32 ffxDofCoarseNearCoverage(FfxFloat32 coc)
{
    FfxUInt32 level = (ffxDofAsUInt(coc) >> FFX_DOF_NEAR_COVERAGE_SHIFT) & (FFX_DOF_COARSE_COVERAGE_STEPS - 1u);
    return FfxFloat32(level + 1u) * (1.0f / FfxFloat32(FFX_DOF_COARSE_COVERAGE_STEPS));
}

// ---- Layer alpha -------------------------------------------------------------------------------------
//
// LAYER_ALPHA holds, per half-res texel, the near-field opacity and whether the far layer holds gathered
// colour (a yes or no) in one 8-bit unorm: the validity in the top bit, the opacity's square root in 127ths
// below it (see below). Two 8-bit channels (R8G8) cost 0.52 MB more at 1080p; the composite averages the
// opacity over 3 x 3 texels and interpolates it: every gate of docs/quality.md holds, no scene moved by more than 0.01
// dB, and a thin near bar's summed veil moved by up to 4% of its width, its worst case within the gate's 10% as before
// (0.971 of the width against 0.967; docs/performance.md, "LAYER_ALPHA in one byte").
// The value stored lies a quarter of a step above its byte's multiple of 1/255, so that a conversion that
// rounds to nearest and one that truncates (as lavapipe does its R16 float stores) store the same byte.
//
// A near opacity below half a step would round to none: a small near light, whose disc's opacity is its share of
// the disc (a 1 px light at radius 8 half-res px: 0.0012), vanished, and one of a few steps drew up to 1.5 times
// its energy. So an opacity from FFX_DOF_NEAR_OPACITY_KEPT up keeps at least one step, and the blur makes up the
// difference between the stored and the gathered opacity in the near colour it stores (ffxDofFinishGather): the
// composite's blend with the stored step then gives what the gathered opacity would over the texel's far layer.
//
// The steps are of the opacity's square root, so that the opacities near zero, where a small near disc's rim
// lies, come in fine steps (the smallest 1/16129, then 4/16129, ...) and the largest in steps of at most 2/127.
// With steps of the opacity itself (1/127), a rim texel of a near speck gathered an opacity of a few ten-thousandths
// and stored one step with a colour made up almost entirely of its far layer; the composite's post-filter, which
// averages the opacity over 3 x 3 texels and keeps each texel's colour, then gave that colour the disc's opacity:
// a speck at 2.25 half-res px kept 0.81 of its light (docs/technique.md, "Near opacity in whole steps"; 1.02 since
// the near weights and the post-filter keep it too, "Near specks keep their light").
#define FFX_DOF_NEAR_OPACITY_STEPS 127.0f
#define FFX_DOF_NEAR_OPACITY_KEPT 1e-4f
// The whole steps of the opacity's square root that LAYER_ALPHA keeps of `opacity`.
FFX_DOF_INLINE FfxFloat32 ffxDofNearOpacitySteps(FfxFloat32 opacity)
{
    FfxFloat32 steps = floor(sqrt(ffxDofSaturate(opacity)) * FFX_DOF_NEAR_OPACITY_STEPS + 0.5f);
    return opacity >= FFX_DOF_NEAR_OPACITY_KEPT ? max(steps, 1.0f) : steps;
}
FFX_DOF_INLINE FfxFloat32 ffxDofStoredNearOpacity(FfxFloat32 opacity)
{
    FfxFloat32 root = ffxDofNearOpacitySteps(opacity) * (1.0f / FFX_DOF_NEAR_OPACITY_STEPS);
    return root * root;
}
// The blur stores ffxDofStoredNearOpacity's value, whose steps are its own.
FFX_DOF_INLINE FfxFloat32 ffxDofPackLayerAlpha(FfxFloat32x2 nearOpacityFarValidity)
{
    FfxFloat32 opacitySteps = ffxDofNearOpacitySteps(nearOpacityFarValidity.x);
    return (opacitySteps + (nearOpacityFarValidity.y > 0.0f ? 128.0f : 0.0f) + 0.25f) * (1.0f / 255.0f);
}
FFX_DOF_INLINE FfxFloat32x2 ffxDofUnpackLayerAlpha(FfxFloat32 packed)
{
    FfxFloat32 value = floor(packed * 255.0f + 0.5f);
    FfxFloat32 validity = value >= 128.0f ? 1.0f : 0.0f;
    FfxFloat32 root = (value - 128.0f * validity) * (1.0f / FFX_DOF_NEAR_OPACITY_STEPS);
    return FfxFloat32x2(root * root, validity);
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

// ---- Workgroup and tile arithmetic --------------------------------------------------------------

// Cell `index` (0 to 4 (side - 1) - 1) of the border ring of a square grid of `side` cells: the top row, the bottom
// row, then the sides.
FFX_DOF_INLINE FfxUInt32x2 ffxDofBorderCell(FfxUInt32 index, FfxUInt32 side)
{
    if (index < side)
        return FfxUInt32x2(index, 0u);
    if (index < 2u * side)
        return FfxUInt32x2(index - side, side - 1u);
    FfxUInt32 row = index - 2u * side;
    return FfxUInt32x2(row < side - 2u ? 0u : side - 1u, 1u + row % (side - 2u));
}

// Position of an invocation in its 8 x 8 workgroup.
FFX_DOF_INLINE FfxUInt32x2 ffxDofLocalCoord(FfxUInt32 localIndex)
{
    return FfxUInt32x2(localIndex % FfxUInt32(FFX_DOF_GROUP_SIDE), localIndex / FfxUInt32(FFX_DOF_GROUP_SIDE));
}

// A group reduces one value per wave, kept in group-shared slots indexed by ffxDofWaveIndex, in a loop over
// `first` = 0, ffxDofWaveLaneCount(), ... below ffxDofWaveCount(): each lane folds in slot ffxDofLaneWaveSlot(first)
// where it is below ffxDofWaveCount(), then the wave reduces its lanes (ffxDofWaveMin, ...), and every wave holds
// the group's result. Where a wave has at least as many lanes as the group has waves (lavapipe: 8 and 8; GPUs: one
// or two waves) that is one group-shared read per lane. Every invocation reading every slot made 8 reads, and
// lavapipe runs each group-shared read as a loop over the wave's lanes: in the colour downsample that was a third of
// the pass (docs/performance.md, "Wave slots read a lane each"). The depth downsample keeps one invocation's loop
// over the slots: there only its wave loops (lavapipe leaves a loop once no lane is active), and this way measured
// slower.
FFX_DOF_INLINE FfxUInt32 ffxDofLaneWaveSlot(FfxUInt32 first) { return first + ffxDofWaveLaneIndex(); }

// Whether the condition holds in any lane of the wave, for a branch the whole wave takes or skips: by the wave
// arithmetic every pass needs anyway (ffxDofWaveAnyTrue would add the vote operations to a device's requirements).
FFX_DOF_INLINE FfxBoolean ffxDofWaveAny(FfxBoolean condition) { return ffxDofWaveMax(condition ? 1u : 0u) != 0u; }

// Size of MIP level `mip` of an image whose level 0 is `size` (the Vulkan/D3D rule).
FFX_DOF_INLINE FfxUInt32x2 ffxDofMipSize(FfxUInt32x2 size, FfxUInt32 mip)
{
    return max(FfxUInt32x2(size.x >> mip, size.y >> mip), FfxUInt32x2(1u, 1u));
}

// Largest kernel radius of any texel of a tile whose dilated (far, near) range is `farNear`: a texel's
// kernel is max(dilated near radius, |own radius|), and its own radius is within the range.
FFX_DOF_INLINE FfxFloat32 ffxDofTileKernelRadius(FfxFloat32x2 farNear) { return max(max(farNear.y, -farNear.x), 0.0f); }

// Median of nine values by a 19-exchange selection network (autofocus's reference depth at the
// centre).
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

// ---- Output encoding (the callback headers' output accessors) ---------------------------------------

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
