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
// near sample from a tile that does not reach has zero reach); flat far field (all radii within one
// pixel of each other) with FFX_DOF_OPTION_MAX_RING_MERGE_LOG > 0: inner rings are gathered from a
// coarser MIP, 2^log rings at a time, the outermost ring at full resolution to keep the circle.
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

// Below this spread of radii (half-res px) a far-field tile counts as flat for ring merging.
#define FFX_DOF_FLAT_RADIUS_RANGE 1.0f

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

// The blur of one half-res texel; `dilated` is its tile's (far, near) range from pass 3.
FFX_DOF_INLINE FfxDofBlurResult ffxDofBlurTexel(FfxUInt32x2 texel, FfxFloat32x2 dilated, FfxDofConstants constants)
{
    FfxDofBlurResult result;
    result.nearColor = FfxDofFloat3(0.0f, 0.0f, 0.0f);
    result.farColor = ffxDofLoadColorMip(FfxInt32x2(texel), 0u);
    result.alpha = FfxFloat32x2(0.0f, 1.0f);

    FfxFloat32 centerCoc = ffxDofLoadCocMip(FfxInt32x2(texel), 0u);
    FfxFloat32 nearRadius = max(dilated.y, 0.0f);
    FfxFloat32 kernelRadius = max(nearRadius, abs(centerCoc));
    FfxUInt32 rings = ffxDofRingCount(kernelRadius, constants.maxRings);
    if (rings == 0u)
        return result;  // in focus: the far layer holds the texel itself

    FfxBoolean withNear = dilated.y >= FFX_DOF_NEAR_THRESHOLD;
    FfxBoolean centerIsNear = centerCoc >= FFX_DOF_NEAR_THRESHOLD;
    FfxUInt32 mergeLog = 0u;
#if FFX_DOF_OPTION_MAX_RING_MERGE_LOG > 0
    if (dilated.y <= -FFX_DOF_IN_FOCUS_RADIUS && dilated.y - dilated.x < FFX_DOF_FLAT_RADIUS_RANGE && rings >= 2u)
        mergeLog = FfxUInt32(FFX_DOF_OPTION_MAX_RING_MERGE_LOG);
#endif
    FfxUInt32 mergeStep = 1u << mergeLog;

    FfxFloat32 spacing = kernelRadius / FfxFloat32(rings);
    FfxUInt32 baseMip = FfxUInt32(ffxDofMipForSpacing(spacing));
    FfxFloat32x2 center = FfxFloat32x2(texel) + FfxFloat32x2(0.5f, 0.5f);
    FfxFloat32x2 origin = center + ffxDofKernelJitter(texel, constants.frameIndex);

    FfxFloat32x3 nearSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 nearWeight = 0.0f;
    FfxFloat32x3 fillSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 fillCount = 0.0f;
    FfxFloat32 weightedSamples = 0.0f;
    FfxDofBucket outer = ffxDofEmptyBucket();

    // Rings from the outside in. With merging, ring `ring` also stands for the mergeStep - 1 rings
    // inside it, and is sampled from a MIP mergeLog levels coarser; the outermost ring never merges.
    FfxInt32 ring = FfxInt32(rings);
    FFX_DOF_LOOP
    while (ring >= 0)
    {
        FfxUInt32 ringIndex = FfxUInt32(ring);
        FfxBoolean merged = mergeStep > 1u && ringIndex < rings && ringIndex > 0u;
        FfxUInt32 mip = min(baseMip + (merged ? mergeLog : 0u), FfxUInt32(FFX_DOF_OPTION_MAX_MIP - 1));
        FfxFloat32 ringWeight = 1.0f;
        if (merged)
        {
            // Rings max(ring - step + 1, 1) .. ring have (first + last) * n / 2 times 6 samples.
            FfxUInt32 first = ringIndex + 1u > mergeStep ? ringIndex + 1u - mergeStep : 1u;
            ringWeight = FfxFloat32((first + ringIndex) * (ringIndex - first + 1u)) / FfxFloat32(2u * ringIndex);
        }
        FfxUInt32 sampleCount = ffxDofRingSampleCount(ringIndex);
        FfxDofBucket ringBucket = ffxDofEmptyBucket();
        FfxFloat32x2 offset = ffxDofRingSamplePosition(ringIndex, 0u) * spacing;
        FfxFloat32x2 step = ffxDofRingSampleStep(ringIndex);
        FfxFloat32 mipScale = 1.0f / FfxFloat32(1u << mip);
        FfxInt32x2 lastTexel = FfxInt32x2(ffxDofMipSize(constants.halfSize, mip)) - FfxInt32x2(1, 1);
        FFX_DOF_LOOP
        for (FfxUInt32 sampleIndex = 0u; sampleIndex < sampleCount; ++sampleIndex)
        {
            FfxInt32x2 sampleTexel = clamp(FfxInt32x2(floor((origin + offset) * mipScale)), FfxInt32x2(0, 0), lastTexel);
            offset = FfxFloat32x2(offset.x * step.x - offset.y * step.y, offset.x * step.y + offset.y * step.x);
            FfxDofFloat3 color = ffxDofLoadColorMip(sampleTexel, mip);
            FfxFloat32 coc = ffxDofLoadCocMip(sampleTexel, mip);
            // Reach is judged from the centre of the texel actually read, not from the ring: the
            // ring distance would let a texel spread half a texel beyond its radius.
            FfxFloat32 distance = length(ffxDofMipTexelCenter(sampleTexel, mip) - center);
            // Near and far samples weigh alike (reach times inverse area): computed once, before the
            // branch, because a CPU implementation such as lavapipe runs both sides of every branch.
            FfxFloat32 absCoc = abs(coc);
            FfxFloat32 reach = ffxDofReach(absCoc, distance);
            FfxFloat32 weight = reach * ffxDofAreaWeight(absCoc) * ringWeight;
            if (withNear && coc >= FFX_DOF_NEAR_THRESHOLD)
            {
                nearSum += ffxDofToFloat32x3(color) * weight;
                nearWeight += weight;
            }
            else
            {
                ffxDofBucketAddWeighted(ringBucket, color, absCoc, reach, weight);
                if (centerIsNear)
                {
                    fillSum += ffxDofToFloat32x3(color);
                    fillCount += 1.0f;
                }
            }
        }
        ringBucket.sampleCount = FfxFloat32(sampleCount);
        weightedSamples += FfxFloat32(sampleCount) * ringWeight;
        outer = ffxDofMergeBuckets(outer, ringBucket, spacing);
        ring = merged ? max(ring - FfxInt32(mergeStep), 0) : ring - 1;
    }

    if (nearWeight > 0.0f)
    {
        result.nearColor = ffxDofToDofFloat3(nearSum / nearWeight);
        result.alpha.x = ffxDofNearOpacity(nearWeight, kernelRadius, weightedSamples);
    }
    if (outer.weight > 0.0f)
        result.farColor = ffxDofToDofFloat3(outer.color / outer.weight);
    else if (fillCount > 0.0f)
        result.farColor = ffxDofToDofFloat3(fillSum / fillCount);
    else
        result.alpha.y = 0.0f;
    return result;
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
