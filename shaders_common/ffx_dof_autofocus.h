// Pass 0 (only when a dispatch asks for autofocus): the focus distance from the depth buffer.
//
// One workgroup. The surface under the region's centre is the one focused on: the reference is the
// median inverse distance of the 3x3 pixels at the centre (one stray pixel cannot move it), and the
// focus is the mean inverse distance of the samples of a 16x16 grid over the region that lie on that
// surface (within FFX_DOF_AUTOFOCUS_SURFACE_TOLERANCE of the reference). A region straddling an
// edge therefore focuses on the side its centre is on, and a slanted surface on its depth at the
// centre's neighbourhood. The distance is clamped to the dispatch's [min, max], smoothed over time
// (exponentially in inverse distance, i.e. in dioptres, as a focus puller moves) and turned into the
// CoC line the other passes read from GLOBALS (ffx_dof_focus.h). Nothing is read back to the host.
#ifndef FFX_DOF_AUTOFOCUS_H
#define FFX_DOF_AUTOFOCUS_H

#include "ffx_dof_common.h"

#if defined(FFX_CPU)
FfxDofConstants ffxDofGetConstants();
FfxFloat32 ffxDofLoadInputDepth(FfxUInt32x2 pixel);
FfxFloat32 ffxDofLoadFocusDistance();
void ffxDofStoreFocus(FfxFloat32 distance, FfxFloat32 cocScale, FfxFloat32 cocBias);
#endif

// Samples per side of the grid over the region; each thread takes the same number of them.
#define FFX_DOF_AUTOFOCUS_GRID 16u
#define FFX_DOF_AUTOFOCUS_SAMPLES_PER_THREAD (FFX_DOF_AUTOFOCUS_GRID * FFX_DOF_AUTOFOCUS_GRID / FFX_DOF_GROUP_THREADS)
// A sample is on the centre's surface when its inverse distance is within this fraction of the
// reference's (about 5% in distance).
#define FFX_DOF_AUTOFOCUS_SURFACE_TOLERANCE 0.05f

// ---- Pure functions ---------------------------------------------------------------------------------

// The inverse of the signed view-space z of device depth `depth`: 1/z = depth * invZScale - invZBias
// (the projection terms p43/p34 and p33/p34, ffxDofCocScale's derivation in docs/coc.md).
FFX_DOF_INLINE FfxFloat32 ffxDofInverseViewZ(FfxFloat32 depth, FfxDofConstants constants)
{
    return depth * constants.focusInvZScale - constants.focusInvZBias;
}

// Whether a sample of inverse distance `invZ` lies on the surface of the reference `referenceInvZ`.
FFX_DOF_INLINE FfxBoolean ffxDofOnFocusSurface(FfxFloat32 invZ, FfxFloat32 referenceInvZ)
{
    return abs(invZ - referenceInvZ) <= FFX_DOF_AUTOFOCUS_SURFACE_TOLERANCE * abs(referenceInvZ);
}

// The focus, signed like view z, for a measured inverse distance: its magnitude clamped to the
// dispatch's [min, max] distance. The host signs both limits like view z in front of the camera, so
// infinity (invZ = 0, an infinite far plane) becomes the farthest focus on the right side.
FFX_DOF_INLINE FfxFloat32 ffxDofClampFocus(FfxFloat32 invZ, FfxDofConstants constants)
{
    FfxFloat32 distance = invZ != 0.0f ? 1.0f / invZ : constants.focusMaxDistance;
    FfxFloat32 magnitude = clamp(abs(distance), abs(constants.focusMinDistance), abs(constants.focusMaxDistance));
    return distance < 0.0f ? -magnitude : magnitude;
}

// One step of the temporal smoothing, in inverse distance: `blend` is 1 - exp(-dt / timeConstant),
// which the host computes (1 without history or after a reset).
FFX_DOF_INLINE FfxFloat32 ffxDofSmoothFocus(FfxFloat32 previous, FfxFloat32 target, FfxFloat32 blend)
{
    if (previous == 0.0f || blend >= 1.0f)
        return target;
    return 1.0f / ffxDofLerp(1.0f / previous, 1.0f / target, blend);
}

// The CoC line of a focus distance (signed like z): radius = depth * scale + bias, half-res px. The
// same thin-lens terms as ffxDofCalculateCocScale / ffxDofCalculateCocBias (sdk/src/ffx_dof_coc.cpp,
// which works in double for host callers): lensFactor = aperture * focalLength * conversion.
FFX_DOF_INLINE FfxFloat32x2 ffxDofFocusCocLine(FfxFloat32 focus, FfxDofConstants constants)
{
    FfxFloat32 k = constants.focusLensFactor / (abs(focus) - constants.focusFocalLength);
    return FfxFloat32x2(k * focus * constants.focusInvZScale, k * (-focus * constants.focusInvZBias - 1.0f));
}

// The pixel of grid sample `index` (0..GRID^2-1) over the region.
FFX_DOF_INLINE FfxUInt32x2 ffxDofFocusSamplePixel(FfxUInt32 index, FfxDofConstants constants)
{
    FfxFloat32x2 size = FfxFloat32x2(constants.fullSize);
    FfxFloat32 u = (FfxFloat32(index % FFX_DOF_AUTOFOCUS_GRID) + 0.5f) / FfxFloat32(FFX_DOF_AUTOFOCUS_GRID);
    FfxFloat32 v = (FfxFloat32(index / FFX_DOF_AUTOFOCUS_GRID) + 0.5f) / FfxFloat32(FFX_DOF_AUTOFOCUS_GRID);
    FfxFloat32 x = (constants.focusRegionCenter.x + (u - 0.5f) * constants.focusRegionSize.x) * size.x;
    FfxFloat32 y = (constants.focusRegionCenter.y + (v - 0.5f) * constants.focusRegionSize.y) * size.y;
    return FfxUInt32x2(FfxUInt32(clamp(x, 0.0f, size.x - 1.0f)), FfxUInt32(clamp(y, 0.0f, size.y - 1.0f)));
}

// The pixel of the centre's 3x3 neighbourhood `index` (0..8).
FFX_DOF_INLINE FfxUInt32x2 ffxDofFocusCentrePixel(FfxUInt32 index, FfxDofConstants constants)
{
    FfxFloat32x2 size = FfxFloat32x2(constants.fullSize);
    FfxFloat32 x = constants.focusRegionCenter.x * size.x + FfxFloat32(FfxInt32(index % 3u) - 1);
    FfxFloat32 y = constants.focusRegionCenter.y * size.y + FfxFloat32(FfxInt32(index / 3u) - 1);
    return FfxUInt32x2(FfxUInt32(clamp(x, 0.0f, size.x - 1.0f)), FfxUInt32(clamp(y, 0.0f, size.y - 1.0f)));
}

// ---- The pass ---------------------------------------------------------------------------------------

#if !defined(FFX_CPU)
FFX_DOF_GROUPSHARED FfxFloat32 ffxDofSharedCentreInvZ[9];
FFX_DOF_GROUPSHARED FfxFloat32 ffxDofSharedFocusSum[FFX_DOF_GROUP_THREADS];
FFX_DOF_GROUPSHARED FfxUInt32 ffxDofSharedFocusCount[FFX_DOF_GROUP_THREADS];

void ffxDofAutofocus(FfxUInt32 localIndex)
{
    FfxDofConstants constants = ffxDofGetConstants();
    if (localIndex < 9u)
        ffxDofSharedCentreInvZ[localIndex] =
            ffxDofInverseViewZ(ffxDofLoadInputDepth(ffxDofFocusCentrePixel(localIndex, constants)), constants);
    ffxDofGroupBarrier();

    FfxFloat32 referenceInvZ =
        ffxDofMedian9(ffxDofSharedCentreInvZ[0], ffxDofSharedCentreInvZ[1], ffxDofSharedCentreInvZ[2],
                      ffxDofSharedCentreInvZ[3], ffxDofSharedCentreInvZ[4], ffxDofSharedCentreInvZ[5],
                      ffxDofSharedCentreInvZ[6], ffxDofSharedCentreInvZ[7], ffxDofSharedCentreInvZ[8]);

    FfxFloat32 sum = 0.0f;
    FfxUInt32 count = 0u;
    FFX_DOF_UNROLL
    for (FfxUInt32 s = 0u; s < FFX_DOF_AUTOFOCUS_SAMPLES_PER_THREAD; ++s)
    {
        FfxUInt32 index = s * FFX_DOF_GROUP_THREADS + localIndex;
        FfxFloat32 invZ = ffxDofInverseViewZ(ffxDofLoadInputDepth(ffxDofFocusSamplePixel(index, constants)), constants);
        if (ffxDofOnFocusSurface(invZ, referenceInvZ))
        {
            sum += invZ;
            count += 1u;
        }
    }
    ffxDofSharedFocusSum[localIndex] = sum;
    ffxDofSharedFocusCount[localIndex] = count;
    ffxDofGroupBarrier();

    if (localIndex == 0u)
    {
        FFX_DOF_LOOP
        for (FfxUInt32 t = 1u; t < FfxUInt32(FFX_DOF_GROUP_THREADS); ++t)
        {
            sum += ffxDofSharedFocusSum[t];
            count += ffxDofSharedFocusCount[t];
        }
        // The grid may miss a small surface that the centre hits: then the centre alone decides.
        FfxFloat32 measuredInvZ = count > 0u ? sum / FfxFloat32(count) : referenceInvZ;
        FfxFloat32 target = ffxDofClampFocus(measuredInvZ, constants);
        FfxFloat32 previous =
            (constants.focusFlags & FFX_DOF_FOCUS_FLAG_RESET) != 0u ? 0.0f : ffxDofLoadFocusDistance();
        FfxFloat32 focus = ffxDofSmoothFocus(previous, target, constants.focusBlend);
        FfxFloat32x2 cocLine = ffxDofFocusCocLine(focus, constants);
        ffxDofStoreFocus(focus, cocLine.x, cocLine.y);
    }
}
#endif

#endif  // FFX_DOF_AUTOFOCUS_H
