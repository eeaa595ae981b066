// Pass 1 of 5: depth to CoC, (min, max) signed CoC per tile and global max |CoC|. It reads no colour: the
// colour peaks (the tiles', and the frame's for ffxDofColorRangeScale) come from pass 2, which reads every pixel's
// colour anyway (docs/technique.md, HDR range); here they were 40% of the pass on lavapipe.
//
// One workgroup covers one tile (FFX_DOF_TILE_SIZE half-res px = 16 full-res px square); each of
// its 64 invocations reduces a 2 x 2 full-res quad. Depth is reduced instead of CoC: the radius is a
// monotonic function of depth (nearer is more positive), so converting the nearest and farthest
// depth gives the same extremes with two conversions per tile. FFX_DOF_OPTION_REVERSE_DEPTH says
// which end of the depth range is near.
#ifndef FFX_DOF_DOWNSAMPLE_DEPTH_H
#define FFX_DOF_DOWNSAMPLE_DEPTH_H

#include "ffx_dof_common.h"
#include "ffx_dof_focus.h"

#if defined(FFX_CPU)
// Accessors this pass calls; each API's callback header implements them.
FfxDofConstants ffxDofGetConstants();
FfxFloat32 ffxDofLoadInputDepth(FfxUInt32x2 pixel);
void ffxDofStoreTile(FfxUInt32x2 tile, FfxFloat32x2 cocMinMax);
void ffxDofAtomicMaxGlobalRadius(FfxFloat32 radius);
void ffxDofStoreTileListArgs(FfxUInt32 list, FfxUInt32x3 groupCounts);
#endif

// ---- Depth order ------------------------------------------------------------------------------------

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

// One slot per wave (a wave of one lane on the CPU, so up to one per invocation).
FFX_DOF_GROUPSHARED FfxFloat32 ffxDofSharedNearDepth[FFX_DOF_GROUP_THREADS];
FFX_DOF_GROUPSHARED FfxFloat32 ffxDofSharedFarDepth[FFX_DOF_GROUP_THREADS];

FFX_DOF_INLINE FfxFloat32 ffxDofWaveNearestDepth(FfxFloat32 depth)
{
#if FFX_DOF_OPTION_REVERSE_DEPTH
    return ffxDofWaveMax(depth);
#else
    return ffxDofWaveMin(depth);
#endif
}
FFX_DOF_INLINE FfxFloat32 ffxDofWaveFarthestDepth(FfxFloat32 depth)
{
#if FFX_DOF_OPTION_REVERSE_DEPTH
    return ffxDofWaveMin(depth);
#else
    return ffxDofWaveMax(depth);
#endif
}

// The group reduces in two steps, wave operations then one pass over one slot per wave, so that it
// needs a single barrier: a barrier is cheap on a GPU but costs about as much as the whole pass's
// memory traffic on a CPU implementation such as lavapipe, where the group's waves run as coroutines
// (a log2(64)-step tree in group-shared memory, one barrier per step, made this pass 2.5x a copy pass).
// Every tile list empty (TILE_LIST_ARGS: no workgroups) until dilate counts its tiles, and pass 2's second run
// none until its first run arms it (FFX_DOF_COLOR_RANGE_RERUN_ARGS, the entry after the lists'); invocation `entry`
// of the workgroup that calls it empties entry `entry`, under a condition of the workgroup alone: the same stores
// as a loop in one invocation under a condition of the invocation cost lavapipe about 0.4 ms per list at
// 1080p (docs/performance.md, "What pass 1 costs now").
#if FFX_DOF_TILE_LIST_ARGS_ENTRIES > FFX_DOF_GROUP_THREADS
#error "ffxDofEmptyTileLists gives each entry one invocation"
#endif
FFX_DOF_INLINE void ffxDofEmptyTileLists(FfxUInt32 localIndex)
{
    if (localIndex < FfxUInt32(FFX_DOF_TILE_LIST_ARGS_ENTRIES))
        ffxDofStoreTileListArgs(localIndex, FfxUInt32x3(0u, 1u, 1u));
}

FFX_DOF_INLINE void ffxDofDownsampleDepth(FfxUInt32x2 groupId, FfxUInt32 localIndex)
{
    FfxDofConstants constants = ffxDofGetFocusedConstants();
    // Empty lists for dilate (the previous dispatch's composite has read them).
    if (groupId.x == 0u && groupId.y == 0u)
        ffxDofEmptyTileLists(localIndex);
    FfxUInt32x2 quad = groupId * FfxUInt32(FFX_DOF_DOWNSAMPLE_DEPTH_GROUP_EXTENT) + ffxDofLocalCoord(localIndex) * 2u;
    FfxUInt32x2 lastPixel = constants.fullSize - FfxUInt32x2(1u, 1u);

    // Pixels past the image edge repeat the edge, which leaves the extremes unchanged.
    FfxUInt32x2 pixel0 = min(quad, lastPixel);
    FfxUInt32x2 pixel1 = min(quad + FfxUInt32x2(1u, 0u), lastPixel);
    FfxUInt32x2 pixel2 = min(quad + FfxUInt32x2(0u, 1u), lastPixel);
    FfxUInt32x2 pixel3 = min(quad + FfxUInt32x2(1u, 1u), lastPixel);
    FfxFloat32 depth0 = ffxDofLoadInputDepth(pixel0);
    FfxFloat32 depth1 = ffxDofLoadInputDepth(pixel1);
    FfxFloat32 depth2 = ffxDofLoadInputDepth(pixel2);
    FfxFloat32 depth3 = ffxDofLoadInputDepth(pixel3);
    FfxFloat32 nearDepth =
        ffxDofWaveNearestDepth(ffxDofNearerDepth(ffxDofNearerDepth(depth0, depth1), ffxDofNearerDepth(depth2, depth3)));
    FfxFloat32 farDepth = ffxDofWaveFarthestDepth(
        ffxDofFartherDepth(ffxDofFartherDepth(depth0, depth1), ffxDofFartherDepth(depth2, depth3)));
    if (ffxDofWaveIsFirstLane())
    {
        FfxUInt32 wave = ffxDofWaveIndex(localIndex);
        ffxDofSharedNearDepth[wave] = nearDepth;
        ffxDofSharedFarDepth[wave] = farDepth;
    }
    ffxDofGroupBarrier();

    if (localIndex == 0u)
    {
        // From slot 0: invocation 0 need not be in wave 0 (GLSL does not say which wave holds it).
        FFX_DOF_LOOP
        for (FfxUInt32 wave = 0u; wave < ffxDofWaveCount(); ++wave)
        {
            nearDepth = ffxDofNearerDepth(nearDepth, ffxDofSharedNearDepth[wave]);
            farDepth = ffxDofFartherDepth(farDepth, ffxDofSharedFarDepth[wave]);
        }
        FfxFloat32 nearCoc = ffxDofCocFromDepth(nearDepth, constants.cocScale, constants.cocBias, constants.cocLimit);
        FfxFloat32 farCoc = ffxDofCocFromDepth(farDepth, constants.cocScale, constants.cocBias, constants.cocLimit);
        ffxDofStoreTile(groupId, FfxFloat32x2(farCoc, nearCoc));
        ffxDofAtomicMaxGlobalRadius(max(abs(farCoc), abs(nearCoc)));
    }
}

#endif  // FFX_DOF_DOWNSAMPLE_DEPTH_H
