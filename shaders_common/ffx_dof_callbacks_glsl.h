// GLSL bindings and accessors of ffx-dof. The entry point defines FFX_GLSL and one
// FFX_DOF_PASS_<NAME>; only the bindings that pass uses are declared (backends bind by reflection).
// Vulkan binding = class base + index from ffx_dof_resources.h, set 0. Constants are push constants.
#ifndef FFX_DOF_CALLBACKS_GLSL_H
#define FFX_DOF_CALLBACKS_GLSL_H

#include "ffx_dof_common.h"
#include "ffx_dof_pass_resources.h"

#define FFX_DOF_BINDING_SRV(index) layout(set = 0, binding = FFX_DOF_SRV_BASE + (index))
#define FFX_DOF_BINDING_UAV_IMAGE(index, format) layout(set = 0, binding = FFX_DOF_UAV_IMAGE_BASE + (index), format)
#define FFX_DOF_BINDING_UAV_BUFFER(index) layout(set = 0, binding = FFX_DOF_UAV_BUFFER_BASE + (index), std430)

layout(push_constant) uniform FfxDofPushConstants { FfxDofConstants ffxDofPushedConstants; };
FfxDofConstants ffxDofGetConstants() { return ffxDofPushedConstants; }

#if FFX_DOF_USES_INPUT_COLOR
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_INPUT_COLOR) uniform texture2D ffxDofInputColor;
FfxFloat32x4 ffxDofLoadInputColor(FfxUInt32x2 pixel) { return texelFetch(ffxDofInputColor, ivec2(pixel), 0); }
#endif

#if FFX_DOF_USES_INPUT_DEPTH
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_INPUT_DEPTH) uniform texture2D ffxDofInputDepth;
FfxFloat32 ffxDofLoadInputDepth(FfxUInt32x2 pixel) { return texelFetch(ffxDofInputDepth, ivec2(pixel), 0).x; }
#endif

#if FFX_DOF_USES_HALF_COLOR
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_HALF_COLOR) uniform texture2D ffxDofHalfColor;
FfxDofFloat3 ffxDofLoadHalfColor(FfxInt32x2 texel)
{
    vec4 color = texelFetch(ffxDofHalfColor, texel, 0);
    return FfxDofFloat3(color.x, color.y, color.z);
}
#endif

#if FFX_DOF_USES_HALF_COC
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_HALF_COC) uniform texture2D ffxDofHalfCoc;
FfxFloat32 ffxDofLoadHalfCoc(FfxInt32x2 texel) { return texelFetch(ffxDofHalfCoc, texel, 0).x; }
#endif

#if FFX_DOF_USES_COARSE_MIPS
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_COARSE_MIPS) uniform utexture2D ffxDofCoarseMips;
// `mip` of the half-res chain, 1 or more: COARSE_MIPS starts at MIP 1 (ffxDofPackCoarseTexel).
FfxUInt32x2 ffxDofLoadCoarseMip(FfxInt32x2 texel, FfxUInt32 mip)
{
    return texelFetch(ffxDofCoarseMips, texel, int(mip) - 1).xy;
}
#endif

#if FFX_DOF_USES_TILES
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_TILES) uniform texture2D ffxDofTiles;
FfxFloat32x2 ffxDofLoadTile(FfxUInt32x2 tile) { return texelFetch(ffxDofTiles, ivec2(tile), 0).xy; }
#endif

#if FFX_DOF_USES_DILATED_TILES
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_DILATED_TILES) uniform texture2D ffxDofDilatedTiles;
FfxFloat32x4 ffxDofLoadDilatedTile(FfxUInt32x2 tile) { return texelFetch(ffxDofDilatedTiles, ivec2(tile), 0); }
#endif

#if FFX_DOF_USES_LAYERS
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_NEAR_COLOR) uniform texture2D ffxDofNearColor;
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_FAR_COLOR) uniform texture2D ffxDofFarColor;
FFX_DOF_BINDING_SRV(FFX_DOF_SRV_LAYER_ALPHA) uniform texture2D ffxDofLayerAlpha;
FfxDofFloat3 ffxDofLoadNearColor(FfxInt32x2 texel)
{
    vec4 color = texelFetch(ffxDofNearColor, texel, 0);
    return FfxDofFloat3(color.x, color.y, color.z);
}
FfxDofFloat3 ffxDofLoadFarColor(FfxInt32x2 texel)
{
    vec4 color = texelFetch(ffxDofFarColor, texel, 0);
    return FfxDofFloat3(color.x, color.y, color.z);
}
FfxFloat32x2 ffxDofLoadLayerAlpha(FfxInt32x2 texel)
{
    return ffxDofUnpackLayerAlpha(texelFetch(ffxDofLayerAlpha, texel, 0).x);
}
#endif

#if FFX_DOF_USES_RW_MIPS
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_HALF_COLOR, r11f_g11f_b10f) uniform writeonly image2D ffxDofRwHalfColor;
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_HALF_COC, r16f) uniform writeonly image2D ffxDofRwHalfCoc;
#if FFX_DOF_OPTION_MAX_MIP > 1
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_COARSE_MIP1, rg32ui) uniform writeonly uimage2D ffxDofCoarseMip1;
#endif
#if FFX_DOF_OPTION_MAX_MIP > 2
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_COARSE_MIP2, rg32ui) uniform writeonly uimage2D ffxDofCoarseMip2;
#endif
#if FFX_DOF_OPTION_MAX_MIP > 3
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_COARSE_MIP3, rg32ui) uniform writeonly uimage2D ffxDofCoarseMip3;
#endif
void ffxDofStoreHalfColor(FfxUInt32x2 texel, FfxDofFloat3 color)
{
    imageStore(ffxDofRwHalfColor, ivec2(texel), vec4(color.x, color.y, color.z, 1.0f));
}
void ffxDofStoreHalfCoc(FfxUInt32x2 texel, FfxFloat32 coc)
{
    imageStore(ffxDofRwHalfCoc, ivec2(texel), vec4(coc, 0.0f, 0.0f, 0.0f));
}
// `mip` 1 or more (ffxDofPackCoarseTexel).
void ffxDofStoreCoarseMip(FfxUInt32 mip, FfxUInt32x2 texel, FfxUInt32x2 packed)
{
    uvec4 value = uvec4(packed.x, packed.y, 0u, 0u);
#if FFX_DOF_OPTION_MAX_MIP > 1
    if (mip == 1u)
        imageStore(ffxDofCoarseMip1, ivec2(texel), value);
#endif
#if FFX_DOF_OPTION_MAX_MIP > 2
    if (mip == 2u)
        imageStore(ffxDofCoarseMip2, ivec2(texel), value);
#endif
#if FFX_DOF_OPTION_MAX_MIP > 3
    if (mip == 3u)
        imageStore(ffxDofCoarseMip3, ivec2(texel), value);
#endif
}
#endif

#if FFX_DOF_USES_RW_TILES
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_TILES, rgba16f) uniform writeonly image2D ffxDofRwTiles;
void ffxDofStoreTile(FfxUInt32x2 tile, FfxFloat32x2 cocMinMax)
{
    imageStore(ffxDofRwTiles, ivec2(tile), vec4(cocMinMax.x, cocMinMax.y, 0.0f, 0.0f));
}
#endif

#if FFX_DOF_USES_RW_DILATED_TILES
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_DILATED_TILES, rgba16f) uniform writeonly image2D ffxDofRwDilatedTiles;
void ffxDofStoreDilatedTile(FfxUInt32x2 tile, FfxFloat32x4 farNearFootprint)
{
    imageStore(ffxDofRwDilatedTiles, ivec2(tile), farNearFootprint);
}
#endif

#if FFX_DOF_USES_RW_LAYERS
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_NEAR_COLOR, r11f_g11f_b10f) uniform writeonly image2D ffxDofRwNearColor;
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_FAR_COLOR, r11f_g11f_b10f) uniform writeonly image2D ffxDofRwFarColor;
FFX_DOF_BINDING_UAV_IMAGE(FFX_DOF_UAV_LAYER_ALPHA, r8) uniform writeonly image2D ffxDofRwLayerAlpha;
void ffxDofStoreNearColor(FfxUInt32x2 texel, FfxDofFloat3 color)
{
    imageStore(ffxDofRwNearColor, ivec2(texel), vec4(color.x, color.y, color.z, 1.0f));
}
void ffxDofStoreFarColor(FfxUInt32x2 texel, FfxDofFloat3 color)
{
    imageStore(ffxDofRwFarColor, ivec2(texel), vec4(color.x, color.y, color.z, 1.0f));
}
void ffxDofStoreLayerAlpha(FfxUInt32x2 texel, FfxFloat32x2 nearOpacityFarValidity)
{
    imageStore(ffxDofRwLayerAlpha, ivec2(texel), vec4(ffxDofPackLayerAlpha(nearOpacityFarValidity), 0.0f, 0.0f, 0.0f));
}
#endif

#if FFX_DOF_USES_RW_OUTPUT
// The engine's output may be any of several formats: no format qualifier
// (shaderStorageImageWriteWithoutFormat).
layout(set = 0, binding = FFX_DOF_UAV_IMAGE_BASE + FFX_DOF_UAV_OUTPUT) uniform writeonly image2D ffxDofOutput;
void ffxDofStoreOutput(FfxUInt32x2 pixel, FfxFloat32x4 color)
{
    if ((ffxDofPushedConstants.outputFlags & FFX_DOF_OUTPUT_FLAG_ENCODE_SRGB) != 0u)
        color = vec4(ffxDofLinearToSrgb(color.x), ffxDofLinearToSrgb(color.y), ffxDofLinearToSrgb(color.z), color.w);
    imageStore(ffxDofOutput, ivec2(pixel), color);
}
#endif

#if FFX_DOF_USES_GLOBALS
FFX_DOF_BINDING_UAV_BUFFER(FFX_DOF_UAV_BUFFER_GLOBALS) buffer FfxDofGlobals
{
    uint ffxDofGlobalWords[FFX_DOF_GLOBALS_WORD_COUNT];
};
FfxFloat32 ffxDofLoadGlobalMaxRadius() { return uintBitsToFloat(ffxDofGlobalWords[FFX_DOF_GLOBALS_MAX_RADIUS]); }
void ffxDofAtomicMaxGlobalRadius(FfxFloat32 radius)
{
    // Non-negative floats order like their bit patterns.
    atomicMax(ffxDofGlobalWords[FFX_DOF_GLOBALS_MAX_RADIUS], floatBitsToUint(max(radius, 0.0f)));
}
void ffxDofResetGlobals() { ffxDofGlobalWords[FFX_DOF_GLOBALS_MAX_RADIUS] = 0u; }
void ffxDofAtomicMaxColorPeak(FfxFloat32 peak)
{
    atomicMax(ffxDofGlobalWords[FFX_DOF_GLOBALS_COLOR_PEAK], floatBitsToUint(max(peak, 0.0f)));
}
FfxFloat32 ffxDofLoadColorPeak() { return uintBitsToFloat(ffxDofGlobalWords[FFX_DOF_GLOBALS_COLOR_PEAK]); }
void ffxDofResetColorPeak() { ffxDofGlobalWords[FFX_DOF_GLOBALS_COLOR_PEAK] = 0u; }
void ffxDofStoreColorScale(FfxFloat32 scale)
{
    ffxDofGlobalWords[FFX_DOF_GLOBALS_COLOR_SCALE] = floatBitsToUint(scale);
}
FfxFloat32 ffxDofLoadColorScale() { return uintBitsToFloat(ffxDofGlobalWords[FFX_DOF_GLOBALS_COLOR_SCALE]); }
FfxFloat32 ffxDofLoadFocusDistance() { return uintBitsToFloat(ffxDofGlobalWords[FFX_DOF_GLOBALS_FOCUS_DISTANCE]); }
FfxFloat32x2 ffxDofLoadFocusCocLine()
{
    return FfxFloat32x2(uintBitsToFloat(ffxDofGlobalWords[FFX_DOF_GLOBALS_FOCUS_COC_SCALE]),
                        uintBitsToFloat(ffxDofGlobalWords[FFX_DOF_GLOBALS_FOCUS_COC_BIAS]));
}
void ffxDofStoreFocus(FfxFloat32 distance, FfxFloat32 cocScale, FfxFloat32 cocBias)
{
    ffxDofGlobalWords[FFX_DOF_GLOBALS_FOCUS_DISTANCE] = floatBitsToUint(distance);
    ffxDofGlobalWords[FFX_DOF_GLOBALS_FOCUS_COC_SCALE] = floatBitsToUint(cocScale);
    ffxDofGlobalWords[FFX_DOF_GLOBALS_FOCUS_COC_BIAS] = floatBitsToUint(cocBias);
}
#endif

#if FFX_DOF_USES_RW_TILE_LIST_ARGS
FFX_DOF_BINDING_UAV_BUFFER(FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS) buffer FfxDofTileListArgs
{
    uint ffxDofTileListArgWords[FFX_DOF_TILE_LIST_ARGS_ENTRIES * FFX_DOF_TILE_LIST_ARGS_WORDS];
};
// The dispatch arguments of tile list `list` (FFX_DOF_TILE_LIST_ARGS_WORDS words apart).
void ffxDofStoreTileListArgs(FfxUInt32 list, FfxUInt32x3 groupCounts)
{
    ffxDofTileListArgWords[list * FFX_DOF_TILE_LIST_ARGS_WORDS + 0u] = groupCounts.x;
    ffxDofTileListArgWords[list * FFX_DOF_TILE_LIST_ARGS_WORDS + 1u] = groupCounts.y;
    ffxDofTileListArgWords[list * FFX_DOF_TILE_LIST_ARGS_WORDS + 2u] = groupCounts.z;
}
// Pass 2's second run over every tile (its arguments are (0, 1, 1) until then).
void ffxDofArmColorRangeRerun(FfxUInt32x2 tileCount)
{
    atomicMax(ffxDofTileListArgWords[FFX_DOF_COLOR_RANGE_RERUN_ARGS * FFX_DOF_TILE_LIST_ARGS_WORDS + 0u], tileCount.x);
    atomicMax(ffxDofTileListArgWords[FFX_DOF_COLOR_RANGE_RERUN_ARGS * FFX_DOF_TILE_LIST_ARGS_WORDS + 1u], tileCount.y);
}
#endif

#if FFX_DOF_USES_RW_TILE_LISTS || FFX_DOF_USES_TILE_LISTS
FFX_DOF_BINDING_UAV_BUFFER(FFX_DOF_UAV_BUFFER_TILE_LISTS) buffer FfxDofTileLists { uint ffxDofTileListWords[]; };
#endif
#if FFX_DOF_USES_RW_TILE_LISTS
// The next entry of tile list `list`: its count so far, counted up (ffxDofTileListWord places it).
FfxUInt32 ffxDofCountIntoTileList(FfxUInt32 list)
{
    return atomicAdd(ffxDofTileListArgWords[list * FFX_DOF_TILE_LIST_ARGS_WORDS], 1u);
}
void ffxDofStoreTileListWord(FfxUInt32 word, FfxUInt32 packedTile) { ffxDofTileListWords[word] = packedTile; }
#endif
#if FFX_DOF_USES_TILE_LISTS
FfxUInt32 ffxDofLoadTileListWord(FfxUInt32 word) { return ffxDofTileListWords[word]; }
#endif

#if FFX_DOF_USES_RW_HIGHLIGHTS || FFX_DOF_USES_HIGHLIGHTS
FFX_DOF_BINDING_UAV_BUFFER(FFX_DOF_UAV_BUFFER_HIGHLIGHTS) buffer FfxDofHighlights { uint ffxDofHighlightWords[]; };
#endif
#if FFX_DOF_USES_RW_HIGHLIGHTS
void ffxDofStoreHighlightWord(FfxUInt32 word, FfxUInt32 value) { ffxDofHighlightWords[word] = value; }
#endif
#if FFX_DOF_USES_HIGHLIGHTS
FfxUInt32 ffxDofLoadHighlightWord(FfxUInt32 word) { return ffxDofHighlightWords[word]; }
#endif

#endif  // FFX_DOF_CALLBACKS_GLSL_H
