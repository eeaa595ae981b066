// Pass 3 of 5: tile dilation by scatter-as-gather.
//
// One invocation per tile. Every tile within the global maximum radius (plus the margin of
// ffxDofTileReaches) is examined; a tile contributes its near (max) or far (min) end when that end's
// radius can reach the nearest pixel of the central tile. The distance is measured from the
// central tile's rectangle, not its centre, so nothing is ever under-dilated.
// It also lists the tile for the blur and for the composite under its class in each (ffxDofBlurTileClass,
// ffxDofCompositeTileClass; TILE_LISTS).
// Output (DILATED_TILES): x = most negative (far) radius, y = most positive (near) radius among the
// tile itself and every tile that reaches it; z, w = smallest and largest signed radius of every tile
// the blur's kernels of this tile can read (ffxDofKernelFootprintRadius): the blur's tile
// classification (ffxDofBlurTileClass) needs them, since a tile that does not reach this one still has
// its samples read (with zero reach) and so decides whether all sample weights can be equal.
#ifndef FFX_DOF_DILATE_H
#define FFX_DOF_DILATE_H

#include "ffx_dof_common.h"
#include "ffx_dof_tile_classes.h"
#include "ffx_dof_small_sources.h"
#include "ffx_dof_highlights.h"

#if defined(FFX_CPU)
FfxDofConstants ffxDofGetConstants();
FfxFloat32 ffxDofLoadGlobalMaxRadius();
FfxFloat32x2 ffxDofLoadTile(FfxUInt32x2 tile);
void ffxDofStoreDilatedTile(FfxUInt32x2 tile, FfxFloat32x4 farNearFootprint);
void ffxDofResetColorPeak();
FfxUInt32 ffxDofCountIntoTileList(FfxUInt32 list);
void ffxDofStoreTileListWord(FfxUInt32 word, FfxUInt32 packedTile);
#endif

// ---- Tile reach -------------------------------------------------------------------------------------

// Extra half-res px a tile's radius is granted during dilation: soft sample reach (0.5), the
// sub-pixel kernel jitter (< 0.36) and the composite's 3x3 filter plus bilinear footprint (2).
#define FFX_DOF_DILATE_MARGIN 3.0f

// Shortest distance, in half-res px, between a pixel centre of the central tile and a pixel centre
// of the tile `tileOffset` tiles away.
FFX_DOF_INLINE FfxFloat32 ffxDofTileGapDistance(FfxInt32x2 tileOffset)
{
    FfxFloat32 tileSize = FfxFloat32(FFX_DOF_TILE_SIZE);
    FfxFloat32 gapX = max(FfxFloat32(abs(tileOffset.x)) * tileSize - (tileSize - 1.0f), 0.0f);
    FfxFloat32 gapY = max(FfxFloat32(abs(tileOffset.y)) * tileSize - (tileSize - 1.0f), 0.0f);
    return sqrt(gapX * gapX + gapY * gapY);
}

// Whether a tile whose largest spreading radius is `radius` can affect any pixel `distance` away
// (ffxDofTileGapDistance), including everything the later passes derive from that pixel.
FFX_DOF_INLINE FfxBoolean ffxDofTileReaches(FfxFloat32 radius, FfxFloat32 distance)
{
    return radius > 0.0f && radius + FFX_DOF_DILATE_MARGIN > distance;
}

// Number of tiles to look at on each side of the central tile during dilation.
FFX_DOF_INLINE FfxInt32 ffxDofDilateTileRange(FfxFloat32 globalMaxRadius)
{
    return FfxInt32(ceil((globalMaxRadius + FFX_DOF_DILATE_MARGIN) / FfxFloat32(FFX_DOF_TILE_SIZE)));
}

// Distance (half-res px, from texel centre to texel centre) within which the blur kernels of a tile
// whose largest kernel radius is `kernelRadius` can read a texel or a MIP texel covering it: the
// radius, the sub-pixel origin (FFX_DOF_DILATE_MARGIN covers it), and 3.5 ring spacings for the
// MIP texels read. The outermost ring reads texel centres up to half a spacing and
// FFX_DOF_LIGHT_OFFSET_REACH (0.75) texels beyond the radius, and each texel reaches half its diagonal
// (0.71 texels) farther: with ffxDofCoarserMipForSpacing's texels, up to 2 spacings wide, 0.5 + 1.46 x 2
// = 3.42 spacings (a merged ring's texels, up to 4 spacings wide, end inside that).
#define FFX_DOF_FOOTPRINT_SPACINGS 3.5f
FFX_DOF_INLINE FfxFloat32 ffxDofKernelFootprintRadius(FfxFloat32 kernelRadius, FfxUInt32 maxRings)
{
    FfxFloat32 rings = FfxFloat32(clamp(maxRings, 1u, FfxUInt32(FFX_DOF_OPTION_MAX_RINGS)));
    return kernelRadius + FFX_DOF_DILATE_MARGIN + FFX_DOF_FOOTPRINT_SPACINGS * max(kernelRadius / rings, 1.0f);
}

// The dilated (far, near) range of `centerTile` given the radius every tile spreads.
// `extent` (ffxDofApertureExtent): how far a disc reaches over its radius. `reachedByHighlights`: whether the
// near or far discs of a tile whose pixels gave light to the highlights (ffxDofLoadGivenHighlightFloors) reach it.
FFX_DOF_INLINE FfxFloat32x2 ffxDofDilateTile(FfxUInt32x2 centerTile, FfxUInt32x2 tileCount, FfxFloat32 globalMaxRadius,
                                             FfxFloat32 extent, FFX_DOF_OUT(FfxBoolean) reachedByHighlights)
{
    reachedByHighlights = false;
    FfxFloat32x2 own = ffxDofLoadTile(centerTile);
    FfxFloat32 farCoc = own.x;
    FfxFloat32 nearCoc = own.y;
    FfxInt32x2 center = FfxInt32x2(centerTile);
    FfxInt32x2 first;
    FfxInt32x2 last;
    ffxDofTileWindow(center, ffxDofDilateTileRange(globalMaxRadius * extent), tileCount, first, last);
    FFX_DOF_LOOP
    for (FfxInt32 y = first.y; y <= last.y; ++y)
    {
        FFX_DOF_LOOP
        for (FfxInt32 x = first.x; x <= last.x; ++x)
        {
            FfxFloat32x3 tile = ffxDofTileRangeAndPeak(FfxUInt32x2(FfxUInt32(x), FfxUInt32(y)), tileCount);
            FfxFloat32 distance = ffxDofTileGapDistance(FfxInt32x2(x, y) - center);
            FfxBoolean farReaches = ffxDofTileReaches(-tile.x * extent, distance);
            FfxBoolean nearReaches = ffxDofTileReaches(tile.y * extent, distance);
            if (farReaches)
                farCoc = min(farCoc, tile.x);
            if (nearReaches)
                nearCoc = max(nearCoc, tile.y);
            if ((farReaches || nearReaches) && !reachedByHighlights)
                reachedByHighlights = ffxDofHighlightFloorsGaveLight(
                    ffxDofLoadGivenHighlightFloors(FfxUInt32x2(FfxUInt32(x), FfxUInt32(y)), tile, tileCount));
        }
    }
    return FfxFloat32x2(farCoc, nearCoc);
}

// The (smallest, largest) signed radius among the tiles within `footprintRadius` of `centerTile`.
FFX_DOF_INLINE FfxFloat32x2 ffxDofFootprintRange(FfxUInt32x2 centerTile, FfxUInt32x2 tileCount,
                                                 FfxFloat32 footprintRadius)
{
    FfxFloat32x2 range = ffxDofLoadTile(centerTile);
    FfxInt32x2 center = FfxInt32x2(centerTile);
    FfxInt32x2 first;
    FfxInt32x2 last;
    ffxDofTileWindow(center, FfxInt32(ceil(footprintRadius / FfxFloat32(FFX_DOF_TILE_SIZE))), tileCount, first, last);
    FFX_DOF_LOOP
    for (FfxInt32 y = first.y; y <= last.y; ++y)
    {
        FFX_DOF_LOOP
        for (FfxInt32 x = first.x; x <= last.x; ++x)
        {
            if (ffxDofTileGapDistance(FfxInt32x2(x, y) - center) > footprintRadius)
                continue;
            FfxFloat32x2 tile = ffxDofLoadTile(FfxUInt32x2(FfxUInt32(x), FfxUInt32(y)));
            range = FfxFloat32x2(min(range.x, tile.x), max(range.y, tile.y));
        }
    }
    return range;
}

// The block of FFX_DOF_DILATE_GROUP_EXTENT x FFX_DOF_DILATE_GROUP_EXTENT tiles that workgroup `groupId` dilates:
// the blocks in transposed order (block row and column of the workgroup index swapped), a bijection.
// The lists come out in the order dilate appends to them, and lavapipe runs each dispatch of the blur and
// the composite as one contiguous range of workgroups per thread: lists in image order gave each thread
// one region of the image, and the threads of a class whose costly tiles lie together waited for the
// slowest (the blur per class took 1.14 times as long as one blur of every class, though it did 0.87
// times the work; docs/performance.md, "The blur per tile class"). Each block keeps its tiles together.
FFX_DOF_INLINE FfxUInt32x2 ffxDofDilateBlock(FfxUInt32x2 groupId, FfxUInt32x2 tileCount)
{
    FfxUInt32 extent = FfxUInt32(FFX_DOF_DILATE_GROUP_EXTENT);
    FfxUInt32x2 blocks = (tileCount + FfxUInt32x2(extent - 1u, extent - 1u)) / extent;
    FfxUInt32 transposed = groupId.x * blocks.y + groupId.y;
    return FfxUInt32x2(transposed % blocks.x, transposed / blocks.x);
}

// What the blur and the composite need to know of the 3 x 3 tiles around `tile` (FFX_DOF_LISTED_TILE_*: a source or a
// highlight's light reaches at most 2 FFX_DOF_FAR_LAYER_ONLY_RADIUS + 0.5 full-res px beyond its pixel, less than a
// tile).
FFX_DOF_INLINE FfxUInt32 ffxDofSurveyTilesAround(FfxUInt32x2 tile, FfxUInt32x2 tileCount)
{
    FfxUInt32 flags = 0u;
    FFX_DOF_UNROLL
    for (FfxUInt32 k = 0u; k < 9u; ++k)
    {
        FfxUInt32x2 around = ffxDofTileAround(tile, k, tileCount);
        FfxFloat32x3 rangeAndPeak = ffxDofTileRangeAndPeak(around, tileCount);
        if (ffxDofTileMayHoldBrightSmallSources(rangeAndPeak))
            flags |= FfxUInt32(FFX_DOF_LISTED_TILE_SMALL_SOURCES);
        if (ffxDofHighlightFloorsGaveLight(ffxDofLoadGivenHighlightFloors(around, rangeAndPeak, tileCount)))
            flags |= FfxUInt32(FFX_DOF_LISTED_TILE_LIGHTS);
    }
    return flags;
}

// Lists `packedTile` under `list`: the next entry of the list (its count in TILE_LIST_ARGS).
FFX_DOF_INLINE void ffxDofListTile(FfxUInt32 list, FfxUInt32 packedTile, FfxUInt32 tilesPerList)
{
    ffxDofStoreTileListWord(ffxDofTileListWord(list, ffxDofCountIntoTileList(list), tilesPerList), packedTile);
}

FFX_DOF_INLINE void ffxDofDilate(FfxUInt32x2 groupId, FfxUInt32 localIndex)
{
    FfxDofConstants constants = ffxDofGetConstants();
    // Pass 2 has read the colour peak; the next frame's pass 1 needs it at 0.
    if (groupId.x == 0u && groupId.y == 0u && localIndex == 0u)
        ffxDofResetColorPeak();
    FfxUInt32x2 tile = ffxDofDilateBlock(groupId, constants.tileCount) * FfxUInt32(FFX_DOF_DILATE_GROUP_EXTENT) +
                       ffxDofLocalCoord(localIndex);
    if (tile.x >= constants.tileCount.x || tile.y >= constants.tileCount.y)
        return;
    // A shaped disc reaches at most its extent times its radius in any direction: the dilation and the
    // footprint take that, a circle of the shape's largest extent.
    FfxFloat32 extent = ffxDofApertureExtent(constants);
    FfxBoolean reachedByHighlights;
    FfxFloat32x2 farNear =
        ffxDofDilateTile(tile, constants.tileCount, ffxDofLoadGlobalMaxRadius(), extent, reachedByHighlights);
    FfxFloat32 footprint = ffxDofKernelFootprintRadius(ffxDofTileKernelRadius(farNear) * extent, constants.maxRings);
    FfxFloat32x4 dilated = FfxFloat32x4(farNear, ffxDofFootprintRange(tile, constants.tileCount, footprint));
    ffxDofStoreDilatedTile(tile, dilated);
    FfxUInt32 tilesPerList = constants.tileCount.x * constants.tileCount.y;
    FfxUInt32 around = ffxDofSurveyTilesAround(tile, constants.tileCount);
    ffxDofListTile(FfxUInt32(FFX_DOF_BLUR_TILE_LIST_FIRST) + ffxDofBlurTileClass(dilated),
                   ffxDofPackListedTile(tile, around), tilesPerList);
    FfxBoolean drawsSmallSources = (around & FfxUInt32(FFX_DOF_LISTED_TILE_SMALL_SOURCES)) != 0u;
    FfxUInt32 compositeClass =
        ffxDofCompositeTileClass(ffxDofLoadTile(tile), farNear.y, drawsSmallSources || reachedByHighlights);
    ffxDofListTile(FfxUInt32(FFX_DOF_COMPOSITE_TILE_LIST_FIRST) + compositeClass, ffxDofPackListedTile(tile, around),
                   tilesPerList);
}

#endif  // FFX_DOF_DILATE_H
