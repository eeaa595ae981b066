// Pass 2 of 5: bilateral downsample of the input color to half resolution, with the CoC, and the
// MIP chain up to FFX_DOF_OPTION_MAX_MIP levels, in one dispatch. It also takes each tile's colour peak (the
// largest finite channel, for dilate and the composite) and the frame's (docs/technique.md, HDR range): its first run
// takes the colour as it is, and where a channel exceeds FFX_DOF_COLOR_RANGE_LIMIT it raises the frame's peak and
// arms its second run (FFX_DOF_COLOR_RANGE_RERUN_ARGS), which the backend dispatches indirectly with
// FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN: that run multiplies the colour by ffxDofColorRangeScale of the frame's peak
// first, in 32-bit, and writes everything again. The scale goes to GLOBALS for the composite.
//
// One workgroup covers one tile: the group first shares the luminance and radius of its 16 x 16
// full-res pixels and a border of one (a light's anti-aliased rim takes the light's radius:
// ffxDofLightRimCoc; 2,592 bytes), its 64 invocations make the 8 x 8 texels of MIP 0, then the group
// reduces them in group-shared memory to 4 x 4, 2 x 2 and 1 x 1 (MIPs 1..3), so no global
// synchronisation is needed. Every level uses ffxDofBilateralReduceLight, which also tells where in
// each texel of MIPs 1..3 its light lies. MIP 0 goes to HALF_COLOR and HALF_COC; MIPs 1..3 go to
// COARSE_MIPS, colour, radius and light offset packed in one texel (ffxDofPackCoarseTexel). Before MIP 0, far
// pixels above white and far brighter than the tile's dimmest far pixel give that light to HIGHLIGHTS, one
// highlight per quadrant of the tile, for the composite to draw at full resolution (ffx_dof_highlights.h).
#ifndef FFX_DOF_DOWNSAMPLE_COLOR_H
#define FFX_DOF_DOWNSAMPLE_COLOR_H

#include "ffx_dof_common.h"
#include "ffx_dof_focus.h"
#include "ffx_dof_highlights.h"

#if defined(FFX_CPU)
FfxDofConstants ffxDofGetConstants();
FfxFloat32 ffxDofLoadInputDepth(FfxUInt32x2 pixel);
FfxFloat32x4 ffxDofLoadInputColor(FfxUInt32x2 pixel);
void ffxDofStoreHalfColor(FfxUInt32x2 texel, FfxDofFloat3 color);
void ffxDofStoreHalfCoc(FfxUInt32x2 texel, FfxFloat32 coc);
void ffxDofStoreCoarseMip(FfxUInt32 mip, FfxUInt32x2 texel, FfxUInt32x2 packed);
FfxFloat32 ffxDofLoadColorPeak();
void ffxDofAtomicMaxColorPeak(FfxFloat32 peak);
void ffxDofArmColorRangeRerun(FfxUInt32x2 tileCount);
void ffxDofStoreColorScale(FfxFloat32 scale);
void ffxDofStoreHighlightWord(FfxUInt32 word, FfxUInt32 value);
#endif

// ---- Bilateral downsampling -------------------------------------------------------------------------

// Weight of a pixel of a 2x2 quad from how far its radius is from the quad's reference radius
// (ffxDofQuadReferenceCoc): 1 for equal radii, falling linearly to 0 at a difference of one pixel.
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
                                                       FfxFloat32 coc2, FfxFloat32x3 color0, FfxFloat32x3 color1,
                                                       FfxFloat32x3 color2, FfxFloat32x3 color3)
{
    if (coc0 == reference)
        return ffxDofLuminance32(color0);
    if (coc1 == reference)
        return ffxDofLuminance32(color1);
    if (coc2 == reference)
        return ffxDofLuminance32(color2);
    return ffxDofLuminance32(color3);
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
FFX_DOF_INLINE FfxFloat32 ffxDofLightKeep(FfxFloat32x3 color, FfxFloat32 coc, FfxFloat32 referenceCoc,
                                          FfxFloat32 referenceLuminance)
{
    // Only within the far field: a near-field pixel in a far texel, or the reverse,
    // would move the texel's radius across the layers.
    if (coc >= FFX_DOF_NEAR_THRESHOLD || referenceCoc >= FFX_DOF_NEAR_THRESHOLD)
        return 0.0f;
    FfxFloat32 luminance = ffxDofLuminance32(color);
    // An in-focus pixel is drawn from the full-resolution input: kept in a blurred texel, it would
    // only spread its color into the background.
    FfxFloat32 brighter = ffxDofSaturate(luminance / (2.0f * referenceLuminance + 1e-4f) - 1.0f) *
                          ffxDofSaturate(-coc - FFX_DOF_IN_FOCUS_RADIUS);
    FfxFloat32 darkerBehind = ffxDofSaturate(referenceLuminance / (2.0f * luminance + 1e-4f) - 1.0f) *
                              ffxDofSaturate(referenceCoc - coc) *
                              ffxDofSaturate(-referenceCoc - FFX_DOF_IN_FOCUS_RADIUS);
    return max(brighter, darkerBehind);
}

// The light offset of a reduced texel: where its light lies, as the offset of the luminance-weighted
// centre of its four sources (`light0..3`: their weights in the reduction times their luminance) from
// the texel's centre, in texels of its level (each axis within +-0.5). `offset0..3` are the sources'
// own offsets in their level's texels (0 for full-resolution pixels). The blur judges the reach of a
// sample from a coarse MIP from this point instead of the texel's centre: a light of a few pixels
// read from a MIP-1 texel was drawn about that texel's centre, up to 1.4 full-res px from its place.
FFX_DOF_INLINE FfxFloat32x2 ffxDofReduceLightOffset(FfxFloat32 light0, FfxFloat32 light1, FfxFloat32 light2,
                                                    FfxFloat32 light3, FfxFloat32x2 offset0, FfxFloat32x2 offset1,
                                                    FfxFloat32x2 offset2, FfxFloat32x2 offset3)
{
    // A source's centre lies a quarter of the reduced texel from its centre; its offset is halved.
    FfxFloat32x2 sum = (FfxFloat32x2(-0.25f, -0.25f) + offset0 * 0.5f) * light0 +
                       (FfxFloat32x2(0.25f, -0.25f) + offset1 * 0.5f) * light1 +
                       (FfxFloat32x2(-0.25f, 0.25f) + offset2 * 0.5f) * light2 +
                       (FfxFloat32x2(0.25f, 0.25f) + offset3 * 0.5f) * light3;
    return sum / (light0 + light1 + light2 + light3);
}

// A texel of the MIP chain as the levels above reduce it: colour, radius, the share of it its near sources cover
// (1 where it is not partly near) and where its light lies (a full-resolution pixel: coverage 1, offset 0).
struct FfxDofMipTexel
{
    FfxFloat32x3 color;
    FfxFloat32 coc;
    FfxFloat32 coverage;
    FfxFloat32x2 lightOffset;
};
FFX_DOF_INLINE FfxDofMipTexel ffxDofMakeMipTexel(FfxFloat32x3 color, FfxFloat32 coc, FfxFloat32 coverage,
                                                 FfxFloat32x2 lightOffset)
{
    FfxDofMipTexel texel;
    texel.color = color;
    texel.coc = coc;
    texel.coverage = coverage;
    texel.lightOffset = lightOffset;
    return texel;
}
FFX_DOF_INLINE FfxDofMipTexel ffxDofPixelTexel(FfxFloat32x3 color, FfxFloat32 coc)
{
    return ffxDofMakeMipTexel(color, coc, 1.0f, FfxFloat32x2(0.0f, 0.0f));
}

// The weights of a quad's four sources in the bilateral reduction: ffxDofQuadWeight about the quad's reference
// radius, or more where ffxDofLightKeep keeps a source's light.
FFX_DOF_INLINE FfxFloat32x4 ffxDofBilateralWeights(FfxDofMipTexel source0, FfxDofMipTexel source1,
                                                   FfxDofMipTexel source2, FfxDofMipTexel source3)
{
    FfxFloat32 reference = ffxDofQuadReferenceCoc(source0.coc, source1.coc, source2.coc, source3.coc);
    FfxFloat32 range = max(max(source0.coc, source1.coc), max(source2.coc, source3.coc)) -
                       min(min(source0.coc, source1.coc), min(source2.coc, source3.coc));
    FfxFloat32 referenceLight = ffxDofQuadReferenceLuminance(
        reference, source0.coc, source1.coc, source2.coc, source0.color, source1.color, source2.color, source3.color);
    return FfxFloat32x4(max(ffxDofQuadWeight(reference, range, source0.coc),
                            ffxDofLightKeep(source0.color, source0.coc, reference, referenceLight)),
                        max(ffxDofQuadWeight(reference, range, source1.coc),
                            ffxDofLightKeep(source1.color, source1.coc, reference, referenceLight)),
                        max(ffxDofQuadWeight(reference, range, source2.coc),
                            ffxDofLightKeep(source2.color, source2.coc, reference, referenceLight)),
                        max(ffxDofQuadWeight(reference, range, source3.coc),
                            ffxDofLightKeep(source3.color, source3.coc, reference, referenceLight)));
}

// The weight of a source among a quad's near sources: its coverage times its radius's closeness to the nearest
// (ffxDofBilateralWeight, at least a trace so that every near source counts); 0 for a source behind the near field.
FFX_DOF_INLINE FfxFloat32 ffxDofNearQuadWeight(FfxFloat32 nearest, FfxDofMipTexel source)
{
    return source.coc >= FFX_DOF_NEAR_THRESHOLD
               ? max(ffxDofBilateralWeight(nearest, source.coc), 1e-3f) * source.coverage
               : 0.0f;
}
FFX_DOF_INLINE FfxFloat32 ffxDofNearShare(FfxDofMipTexel source)
{
    return source.coc >= FFX_DOF_NEAR_THRESHOLD ? source.coverage : 0.0f;
}

// Reduces a 2x2 quad of sources (0: top-left, 1: top-right, 2: bottom-left, 3: bottom-right) to one texel; the
// same kernel makes every level, MIP 0 from full-resolution pixels and MIPs 1..3 from the level below.
// - `partial` true: the quad's nearest source is near, at least `minRadius`, and the quad also holds sources
//   behind the near field or near sources that cover their own texel in part (Near coverage, ffx_dof_common.h).
//   The texel is its near sources alone (ffxDofNearQuadWeight), with the sum of their coverages over 4, their
//   radius less `inset`.
// - Otherwise the bilateral reduction (ffxDofBilateralWeights), coverage 1. Its radius is averaged with the square
//   of each source's light (weight x luminance) as its weight: the texel's light spreads with the radius of the
//   sources it comes from, and a bright point keeps its own radius among darker pixels of another one through
//   every level. Weighted by the light itself, a 1 px light of radius 2 among pixels of radius 16 and a thousandth
//   of its luminance came out at 2.04 in MIP 0 and 4.9 in MIP 3 (now 2.00 and 2.17), so the blur judged it by a
//   larger radius than the composite does (ffx_dof_small_sources.h).
// Both take where the light lies from the same weights (ffxDofReduceLightOffset). One tail serves both: every
// level of the chain runs this kernel, and lavapipe runs both sides of a branch (one tail saved about 1 ms of the
// pass's 90 at 1080p; docs/performance.md, "The colour downsample in 32-bit").
struct FfxDofNearQuad
{
    FfxBoolean partial;
    FfxDofMipTexel texel;
};
FFX_DOF_INLINE FfxDofNearQuad ffxDofReduceSources(FfxDofMipTexel source0, FfxDofMipTexel source1,
                                                  FfxDofMipTexel source2, FfxDofMipTexel source3, FfxFloat32 minRadius,
                                                  FfxFloat32 inset)
{
    FfxDofNearQuad quad;
    FfxFloat32 nearest = max(max(source0.coc, source1.coc), max(source2.coc, source3.coc));
    FfxFloat32 nearCoverage =
        (ffxDofNearShare(source0) + ffxDofNearShare(source1) + ffxDofNearShare(source2) + ffxDofNearShare(source3)) *
        0.25f;
    quad.partial = nearest >= minRadius && nearCoverage < 1.0f;
    FfxFloat32x4 weight;
    FfxFloat32x4 light;
    FfxFloat32x4 cocWeight;
    if (quad.partial)
    {
        weight = FfxFloat32x4(ffxDofNearQuadWeight(nearest, source0), ffxDofNearQuadWeight(nearest, source1),
                              ffxDofNearQuadWeight(nearest, source2), ffxDofNearQuadWeight(nearest, source3));
        light = weight + FfxFloat32x4(1e-6f, 1e-6f, 1e-6f, 1e-6f);
        cocWeight = weight;
    }
    else
    {
        weight = ffxDofBilateralWeights(source0, source1, source2, source3);
        // A small floor keeps black quads at the plain weighted mean.
        light = weight * (FfxFloat32x4(ffxDofLuminance32(source0.color), ffxDofLuminance32(source1.color),
                                       ffxDofLuminance32(source2.color), ffxDofLuminance32(source3.color)) +
                          FfxFloat32x4(1e-3f, 1e-3f, 1e-3f, 1e-3f));
        cocWeight = light * light;
    }
    // The bilateral weights sum to at least 1 (the reference's own).
    FfxFloat32 normalization = 1.0f / max(weight.x + weight.y + weight.z + weight.w, 1e-6f);
    quad.texel.color =
        (source0.color * weight.x + source1.color * weight.y + source2.color * weight.z + source3.color * weight.w) *
        normalization;
    FfxFloat32 cocSum =
        source0.coc * cocWeight.x + source1.coc * cocWeight.y + source2.coc * cocWeight.z + source3.coc * cocWeight.w;
    quad.texel.coc = quad.partial ? max(cocSum * normalization - inset, FFX_DOF_NEAR_THRESHOLD)
                                  : cocSum / (cocWeight.x + cocWeight.y + cocWeight.z + cocWeight.w);
    quad.texel.coverage = quad.partial ? nearCoverage : 1.0f;
    quad.texel.lightOffset = ffxDofReduceLightOffset(light.x, light.y, light.z, light.w, source0.lightOffset,
                                                     source1.lightOffset, source2.lightOffset, source3.lightOffset);
    return quad;
}

// The bilateral reduction alone (a `minRadius` no radius reaches), of four sources with light offsets.
FFX_DOF_INLINE void ffxDofBilateralReduceLight(FfxFloat32x3 color0, FfxFloat32x3 color1, FfxFloat32x3 color2,
                                               FfxFloat32x3 color3, FfxFloat32 coc0, FfxFloat32 coc1, FfxFloat32 coc2,
                                               FfxFloat32 coc3, FfxFloat32x2 offset0, FfxFloat32x2 offset1,
                                               FfxFloat32x2 offset2, FfxFloat32x2 offset3,
                                               FFX_DOF_OUT(FfxFloat32x3) color, FFX_DOF_OUT(FfxFloat32) coc,
                                               FFX_DOF_OUT(FfxFloat32x2) offset)
{
    FfxDofNearQuad quad = ffxDofReduceSources(
        ffxDofMakeMipTexel(color0, coc0, 1.0f, offset0), ffxDofMakeMipTexel(color1, coc1, 1.0f, offset1),
        ffxDofMakeMipTexel(color2, coc2, 1.0f, offset2), ffxDofMakeMipTexel(color3, coc3, 1.0f, offset3),
        FFX_DOF_FLOAT32_MAX, 0.0f);
    color = quad.texel.color;
    coc = quad.texel.coc;
    offset = quad.texel.lightOffset;
}

// ffxDofBilateralReduceLight of four full-resolution pixels (no offsets of their own), the offset dropped.
FFX_DOF_INLINE void ffxDofBilateralReduce(FfxFloat32x3 color0, FfxFloat32x3 color1, FfxFloat32x3 color2,
                                          FfxFloat32x3 color3, FfxFloat32 coc0, FfxFloat32 coc1, FfxFloat32 coc2,
                                          FfxFloat32 coc3, FFX_DOF_OUT(FfxFloat32x3) color, FFX_DOF_OUT(FfxFloat32) coc)
{
    FfxFloat32x2 none = FfxFloat32x2(0.0f, 0.0f);
    FfxFloat32x2 offset;
    ffxDofBilateralReduceLight(color0, color1, color2, color3, coc0, coc1, coc2, coc3, none, none, none, none, color,
                               coc, offset);
}

// MIP 0 of a quad of full-resolution pixels (each a point of coverage 1): ffxDofReduceSources.
FFX_DOF_INLINE FfxDofNearQuad ffxDofReduceNearQuad(FfxFloat32x3 color0, FfxFloat32x3 color1, FfxFloat32x3 color2,
                                                   FfxFloat32x3 color3, FfxFloat32 coc0, FfxFloat32 coc1,
                                                   FfxFloat32 coc2, FfxFloat32 coc3)
{
    return ffxDofReduceSources(ffxDofPixelTexel(color0, coc0), ffxDofPixelTexel(color1, coc1),
                               ffxDofPixelTexel(color2, coc2), ffxDofPixelTexel(color3, coc3),
                               FFX_DOF_NEAR_COVERAGE_MIN_RADIUS, FFX_DOF_NEAR_COVERAGE_INSET);
}
FFX_DOF_INLINE FfxDofMipTexel ffxDofReduceQuadTexel(FfxFloat32x3 color0, FfxFloat32x3 color1, FfxFloat32x3 color2,
                                                    FfxFloat32x3 color3, FfxFloat32 coc0, FfxFloat32 coc1,
                                                    FfxFloat32 coc2, FfxFloat32 coc3)
{
    return ffxDofReduceNearQuad(color0, color1, color2, color3, coc0, coc1, coc2, coc3).texel;
}

// A texel of MIP 1..3 from four of the level below. A partly covered child's radius is at least
// FFX_DOF_NEAR_COVERAGE_MIN_RADIUS less the inset, so from there its share always carries on up; the inset is
// taken once, at MIP 0.
FFX_DOF_INLINE FfxDofMipTexel ffxDofReduceMipTexel(FfxDofMipTexel texel0, FfxDofMipTexel texel1, FfxDofMipTexel texel2,
                                                   FfxDofMipTexel texel3)
{
    return ffxDofReduceSources(texel0, texel1, texel2, texel3,
                               FFX_DOF_NEAR_COVERAGE_MIN_RADIUS - FFX_DOF_NEAR_COVERAGE_INSET, 0.0f)
        .texel;
}

// ---- Light rims -------------------------------------------------------------------------------------

// A depth buffer holds one surface per pixel, so the anti-aliased rim of a small light, which the light
// covers only in part, has the depth of the surface behind it. Blurred with that surface's larger
// radius, the light's rim spread into a wide faint halo around its disc and the disc lost that light
// (docs/technique.md, "Light rims"). A far-field pixel at least FFX_DOF_LIGHT_RIM_CONTRAST times
// brighter than the dimmest pixel of its own surface among its 8 neighbours takes the radius of its
// nearest far-field neighbour that is at least as bright: its light spreads with the light's disc.
#define FFX_DOF_LIGHT_RIM_CONTRAST 4.0f

struct FfxDofLightRim
{
    FfxFloat32 dimmest;  // dimmest luminance of the pixel's own surface (radii within 1 px), itself included
    FfxFloat32 nearest;  // largest (nearest) far-field radius of a neighbour at least as bright, or its own
};

FFX_DOF_INLINE FfxDofLightRim ffxDofLightRimBegin(FfxFloat32 luminance, FfxFloat32 coc)
{
    FfxDofLightRim rim;
    rim.dimmest = luminance;
    rim.nearest = coc;
    return rim;
}

FFX_DOF_INLINE FfxDofLightRim ffxDofLightRimAdd(FfxDofLightRim rim, FfxFloat32 luminance, FfxFloat32 coc,
                                                FfxFloat32 neighbourLuminance, FfxFloat32 neighbourCoc)
{
    if (abs(neighbourCoc - coc) <= 1.0f)
        rim.dimmest = min(rim.dimmest, neighbourLuminance);
    if (neighbourLuminance >= luminance && neighbourCoc <= -1.0f)
        rim.nearest = max(rim.nearest, neighbourCoc);
    return rim;
}

// Whether a far pixel of `luminance` is the rim of a light, the dimmest pixel of its own surface around it (itself
// included) `dimmest`; with a lower bound of that for `dimmest`, whether it may be one.
FFX_DOF_INLINE FfxBoolean ffxDofIsLightRim(FfxFloat32 luminance, FfxFloat32 coc, FfxFloat32 dimmest)
{
    return coc <= -1.0f && luminance > 0.0f && luminance >= FFX_DOF_LIGHT_RIM_CONTRAST * dimmest;
}

// The radius the pixel is downsampled with: a light's rim takes the light's.
FFX_DOF_INLINE FfxFloat32 ffxDofLightRimCoc(FfxDofLightRim rim, FfxFloat32 luminance, FfxFloat32 coc)
{
    return ffxDofIsLightRim(luminance, coc, rim.dimmest) ? rim.nearest : coc;
}

// ---- HDR range --------------------------------------------------------------------------------------

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

// A level's texel in group-shared memory: its colour and radius in one element, its light offset in another (on
// lavapipe every group-shared read is a loop over the lanes, whatever its width). The radius carries the coverage in
// its 8 lowest mantissa bits (in 256ths, exact: MIP 0's quarters summed over three levels; a 32-bit radius keeps 15
// bits): a third array for the coverage cost about half of what the coarse levels' coverage added to the pass
// (docs/performance.md, "Near coverage in the coarse MIPs").
FFX_DOF_GROUPSHARED FfxFloat32x4 ffxDofSharedMipColorCoc[FFX_DOF_GROUP_THREADS];
FFX_DOF_GROUPSHARED FfxFloat32x2 ffxDofSharedMipLightOffset[FFX_DOF_GROUP_THREADS];

#define FFX_DOF_SHARED_COVERAGE_MASK 0xffu
FFX_DOF_INLINE FfxFloat32x4 ffxDofEncodeSharedMipColorCoc(FfxDofMipTexel texel)
{
    FfxUInt32 code = FfxUInt32(clamp(floor(texel.coverage * 256.0f + 0.5f), 1.0f, 256.0f)) - 1u;
    return FfxFloat32x4(texel.color, ffxDofAsFloat((ffxDofAsUInt(texel.coc) & ~FFX_DOF_SHARED_COVERAGE_MASK) | code));
}
FFX_DOF_INLINE FfxDofMipTexel ffxDofDecodeSharedMipTexel(FfxFloat32x4 colorCoc, FfxFloat32x2 lightOffset)
{
    FfxUInt32 cocBits = ffxDofAsUInt(colorCoc.w);
    return ffxDofMakeMipTexel(FfxFloat32x3(colorCoc.x, colorCoc.y, colorCoc.z),
                              ffxDofAsFloat(cocBits & ~FFX_DOF_SHARED_COVERAGE_MASK),
                              FfxFloat32((cocBits & FFX_DOF_SHARED_COVERAGE_MASK) + 1u) * (1.0f / 256.0f), lightOffset);
}
FFX_DOF_INLINE void ffxDofStoreSharedMipTexel(FfxUInt32 index, FfxDofMipTexel texel)
{
    ffxDofSharedMipColorCoc[index] = ffxDofEncodeSharedMipColorCoc(texel);
    ffxDofSharedMipLightOffset[index] = texel.lightOffset;
}
FFX_DOF_INLINE FfxDofMipTexel ffxDofSharedMipTexel(FfxUInt32 index)
{
    return ffxDofDecodeSharedMipTexel(ffxDofSharedMipColorCoc[index], ffxDofSharedMipLightOffset[index]);
}
// The texel as its slot holds it, from registers: what the invocation that stored it would read back.
FFX_DOF_INLINE FfxDofMipTexel ffxDofAsSharedMipTexel(FfxDofMipTexel texel)
{
    return ffxDofDecodeSharedMipTexel(ffxDofEncodeSharedMipColorCoc(texel), texel.lightOffset);
}

// The group's full-resolution pixels and a one-pixel border: (luminance, radius) for the light rims.
#define FFX_DOF_RIM_SIDE (2u * FFX_DOF_TILE_SIZE + 2u)
FFX_DOF_GROUPSHARED FfxFloat32x2 ffxDofSharedRimSample[FFX_DOF_RIM_SIDE * FFX_DOF_RIM_SIDE];

// The highlight sums of the group's quads (ffxDofQuadHighlightSums), summed up the same 2 x 2 tree as the MIP levels
// to one per quadrant of the tile (4 x 4 quads, after two levels), and whether any quad gives light.
FFX_DOF_GROUPSHARED FfxFloat32x4 ffxDofSharedHighlightEnergyLight[FFX_DOF_GROUP_THREADS];
FFX_DOF_GROUPSHARED FfxFloat32x4 ffxDofSharedHighlightPlaceRadius[FFX_DOF_GROUP_THREADS];
// The anisotropy (xy) and the near pixels' light (z) in one array: one group-shared read for both.
FFX_DOF_GROUPSHARED FfxFloat32x4 ffxDofSharedHighlightAnisotropyNear[FFX_DOF_GROUP_THREADS];
// Bit i (of word i / 32): quad i stored its sums, which only the quads of a wave where some quad gives light do (the
// others' sums hold none, and most groups give no light): 12 components a quad (docs/performance.md, "Floors and
// highlight sums where a wave gives light").
FFX_DOF_GROUPSHARED FfxUInt32 ffxDofSharedHighlightQuads[FFX_DOF_GROUP_THREADS / 32];

FFX_DOF_INLINE void ffxDofStoreSharedHighlightSums(FfxUInt32 index, FfxDofHighlightSums sums)
{
    ffxDofSharedHighlightEnergyLight[index] = sums.energyLight;
    ffxDofSharedHighlightPlaceRadius[index] = sums.placeRadius;
    ffxDofSharedHighlightAnisotropyNear[index] =
        FfxFloat32x4(sums.anisotropy.x, sums.anisotropy.y, sums.nearLight, 0.0f);
}
FFX_DOF_INLINE FfxDofHighlightSums ffxDofSharedHighlightSums(FfxUInt32 index)
{
    FfxDofHighlightSums sums;
    sums.energyLight = ffxDofSharedHighlightEnergyLight[index];
    sums.placeRadius = ffxDofSharedHighlightPlaceRadius[index];
    FfxFloat32x4 anisotropyNear = ffxDofSharedHighlightAnisotropyNear[index];
    sums.anisotropy = FfxFloat32x2(anisotropyNear.x, anisotropyNear.y);
    sums.nearLight = anisotropyNear.z;
    return sums;
}
// Quad `index`'s sums: those it stored, else none (the sums of a quad whose wave gave no light).
FFX_DOF_INLINE FfxDofHighlightSums ffxDofQuadSharedHighlightSums(FfxUInt32 index)
{
    if ((ffxDofSharedHighlightQuads[index / 32u] & (1u << (index % 32u))) != 0u)
        return ffxDofSharedHighlightSums(index);
    return ffxDofNoHighlightSums();
}
// Whether any quad of the group gives light.
FFX_DOF_INLINE FfxBoolean ffxDofGroupGivesHighlights()
{
    FfxUInt32 stored = 0u;
    FFX_DOF_UNROLL
    for (FfxUInt32 word = 0u; word < FfxUInt32(FFX_DOF_GROUP_THREADS / 32); ++word)
        stored |= ffxDofSharedHighlightQuads[word];
    return stored != 0u;
}

// The quadrants' sums are two levels up the tree: the chain's loop runs at least that far.
#define FFX_DOF_HIGHLIGHT_QUADRANT_LEVEL 2u
#if FFX_DOF_OPTION_MAX_MIP > 3
#define FFX_DOF_DOWNSAMPLE_COLOR_LEVELS FFX_DOF_OPTION_MAX_MIP
#else
#define FFX_DOF_DOWNSAMPLE_COLOR_LEVELS 3
#endif

// Per wave, over the group's pixels and border: the dimmest luminance (the floor near highlights stand on, and the
// light rims' bound); the dimmest far luminance (the far highlights' floor, ffxDofPackHighlightFloors) and the radii
// of the far pixels above white, with the colour peak of the group's own pixels; and the far sums (ffxDofFarSums: the
// far surround, and whether the tile is a bright far field behind nearer far content). Every wave reads the first;
// only a wave with a pixel above white, or the one that stores the tile's floors and peak, reads the others
// (docs/performance.md, "Floors and highlight sums where a wave gives light").
FFX_DOF_GROUPSHARED FfxFloat32 ffxDofSharedWaveDimmest[FFX_DOF_GROUP_THREADS];
FFX_DOF_GROUPSHARED FfxFloat32x3 ffxDofSharedWaveFarFloors[FFX_DOF_GROUP_THREADS];
FFX_DOF_GROUPSHARED FfxFloat32x4 ffxDofSharedWaveFarSums[FFX_DOF_GROUP_THREADS];

// Scaled in 32-bit (and clamped to the half range) before any conversion to 16 bits.
FFX_DOF_INLINE FfxFloat32x4 ffxDofLoadScaledInputColor(FfxUInt32x2 pixel, FfxFloat32 scale)
{
    return ffxDofScaleColor(ffxDofLoadInputColor(pixel), scale);
}

// A pixel's radius before the limit clamps it (ffxDofCocFromDepth without the clamp): the depth order of far pixels
// that the limit gives one radius.
FFX_DOF_INLINE FfxFloat32 ffxDofUnclampedCoc(FfxFloat32 depth, FfxDofConstants constants)
{
    return depth * constants.cocScale + constants.cocBias;
}
// A pixel's (luminance, radius) for the rim grid, from its colour and its radius before the limit
// (ffxDofUnclampedCoc), and the luminance where it is in the far field (else the largest float): what the highlights'
// floor takes.
FFX_DOF_INLINE FfxFloat32x2 ffxDofRimSample(FfxFloat32x4 color, FfxFloat32 unclampedCoc, FfxDofConstants constants)
{
    return FfxFloat32x2(ffxDofLuminance32(FfxFloat32x3(color.x, color.y, color.z)),
                        clamp(unclampedCoc, -constants.cocLimit, constants.cocLimit));
}
FFX_DOF_INLINE FfxFloat32 ffxDofFarLuminance(FfxFloat32x2 rimSample)
{
    return rimSample.y <= -FFX_DOF_IN_FOCUS_RADIUS ? rimSample.x : FFX_DOF_FLOAT32_MAX;
}

// The radius pixel `inQuad` (0: top-left .. 3: bottom-right) of a quad is downsampled with, from the quad's 4 x 4
// neighbourhood of (luminance, radius), row by row from its top-left neighbour.
FFX_DOF_INLINE FfxFloat32 ffxDofLightRimCocInQuad(FfxFloat32x2 around[16], FfxUInt32 inQuad)
{
    FfxUInt32 centre = (1u + (inQuad >> 1u)) * 4u + 1u + (inQuad & 1u);
    FfxDofLightRim rim = ffxDofLightRimBegin(around[centre].x, around[centre].y);
    FFX_DOF_UNROLL
    for (FfxUInt32 neighbour = 0u; neighbour < 9u; ++neighbour)
    {
        if (neighbour == 4u)
            continue;
        FfxUInt32 at = centre + (neighbour / 3u) * 4u + neighbour % 3u - 5u;
        rim = ffxDofLightRimAdd(rim, around[centre].x, around[centre].y, around[at].x, around[at].y);
    }
    return ffxDofLightRimCoc(rim, around[centre].x, around[centre].y);
}

FFX_DOF_INLINE FfxFloat32x3 ffxDofRgb(FfxFloat32x4 color) { return FfxFloat32x3(color.x, color.y, color.z); }

FFX_DOF_INLINE void ffxDofDownsampleColor(FfxUInt32x2 groupId, FfxUInt32 localIndex)
{
    FfxDofConstants constants = ffxDofGetFocusedConstants();
    FfxUInt32x2 local = ffxDofLocalCoord(localIndex);
    FfxUInt32x2 texel = groupId * FfxUInt32(FFX_DOF_TILE_SIZE) + local;
    FfxUInt32x2 quad = texel * 2u;
    FfxUInt32x2 lastPixel = constants.fullSize - FfxUInt32x2(1u, 1u);
    // The first run takes the colour as it is; the second reads the peak the first one raised (no run reads a word
    // that its own workgroups write).
    FfxBoolean rerun = (constants.outputFlags & FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN) != 0u;
    FfxFloat32 scale = rerun ? ffxDofColorRangeScale(ffxDofLoadColorPeak()) : 1.0f;
    // One store is enough (the composite runs after a barrier); pass 3 resets the peak.
    if (groupId.x == 0u && groupId.y == 0u && localIndex == 0u)
        ffxDofStoreColorScale(scale);

    FfxUInt32x2 pixel0 = min(quad, lastPixel);
    FfxUInt32x2 pixel1 = min(quad + FfxUInt32x2(1u, 0u), lastPixel);
    FfxUInt32x2 pixel2 = min(quad + FfxUInt32x2(0u, 1u), lastPixel);
    FfxUInt32x2 pixel3 = min(quad + FfxUInt32x2(1u, 1u), lastPixel);
    FfxFloat32x4 raw0 = ffxDofLoadInputColor(pixel0);
    FfxFloat32x4 raw1 = ffxDofLoadInputColor(pixel1);
    FfxFloat32x4 raw2 = ffxDofLoadInputColor(pixel2);
    FfxFloat32x4 raw3 = ffxDofLoadInputColor(pixel3);
    FfxFloat32 colorPeak =
        max(max(ffxDofColorPeak(raw0), ffxDofColorPeak(raw1)), max(ffxDofColorPeak(raw2), ffxDofColorPeak(raw3)));
    FfxFloat32x4 input0 = ffxDofScaleColor(raw0, scale);
    FfxFloat32x4 input1 = ffxDofScaleColor(raw1, scale);
    FfxFloat32x4 input2 = ffxDofScaleColor(raw2, scale);
    FfxFloat32x4 input3 = ffxDofScaleColor(raw3, scale);

    // The light rims need each pixel's 8 neighbours: the group's pixels and a border of one.
    FfxUInt32x2 cell = local * 2u + FfxUInt32x2(1u, 1u);
    FfxFloat32 unclamped0 = ffxDofUnclampedCoc(ffxDofLoadInputDepth(pixel0), constants);
    FfxFloat32 unclamped1 = ffxDofUnclampedCoc(ffxDofLoadInputDepth(pixel1), constants);
    FfxFloat32 unclamped2 = ffxDofUnclampedCoc(ffxDofLoadInputDepth(pixel2), constants);
    FfxFloat32 unclamped3 = ffxDofUnclampedCoc(ffxDofLoadInputDepth(pixel3), constants);
    FfxFloat32x2 rim0 = ffxDofRimSample(input0, unclamped0, constants);
    FfxFloat32x2 rim1 = ffxDofRimSample(input1, unclamped1, constants);
    FfxFloat32x2 rim2 = ffxDofRimSample(input2, unclamped2, constants);
    FfxFloat32x2 rim3 = ffxDofRimSample(input3, unclamped3, constants);
    ffxDofSharedRimSample[cell.y * FFX_DOF_RIM_SIDE + cell.x] = rim0;
    ffxDofSharedRimSample[cell.y * FFX_DOF_RIM_SIDE + cell.x + 1u] = rim1;
    ffxDofSharedRimSample[(cell.y + 1u) * FFX_DOF_RIM_SIDE + cell.x] = rim2;
    ffxDofSharedRimSample[(cell.y + 1u) * FFX_DOF_RIM_SIDE + cell.x + 1u] = rim3;
    if (localIndex < FfxUInt32(FFX_DOF_GROUP_THREADS / 32))
        ffxDofSharedHighlightQuads[localIndex] = 0u;
    // The highlights' floors (below): the dimmest far pixel and the dimmest pixel of the group's and of the border,
    // per wave here.
    FfxFloat32 dimmestFar = min(min(ffxDofFarLuminance(rim0), ffxDofFarLuminance(rim1)),
                                min(ffxDofFarLuminance(rim2), ffxDofFarLuminance(rim3)));
    FfxFloat32 dimmest = min(min(rim0.x, rim1.x), min(rim2.x, rim3.x));
    FfxFloat32 white = ffxDofHighlightWhite(scale);
    FfxFloat32x4 far0 = ffxDofFarSums(rim0, unclamped0, white);
    FfxFloat32x4 far1 = ffxDofFarSums(rim1, unclamped1, white);
    FfxFloat32x4 far2 = ffxDofFarSums(rim2, unclamped2, white);
    FfxFloat32x4 far3 = ffxDofFarSums(rim3, unclamped3, white);
    FfxFloat32x4 farSums = far0 + far1 + far2 + far3;
    FfxFloat32 brightRadiusSum = far0.w * unclamped0 + far1.w * unclamped1 + far2.w * unclamped2 + far3.w * unclamped3;
    FfxInt32x2 origin = FfxInt32x2(groupId * (2u * FfxUInt32(FFX_DOF_TILE_SIZE))) - FfxInt32x2(1, 1);
    FFX_DOF_LOOP
    for (FfxUInt32 border = localIndex; border < 4u * (FFX_DOF_RIM_SIDE - 1u); border += FFX_DOF_GROUP_THREADS)
    {
        FfxUInt32x2 borderCell = ffxDofBorderCell(border, FfxUInt32(FFX_DOF_RIM_SIDE));
        FfxUInt32x2 pixel =
            FfxUInt32x2(clamp(origin + FfxInt32x2(borderCell), FfxInt32x2(0, 0), FfxInt32x2(lastPixel)));
        FfxFloat32 borderingUnclamped = ffxDofUnclampedCoc(ffxDofLoadInputDepth(pixel), constants);
        FfxFloat32x2 bordering =
            ffxDofRimSample(ffxDofLoadScaledInputColor(pixel, scale), borderingUnclamped, constants);
        ffxDofSharedRimSample[borderCell.y * FFX_DOF_RIM_SIDE + borderCell.x] = bordering;
        dimmestFar = min(dimmestFar, ffxDofFarLuminance(bordering));
        dimmest = min(dimmest, bordering.x);
        FfxFloat32x4 borderingFar = ffxDofFarSums(bordering, borderingUnclamped, white);
        farSums += borderingFar;
        brightRadiusSum += borderingFar.w * borderingUnclamped;
    }
    dimmestFar = ffxDofWaveMin(dimmestFar);
    dimmest = ffxDofWaveMin(dimmest);
    farSums = ffxDofWaveSum(farSums);
    brightRadiusSum = ffxDofWaveSum(brightRadiusSum);
    colorPeak = ffxDofWaveMax(colorPeak);
    if (ffxDofWaveIsFirstLane())
    {
        ffxDofSharedWaveDimmest[ffxDofWaveIndex(localIndex)] = dimmest;
        ffxDofSharedWaveFarFloors[ffxDofWaveIndex(localIndex)] = FfxFloat32x3(dimmestFar, brightRadiusSum, colorPeak);
        ffxDofSharedWaveFarSums[ffxDofWaveIndex(localIndex)] = farSums;
    }
    ffxDofGroupBarrier();
    FfxFloat32 tileDimmest = FFX_DOF_FLOAT32_MAX;
    FFX_DOF_LOOP
    for (FfxUInt32 first = 0u; first < ffxDofWaveCount(); first += ffxDofWaveLaneCount())
    {
        FfxUInt32 wave = ffxDofLaneWaveSlot(first);
        if (wave < ffxDofWaveCount())
            tileDimmest = min(tileDimmest, ffxDofSharedWaveDimmest[wave]);
    }
    tileDimmest = ffxDofWaveMin(tileDimmest);

    // The radii the quad's pixels are downsampled with (light rims). No pixel of the rim grid is dimmer than the
    // tile's dimmest, so a pixel that is no rim against that is none whatever its neighbours: a quad without such far
    // pixels keeps its radii and reads none of its 12 neighbours (ffxDofLightRimCocInQuad would return the same; on
    // lavapipe the reads were a third of the pass, docs/performance.md, "Light rims only where the tile's contrast
    // allows them").
    FfxFloat32 coc0 = rim0.y;
    FfxFloat32 coc1 = rim1.y;
    FfxFloat32 coc2 = rim2.y;
    FfxFloat32 coc3 = rim3.y;
    if (ffxDofIsLightRim(rim0.x, rim0.y, tileDimmest) || ffxDofIsLightRim(rim1.x, rim1.y, tileDimmest) ||
        ffxDofIsLightRim(rim2.x, rim2.y, tileDimmest) || ffxDofIsLightRim(rim3.x, rim3.y, tileDimmest))
    {
        // The quad's 4 x 4 neighbourhood read once for its four pixels (12 group-shared reads instead of 32: on
        // lavapipe each is a loop over the lanes).
        FfxFloat32x2 around[16];
        FFX_DOF_UNROLL
        for (FfxUInt32 k = 0u; k < 16u; ++k)
        {
            if (k == 5u || k == 6u || k == 9u || k == 10u)
                continue;
            around[k] = ffxDofSharedRimSample[(cell.y + k / 4u - 1u) * FFX_DOF_RIM_SIDE + cell.x + k % 4u - 1u];
        }
        around[5] = rim0;
        around[6] = rim1;
        around[9] = rim2;
        around[10] = rim3;
        coc0 = ffxDofLightRimCocInQuad(around, 0u);
        coc1 = ffxDofLightRimCocInQuad(around, 1u);
        coc2 = ffxDofLightRimCocInQuad(around, 2u);
        coc3 = ffxDofLightRimCocInQuad(around, 3u);
    }
    // Highlights: the light of pixels far brighter than the tile's floor leaves the half-res colour for the
    // composite's full-resolution discs (ffx_dof_highlights.h), one per quadrant of the tile.
    // The floors: of the tile and its border (the waves' minima above), so that every pixel of a light within it
    // gives its light (a light split between both paths drew its rest from the layers 1.05 to 1.10 times too
    // bright, docs/technique.md); as the composite reads them back (ffxDofPackHighlightFloors). A pixel not above
    // white gives nothing over any floors (ffxDofHighlightBrightness), so a wave none of whose pixels is reads them
    // only where it holds the invocation that stores them.
    FfxUInt32 packedFloors = 0u;
    FfxFloat32 tilePeak = 0.0f;
    FfxFloat32x4 shares = FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
    FfxBoolean quadAboveWhite =
        max(max(ffxDofHighlightBrightness(rim0.x, scale), ffxDofHighlightBrightness(rim1.x, scale)),
            max(ffxDofHighlightBrightness(rim2.x, scale), ffxDofHighlightBrightness(rim3.x, scale))) > 0.0f;
    if (ffxDofWaveAny(quadAboveWhite || localIndex == 1u))
    {
        FfxFloat32 tileDimmestFar = FFX_DOF_FLOAT32_MAX;
        FfxFloat32 tileBrightRadiusSum = 0.0f;
        FfxFloat32x4 tileFarSums = FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
        FFX_DOF_LOOP
        for (FfxUInt32 first = 0u; first < ffxDofWaveCount(); first += ffxDofWaveLaneCount())
        {
            FfxUInt32 wave = ffxDofLaneWaveSlot(first);
            if (wave < ffxDofWaveCount())
            {
                FfxFloat32x3 waveFarFloors = ffxDofSharedWaveFarFloors[wave];
                tileDimmestFar = min(tileDimmestFar, waveFarFloors.x);
                tileBrightRadiusSum += waveFarFloors.y;
                tilePeak = max(tilePeak, waveFarFloors.z);
                tileFarSums += ffxDofSharedWaveFarSums[wave];
            }
        }
        tileDimmestFar = ffxDofWaveMin(tileDimmestFar);
        tileBrightRadiusSum = ffxDofWaveSum(tileBrightRadiusSum);
        tileFarSums = ffxDofWaveSum(tileFarSums);
        tilePeak = ffxDofWaveMax(tilePeak);
        // A bright far field behind nearer far content gives no far light: its far floor is none.
        if (ffxDofBrightFieldBehind(tileFarSums, tileBrightRadiusSum))
            tileDimmestFar = FFX_DOF_HIGHLIGHT_NO_FLOOR;
        packedFloors = ffxDofPackHighlightFloors(
            FfxFloat32x3(tileDimmestFar, tileDimmest, ffxDofFarSurround(FfxFloat32x2(tileFarSums.x, tileFarSums.y))));
        FfxFloat32x3 tileFloors = ffxDofUnpackHighlightFloors(packedFloors);
        shares = FfxFloat32x4(ffxDofHighlightShare(rim0.x, coc0, ffxDofHighlightFloor(tileFloors, coc0), scale),
                              ffxDofHighlightShare(rim1.x, coc1, ffxDofHighlightFloor(tileFloors, coc1), scale),
                              ffxDofHighlightShare(rim2.x, coc2, ffxDofHighlightFloor(tileFloors, coc2), scale),
                              ffxDofHighlightShare(rim3.x, coc3, ffxDofHighlightFloor(tileFloors, coc3), scale));
    }
    if (ffxDofQuadCutByEdge(quad, constants.fullSize))
        shares = FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
    FfxDofHighlightSums highlightSums =
        ffxDofQuadHighlightSums(FfxFloat32x3(input0.x, input0.y, input0.z), FfxFloat32x3(input1.x, input1.y, input1.z),
                                FfxFloat32x3(input2.x, input2.y, input2.z), FfxFloat32x3(input3.x, input3.y, input3.z),
                                FfxFloat32x4(coc0, coc1, coc2, coc3), shares, FfxFloat32x2(local * 2u));
    FfxBoolean quadGivesLight = ffxDofHighlightSumsHoldLight(highlightSums);
    if (ffxDofWaveAny(quadGivesLight))
    {
        ffxDofStoreSharedHighlightSums(localIndex, highlightSums);
        ffxDofGroupAtomicOr(ffxDofSharedHighlightQuads[localIndex / 32u], 1u << (localIndex % 32u));
    }
    if (quadGivesLight)
    {
        input0 = FfxFloat32x4(FfxFloat32x3(input0.x, input0.y, input0.z) * (1.0f - shares.x), input0.w);
        input1 = FfxFloat32x4(FfxFloat32x3(input1.x, input1.y, input1.z) * (1.0f - shares.y), input1.w);
        input2 = FfxFloat32x4(FfxFloat32x3(input2.x, input2.y, input2.z) * (1.0f - shares.z), input2.w);
        input3 = FfxFloat32x4(FfxFloat32x3(input3.x, input3.y, input3.z) * (1.0f - shares.w), input3.w);
    }

    // MIP 0 keeps a partly near quad's near pixels with their coverage (Near coverage, ffx_dof_common.h), and the
    // coarse levels reduce what it keeps.
    FfxDofMipTexel mip0 = ffxDofReduceQuadTexel(ffxDofRgb(input0), ffxDofRgb(input1), ffxDofRgb(input2),
                                                ffxDofRgb(input3), coc0, coc1, coc2, coc3);
    if (texel.x < constants.halfSize.x && texel.y < constants.halfSize.y)
    {
        ffxDofStoreHalfColor(texel, ffxDofToDofFloat3(ffxDofRoundForPackedColor32(mip0.color)));
        ffxDofStoreHalfCoc(texel, ffxDofPackNearCoverage(ffxDofRoundForHalfCoc(mip0.coc), mip0.coverage));
    }
    ffxDofStoreSharedMipTexel(localIndex, mip0);

    // Level m is kept at the top-left texel of each 2^m block: a thread only overwrites a slot it has read itself, so
    // one barrier per level suffices. A block's top-left slot is the invocation's own, whose texel (and highlight
    // sums) it keeps in registers: it reads the other three (on lavapipe every group-shared read is a loop over the
    // lanes, and masked-off invocations run every level). The quadrants' highlight sums climb the same tree.
    FfxDofMipTexel ownTexel = ffxDofAsSharedMipTexel(mip0);
    FFX_DOF_UNROLL
    for (FfxUInt32 mip = 1u; mip < FfxUInt32(FFX_DOF_DOWNSAMPLE_COLOR_LEVELS); ++mip)
    {
        ffxDofGroupBarrier();
        FfxUInt32 step = 1u << mip;
        FfxUInt32 halfStep = step >> 1u;
        if ((local.x & (step - 1u)) == 0u && (local.y & (step - 1u)) == 0u)
        {
            FfxUInt32 i1 = localIndex + halfStep;
            FfxUInt32 i2 = localIndex + halfStep * FfxUInt32(FFX_DOF_GROUP_SIDE);
            FfxUInt32 i3 = i2 + halfStep;
            if (mip < FfxUInt32(FFX_DOF_OPTION_MAX_MIP))
            {
                FfxDofMipTexel reduced = ffxDofReduceMipTexel(ownTexel, ffxDofSharedMipTexel(i1),
                                                              ffxDofSharedMipTexel(i2), ffxDofSharedMipTexel(i3));
                if (mip + 1u < FfxUInt32(FFX_DOF_OPTION_MAX_MIP))
                {
                    ffxDofStoreSharedMipTexel(localIndex, reduced);
                    ownTexel = ffxDofAsSharedMipTexel(reduced);
                }
                FfxUInt32x2 mipTexel =
                    groupId * (FfxUInt32(FFX_DOF_TILE_SIZE) >> mip) + FfxUInt32x2(local.x >> mip, local.y >> mip);
                FfxUInt32x2 mipSize = ffxDofMipSize(constants.halfSize, mip);
                if (mipTexel.x < mipSize.x && mipTexel.y < mipSize.y)
                {
                    ffxDofStoreCoarseMip(
                        mip, mipTexel,
                        ffxDofPackCoarseTexel(ffxDofRoundForPackedColor32(reduced.color),
                                              ffxDofPackCoarseNearCoverage(reduced.coc, reduced.coverage),
                                              reduced.lightOffset));
                }
            }
            // A group none of whose quads gives light skips its sums (a branch of the whole group on a GPU). The
            // first level reads the quads' sums where they stored them, the second what the first level's blocks
            // stored (every one of them, in a group with light).
            if (mip <= FFX_DOF_HIGHLIGHT_QUADRANT_LEVEL && ffxDofGroupGivesHighlights())
            {
                highlightSums = ffxDofAddHighlightSums(
                    ffxDofAddHighlightSums(
                        highlightSums, mip == 1u ? ffxDofQuadSharedHighlightSums(i1) : ffxDofSharedHighlightSums(i1)),
                    ffxDofAddHighlightSums(
                        mip == 1u ? ffxDofQuadSharedHighlightSums(i2) : ffxDofSharedHighlightSums(i2),
                        mip == 1u ? ffxDofQuadSharedHighlightSums(i3) : ffxDofSharedHighlightSums(i3)));
                if (mip < FFX_DOF_HIGHLIGHT_QUADRANT_LEVEL)
                    ffxDofStoreSharedHighlightSums(localIndex, highlightSums);
            }
        }
    }

    // The quadrants' highlights, from the invocation at each quadrant's top-left (its sums are the quadrant's; in a
    // group without light, every quad's sums hold none).
    FfxUInt32 quadrantSide = 1u << FFX_DOF_HIGHLIGHT_QUADRANT_LEVEL;
    if ((local.x & (quadrantSide - 1u)) == 0u && (local.y & (quadrantSide - 1u)) == 0u)
    {
        FfxUInt32 quadrant = (local.y / quadrantSide) * 2u + local.x / quadrantSide;
        FfxUInt32x3 packed = FfxUInt32x3(0u, 0u, 0u);
        if (ffxDofHighlightSumsHoldLight(highlightSums))
            packed = ffxDofPackHighlight(ffxDofFinishHighlight(highlightSums));
        FfxUInt32 word = ffxDofHighlightWord(groupId, quadrant, constants.tileCount);
        ffxDofStoreHighlightWord(word, packed.x);
        ffxDofStoreHighlightWord(word + 1u, packed.y);
        ffxDofStoreHighlightWord(word + 2u, packed.z);
    }
    // The floors, from which the composite knows what the tile's pixels gave (ffxDofPixelHighlightShare), and
    // whether they gave any (from an invocation that stores no quadrant's words).
    // The tile's colour peak, for dilate and the composite; the first run raises the frame's where the peak is above
    // the range limit (most frames stay below it, and a peak the scale ignores need not cost an atomic), and arms the
    // second run.
    if (localIndex == 1u)
    {
        ffxDofStoreHighlightWord(ffxDofHighlightFloorWord(groupId, constants.tileCount),
                                 packedFloors | (ffxDofGroupGivesHighlights() ? FFX_DOF_HIGHLIGHT_GIVEN_BIT : 0u));
        ffxDofStoreHighlightWord(ffxDofHighlightPeakWord(groupId, constants.tileCount), ffxDofPackTilePeak(tilePeak));
        if (!rerun && tilePeak > FFX_DOF_COLOR_RANGE_LIMIT)
        {
            ffxDofAtomicMaxColorPeak(tilePeak);
            ffxDofArmColorRangeRerun(constants.tileCount);
        }
    }
}

#endif  // FFX_DOF_DOWNSAMPLE_COLOR_H
