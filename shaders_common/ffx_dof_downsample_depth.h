// Pass 1 of 5: depth to CoC, (min, max) signed CoC per tile, global max |CoC|.
//
// One workgroup covers one tile (FFX_DOF_TILE_SIZE half-res px = 16 full-res px square); each of
// its 64 invocations reduces a 2 x 2 full-res quad. Depth is reduced instead of CoC: the radius is a
// monotonic function of depth (nearer is more positive), so converting the nearest and farthest
// depth gives the same extremes with two conversions per tile. FFX_DOF_OPTION_REVERSE_DEPTH says
// which end of the depth range is near.
#ifndef FFX_DOF_DOWNSAMPLE_DEPTH_H
#define FFX_DOF_DOWNSAMPLE_DEPTH_H

#include "ffx_dof_common.h"

#if defined(FFX_CPU)
// Accessors this pass calls; each API's callback header implements them.
FfxDofConstants ffxDofGetConstants();
FfxFloat32 ffxDofLoadInputDepth(FfxUInt32x2 pixel);
void ffxDofStoreTile(FfxUInt32x2 tile, FfxFloat32x2 cocMinMax);
void ffxDofAtomicMaxGlobalRadius(FfxFloat32 radius);
#endif

FFX_DOF_GROUPSHARED FfxFloat32 ffxDofSharedNearDepth[FFX_DOF_GROUP_THREADS];
FFX_DOF_GROUPSHARED FfxFloat32 ffxDofSharedFarDepth[FFX_DOF_GROUP_THREADS];

FFX_DOF_INLINE void ffxDofDownsampleDepth(FfxUInt32x2 groupId, FfxUInt32 localIndex)
{
    FfxDofConstants constants = ffxDofGetConstants();
    FfxUInt32x2 quad = groupId * 16u + ffxDofLocalCoord(localIndex) * 2u;
    FfxUInt32x2 lastPixel = constants.fullSize - FfxUInt32x2(1u, 1u);

    // Pixels past the image edge repeat the edge, which leaves the extremes unchanged.
    FfxFloat32 depth0 = ffxDofLoadInputDepth(min(quad, lastPixel));
    FfxFloat32 depth1 = ffxDofLoadInputDepth(min(quad + FfxUInt32x2(1u, 0u), lastPixel));
    FfxFloat32 depth2 = ffxDofLoadInputDepth(min(quad + FfxUInt32x2(0u, 1u), lastPixel));
    FfxFloat32 depth3 = ffxDofLoadInputDepth(min(quad + FfxUInt32x2(1u, 1u), lastPixel));
    ffxDofSharedNearDepth[localIndex] = ffxDofNearerDepth(ffxDofNearerDepth(depth0, depth1), ffxDofNearerDepth(depth2, depth3));
    ffxDofSharedFarDepth[localIndex] = ffxDofFartherDepth(ffxDofFartherDepth(depth0, depth1), ffxDofFartherDepth(depth2, depth3));
    ffxDofGroupBarrier();

    FFX_DOF_UNROLL
    for (FfxUInt32 stride = FfxUInt32(FFX_DOF_GROUP_THREADS) / 2u; stride > 0u; stride >>= 1u)
    {
        if (localIndex < stride)
        {
            ffxDofSharedNearDepth[localIndex] = ffxDofNearerDepth(ffxDofSharedNearDepth[localIndex], ffxDofSharedNearDepth[localIndex + stride]);
            ffxDofSharedFarDepth[localIndex] = ffxDofFartherDepth(ffxDofSharedFarDepth[localIndex], ffxDofSharedFarDepth[localIndex + stride]);
        }
        ffxDofGroupBarrier();
    }

    if (localIndex == 0u)
    {
        FfxFloat32 nearCoc = ffxDofCocFromDepth(ffxDofSharedNearDepth[0], constants.cocScale, constants.cocBias, constants.cocLimit);
        FfxFloat32 farCoc = ffxDofCocFromDepth(ffxDofSharedFarDepth[0], constants.cocScale, constants.cocBias, constants.cocLimit);
        ffxDofStoreTile(groupId, FfxFloat32x2(farCoc, nearCoc));
        ffxDofAtomicMaxGlobalRadius(max(abs(farCoc), abs(nearCoc)));
    }
}

#endif  // FFX_DOF_DOWNSAMPLE_DEPTH_H
