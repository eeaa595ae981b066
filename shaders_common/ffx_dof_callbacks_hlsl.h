// HLSL bindings and accessors of ffx-dof. The entry point defines FFX_HLSL and one
// FFX_DOF_PASS_<NAME>; only the bindings that pass uses are declared.
// D3D12: t#/u#/s# = the index from ffx_dof_resources.h in space 0; the storage buffers are u<index>
// in space 1 (u# is shared by images and buffers on D3D12). Constants are root constants (the
// only constant buffer, so b0). Vulkan (glslang or dxc -spirv): [[vk::binding(base + index, 0)]]
// gives the same bindings as the GLSL path, and the constants become push constants.
// Storage images carry no format on Vulkan: compile with glslang's --no-storage-format (dxc picks
// Unknown for these template types with -fspv-... defaults the backend sets).
#ifndef FFX_DOF_CALLBACKS_HLSL_H
#define FFX_DOF_CALLBACKS_HLSL_H

#include "ffx_dof_common.h"
#include "ffx_dof_pass_resources.h"

#define FFX_DOF_HLSL_REGISTER_(registerClass, index) register(registerClass##index)
#define FFX_DOF_HLSL_REGISTER(registerClass, index) FFX_DOF_HLSL_REGISTER_(registerClass, index)
// Storage buffers: u<index> in space 1.
#define FFX_DOF_HLSL_BUFFER_REGISTER_(index) register(u##index, space1)
#define FFX_DOF_HLSL_BUFFER_REGISTER(index) FFX_DOF_HLSL_BUFFER_REGISTER_(index)
#define FFX_DOF_BINDING_SRV(index) [[vk::binding(FFX_DOF_SRV_BASE + index, 0)]]
#define FFX_DOF_BINDING_UAV_IMAGE(index) [[vk::binding(FFX_DOF_UAV_IMAGE_BASE + index, 0)]]
#define FFX_DOF_BINDING_UAV_BUFFER(index) [[vk::binding(FFX_DOF_UAV_BUFFER_BASE + index, 0)]]

#if FFX_DOF_OPTION_WAVE64 && defined(__DXC_VERSION_MAJOR)
#define FFX_DOF_WAVE_SIZE_ATTRIBUTE [WaveSize(64)]
#else
#define FFX_DOF_WAVE_SIZE_ATTRIBUTE
#endif

[[vk::push_constant]] cbuffer FfxDofConstantBuffer { FfxDofConstants ffxDofPushedConstants; };
FfxDofConstants ffxDofGetConstants() { return ffxDofPushedConstants; }

// In place, D3D12 cannot have the color image as SRV and UAV at once: the composite pass reads the
// input through the output UAV (ffxDofLoadInputColor below, next to the output). Vulkan (SPIR-V from
// glslang or dxc -spirv) keeps the sampled view of the same GENERAL-layout image, which is valid
// there and needs no shaderStorageImageReadWithoutFormat.
#if defined(FFX_DOF_PASS_COMPOSITE) && FFX_DOF_OPTION_OUTPUT_PRE_INIT && defined(__DXC_VERSION_MAJOR) && \
    !defined(__spirv__)
#define FFX_DOF_INPUT_COLOR_THROUGH_OUTPUT 1
#else
#define FFX_DOF_INPUT_COLOR_THROUGH_OUTPUT 0
#endif
#if FFX_DOF_USES_INPUT_COLOR && !FFX_DOF_INPUT_COLOR_THROUGH_OUTPUT
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_INPUT_COLOR)
Texture2D<float4> ffxDofInputColor : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_INPUT_COLOR);
FfxFloat32x4 ffxDofLoadInputColor(FfxUInt32x2 pixel) { return ffxDofInputColor.Load(int3(pixel, 0)); }
#endif

#if FFX_DOF_USES_INPUT_DEPTH
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_INPUT_DEPTH)
Texture2D<float> ffxDofInputDepth : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_INPUT_DEPTH);
FfxFloat32 ffxDofLoadInputDepth(FfxUInt32x2 pixel) { return ffxDofInputDepth.Load(int3(pixel, 0)); }
#endif

#if FFX_DOF_USES_HALF_COLOR
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_HALF_COLOR)
Texture2D<float3> ffxDofHalfColor : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_HALF_COLOR);
FfxDofFloat3 ffxDofLoadHalfColor(FfxInt32x2 texel) { return FfxDofFloat3(ffxDofHalfColor.Load(int3(texel, 0))); }
#endif

#if FFX_DOF_USES_HALF_COC
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_HALF_COC)
Texture2D<float> ffxDofHalfCoc : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_HALF_COC);
FfxFloat32 ffxDofLoadHalfCoc(FfxInt32x2 texel) { return ffxDofHalfCoc.Load(int3(texel, 0)); }
#endif

#if FFX_DOF_USES_COARSE_MIPS
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_COARSE_MIPS)
Texture2D<uint2> ffxDofCoarseMips : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_COARSE_MIPS);
// `mip` of the half-res chain, 1 or more: COARSE_MIPS starts at MIP 1 (ffxDofPackCoarseTexel).
FfxUInt32x2 ffxDofLoadCoarseMip(FfxInt32x2 texel, FfxUInt32 mip)
{
    return ffxDofCoarseMips.Load(int3(texel, int(mip) - 1));
}
#endif

#if FFX_DOF_USES_TILES
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_TILES) Texture2D<float4> ffxDofTiles : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_TILES);
FfxFloat32x2 ffxDofLoadTile(FfxUInt32x2 tile) { return ffxDofTiles.Load(int3(tile, 0)).xy; }
#endif

#if FFX_DOF_USES_DILATED_TILES
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_DILATED_TILES)
Texture2D<float4> ffxDofDilatedTiles : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_DILATED_TILES);
FfxFloat32x4 ffxDofLoadDilatedTile(FfxUInt32x2 tile) { return ffxDofDilatedTiles.Load(int3(tile, 0)); }
#endif

#if FFX_DOF_USES_LAYERS
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_NEAR_COLOR)
Texture2D<float3> ffxDofNearColor : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_NEAR_COLOR);
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_FAR_COLOR)
Texture2D<float3> ffxDofFarColor : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_FAR_COLOR);
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_LAYER_ALPHA)
Texture2D<float> ffxDofLayerAlpha : FFX_DOF_HLSL_REGISTER(t, FFX_DOF_SRV_LAYER_ALPHA);
FfxDofFloat3 ffxDofLoadNearColor(FfxInt32x2 texel) { return FfxDofFloat3(ffxDofNearColor.Load(int3(texel, 0))); }
FfxDofFloat3 ffxDofLoadFarColor(FfxInt32x2 texel) { return FfxDofFloat3(ffxDofFarColor.Load(int3(texel, 0))); }
FfxFloat32x2 ffxDofLoadLayerAlpha(FfxInt32x2 texel)
{
    return ffxDofUnpackLayerAlpha(ffxDofLayerAlpha.Load(int3(texel, 0)));
}
#endif

#if FFX_DOF_USES_RW_MIPS
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_HALF_COLOR)
RWTexture2D<float3> ffxDofRwHalfColor : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_HALF_COLOR);
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_HALF_COC)
RWTexture2D<float> ffxDofRwHalfCoc : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_HALF_COC);
#if FFX_DOF_OPTION_MAX_MIP > 1
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_COARSE_MIP1)
RWTexture2D<uint2> ffxDofCoarseMip1 : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_COARSE_MIP1);
#endif
#if FFX_DOF_OPTION_MAX_MIP > 2
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_COARSE_MIP2)
RWTexture2D<uint2> ffxDofCoarseMip2 : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_COARSE_MIP2);
#endif
#if FFX_DOF_OPTION_MAX_MIP > 3
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_COARSE_MIP3)
RWTexture2D<uint2> ffxDofCoarseMip3 : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_COARSE_MIP3);
#endif
void ffxDofStoreHalfColor(FfxUInt32x2 texel, FfxDofFloat3 color) { ffxDofRwHalfColor[texel] = float3(color); }
void ffxDofStoreHalfCoc(FfxUInt32x2 texel, FfxFloat32 coc) { ffxDofRwHalfCoc[texel] = coc; }
// `mip` 1 or more (ffxDofPackCoarseTexel).
void ffxDofStoreCoarseMip(FfxUInt32 mip, FfxUInt32x2 texel, FfxUInt32x2 packed)
{
#if FFX_DOF_OPTION_MAX_MIP > 1
    if (mip == 1u)
        ffxDofCoarseMip1[texel] = packed;
#endif
#if FFX_DOF_OPTION_MAX_MIP > 2
    if (mip == 2u)
        ffxDofCoarseMip2[texel] = packed;
#endif
#if FFX_DOF_OPTION_MAX_MIP > 3
    if (mip == 3u)
        ffxDofCoarseMip3[texel] = packed;
#endif
}
#endif

#if FFX_DOF_USES_RW_TILES
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_TILES)
RWTexture2D<float4> ffxDofRwTiles : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_TILES);
void ffxDofStoreTile(FfxUInt32x2 tile, FfxFloat32x2 cocMinMax) { ffxDofRwTiles[tile] = float4(cocMinMax, 0.0f, 0.0f); }
#endif

#if FFX_DOF_USES_RW_DILATED_TILES
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_DILATED_TILES)
RWTexture2D<float4> ffxDofRwDilatedTiles : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_DILATED_TILES);
void ffxDofStoreDilatedTile(FfxUInt32x2 tile, FfxFloat32x4 farNearFootprint)
{
    ffxDofRwDilatedTiles[tile] = farNearFootprint;
}
#endif

#if FFX_DOF_USES_RW_LAYERS
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_NEAR_COLOR)
RWTexture2D<float3> ffxDofRwNearColor : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_NEAR_COLOR);
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_FAR_COLOR)
RWTexture2D<float3> ffxDofRwFarColor : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_FAR_COLOR);
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_LAYER_ALPHA)
RWTexture2D<float> ffxDofRwLayerAlpha : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_LAYER_ALPHA);
void ffxDofStoreNearColor(FfxUInt32x2 texel, FfxDofFloat3 color) { ffxDofRwNearColor[texel] = float3(color); }
void ffxDofStoreFarColor(FfxUInt32x2 texel, FfxDofFloat3 color) { ffxDofRwFarColor[texel] = float3(color); }
void ffxDofStoreLayerAlpha(FfxUInt32x2 texel, FfxFloat32x2 nearOpacityFarValidity)
{
    ffxDofRwLayerAlpha[texel] = ffxDofPackLayerAlpha(nearOpacityFarValidity);
}
#endif

#if FFX_DOF_USES_RW_OUTPUT
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_OUTPUT)
RWTexture2D<float4> ffxDofOutput : FFX_DOF_HLSL_REGISTER(u, FFX_DOF_UAV_OUTPUT);
void ffxDofStoreOutput(FfxUInt32x2 pixel, FfxFloat32x4 color)
{
    if ((ffxDofPushedConstants.outputFlags & FFX_DOF_OUTPUT_FLAG_ENCODE_SRGB) != 0u)
        color = float4(ffxDofLinearToSrgb(color.x), ffxDofLinearToSrgb(color.y), ffxDofLinearToSrgb(color.z), color.w);
    ffxDofOutput[pixel] = color;
}
#if FFX_DOF_INPUT_COLOR_THROUGH_OUTPUT
// Only called for pixels of the workgroup's own tile, before the group writes any of them.
FfxFloat32x4 ffxDofLoadInputColor(FfxUInt32x2 pixel)
{
    FfxFloat32x4 color = ffxDofOutput[pixel];
    if ((ffxDofPushedConstants.outputFlags & FFX_DOF_OUTPUT_FLAG_ENCODE_SRGB) != 0u)
        color = float4(ffxDofSrgbToLinear(color.x), ffxDofSrgbToLinear(color.y), ffxDofSrgbToLinear(color.z), color.w);
    return color;
}
#endif
#endif

#if FFX_DOF_USES_GLOBALS
FFX_DOF_BINDING_UAV_BUFFER(FFX_DOF_UAV_BUFFER_GLOBALS)
RWStructuredBuffer<uint> ffxDofGlobals : FFX_DOF_HLSL_BUFFER_REGISTER(FFX_DOF_UAV_BUFFER_GLOBALS);
FfxFloat32 ffxDofLoadGlobalMaxRadius() { return asfloat(ffxDofGlobals[FFX_DOF_GLOBALS_MAX_RADIUS]); }
void ffxDofAtomicMaxGlobalRadius(FfxFloat32 radius)
{
    // Non-negative floats order like their bit patterns.
    uint previous;
    InterlockedMax(ffxDofGlobals[FFX_DOF_GLOBALS_MAX_RADIUS], asuint(max(radius, 0.0f)), previous);
}
void ffxDofResetGlobals() { ffxDofGlobals[FFX_DOF_GLOBALS_MAX_RADIUS] = 0u; }
void ffxDofAtomicMaxColorPeak(FfxFloat32 peak)
{
    uint previous;
    InterlockedMax(ffxDofGlobals[FFX_DOF_GLOBALS_COLOR_PEAK], asuint(max(peak, 0.0f)), previous);
}
FfxFloat32 ffxDofLoadColorPeak() { return asfloat(ffxDofGlobals[FFX_DOF_GLOBALS_COLOR_PEAK]); }
void ffxDofResetColorPeak() { ffxDofGlobals[FFX_DOF_GLOBALS_COLOR_PEAK] = 0u; }
void ffxDofStoreColorScale(FfxFloat32 scale) { ffxDofGlobals[FFX_DOF_GLOBALS_COLOR_SCALE] = asuint(scale); }
FfxFloat32 ffxDofLoadColorScale() { return asfloat(ffxDofGlobals[FFX_DOF_GLOBALS_COLOR_SCALE]); }
FfxFloat32 ffxDofLoadFocusDistance() { return asfloat(ffxDofGlobals[FFX_DOF_GLOBALS_FOCUS_DISTANCE]); }
FfxFloat32x2 ffxDofLoadFocusCocLine()
{
    return FfxFloat32x2(asfloat(ffxDofGlobals[FFX_DOF_GLOBALS_FOCUS_COC_SCALE]),
                        asfloat(ffxDofGlobals[FFX_DOF_GLOBALS_FOCUS_COC_BIAS]));
}
void ffxDofStoreFocus(FfxFloat32 distance, FfxFloat32 cocScale, FfxFloat32 cocBias)
{
    ffxDofGlobals[FFX_DOF_GLOBALS_FOCUS_DISTANCE] = asuint(distance);
    ffxDofGlobals[FFX_DOF_GLOBALS_FOCUS_COC_SCALE] = asuint(cocScale);
    ffxDofGlobals[FFX_DOF_GLOBALS_FOCUS_COC_BIAS] = asuint(cocBias);
}
#endif

#if FFX_DOF_USES_RW_TILE_LIST_ARGS
FFX_DOF_BINDING_UAV_BUFFER(FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS)
RWStructuredBuffer<uint> ffxDofTileListArgs : FFX_DOF_HLSL_BUFFER_REGISTER(FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS);
// The dispatch arguments of tile list `list` (FFX_DOF_TILE_LIST_ARGS_WORDS words apart).
void ffxDofStoreTileListArgs(FfxUInt32 list, FfxUInt32x3 groupCounts)
{
    ffxDofTileListArgs[list * FFX_DOF_TILE_LIST_ARGS_WORDS + 0u] = groupCounts.x;
    ffxDofTileListArgs[list * FFX_DOF_TILE_LIST_ARGS_WORDS + 1u] = groupCounts.y;
    ffxDofTileListArgs[list * FFX_DOF_TILE_LIST_ARGS_WORDS + 2u] = groupCounts.z;
}
// Pass 2's second run over every tile (its arguments are (0, 1, 1) until then).
void ffxDofArmColorRangeRerun(FfxUInt32x2 tileCount)
{
    uint previous;
    InterlockedMax(ffxDofTileListArgs[FFX_DOF_COLOR_RANGE_RERUN_ARGS * FFX_DOF_TILE_LIST_ARGS_WORDS + 0u], tileCount.x,
                   previous);
    InterlockedMax(ffxDofTileListArgs[FFX_DOF_COLOR_RANGE_RERUN_ARGS * FFX_DOF_TILE_LIST_ARGS_WORDS + 1u], tileCount.y,
                   previous);
}
#endif

#if FFX_DOF_USES_RW_TILE_LISTS || FFX_DOF_USES_TILE_LISTS
FFX_DOF_BINDING_UAV_BUFFER(FFX_DOF_UAV_BUFFER_TILE_LISTS)
RWStructuredBuffer<uint> ffxDofTileLists : FFX_DOF_HLSL_BUFFER_REGISTER(FFX_DOF_UAV_BUFFER_TILE_LISTS);
#endif
#if FFX_DOF_USES_RW_TILE_LISTS
// The next entry of tile list `list`: its count so far, counted up (ffxDofTileListWord places it).
FfxUInt32 ffxDofCountIntoTileList(FfxUInt32 list)
{
    uint index;
    InterlockedAdd(ffxDofTileListArgs[list * FFX_DOF_TILE_LIST_ARGS_WORDS], 1u, index);
    return index;
}
void ffxDofStoreTileListWord(FfxUInt32 word, FfxUInt32 packedTile) { ffxDofTileLists[word] = packedTile; }
#endif
#if FFX_DOF_USES_TILE_LISTS
FfxUInt32 ffxDofLoadTileListWord(FfxUInt32 word) { return ffxDofTileLists[word]; }
#endif

#if FFX_DOF_USES_RW_HIGHLIGHTS || FFX_DOF_USES_HIGHLIGHTS
FFX_DOF_BINDING_UAV_BUFFER(FFX_DOF_UAV_BUFFER_HIGHLIGHTS)
RWStructuredBuffer<uint> ffxDofHighlights : FFX_DOF_HLSL_BUFFER_REGISTER(FFX_DOF_UAV_BUFFER_HIGHLIGHTS);
#endif
#if FFX_DOF_USES_RW_HIGHLIGHTS
void ffxDofStoreHighlightWord(FfxUInt32 word, FfxUInt32 value) { ffxDofHighlights[word] = value; }
#endif
#if FFX_DOF_USES_HIGHLIGHTS
FfxUInt32 ffxDofLoadHighlightWord(FfxUInt32 word) { return ffxDofHighlights[word]; }
#endif

#endif  // FFX_DOF_CALLBACKS_HLSL_H
