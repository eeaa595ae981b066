// Pass 4 of 5: the blur at half resolution, near and far field in one gather.
//
// One workgroup covers one tile (8 x 8 half-res px), one invocation per texel. Per texel:
//   kernel radius R = max(dilated near radius of the tile, |own radius|); rings from R and the
//   quality (ffxDofRingCount) -- per texel, so the ring count never changes at a tile border;
//   a random sub-pixel kernel origin; rings gathered from the outside in, ring k being every texel of
//   the MIP read whose centre lies (k -+ 1/2) ring spacings from the origin, each read once (a
//   one-texel source is read once by every texel whose kernel covers it: a flat bokeh disc).
//   Near field (radius >= FFX_DOF_NEAR_THRESHOLD): scatter-as-gather, each sample weighted by reach
//   and inverse area; opacity from the summed area weights (ffxDofNearOpacity).
//   Far field (everything else): two layers, the texel's own surface and nearer (front) and what
//   lies behind it (back), composed by the front's coverage (ffxDofComposeFarLayers). A sample only
//   counts within its own radius, so in-focus and foreground color never spreads into the far field
//   beyond it.
//   Hole filling: when the texel itself is near, every far-field sample, whatever its reach, is
//   also summed as the fill and added to the far color at the end, each weighing what a sample of
//   the texel's own radius would: the hidden background is extrapolated from around the object.
// Tile classes (ffxDofClassifyTile, from pass 3's dilated range and kernel footprint), each a path
// that leaves out what cannot matter on that tile and gives what the mixed path would give:
//   copy       every kernel is in focus (R < 0.5): the texel is the far layer;
//   equal      every radius the kernels read is within FFX_DOF_EQUAL_WEIGHT_SPREAD of the others
//              (all near or all far): no CoC is read, each sample weighs what the texel's own
//              radius gives at its distance, and a far texel's inner rings are merged fully;
//   far-only   no near radius reaches the tile: no near sums, no hole fill (a near sample from a
//              tile that does not reach has zero reach, so counting it as far changes nothing);
//   near-only  every radius read is near-field: no far buckets, no hole fill (no background sample);
//   mixed      everything.
// The class is uniform over the workgroup (loaded at the group's tile), so GPUs skip the paths not
// taken. lavapipe runs every `if` under lane masks, taken or not, but each path is made of loops
// (rings, samples), and a loop ends once no lane is left in it: a path not taken costs one pass of
// its loops, a few samples (docs/performance.md).
// Ring merging (unless FFX_DOF_OPTION_DISABLE_RING_MERGE) is decided per texel, not per tile: the
// outermost ring is gathered at full resolution first; where its radii are all within half a pixel
// of the texel's own (a flat far field), inner rings are gathered from a coarser MIP, 2^log rings at
// a time; between half a pixel and one pixel the groups of rings are merged one after the other as
// the spread falls, the one part-way mixed ring by ring (ffxDofRingMergeAmount,
// ffxDofGatherInnerRings), so the result is continuous and costs at most one ring more than the
// full path. Walks at two MIPs judge their common border by the coarse texels (FfxDofAnnulus).
// Samples are point-sampled (no bilinear mixing of a foreground and a background texel, which
// would let the foreground color leak with a halfway radius).
//
// Outputs: NEAR_COLOR, FAR_COLOR, LAYER_ALPHA (x: near opacity, y: far validity).
#ifndef FFX_DOF_BLUR_H
#define FFX_DOF_BLUR_H

#include "ffx_dof_common.h"

#if defined(FFX_CPU)
FfxDofConstants ffxDofGetConstants();
FfxFloat32x4 ffxDofLoadDilatedTile(FfxUInt32x2 tile);
FfxDofFloat3 ffxDofLoadColorMip(FfxInt32x2 texel, FfxUInt32 mip);
FfxFloat32 ffxDofLoadCocMip(FfxInt32x2 texel, FfxUInt32 mip);
void ffxDofStoreNearColor(FfxUInt32x2 texel, FfxDofFloat3 color);
void ffxDofStoreFarColor(FfxUInt32x2 texel, FfxDofFloat3 color);
void ffxDofStoreLayerAlpha(FfxUInt32x2 texel, FfxFloat32x2 nearOpacityFarValidity);
#endif

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
    FfxDofBucket farFront;  // far-field samples of the texel's own surface and nearer
    FfxDofBucket farBack;   // far-field samples behind it
    FfxFloat32 cocSpread;   // largest |radius - own radius| among the samples seen
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
    FfxBoolean centerIsNear;
};

// Which parts of the gather a tile class needs; literals at every call, so what a path leaves out
// compiles away.
struct FfxDofGatherParts
{
    FfxBoolean nearField;     // near sums (scatter-as-gather near layer)
    FfxBoolean farField;      // far buckets
    FfxBoolean equalWeights;  // every radius read is the texel's own: no CoC reads
};

// Gathers rings firstRing..lastRing from MIP `mip`: every texel of that MIP whose centre lies in
// the rings' annulus around the kernel origin, once. A sample weighs the texel's area (4^mip
// half-res px^2), so rings from different MIPs add up, and the whole ring counts `presence` (0..1)
// times. trackSpread (a literal at every call, so it compiles away) records the radius spread of
// the samples for the ring-merge decision: only the outermost ring needs it. Hole filling needs both
// fields (a near texel with background samples around it): only the mixed path has it.
// The sample loop is written for devices that run both sides of every branch (lavapipe, which runs
// groups of 8 lanes under masks): near and far samples are added with 0/1 shares instead of a
// branch, and a step of the walk that lands on an empty row counts with weight 0 (`valid`) rather
// than looping on to the next row.
FFX_DOF_INLINE void ffxDofGatherRing(FFX_DOF_INOUT(FfxDofGather) gather, FfxDofKernel kernel, FfxUInt32 firstRing,
                                     FfxUInt32 lastRing, FfxUInt32 mip, FfxUInt32 innerBorderMip,
                                     FfxUInt32 outerBorderMip, FfxFloat32 presence, FfxBoolean trackSpread,
                                     FfxDofGatherParts parts, FfxDofConstants constants)
{
    FfxBoolean holeFill = parts.nearField && parts.farField;
    FfxFloat32 texelSize = FfxFloat32(1u << mip);
    FfxFloat32 sampleWeight = texelSize * texelSize * presence;
    FfxFloat32 centerAbsCoc = abs(kernel.centerCoc);
    FfxFloat32x3 ringFillSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 ringFillCount = 0.0f;
    FfxFloat32 mipScale = 1.0f / texelSize;
    FfxFloat32 spacing = kernel.spacing * mipScale;
    // In units of MIP texels: the kernel centre less half a texel, so that (texel - centre) is the
    // offset of the texel's centre.
    FfxFloat32x2 centerToCorner = kernel.center * mipScale - FfxFloat32x2(0.5f, 0.5f);
    FfxFloat32x2 lastTexel = FfxFloat32x2(ffxDofMipSize(constants.halfSize, mip) - FfxUInt32x2(1u, 1u));
    // Borders shared with a walk at a coarser MIP are judged by its texels (FfxDofAnnulus).
    FfxFloat32 innerRadius = ffxDofRingInnerRadius(firstRing, spacing);
    FfxFloat32 outerRadius = ffxDofRingInnerRadius(lastRing + 1u, spacing);
    FfxFloat32 innerBlock = FfxFloat32(1u << (innerBorderMip - mip));
    FfxFloat32 outerBlock = FfxFloat32(1u << (outerBorderMip - mip));
    FfxDofAnnulus annulus =
        ffxDofMakeAnnulus(kernel.origin * mipScale, innerRadius, outerRadius, innerBlock, outerBlock);
    FfxDofAnnulusWalk walk = ffxDofAnnulusBegin(annulus);
    FFX_DOF_LOOP
    while (ffxDofAnnulusRowsLeft(annulus, walk))
    {
        FfxFloat32x2 sampleTexel = clamp(walk.texel, FfxFloat32x2(0.0f, 0.0f), lastTexel);
        FfxFloat32 valid = ffxDofAnnulusValid(walk) ? 1.0f : 0.0f;
        walk = ffxDofAnnulusNext(annulus, walk);
        FfxFloat32x3 color = ffxDofToFloat32x3(ffxDofLoadColorMip(FfxInt32x2(sampleTexel), mip));
        FfxFloat32 coc = kernel.centerCoc;
        if (!parts.equalWeights)
            coc = ffxDofLoadCocMip(FfxInt32x2(sampleTexel), mip);
        if (trackSpread)
            gather.cocSpread = max(gather.cocSpread, abs(coc - kernel.centerCoc) * valid);
        // Reach is judged from the centre of the texel actually read (at the image border, the
        // clamped one).
        FfxFloat32x2 toTexel = sampleTexel - centerToCorner;
        FfxFloat32 distance = sqrt(dot(toTexel, toTexel)) * texelSize;
        // Near and far samples weigh alike (reach times inverse area).
        FfxFloat32 absCoc = abs(coc);
        FfxFloat32 reach = ffxDofReach(absCoc, distance);
        reach *= valid;
        FfxFloat32 weight = reach * ffxDofAreaWeight(absCoc) * sampleWeight;
        FfxFloat32 farShare = coc >= FFX_DOF_NEAR_THRESHOLD ? 0.0f : valid;
        if (!parts.nearField)
            farShare = valid;
        if (!parts.farField)
            farShare = 0.0f;
        FfxFloat32 farWeight = weight * farShare;
        if (parts.nearField)
        {
            FfxFloat32 nearWeight = weight - farWeight;
            gather.nearSum += color * nearWeight;
            gather.nearWeight += nearWeight;
        }
        if (parts.farField)
        {
            FfxFloat32 frontShare = kernel.centerIsNear ? 0.0f : ffxDofFarFrontShare(absCoc, centerAbsCoc);
            FfxFloat32 frontWeight = farWeight * frontShare;
            gather.farFront.color += color * frontWeight;
            gather.farFront.weight += frontWeight;
            gather.farBack.color += color * (farWeight - frontWeight);
            gather.farBack.weight += farWeight - frontWeight;
        }
        if (holeFill)
        {
            ringFillSum += color * farShare;
            ringFillCount += farShare;
        }
    }
    gather.fillSum += ringFillSum * sampleWeight;
    gather.fillCount += ringFillCount * sampleWeight;
}

// Gathers every ring inside the outermost one, from the outside in. Rings 1 .. rings - 1 form groups
// of 2^FFX_DOF_RING_MERGE_LOG; a group is gathered either ring by ring at the kernel's MIP
// (full) or in one walk over the group's annulus from a MIP that much coarser (merged). A border
// between the two levels is judged by each side's own texel centres, so there a one-texel source
// can be read twice or not at all (docs/technique.md, Kernel shape and walk). mergeAmount (0..1) merges
// the groups one after the other, from the outside in, and mixes the one group it is part-way
// through: that group's merged ring with presence f and its full rings with presence 1 - f. So the
// result is continuous in mergeAmount, and a texel walks at most one ring more than the full path.
// One loop walks one ring per pass whatever each lane's schedule is: on devices that run groups of
// lanes in lock step (lavapipe: 8), lanes that merge and lanes that do not share the passes instead
// of running a merged loop and a full loop one after the other.
FFX_DOF_INLINE void ffxDofGatherInnerRings(FFX_DOF_INOUT(FfxDofGather) gather, FfxDofKernel kernel,
                                           FfxBoolean mergeEligible, FfxFloat32 mergeAmount, FfxDofGatherParts parts,
                                           FfxDofConstants constants)
{
    FfxUInt32 mergeLog = FfxUInt32(FFX_DOF_RING_MERGE_LOG);
    FfxUInt32 groupSize = 1u << mergeLog;
    FfxUInt32 groupCount = (kernel.rings - 1u + groupSize - 1u) / groupSize;
    FfxFloat32 mergedGroups = mergeAmount * FfxFloat32(groupCount);
    FfxUInt32 coarseMip = min(kernel.baseMip + mergeLog, FfxUInt32(FFX_DOF_OPTION_MAX_MIP - 1));
    // The border with the outermost ring is judged at the coarse MIP wherever merging may happen
    // (ffxDofGatherKernel judges it so on the outermost ring's side).
    FfxBoolean outerBorderCoarse = mergeEligible;
    FfxInt32 top = FfxInt32(kernel.rings) - 1;  // outermost ring of the current group
    FfxUInt32 group = 0u;
    FfxUInt32 walk = 0u;  // rings of the current group walked so far
    FFX_DOF_LOOP
    while (top >= 0)
    {
        FfxUInt32 topRing = FfxUInt32(top);
        // Ring 0 (the centre sample) is a group of its own, never merged.
        FfxUInt32 first = topRing == 0u ? 0u : (topRing + 1u > groupSize ? topRing + 1u - groupSize : 1u);
        FfxFloat32 merged = topRing == 0u ? 0.0f : ffxDofSaturate(mergedGroups - FfxFloat32(group));
        FfxUInt32 mergedWalks = merged > 0.0f ? 1u : 0u;
        FfxUInt32 walks = mergedWalks + (merged < 1.0f ? topRing - first + 1u : 0u);
        FfxBoolean mergedWalk = walk < mergedWalks;
        FfxUInt32 ring = mergedWalk ? topRing : topRing + mergedWalks - walk;
        FfxUInt32 mip = mergedWalk ? coarseMip : kernel.baseMip;
        FfxFloat32 presence = mergedWalk ? merged : 1.0f - merged;
        // A group with a merged part judges both its borders at the coarse MIP, in every walk of it.
        FfxBoolean innerBorderCoarse = merged > 0.0f;
        FfxUInt32 firstWalked = mergedWalk ? first : ring;
        FfxUInt32 innerBorderMip = firstWalked == first && innerBorderCoarse ? coarseMip : mip;
        FfxUInt32 outerBorderMip = ring == topRing && outerBorderCoarse ? coarseMip : mip;
        ffxDofGatherRing(gather, kernel, firstWalked, ring, mip, innerBorderMip, outerBorderMip, presence, false, parts,
                         constants);
        ++walk;
        if (walk == walks)
        {
            top = FfxInt32(first) - 1;
            ++group;
            walk = 0u;
            outerBorderCoarse = innerBorderCoarse;
        }
    }
}

// The layers of one texel from its finished gather; `result` holds the defaults (texel itself).
FFX_DOF_INLINE FfxDofBlurResult ffxDofFinishGather(FfxDofGather gather, FfxDofKernel kernel, FfxDofBlurResult result)
{
    if (gather.nearWeight > 0.0f)
    {
        result.nearColor = ffxDofToDofFloat3(gather.nearSum / gather.nearWeight);
        result.alpha.x = ffxDofNearOpacity(gather.nearWeight);
    }
    // The hole fill is background to the near texel it fills.
    FfxFloat32 fillWeight = kernel.centerIsNear ? ffxDofAreaWeight(abs(kernel.centerCoc)) : 0.0f;
    FfxDofBucket back = gather.farBack;
    back.color += gather.fillSum * fillWeight;
    back.weight += gather.fillCount * fillWeight;
    FfxFloat32x3 farColor;
    if (ffxDofComposeFarLayers(gather.farFront, back, farColor))
        result.farColor = ffxDofToDofFloat3(farColor);
    else
        result.alpha.y = 0.0f;
    return result;
}

// Gathers the whole kernel with the parts of one tile class.
// The outermost ring is always gathered at full resolution (it keeps the circle), and it tells how
// flat the radii around the texel are: the merged path is taken by how flat, per texel, from the
// texel's own samples, never per tile (a per-tile switch shows as tile-shaped blocks). Equal-weight
// tiles are flat by construction: their far texels merge fully (near texels never merge, as on the
// mixed path: merging them cost near-field PSNR, docs/performance.md).
FFX_DOF_INLINE void ffxDofGatherKernel(FFX_DOF_INOUT(FfxDofGather) gather, FfxDofKernel kernel, FfxDofGatherParts parts,
                                       FfxDofConstants constants)
{
    FfxBoolean trackSpread = !parts.equalWeights;
    FfxBoolean mergeEligible =
        FFX_DOF_RING_MERGE_LOG > 0 && kernel.rings >= 2u && kernel.centerCoc <= -FFX_DOF_IN_FOCUS_RADIUS;
    // Whether the inner rings merge is known only after this ring, so its inner border is judged at
    // the coarse MIP wherever they may.
    FfxUInt32 coarseMip =
        min(kernel.baseMip + FfxUInt32(FFX_DOF_RING_MERGE_LOG), FfxUInt32(FFX_DOF_OPTION_MAX_MIP - 1));
    ffxDofGatherRing(gather, kernel, kernel.rings, kernel.rings, kernel.baseMip,
                     mergeEligible ? coarseMip : kernel.baseMip, kernel.baseMip, 1.0f, trackSpread, parts, constants);
    FfxFloat32 mergeAmount = 0.0f;
    if (mergeEligible)
        mergeAmount = parts.equalWeights ? 1.0f : ffxDofRingMergeAmount(gather.cocSpread);
    ffxDofGatherInnerRings(gather, kernel, mergeEligible, mergeAmount, parts, constants);
}

FFX_DOF_INLINE FfxDofGatherParts ffxDofMakeGatherParts(FfxBoolean nearField, FfxBoolean farField,
                                                       FfxBoolean equalWeights)
{
    FfxDofGatherParts parts;
    parts.nearField = nearField;
    parts.farField = farField;
    parts.equalWeights = equalWeights;
    return parts;
}

// The blur of one half-res texel; `dilated` is its tile's DILATED_TILES texel from pass 3, `tileClass`
// the path (ffxDofClassifyTile; the CPU tests also force the mixed path to compare).
FFX_DOF_INLINE FfxDofBlurResult ffxDofBlurTexel(FfxUInt32x2 texel, FfxFloat32x4 dilated, FfxUInt32 tileClass,
                                                FfxDofConstants constants)
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
    gather.farFront = ffxDofEmptyBucket();
    gather.farBack = ffxDofEmptyBucket();
    gather.cocSpread = 0.0f;

    // An equal-weight tile is all near or all far; the texel's own radius tells which.
    FfxBoolean equalNear = kernel.centerCoc >= FFX_DOF_NEAR_THRESHOLD;
    if (tileClass == FFX_DOF_TILE_CLASS_EQUAL && !equalNear)
        ffxDofGatherKernel(gather, kernel, ffxDofMakeGatherParts(false, true, true), constants);
    if (tileClass == FFX_DOF_TILE_CLASS_EQUAL && equalNear)
        ffxDofGatherKernel(gather, kernel, ffxDofMakeGatherParts(true, false, true), constants);
    if (tileClass == FFX_DOF_TILE_CLASS_FAR_ONLY)
        ffxDofGatherKernel(gather, kernel, ffxDofMakeGatherParts(false, true, false), constants);
    if (tileClass == FFX_DOF_TILE_CLASS_NEAR_ONLY)
        ffxDofGatherKernel(gather, kernel, ffxDofMakeGatherParts(true, false, false), constants);
    if (tileClass == FFX_DOF_TILE_CLASS_MIXED)
        ffxDofGatherKernel(gather, kernel, ffxDofMakeGatherParts(true, true, false), constants);
    return ffxDofFinishGather(gather, kernel, result);
}

FFX_DOF_INLINE void ffxDofBlurTile(FfxUInt32x2 groupId, FfxUInt32 localIndex, FfxFloat32x4 dilated, FfxUInt32 tileClass)
{
    FfxDofConstants constants = ffxDofGetConstants();
    FfxUInt32x2 texel = groupId * FfxUInt32(FFX_DOF_TILE_SIZE) + ffxDofLocalCoord(localIndex);
    if (texel.x >= constants.halfSize.x || texel.y >= constants.halfSize.y)
        return;
    FfxDofBlurResult result = ffxDofBlurTexel(texel, dilated, tileClass, constants);
    ffxDofStoreNearColor(texel, ffxDofRoundForPackedColor(result.nearColor));
    ffxDofStoreFarColor(texel, ffxDofRoundForPackedColor(result.farColor));
    ffxDofStoreLayerAlpha(texel, result.alpha);
}

FFX_DOF_INLINE void ffxDofBlur(FfxUInt32x2 groupId, FfxUInt32 localIndex)
{
    FfxFloat32x4 dilated = ffxDofLoadDilatedTile(groupId);
    ffxDofBlurTile(groupId, localIndex, dilated, ffxDofClassifyTile(dilated));
}

#endif  // FFX_DOF_BLUR_H
