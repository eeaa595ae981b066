// Pass 2 of 5: bilateral downsample of the input color to half resolution, with the CoC, and the
// MIP chain up to FFX_DOF_OPTION_MAX_MIP levels, in one dispatch. The input color is multiplied by
// ffxDofColorRangeScale of the frame's colour peak (pass 1) first, in 32-bit; the scale goes to
// GLOBALS for the composite.
//
// One workgroup covers one tile: its 64 invocations make the 8 x 8 texels of MIP 0, then the group
// reduces them in group-shared memory to 4 x 4, 2 x 2 and 1 x 1 (MIPs 1..3), so no global
// synchronisation is needed. Every level uses ffxDofBilateralReduce.
#ifndef FFX_DOF_DOWNSAMPLE_COLOR_H
#define FFX_DOF_DOWNSAMPLE_COLOR_H

#include "ffx_dof_common.h"

#if defined(FFX_CPU)
FfxDofConstants ffxDofGetConstants();
FfxFloat32 ffxDofLoadInputDepth(FfxUInt32x2 pixel);
FfxFloat32x4 ffxDofLoadInputColor(FfxUInt32x2 pixel);
void ffxDofStoreColorMip(FfxUInt32 mip, FfxUInt32x2 texel, FfxDofFloat3 color);
void ffxDofStoreCocMip(FfxUInt32 mip, FfxUInt32x2 texel, FfxFloat32 coc);
FfxFloat32 ffxDofLoadColorPeak();
void ffxDofStoreColorScale(FfxFloat32 scale);
#endif

FFX_DOF_GROUPSHARED FfxDofFloat3 ffxDofSharedMipColor[FFX_DOF_GROUP_THREADS];
FFX_DOF_GROUPSHARED FfxFloat32 ffxDofSharedMipCoc[FFX_DOF_GROUP_THREADS];

// Scaled in 32-bit (and clamped to the half range) before any conversion to 16 bits.
FFX_DOF_INLINE FfxDofFloat3 ffxDofLoadInputColorRgb(FfxUInt32x2 pixel, FfxFloat32 scale)
{
    FfxFloat32x4 color = ffxDofScaleColor(ffxDofLoadInputColor(pixel), scale);
    return FfxDofFloat3(color.x, color.y, color.z);
}

FFX_DOF_INLINE void ffxDofDownsampleColor(FfxUInt32x2 groupId, FfxUInt32 localIndex)
{
    FfxDofConstants constants = ffxDofGetConstants();
    FfxUInt32x2 local = ffxDofLocalCoord(localIndex);
    FfxUInt32x2 texel = groupId * FfxUInt32(FFX_DOF_TILE_SIZE) + local;
    FfxUInt32x2 quad = texel * 2u;
    FfxUInt32x2 lastPixel = constants.fullSize - FfxUInt32x2(1u, 1u);
    FfxFloat32 scale = ffxDofColorRangeScale(ffxDofLoadColorPeak());
    // One store is enough (the composite runs after a barrier); pass 3 resets the peak.
    if (groupId.x == 0u && groupId.y == 0u && localIndex == 0u)
        ffxDofStoreColorScale(scale);

    FfxUInt32x2 pixel0 = min(quad, lastPixel);
    FfxUInt32x2 pixel1 = min(quad + FfxUInt32x2(1u, 0u), lastPixel);
    FfxUInt32x2 pixel2 = min(quad + FfxUInt32x2(0u, 1u), lastPixel);
    FfxUInt32x2 pixel3 = min(quad + FfxUInt32x2(1u, 1u), lastPixel);
    FfxFloat32 coc0 =
        ffxDofCocFromDepth(ffxDofLoadInputDepth(pixel0), constants.cocScale, constants.cocBias, constants.cocLimit);
    FfxFloat32 coc1 =
        ffxDofCocFromDepth(ffxDofLoadInputDepth(pixel1), constants.cocScale, constants.cocBias, constants.cocLimit);
    FfxFloat32 coc2 =
        ffxDofCocFromDepth(ffxDofLoadInputDepth(pixel2), constants.cocScale, constants.cocBias, constants.cocLimit);
    FfxFloat32 coc3 =
        ffxDofCocFromDepth(ffxDofLoadInputDepth(pixel3), constants.cocScale, constants.cocBias, constants.cocLimit);
    FfxDofFloat3 color;
    FfxFloat32 coc;
    ffxDofBilateralReduce(ffxDofLoadInputColorRgb(pixel0, scale), ffxDofLoadInputColorRgb(pixel1, scale),
                          ffxDofLoadInputColorRgb(pixel2, scale), ffxDofLoadInputColorRgb(pixel3, scale), coc0, coc1,
                          coc2, coc3, color, coc);
    if (texel.x < constants.halfSize.x && texel.y < constants.halfSize.y)
    {
        ffxDofStoreColorMip(0u, texel, ffxDofRoundForPackedColor(color));
        ffxDofStoreCocMip(0u, texel, coc);
    }
    ffxDofSharedMipColor[localIndex] = color;
    ffxDofSharedMipCoc[localIndex] = coc;

    // Level m is kept at the top-left texel of each 2^m block: a thread only overwrites a slot it
    // has read itself, so one barrier per level suffices.
    FFX_DOF_UNROLL
    for (FfxUInt32 mip = 1u; mip < FfxUInt32(FFX_DOF_OPTION_MAX_MIP); ++mip)
    {
        ffxDofGroupBarrier();
        FfxUInt32 step = 1u << mip;
        FfxUInt32 halfStep = step >> 1u;
        if ((local.x & (step - 1u)) == 0u && (local.y & (step - 1u)) == 0u)
        {
            FfxUInt32 i0 = localIndex;
            FfxUInt32 i1 = localIndex + halfStep;
            FfxUInt32 i2 = localIndex + halfStep * 8u;
            FfxUInt32 i3 = i2 + halfStep;
            ffxDofBilateralReduce(ffxDofSharedMipColor[i0], ffxDofSharedMipColor[i1], ffxDofSharedMipColor[i2],
                                  ffxDofSharedMipColor[i3], ffxDofSharedMipCoc[i0], ffxDofSharedMipCoc[i1],
                                  ffxDofSharedMipCoc[i2], ffxDofSharedMipCoc[i3], color, coc);
            ffxDofSharedMipColor[i0] = color;
            ffxDofSharedMipCoc[i0] = coc;
            FfxUInt32x2 mipTexel =
                groupId * (FfxUInt32(FFX_DOF_TILE_SIZE) >> mip) + FfxUInt32x2(local.x >> mip, local.y >> mip);
            FfxUInt32x2 mipSize = ffxDofMipSize(constants.halfSize, mip);
            if (mipTexel.x < mipSize.x && mipTexel.y < mipSize.y)
            {
                ffxDofStoreColorMip(mip, mipTexel, ffxDofRoundForPackedColor(color));
                ffxDofStoreCocMip(mip, mipTexel, coc);
            }
        }
    }
}

#endif  // FFX_DOF_DOWNSAMPLE_COLOR_H
