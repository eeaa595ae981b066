// The one constants layout of ffx-dof, shared by C++ (host), HLSL and GLSL. It is delivered as
// push constants (Vulkan) or root constants (D3D12), so it must stay within 128 bytes.
//
// Layout rules that make the three languages agree: only 32-bit scalars and 2-component vectors,
// every 2-component vector at an 8-byte aligned offset. The C++ side checks size and offsets with
// static_assert; tests/shaderc/test_real_passes.cpp checks them again against the push constant
// block reflected from every pass's SPIR-V, compiled from GLSL and from HLSL.
#ifndef FFX_DOF_CONSTANTS_H
#define FFX_DOF_CONSTANTS_H

#include "ffx_dof_portability.h"

struct FfxDofConstants
{
    FfxFloat32 cocScale;  // radius (half-res px) = depth * cocScale + cocBias
    FfxFloat32 cocBias;
    FfxFloat32 cocLimit;    // largest |radius|, half-res px (cocLimitFactor * height / 2)
    FfxUInt32 maxRings;     // quality: upper bound on kernel rings
    FfxUInt32x2 fullSize;   // input/output size, px
    FfxUInt32x2 halfSize;   // size of MIP 0 of the half-resolution images: ceil(fullSize / 2)
    FfxUInt32x2 tileCount;  // tiles of FFX_DOF_TILE_SIZE x FFX_DOF_TILE_SIZE half-res px
    // Aperture shape (ffx_dof_aperture.h); a circle: bladeCount 0, anamorphicRatio 1, catEye 0.
    FfxFloat32x2 bladeNormal;    // the first blade side's normal (y up) over the blades' inradius
    FfxUInt32 bladeCount;        // 0: round (no blades), else 3..16
    FfxFloat32 anamorphicRatio;  // disc height over width
    FfxUInt32 frameIndex;        // increments every dispatch; seeds the kernel jitter
    FfxUInt32 outputFlags;       // FFX_DOF_OUTPUT_FLAG_* bits
    // Autofocus (ffx_dof_autofocus.h); ignored unless focusFlags has FFX_DOF_FOCUS_FLAG_AUTO.
    FfxFloat32x2 focusRegionCenter;  // normalized image coordinates, origin top-left
    FfxFloat32x2 focusRegionSize;    // normalized width and height
    FfxFloat32 focusInvZScale;       // 1 / view z = depth * focusInvZScale - focusInvZBias (p43 / p34)
    FfxFloat32 focusInvZBias;        // p33 / p34
    FfxFloat32 focusLensFactor;      // aperture * focalLength * conversion (sensor units -> half-res px)
    FfxFloat32 focusFocalLength;
    FfxFloat32 focusMinDistance;   // nearest focus, signed like view z in front of the camera
    FfxFloat32 focusMaxDistance;   // farthest focus, likewise
    FfxFloat32 focusBlend;         // 1 - exp(-deltaTime / timeConstant): the share of the new distance
    FfxUInt32 focusFlags;          // FFX_DOF_FOCUS_FLAG_* bits
    FfxFloat32 catEye;             // optical vignetting: 0 off, 1 the strongest
    FfxFloat32 apertureAreaScale;  // pi / area of the unit shape (before cat's eye) * anamorphicRatio
};

// Bits of FfxDofConstants::outputFlags, which the backend sets per dispatch.
#define FFX_DOF_OUTPUT_FLAG_ENCODE_SRGB 1u  // the output view is UNORM over an sRGB image: encode in shader
// Pass 2's second run, dispatched indirectly where its first run found a colour channel above
// FFX_DOF_COLOR_RANGE_LIMIT (FFX_DOF_COLOR_RANGE_RERUN_ARGS): scale the colour by the frame's peak.
#define FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN 2u

// Bits of FfxDofConstants::focusFlags.
#define FFX_DOF_FOCUS_FLAG_AUTO 1u   // the passes read the CoC line autofocus wrote to GLOBALS
#define FFX_DOF_FOCUS_FLAG_RESET 2u  // autofocus ignores the previous distance (a camera cut)

#if defined(FFX_CPU)
static_assert(sizeof(FfxDofConstants) == 120, "FfxDofConstants layout changed: update the offset checks");
static_assert(offsetof(FfxDofConstants, fullSize) == 16, "FfxDofConstants::fullSize offset");
static_assert(offsetof(FfxDofConstants, halfSize) == 24, "FfxDofConstants::halfSize offset");
static_assert(offsetof(FfxDofConstants, tileCount) == 32, "FfxDofConstants::tileCount offset");
static_assert(offsetof(FfxDofConstants, bladeNormal) == 40, "FfxDofConstants::bladeNormal offset");
static_assert(offsetof(FfxDofConstants, bladeCount) == 48, "FfxDofConstants::bladeCount offset");
static_assert(offsetof(FfxDofConstants, anamorphicRatio) == 52, "FfxDofConstants::anamorphicRatio offset");
static_assert(offsetof(FfxDofConstants, frameIndex) == 56, "FfxDofConstants::frameIndex offset");
static_assert(offsetof(FfxDofConstants, outputFlags) == 60, "FfxDofConstants::outputFlags offset");
static_assert(offsetof(FfxDofConstants, focusRegionCenter) == 64, "FfxDofConstants::focusRegionCenter offset");
static_assert(offsetof(FfxDofConstants, focusRegionSize) == 72, "FfxDofConstants::focusRegionSize offset");
static_assert(offsetof(FfxDofConstants, focusInvZScale) == 80, "FfxDofConstants::focusInvZScale offset");
static_assert(offsetof(FfxDofConstants, focusFlags) == 108, "FfxDofConstants::focusFlags offset");
static_assert(offsetof(FfxDofConstants, catEye) == 112, "FfxDofConstants::catEye offset");
static_assert(offsetof(FfxDofConstants, apertureAreaScale) == 116, "FfxDofConstants::apertureAreaScale offset");
#endif

#endif  // FFX_DOF_CONSTANTS_H
