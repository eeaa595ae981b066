// Which work a tile needs in the blur (FFX_DOF_BLUR_CLASS_*) and in the composite
// (FFX_DOF_COMPOSITE_CLASS_*): dilate decides both for every tile and lists the tile under each class
// (TILE_LISTS), and each of the two passes runs one pipeline per class over its list. One decision per
// pass, made in one place, so dilate and the pass cannot disagree.
#ifndef FFX_DOF_TILE_CLASSES_H
#define FFX_DOF_TILE_CLASSES_H

#include "ffx_dof_common.h"

#if defined(FFX_CPU)
FfxUInt32 ffxDofLoadTileListWord(FfxUInt32 word);
#endif

// ---- Blur classes -------------------------------------------------------------------------------

// A blur tile whose kernels read only radii within this of each other (half-res px) takes the
// equal-weight path, where every sample weighs what the texel's own radius gives. Small: bright
// highlights a fraction of a pixel nearer than their background must keep their own radius
// (0.5 cost the far-highlights scene 0.29 dB, 0.1 nothing; docs/technique.md).
#define FFX_DOF_EQUAL_WEIGHT_SPREAD 0.1f

// The blur's class of a tile from its DILATED_TILES texel (far, near, footprint min, footprint max).
// Per tile, never per texel, so that a workgroup runs one path; every path gives what the mixed path
// would give on that tile (the equal-weight paths up to radii within the spread), so the choice never
// shows as a tile border. An equal-weight tile is all near or all far: every texel's radius lies within
// the footprint (it reads its own tile), so the class tells the texels' side.
FFX_DOF_INLINE FfxUInt32 ffxDofBlurTileClass(FfxFloat32x4 dilated)
{
    if (ffxDofTileKernelRadius(FfxFloat32x2(dilated.x, dilated.y)) < FFX_DOF_IN_FOCUS_RADIUS)
        return FfxUInt32(FFX_DOF_BLUR_CLASS_COPY);
    FfxBoolean allNear = dilated.z >= FFX_DOF_NEAR_THRESHOLD;
    FfxBoolean allFar = dilated.w < FFX_DOF_NEAR_THRESHOLD;
    if (dilated.w - dilated.z <= FFX_DOF_EQUAL_WEIGHT_SPREAD)
    {
        if (allFar)
            return FfxUInt32(FFX_DOF_BLUR_CLASS_EQUAL_FAR);
        if (allNear)
            return FfxUInt32(FFX_DOF_BLUR_CLASS_EQUAL_NEAR);
    }
    if (dilated.y < FFX_DOF_NEAR_THRESHOLD)
        return FfxUInt32(FFX_DOF_BLUR_CLASS_FAR_ONLY);
    if (allNear)
        return FfxUInt32(FFX_DOF_BLUR_CLASS_NEAR_ONLY);
    return FfxUInt32(FFX_DOF_BLUR_CLASS_MIXED);
}

// ---- Composite classes --------------------------------------------------------------------------

// Whether a tile of (min, max) signed radii (TILES) holds pixels whose own surface is gathered at full
// resolution: |radius| from FFX_DOF_OWN_SURFACE_MIN_RADIUS to FFX_DOF_FAR_LAYER_ONLY_RADIUS, near or far.
FFX_DOF_INLINE FfxBoolean ffxDofTileGathersOwnSurface(FfxFloat32x2 tile)
{
    FfxBoolean far = tile.x <= -FFX_DOF_OWN_SURFACE_MIN_RADIUS && tile.y > -FFX_DOF_FAR_LAYER_ONLY_RADIUS;
    FfxBoolean near = tile.y >= FFX_DOF_OWN_SURFACE_MIN_RADIUS && tile.x < FFX_DOF_FAR_LAYER_ONLY_RADIUS;
    return far || near;
}

// Whether every pixel of a tile of (min, max) signed radii `tile` keeps its input: all in focus, and no
// near-field blur reaches the tile (`dilatedNear`, DILATED_TILES' y).
FFX_DOF_INLINE FfxBoolean ffxDofTileKeepsInput(FfxFloat32x2 tile, FfxFloat32 dilatedNear)
{
    return max(abs(tile.x), abs(tile.y)) < FFX_DOF_IN_FOCUS_RADIUS && dilatedNear < FFX_DOF_NEAR_THRESHOLD;
}

// The composite's class of a tile: `drawsLights` whether it draws small sources (FFX_DOF_LISTED_TILE_SMALL_SOURCES) or
// highlights (ffx_dof_highlights.h) at full resolution. A tile that gathers its own surface and draws no light takes
// FULL_RES, whose pipeline has none of the lights' code: on lavapipe every workgroup pays for all of its pipeline's
// code, taken or not (docs/performance.md, "Own surface without the lights"). Such a tile has no neighbour that gave
// light either (whose share of its pixels the own-surface gather would leave out): a tile gives light only at radii
// from FFX_DOF_HIGHLIGHT_MIN_RADIUS, and with FFX_DOF_DILATE_MARGIN its discs reach every tile of the 3 x 3 around it,
// which dilate therefore finds drawing them.
FFX_DOF_INLINE FfxUInt32 ffxDofCompositeTileClass(FfxFloat32x2 tile, FfxFloat32 dilatedNear, FfxBoolean drawsLights)
{
    if (ffxDofTileKeepsInput(tile, dilatedNear))
        return FfxUInt32(FFX_DOF_COMPOSITE_CLASS_COPY);
    if (drawsLights)
        return FfxUInt32(FFX_DOF_COMPOSITE_CLASS_LIGHTS);
    if (ffxDofTileGathersOwnSurface(tile))
        return FfxUInt32(FFX_DOF_COMPOSITE_CLASS_FULL_RES);
    return FfxUInt32(FFX_DOF_COMPOSITE_CLASS_LAYERS);
}

// ---- The lists ----------------------------------------------------------------------------------

// A tile as one word of TILE_LISTS, and back: x in bits 0 to 15, y in bits 16 to 29 (below
// FFX_DOF_LISTED_TILE_Y_LIMIT; the SDK checks that the largest image's tiles fit) and in bits 30 and 31 what dilate
// tells the pass of the tiles around it beyond their DILATED_TILES texel (FFX_DOF_LISTED_TILE_*), decided once per tile
// instead of once per invocation.
#define FFX_DOF_LISTED_TILE_FLAGS_SHIFT 30u
// The flags, in both passes' entries. The tile or one of the 8 around may hold bright small far sources, which the
// composite draws at full resolution (ffxDofTileMayHoldBrightSmallSources) and the blur leaves out of its layers.
#define FFX_DOF_LISTED_TILE_SMALL_SOURCES 1u
// ... or gave light to the highlights (ffxDofLoadGivenHighlightFloors): the far kernels keep the finer MIP
// (ffxDofKernelTakesCoarserMip).
#define FFX_DOF_LISTED_TILE_LIGHTS 2u
FFX_DOF_INLINE FfxUInt32 ffxDofPackListedTile(FfxUInt32x2 tile, FfxUInt32 flags)
{
    return tile.x | (tile.y << 16u) | (flags << FFX_DOF_LISTED_TILE_FLAGS_SHIFT);
}
FFX_DOF_INLINE FfxUInt32x2 ffxDofUnpackListedTile(FfxUInt32 word)
{
    return FfxUInt32x2(word & 0xffffu, (word >> 16u) & FfxUInt32(FFX_DOF_LISTED_TILE_Y_LIMIT - 1));
}
FFX_DOF_INLINE FfxUInt32 ffxDofListedTileFlags(FfxUInt32 word) { return word >> FFX_DOF_LISTED_TILE_FLAGS_SHIFT; }

// The word of TILE_LISTS that holds entry `index` of list `list`, for `tilesPerList` tiles. Lists share
// arrays of one word per tile in pairs, list 2a from the front of array a and list 2a + 1 from its back:
// both lists of a pair belong to one pass, which lists each tile once, so together they never hold more
// than the array has room for. Each pass's first list is even (FFX_DOF_*_TILE_LIST_FIRST), so no pair
// mixes two passes.
FFX_DOF_INLINE FfxUInt32 ffxDofTileListWord(FfxUInt32 list, FfxUInt32 index, FfxUInt32 tilesPerList)
{
    FfxUInt32 arrayStart = (list >> 1u) * tilesPerList;
    return (list & 1u) == 0u ? arrayStart + index : arrayStart + tilesPerList - 1u - index;
}

// The entry (ffxDofPackListedTile) a workgroup of an indirect dispatch over `list` works on (`listIndex`: its
// workgroup index). Only where the pass reads the lists: a GLSL or HLSL function may not call an accessor its pass
// lacks.
#if defined(FFX_CPU) || FFX_DOF_USES_TILE_LISTS
FFX_DOF_INLINE FfxUInt32 ffxDofListedTileWord(FfxUInt32 list, FfxUInt32 listIndex, FfxUInt32 tilesPerList)
{
    return ffxDofLoadTileListWord(ffxDofTileListWord(list, listIndex, tilesPerList));
}
#endif

#endif  // FFX_DOF_TILE_CLASSES_H
