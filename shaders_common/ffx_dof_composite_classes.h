// Which work a tile of the composite needs (FFX_DOF_COMPOSITE_CLASS_*): dilate decides it for every tile
// and lists the tile under its class (TILE_LISTS), the composite runs one pipeline per class over its
// list (ffx_dof_composite.h). One decision, so the two passes cannot disagree.
#ifndef FFX_DOF_COMPOSITE_CLASSES_H
#define FFX_DOF_COMPOSITE_CLASSES_H

#include "ffx_dof_common.h"

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

// The composite's class of a tile: `drawsSmallSources` is ffxDofSurveyTilesAround's for the tile.
FFX_DOF_INLINE FfxUInt32 ffxDofCompositeTileClass(FfxFloat32x2 tile, FfxFloat32 dilatedNear,
                                                  FfxBoolean drawsSmallSources)
{
    if (ffxDofTileKeepsInput(tile, dilatedNear))
        return FfxUInt32(FFX_DOF_COMPOSITE_CLASS_COPY);
    if (ffxDofTileGathersOwnSurface(tile) || drawsSmallSources)
        return FfxUInt32(FFX_DOF_COMPOSITE_CLASS_FULL_RES);
    return FfxUInt32(FFX_DOF_COMPOSITE_CLASS_LAYERS);
}

// A tile as one word of TILE_LISTS, and back (tile coordinates stay below 65536).
FFX_DOF_INLINE FfxUInt32 ffxDofPackListedTile(FfxUInt32x2 tile) { return tile.x | (tile.y << 16u); }
FFX_DOF_INLINE FfxUInt32x2 ffxDofUnpackListedTile(FfxUInt32 word) { return FfxUInt32x2(word & 0xffffu, word >> 16u); }

#endif  // FFX_DOF_COMPOSITE_CLASSES_H
