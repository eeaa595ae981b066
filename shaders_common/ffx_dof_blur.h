// Pass 4 of 5: the blur at half resolution, near and far field in one gather.
//
// One workgroup covers one tile (8 x 8 half-res px), one invocation per texel. Per texel:
//   kernel radius R = max(dilated near radius of the tile, |own radius|); rings from R and the
//   quality (ffxDofRingCount) -- per texel, so the ring count never changes at a tile border;
//   a random sub-pixel kernel origin; rings gathered from the outside in.
//   Near field (radius >= FFX_DOF_NEAR_THRESHOLD): scatter-as-gather, each sample weighted by reach
//   and inverse area; opacity from the summed area weights (ffxDofNearOpacity).
//   Far field (everything else): per ring a bucket, merged into the bucket of the outer rings with
//   ffxDofMergeBuckets (a nearer inner ring occludes). A sample only counts within its own radius,
//   so in-focus and foreground color never spreads into the far field beyond it.
//   Hole filling: when the texel itself is near, the far-field samples are also averaged regardless
//   of reach, and that average is the far color where no far-field sample reaches.
// Tile classes: copy (every radius that reaches the tile is in focus; equal to R < 0.5 per texel);
// far-only (no near radius reaches: the near branch is skipped, which changes nothing because a
// near sample from a tile that does not reach has zero reach).
// Ring merging (FFX_DOF_OPTION_MAX_RING_MERGE_LOG > 0) is decided per texel, not per tile: the
// outermost ring is gathered at full resolution first; where its radii are all within half a pixel
// of the texel's own (a flat far field), inner rings are gathered from a coarser MIP, 2^log rings at
// a time; between half a pixel and one pixel both paths run and are mixed (ffxDofRingMergeAmount).
// Samples are point-sampled (no bilinear mixing of a foreground and a background texel, which
// would let the foreground color leak with a halfway radius).
//
// Outputs: NEAR_COLOR, FAR_COLOR, LAYER_ALPHA (x: near opacity, y: far validity).
#ifndef FFX_DOF_BLUR_H
#define FFX_DOF_BLUR_H

#include "ffx_dof_common.h"

#if defined(FFX_CPU)
FfxDofConstants ffxDofGetConstants();
FfxFloat32x2 ffxDofLoadDilatedTile(FfxUInt32x2 tile);
FfxDofFloat3 ffxDofLoadColorMip(FfxInt32x2 texel, FfxUInt32 mip);
FfxFloat32 ffxDofLoadCocMip(FfxInt32x2 texel, FfxUInt32 mip);
void ffxDofStoreNearColor(FfxUInt32x2 texel, FfxDofFloat3 color);
void ffxDofStoreFarColor(FfxUInt32x2 texel, FfxDofFloat3 color);
void ffxDofStoreLayerAlpha(FfxUInt32x2 texel, FfxFloat32x2 nearOpacityFarValidity);
#endif

// Centre of texel `texel` of MIP `mip`, in half-res px.
FFX_DOF_INLINE FfxFloat32x2 ffxDofMipTexelCenter(FfxInt32x2 texel, FfxUInt32 mip)
{
    return (FfxFloat32x2(texel) + FfxFloat32x2(0.5f, 0.5f)) * FfxFloat32(1u << mip);
}

struct FfxDofBlurResult
{
    FfxDofFloat3 nearColor;
    FfxDofFloat3 farColor;
    FfxFloat32x2 alpha;  // near opacity, far validity
};

// Running sums of the gather of one texel: near sum and weights, hole fill, far buckets.
struct FfxDofGather
{
    FfxFloat32x3 nearSum;
    FfxFloat32 nearWeight;
    FfxFloat32x3 fillSum;
    FfxFloat32 fillCount;
    FfxFloat32 weightedSamples;
    FfxDofBucket outer;
    FfxFloat32 cocSpread;  // largest |radius - own radius| among the samples seen
};

// What every ring of one texel's kernel shares.
struct FfxDofKernel
{
    FfxFloat32x2 center;
    FfxFloat32x2 origin;
    FfxFloat32 centerCoc;
    FfxFloat32 spacing;
    FfxUInt32 baseMip;
    FfxUInt32 rings;
    FfxBoolean withNear;
    FfxBoolean centerIsNear;
};

// Gathers rings firstRing down to lastRing, from the outside in. With mergeLog > 0, a ring also
// stands for the 2^mergeLog - 1 rings inside it and is sampled from a MIP mergeLog levels coarser.
// trackSpread (a literal at every call, so it compiles away) records the radius spread of the
// samples for the ring-merge decision: only the outermost ring needs it.
// The sample loop is written for devices that run both sides of every branch (lavapipe, which runs
// groups of 8 lanes under masks even for a uniform condition): near and far samples are added with
// 0/1 shares instead of a branch, the hole-fill average is kept for every texel (only a near texel
// uses it), and positions stay in the sampled MIP's texel units (no int-to-float conversions).
FFX_DOF_INLINE void ffxDofGatherRings(FFX_DOF_INOUT(FfxDofGather) gather, FfxDofKernel kernel, FfxInt32 firstRing,
                                      FfxInt32 lastRing, FfxUInt32 mergeLog, FfxBoolean trackSpread,
                                      FfxDofConstants constants)
{
    FfxUInt32 mergeStep = 1u << mergeLog;
    FfxFloat32 nearThreshold = kernel.withNear ? FFX_DOF_NEAR_THRESHOLD : 3.4e38f;
    FfxInt32 ring = firstRing;
    FFX_DOF_LOOP
    while (ring >= lastRing)
    {
        FfxUInt32 ringIndex = FfxUInt32(ring);
        FfxBoolean merged = mergeStep > 1u && ringIndex < kernel.rings && ringIndex > 0u;
        FfxUInt32 mip = min(kernel.baseMip + (merged ? mergeLog : 0u), FfxUInt32(FFX_DOF_OPTION_MAX_MIP - 1));
        FfxFloat32 ringWeight = 1.0f;
        if (merged)
        {
            // Rings max(ring - step + 1, 1) .. ring have (first + last) * n / 2 times 6 samples.
            FfxUInt32 first = ringIndex + 1u > mergeStep ? ringIndex + 1u - mergeStep : 1u;
            ringWeight = FfxFloat32((first + ringIndex) * (ringIndex - first + 1u)) / FfxFloat32(2u * ringIndex);
        }
        FfxUInt32 sampleCount = ffxDofRingSampleCount(ringIndex);
        FfxDofBucket ringBucket = ffxDofEmptyBucket();
        FfxFloat32 texelSize = FfxFloat32(1u << mip);
        FfxFloat32 mipScale = 1.0f / texelSize;
        // In units of MIP texels: sample positions, and the kernel centre less half a texel so that
        // (texel - centre) is the offset of the texel's centre.
        FfxFloat32x2 origin = kernel.origin * mipScale;
        FfxFloat32x2 centerToCorner = kernel.center * mipScale - FfxFloat32x2(0.5f, 0.5f);
        FfxFloat32x2 lastTexel = FfxFloat32x2(ffxDofMipSize(constants.halfSize, mip) - FfxUInt32x2(1u, 1u));
        FfxFloat32x2 offset = ffxDofRingSamplePosition(ringIndex, 0u) * (kernel.spacing * mipScale);
        FfxFloat32x2 step = ffxDofRingSampleStep(ringIndex);
        FFX_DOF_LOOP
        for (FfxUInt32 sampleIndex = 0u; sampleIndex < sampleCount; ++sampleIndex)
        {
            FfxFloat32x2 sampleTexel = clamp(floor(origin + offset), FfxFloat32x2(0.0f, 0.0f), lastTexel);
            offset = FfxFloat32x2(offset.x * step.x - offset.y * step.y, offset.x * step.y + offset.y * step.x);
            FfxFloat32x3 color = ffxDofToFloat32x3(ffxDofLoadColorMip(FfxInt32x2(sampleTexel), mip));
            FfxFloat32 coc = ffxDofLoadCocMip(FfxInt32x2(sampleTexel), mip);
            if (trackSpread)
                gather.cocSpread = max(gather.cocSpread, abs(coc - kernel.centerCoc));
            // Reach is judged from the centre of the texel actually read, not from the ring: the
            // ring distance would let a texel spread half a texel beyond its radius.
            FfxFloat32x2 toTexel = sampleTexel - centerToCorner;
            FfxFloat32 distance = sqrt(dot(toTexel, toTexel)) * texelSize;
            // Near and far samples weigh alike (reach times inverse area).
            FfxFloat32 absCoc = abs(coc);
            FfxFloat32 reach = ffxDofReach(absCoc, distance);
            FfxFloat32 weight = reach * ffxDofAreaWeight(absCoc) * ringWeight;
            FfxFloat32 farShare = coc >= nearThreshold ? 0.0f : 1.0f;
            FfxFloat32 farWeight = weight * farShare;
            FfxFloat32 nearWeight = weight - farWeight;
            gather.nearSum += color * nearWeight;
            gather.nearWeight += nearWeight;
            ringBucket.color += color * farWeight;
            ringBucket.weight += farWeight;
            ringBucket.radius += absCoc * farWeight;
            ringBucket.coverage += reach * farShare;
            gather.fillSum += color * farShare;
            gather.fillCount += farShare;
        }
        ringBucket.sampleCount = FfxFloat32(sampleCount);
        gather.weightedSamples += FfxFloat32(sampleCount) * ringWeight;
        gather.outer = ffxDofMergeBuckets(gather.outer, ringBucket, kernel.spacing);
        ring = merged ? max(ring - FfxInt32(mergeStep), 0) : ring - 1;
    }
}

// The layers of one texel from its finished gather; `result` holds the defaults (texel itself).
FFX_DOF_INLINE FfxDofBlurResult ffxDofFinishGather(FfxDofGather gather, FfxDofKernel kernel, FfxFloat32 kernelRadius,
                                                   FfxDofBlurResult result)
{
    if (gather.nearWeight > 0.0f)
    {
        result.nearColor = ffxDofToDofFloat3(gather.nearSum / gather.nearWeight);
        result.alpha.x = ffxDofNearOpacity(gather.nearWeight, kernelRadius, gather.weightedSamples);
    }
    if (gather.outer.weight > 0.0f)
        result.farColor = ffxDofToDofFloat3(gather.outer.color / gather.outer.weight);
    else if (kernel.centerIsNear && gather.fillCount > 0.0f)
        result.farColor = ffxDofToDofFloat3(gather.fillSum / gather.fillCount);
    else
        result.alpha.y = 0.0f;
    return result;
}

// The blur of one half-res texel; `dilated` is its tile's (far, near) range from pass 3.
FFX_DOF_INLINE FfxDofBlurResult ffxDofBlurTexel(FfxUInt32x2 texel, FfxFloat32x2 dilated, FfxDofConstants constants)
{
    FfxDofBlurResult result;
    result.nearColor = FfxDofFloat3(0.0f, 0.0f, 0.0f);
    result.farColor = ffxDofLoadColorMip(FfxInt32x2(texel), 0u);
    result.alpha = FfxFloat32x2(0.0f, 1.0f);

    FfxDofKernel kernel;
    kernel.centerCoc = ffxDofLoadCocMip(FfxInt32x2(texel), 0u);
    FfxFloat32 nearRadius = max(dilated.y, 0.0f);
    FfxFloat32 kernelRadius = max(nearRadius, abs(kernel.centerCoc));
    kernel.rings = ffxDofRingCount(kernelRadius, constants.maxRings);
    if (kernel.rings == 0u)
        return result;  // in focus: the far layer holds the texel itself

    kernel.withNear = dilated.y >= FFX_DOF_NEAR_THRESHOLD;
    kernel.centerIsNear = kernel.centerCoc >= FFX_DOF_NEAR_THRESHOLD;
    kernel.spacing = kernelRadius / FfxFloat32(kernel.rings);
    kernel.baseMip = FfxUInt32(ffxDofMipForSpacing(kernel.spacing));
    kernel.center = FfxFloat32x2(texel) + FfxFloat32x2(0.5f, 0.5f);
    kernel.origin = kernel.center + ffxDofKernelJitter(texel, constants.frameIndex);

    FfxDofGather gather;
    gather.nearSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    gather.nearWeight = 0.0f;
    gather.fillSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    gather.fillCount = 0.0f;
    gather.weightedSamples = 0.0f;
    gather.outer = ffxDofEmptyBucket();
    gather.cocSpread = 0.0f;

    // The outermost ring is always gathered at full resolution (it keeps the circle), and it tells
    // how flat the radii around the texel are: the merged path is taken by how flat, per texel, from
    // the texel's own samples, never per tile (a per-tile switch shows as tile-shaped blocks).
    FfxInt32 outerRing = FfxInt32(kernel.rings);
    ffxDofGatherRings(gather, kernel, outerRing, outerRing, 0u, true, constants);
    FfxFloat32 mergeAmount = 0.0f;
#if FFX_DOF_OPTION_MAX_RING_MERGE_LOG > 0
    if (kernel.rings >= 2u && kernel.centerCoc <= -FFX_DOF_IN_FOCUS_RADIUS)
        mergeAmount = ffxDofRingMergeAmount(gather.cocSpread);
#endif
    FfxDofBlurResult fullResult = result;
    if (mergeAmount < 1.0f)
    {
        FfxDofGather full = gather;
        ffxDofGatherRings(full, kernel, outerRing - 1, 0, 0u, false, constants);
        fullResult = ffxDofFinishGather(full, kernel, kernelRadius, result);
    }
#if FFX_DOF_OPTION_MAX_RING_MERGE_LOG > 0
    if (mergeAmount > 0.0f)
    {
        ffxDofGatherRings(gather, kernel, outerRing - 1, 0, FfxUInt32(FFX_DOF_OPTION_MAX_RING_MERGE_LOG), false,
                          constants);
        FfxDofBlurResult mergedResult = ffxDofFinishGather(gather, kernel, kernelRadius, result);
        if (mergeAmount >= 1.0f)
            return mergedResult;
        // Between flat and not flat both paths run and are mixed, so the switch is continuous.
        FfxDofFloat mergedShare = FfxDofFloat(mergeAmount);
        fullResult.nearColor += (mergedResult.nearColor - fullResult.nearColor) * mergedShare;
        fullResult.farColor += (mergedResult.farColor - fullResult.farColor) * mergedShare;
        fullResult.alpha = ffxDofLerp(fullResult.alpha, mergedResult.alpha, mergeAmount);
    }
#endif
    return fullResult;
}

FFX_DOF_INLINE void ffxDofBlur(FfxUInt32x2 groupId, FfxUInt32 localIndex)
{
    FfxDofConstants constants = ffxDofGetConstants();
    FfxUInt32x2 texel = groupId * FfxUInt32(FFX_DOF_TILE_SIZE) + ffxDofLocalCoord(localIndex);
    if (texel.x >= constants.halfSize.x || texel.y >= constants.halfSize.y)
        return;
    FfxDofBlurResult result = ffxDofBlurTexel(texel, ffxDofLoadDilatedTile(groupId), constants);
    ffxDofStoreNearColor(texel, ffxDofRoundForPackedColor(result.nearColor));
    ffxDofStoreFarColor(texel, ffxDofRoundForPackedColor(result.farColor));
    ffxDofStoreLayerAlpha(texel, result.alpha);
}

#endif  // FFX_DOF_BLUR_H
