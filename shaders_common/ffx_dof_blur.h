// Pass 4 of 5: the blur at half resolution, near and far field in one gather.
//
// One workgroup covers one tile (8 x 8 half-res px), one invocation per texel. Per texel:
//   kernel radius R = max(dilated near radius of the tile, |own radius|); rings from R and the
//   quality (ffxDofRingCount) -- per texel, so the ring count never changes at a tile border;
//   a random sub-pixel kernel origin; rings gathered from the outside in, ring k being every texel of
//   the MIP read whose centre lies (k -+ 1/2) ring spacings from the origin, each read once (a
//   one-texel source is read once by every texel whose kernel covers it: a flat bokeh disc).
//   Near field (radius >= FFX_DOF_NEAR_THRESHOLD): scatter-as-gather, each sample weighted by reach
//   and inverse area; opacity from the summed area weights (ffxDofNearOpacity).
//   Far field (everything else): three layers, what lies nearer than the texel's own surface, the
//   surface itself (front) and what lies behind it (back), each composed over the ones behind by its
//   coverage (ffxDofFarNearerShare, ffxDofComposeFarLayers). A sample only counts within its own
//   radius, so in-focus and foreground color never spreads into the far field beyond it. Where the layers
//   in front leave most of the disc open, what lies behind is also read beyond the kernel, as far as
//   the far radii that reach the tile (ffxDofGatherBehind).
//   Hole filling: when the texel itself is near, every far-field sample, whatever its reach, is
//   also summed as the fill, its color weighted by proximity (ffxDofFillProximity), and added to
//   the far color at the end with the weight that as many samples of the texel's own radius would
//   have: the hidden background is extrapolated from around the object, mostly from nearby.
// Tile classes (ffxDofBlurTileClass, ffx_dof_tile_classes.h: dilate decides them from the dilated range
// and kernel footprint and lists each tile under its class), each a path that leaves out what cannot
// matter on that tile and gives what the mixed path would give:
//   copy         every kernel is in focus (R < 0.5): the texel is the far layer;
//   equal far,   every radius the kernels read is within FFX_DOF_EQUAL_WEIGHT_SPREAD of the others,
//   equal near   all far or all near: no CoC is read, each sample weighs what the texel's own radius
//                gives at its distance, and a far texel's inner rings are merged fully;
//   far-only     no near radius reaches the tile: no near sums, no hole fill (a near sample from a
//                tile that does not reach has zero reach, so counting it as far changes nothing);
//   near-only    every radius read is near-field: no far buckets, no hole fill (no background sample);
//   mixed        everything.
// Each class is a pipeline of its own (FFX_DOF_OPTION_BLUR_CLASS), dispatched indirectly over its tile
// list. One pipeline holding every path, chosen per workgroup, cost lavapipe the paths not taken as
// well (it runs every `if` under lane masks and every loop once) and the register pressure of the
// whole: on one lavapipe thread the blur did about 1.15 times the work (docs/performance.md, "The blur per
// tile class").
// Ring merging (unless FFX_DOF_OPTION_DISABLE_RING_MERGE) is decided per texel, not per tile: the
// outermost ring is gathered at full resolution first; where its radii are all within half a pixel
// of the texel's own (a flat far field), inner rings are gathered from a coarser MIP, 2^log rings at
// a time; between half a pixel and one pixel the groups of rings are merged one after the other as
// the spread falls, the one part-way mixed ring by ring (ffxDofRingMergeAmount,
// ffxDofGatherInnerRings), so the result is continuous and costs at most one ring more than the
// full path. Walks at two MIPs judge their common border by the coarse texels (FfxDofAnnulus).
// Samples are point-sampled (no bilinear mixing of a foreground and a background texel, which
// would let the foreground color leak with a halfway radius).
//
// Outputs: NEAR_COLOR, FAR_COLOR, LAYER_ALPHA (x: near opacity, y: far validity).
#ifndef FFX_DOF_BLUR_H
#define FFX_DOF_BLUR_H

#include "ffx_dof_common.h"
#include "ffx_dof_small_sources.h"
#include "ffx_dof_tile_classes.h"

#if defined(FFX_CPU)
FfxDofConstants ffxDofGetConstants();
FfxFloat32x4 ffxDofLoadDilatedTile(FfxUInt32x2 tile);
FfxDofFloat3 ffxDofLoadHalfColor(FfxInt32x2 texel);
FfxFloat32 ffxDofLoadHalfCoc(FfxInt32x2 texel);
FfxUInt32x2 ffxDofLoadCoarseMip(FfxInt32x2 texel, FfxUInt32 mip);
void ffxDofStoreNearColor(FfxUInt32x2 texel, FfxDofFloat3 color);
void ffxDofStoreFarColor(FfxUInt32x2 texel, FfxDofFloat3 color);
void ffxDofStoreLayerAlpha(FfxUInt32x2 texel, FfxFloat32x2 nearOpacityFarValidity);
void ffxDofResetGlobals();
#endif

// ---- Tuning constants -------------------------------------------------------------------------------

// Amplitude of the random kernel origin: +-half of this, in half-res px.
#define FFX_DOF_JITTER_AMPLITUDE 0.5f
// Ring merging: where every radius on a texel's outermost ring is within FLAT of its own radius
// (half-res px), inner rings are merged; from NOT_FLAT on they are not; in between both are mixed.
#define FFX_DOF_RING_MERGE_FLAT_SPREAD 0.5f
#define FFX_DOF_RING_MERGE_NOT_FLAT_SPREAD 1.0f
// How far the outermost ring's inner border moves in where merged rings meet it, in texels of the
// kernel's MIP (ffxDofWalkBorderRadius). A whole texel since merged samples are drawn from their light
// offsets (docs/technique.md, "Light offsets"): with half a texel a small far light lost up to 1.1% of
// its energy, and a point's rim at radius 12 lay 0.60 px off the circle instead of 0.33.
#define FFX_DOF_RING_MERGE_RIM_INSET 1.0f
// ---- Kernel walk: every texel of a ring read once -----------------------------------------------
//
// Ring k of a kernel whose rings are s apart holds the texels whose centres lie at [(k - 1/2) s,
// (k + 1/2) s) from the kernel origin (ring 0: [0, s / 2)), and the blur reads each of them once,
// walking rows. (Points on a circle read from the nearest texel hit a one-texel source 0, 1 or 2
// times depending on the output texel: a dotted disc, issue 6.)

// The texels (first, last) of a row or column whose centres lie less than `halfWidth` from `center`;
// in texels, texel i spanning [i, i + 1). first > last when there are none. Strict on both sides,
// so two rings that share a border share no texel and miss none.
FFX_DOF_INLINE FfxFloat32x2 ffxDofTexelSpan(FfxFloat32 center, FfxFloat32 halfWidth)
{
    return FfxFloat32x2(floor(center - 0.5f - halfWidth) + 1.0f, ceil(center - 0.5f + halfWidth) - 1.0f);
}

// Inner radius of ring `ring` for rings `spacing` apart; the outer radius of ring k is the inner
// radius of ring k + 1, the same expression, so that the rings tile the kernel exactly.
FFX_DOF_INLINE FfxFloat32 ffxDofRingInnerRadius(FfxUInt32 ring, FfxFloat32 spacing)
{
    return max(FfxFloat32(ring) - 0.5f, 0.0f) * spacing;
}

// How far beyond the outermost ring's outer radius a walk at MIP 1 or coarser reads, in its texels: a
// texel's light lies up to sqrt(1/2) of a texel from its centre (its light offset), so a texel whose light
// the kernel's reach takes may have its centre that much farther out. Without it a point's disc read from
// the coarser MIP was notched at its rim (1.06 px off the circle at radius 27 px, 1.78 at 54, where every
// far kernel read it); at radius 40, read from MIP 1 before as well, 0.20 px instead of 0.51
// (docs/quality.md, point discs).
#define FFX_DOF_LIGHT_OFFSET_REACH 0.75f

// The outer radius of a kernel of `rings` rings `spacing` apart as its walks at MIP `mip` see it (in its
// texels): the outermost ring's outer border and the inner border of the walk beyond the kernel
// (ffxDofGatherBehind), so that the two share no texel and miss none.
FFX_DOF_INLINE FfxFloat32 ffxDofKernelOuterRadius(FfxUInt32 rings, FfxFloat32 spacing, FfxUInt32 mip)
{
    return ffxDofRingInnerRadius(rings + 1u, spacing) + (mip > 0u ? FFX_DOF_LIGHT_OFFSET_REACH : 0.0f);
}

// Radius of the border at the inner edge of ring `ring` (rings `spacing` apart) as a walk sees it.
// The rim border -- the outermost ring's inner edge, `rimRing` -- moves inward by `rimInset` where it
// is judged by coarse texels (`coarseBorder`): inside it, merged rings read a light from the coarse
// texel that holds it, whose centre lies up to 1.41 of the kernel's texels from the light. Drawn about
// that centre, a light's disc bulged past its radius toward it (a point's rim up to 1.3 px off the
// circle, before the inset); drawn from its light offset, it is in place, and the rim's reach ramp is
// left to the outermost ring's own texels. Both walks sharing the border compute it from the same figures.
FFX_DOF_INLINE FfxFloat32 ffxDofWalkBorderRadius(FfxUInt32 ring, FfxFloat32 spacing, FfxUInt32 rimRing,
                                                 FfxBoolean coarseBorder, FfxFloat32 rimInset)
{
    FfxFloat32 radius = ffxDofRingInnerRadius(ring, spacing);
    return ring == rimRing && coarseBorder ? max(radius - rimInset, 0.0f) : radius;
}

// The texels whose centres lie at [innerRadius, outerRadius) from `origin` (all in texels of one
// MIP level), walked row by row: what does not change during the walk ...
// Each border may be judged at a coarser MIP than the walk's (a block of `innerBlock` / `outerBlock`
// texels per side, a power of two; 1: the walk's own texels): where a walk meets a walk of a coarser
// MIP, both judge their common border by the coarse texels' centres, so a texel of the finer level
// is read once, by one of them. Judged by each side's own centres, a one-texel source next to the
// border was read twice or not at all: a notched, soft rim and a dip at the centre of a single
// point's disc, and a small light losing or gaining energy (issue 17).
// One border of an annulus, judged in blocks of `block` texels: what a row's span needs, computed
// once per walk (the span of the next row is computed at every step of the walk).
struct FfxDofAnnulusBorder
{
    FfxFloat32 block;       // texels per block side (a power of two)
    FfxFloat32 scale;       // 1 / block
    FfxFloat32 radius;      // in blocks
    FfxFloat32 spanCenter;  // origin.x in blocks, less half a block (ffxDofTexelSpan's centre - 0.5)
    FfxFloat32 rowOffset;   // half a block less origin.y, in blocks
    FfxFloat32 widthScale;  // row width over height: the inverse anamorphic ratio
};
struct FfxDofAnnulus
{
    FfxFloat32x2 origin;
    FfxDofAnnulusBorder inner;
    FfxDofAnnulusBorder outer;
    FfxFloat32 firstRow;
    FfxFloat32 lastRow;
};
// ... and the walk's position.
struct FfxDofAnnulusWalk
{
    FfxFloat32x2 texel;    // the current position, a texel of the annulus while texel.x <= rowLast
    FfxFloat32 rowLast;    // last texel of the current row
    FfxFloat32 holeFirst;  // first texel of the row inside the inner radius
    FfxFloat32 holeEnd;    // first texel after them (holeFirst when the row has none)
};

// A border of `radius` around `origin` judged in blocks of `block` texels. The block figures are the
// ones the coarse walk computes for itself (scaling by a power of two is exact), so the two walks
// agree to the bit on every block.
FFX_DOF_INLINE FfxDofAnnulusBorder ffxDofMakeAnnulusBorder(FfxFloat32x2 origin, FfxFloat32 radius, FfxFloat32 block,
                                                           FfxFloat32 widthScale)
{
    FfxDofAnnulusBorder border;
    border.block = block;
    border.scale = 1.0f / block;
    border.radius = radius * border.scale;
    border.spanCenter = origin.x * border.scale - 0.5f;
    border.rowOffset = 0.5f - origin.y * border.scale;
    border.widthScale = widthScale;
    return border;
}

// The texels (first, last) of row `y` whose block has its centre less than the border's radius from
// the origin: ffxDofTexelSpan of the block row, widened to whole blocks (with block 1, the texels of
// the row whose centres are inside). first > last when there are none.
FFX_DOF_INLINE FfxFloat32x2 ffxDofBorderSpan(FfxDofAnnulusBorder border, FfxFloat32 y)
{
    FfxFloat32 dy = floor(y * border.scale) + border.rowOffset;
    FfxFloat32 halfWidth = ffxDofKernelRowHalfWidth(border.radius, dy, border.widthScale);
    FfxFloat32 first = floor(border.spanCenter - halfWidth) + 1.0f;
    FfxFloat32 last = ceil(border.spanCenter + halfWidth) - 1.0f;
    return FfxFloat32x2(first * border.block, last * border.block + border.block - 1.0f);
}

// Whether `texel` lies inside the border: a walk whose outer border it is read it, or a walk inside it.
FFX_DOF_INLINE FfxBoolean ffxDofBorderHolds(FfxDofAnnulusBorder border, FfxFloat32x2 texel)
{
    FfxFloat32x2 span = ffxDofBorderSpan(border, texel.y);
    return texel.x >= span.x && texel.x <= span.y;
}

FFX_DOF_INLINE FfxDofAnnulus ffxDofMakeAnnulus(FfxFloat32x2 origin, FfxFloat32 innerRadius, FfxFloat32 outerRadius,
                                               FfxFloat32 innerBlock, FfxFloat32 outerBlock, FfxFloat32 widthScale)
{
    FfxDofAnnulus annulus;
    annulus.origin = origin;
    annulus.inner = ffxDofMakeAnnulusBorder(origin, innerRadius, innerBlock, widthScale);
    annulus.outer = ffxDofMakeAnnulusBorder(origin, outerRadius, outerBlock, widthScale);
    FfxFloat32x2 rows = ffxDofTexelSpan(origin.y * annulus.outer.scale, outerRadius * annulus.outer.scale);
    annulus.firstRow = rows.x * outerBlock;
    annulus.lastRow = rows.y * outerBlock + outerBlock - 1.0f;
    return annulus;
}

// Row `y` of the annulus, positioned on its first texel (past its last one when it has none).
FFX_DOF_INLINE FfxDofAnnulusWalk ffxDofAnnulusRow(FfxDofAnnulus annulus, FfxFloat32 y)
{
    FfxFloat32x2 row = ffxDofBorderSpan(annulus.outer, y);
    FfxFloat32x2 hole = ffxDofBorderSpan(annulus.inner, y);
    FfxDofAnnulusWalk walk;
    walk.rowLast = row.y;
    walk.holeFirst = hole.x;
    // An empty hole (first > last, by 2 where the origin lies exactly on a texel centre) must not
    // send the walk backwards.
    walk.holeEnd = max(hole.y + 1.0f, hole.x);
    // Judged in blocks of different sizes, the hole may begin before the row does.
    walk.texel = FfxFloat32x2(row.x >= walk.holeFirst && row.x < walk.holeEnd ? walk.holeEnd : row.x, y);
    return walk;
}

FFX_DOF_INLINE FfxDofAnnulusWalk ffxDofAnnulusBegin(FfxDofAnnulus annulus)
{
    return ffxDofAnnulusRow(annulus, annulus.firstRow);
}

// Whether the walk has rows left. Its position may still be no texel: a row at the top or bottom,
// or a row of a thin annulus, can be empty, and a walk step finds one row, never loops over rows
// (ffxDofAnnulusValid says).
FFX_DOF_INLINE FfxBoolean ffxDofAnnulusRowsLeft(FfxDofAnnulus annulus, FfxDofAnnulusWalk walk)
{
    return walk.texel.y <= annulus.lastRow;
}
FFX_DOF_INLINE FfxBoolean ffxDofAnnulusValid(FfxDofAnnulusWalk walk) { return walk.texel.x <= walk.rowLast; }

// One step: the next texel of the row, else the first of the next row (never a loop over rows: an empty
// row is one step of weight 0). The next row's figures (two border spans, each with a square root) are
// computed only when the row ends: on lavapipe this measured the same as computing them at every step
// and selecting (blur 0.97 to 1.005 times as long at 1080p, four pairs; docs/performance.md), and a GPU
// skips them wherever a wave's lanes are all within their rows. The texels walked and their order are
// unchanged, so the output is bit for bit the same.
FFX_DOF_INLINE FfxDofAnnulusWalk ffxDofAnnulusNext(FfxDofAnnulus annulus, FfxDofAnnulusWalk walk)
{
    FfxFloat32 x = walk.texel.x + 1.0f;
    walk.texel.x = x == walk.holeFirst ? walk.holeEnd : x;
    if (walk.texel.x > walk.rowLast)
        walk = ffxDofAnnulusRow(annulus, walk.texel.y + 1.0f);
    return walk;
}

// ---- Kernel size --------------------------------------------------------------------------------

// Rings for a kernel of `radius`: none below the in-focus radius (the pixel is copied), else one per
// pixel of radius, at most the quality setting and FFX_DOF_OPTION_MAX_RINGS.
FFX_DOF_INLINE FfxUInt32 ffxDofRingCount(FfxFloat32 radius, FfxUInt32 maxRings)
{
    if (radius < FFX_DOF_IN_FOCUS_RADIUS)
        return 0u;
    FfxUInt32 limit = clamp(maxRings, 1u, FfxUInt32(FFX_DOF_OPTION_MAX_RINGS));
    return min(FfxUInt32(ceil(radius)), limit);
}

// MIP level to read when rings are `spacing` half-res px apart: the level whose texel size is nearest
// the spacing in log2, so the spacing is 0.71 to 1.41 texels (from 0.5 at level 0). The blur reads
// every texel of its kernel, pi ((rings + 1/2) s / texel)^2 of them, where 6k points per ring cost
// 3 rings^2: rounding the level keeps the two about equal (pi E[(s / texel)^2] = 3.4 for a
// log-uniform spacing); the finest level no larger than the spacing cost up to 4 times as much.
FFX_DOF_INLINE FfxFloat32 ffxDofMipForSpacing(FfxFloat32 spacing)
{
    return clamp(floor(log2(max(spacing, 1.0f)) + 0.5f), 0.0f, FfxFloat32(FFX_DOF_OPTION_MAX_MIP - 1));
}

// The coarser level a far texel's kernel reads where nothing bright lies around it
// (ffxDofKernelTakesCoarserMip): the finest whose texels are no smaller than the ring spacing, 0.5 to 1
// texel, so a kernel reads a quarter as many texels where ffxDofMipForSpacing would round down. On
// lavapipe the blur took 0.63 to 0.74 times as long at 1080p quality 10, the bench's floor reading MIP 1
// instead of MIP 0 (one fetch per sample instead of two) and MIP 2 for its merged rings; against the
// thin-lens truth no gated figure moved beyond 0.01 dB, and scenes rendered at 960x540 and 1920x1080
// changed by +0.03 to -0.23 dB (docs/performance.md, "Far kernels at the coarser MIP").
FFX_DOF_INLINE FfxFloat32 ffxDofCoarserMipForSpacing(FfxFloat32 spacing)
{
    return clamp(ceil(log2(max(spacing, 1.0f))), 0.0f, FfxFloat32(FFX_DOF_OPTION_MAX_MIP - 1));
}

// Whether a texel's kernel reads the coarser MIP (ffxDofCoarserMipForSpacing) rather than the nearest
// (ffxDofMipForSpacing): a far texel in a tile that no near-field radius reaches (`dilated`: its tile's
// DILATED_TILES texel; near objects, thin ones too, keep the finer texels: a 2 px bar at radius 24
// doubled its veil from the coarser ones), no light in the 3 x 3 tiles around it (`lightsAround`: bright small
// sources or highlights, FFX_DOF_LISTED_TILE_*), and everything the kernel reads, its walk beyond the kernel included,
// inside the image with a margin of a texel of the coarser MIP and one of its merged rings' MIP (the
// image continued by copies of its edge texels, and a MIP whose size was rounded down that misses the
// last rows, extrapolate coarser there: busy-background's bottom 16 rows lost 2.6 dB).
FFX_DOF_INLINE FfxBoolean ffxDofKernelTakesCoarserMip(FfxFloat32x2 center, FfxFloat32 centerCoc,
                                                      FfxFloat32 kernelRadius, FfxFloat32x4 dilated,
                                                      FfxBoolean lightsAround, FfxFloat32 coarserMip,
                                                      FfxDofConstants constants)
{
    FfxFloat32 texel = exp2(coarserMip);
    FfxFloat32 reach = max(kernelRadius, -dilated.x) * ffxDofApertureExtent(constants) +
                       texel * (1.0f + exp2(FfxFloat32(FFX_DOF_RING_MERGE_LOG)));
    FfxBoolean inside = min(center.x, center.y) >= reach && center.x + reach <= FfxFloat32(constants.halfSize.x) &&
                        center.y + reach <= FfxFloat32(constants.halfSize.y);
    // Not in the shaped permutation: a shaped disc's rim lies inside the walk's circle, in rings walked at
    // the kernel's MIP, and from the coarser one a triangle's point over a sloped far field kept 0.957 of
    // its energy (the CPU test "A shaped far point through the passes" asks 0.97).
    FfxBoolean round = FFX_DOF_OPTION_APERTURE_SHAPES == 0;
    return round && centerCoc <= -FFX_DOF_IN_FOCUS_RADIUS && dilated.y < FFX_DOF_NEAR_THRESHOLD && !lightsAround &&
           inside;
}

// Random sub-pixel kernel origin for one pixel and frame, in half-res px.
FFX_DOF_INLINE FfxUInt32 ffxDofHash(FfxUInt32 x)
{
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}
FFX_DOF_INLINE FfxFloat32x2 ffxDofKernelJitter(FfxUInt32x2 pixel, FfxUInt32 frameIndex)
{
    FfxUInt32 h = ffxDofHash(pixel.x ^ ffxDofHash(pixel.y ^ ffxDofHash(frameIndex)));
    FfxFloat32x2 unit = FfxFloat32x2(FfxFloat32(h & 0xffffu), FfxFloat32(h >> 16u)) * (1.0f / 65536.0f);
    return (unit - FfxFloat32x2(0.5f, 0.5f)) * FFX_DOF_JITTER_AMPLITUDE;
}

// ---- Gathering ----------------------------------------------------------------------------------

// Whether the radii the kernels of a tile read (`dilated`: its DILATED_TILES texel, footprint min and
// max in z and w) lie within FFX_DOF_RING_MERGE_NOT_FLAT_SPREAD of each other.
FFX_DOF_INLINE FfxBoolean ffxDofFootprintFlat(FfxFloat32x4 dilated)
{
    return dilated.w - dilated.z <= FFX_DOF_RING_MERGE_NOT_FLAT_SPREAD;
}

// The smallest far radius a tile's kernels read, in texels of the coarse MIP, for its rings to merge.
// A merged ring draws a sample's disc around the centre of the coarse texel holding it, up to 0.71 of
// that texel away from the light it holds: with two texels per radius, at most 0.35 of the radius.
#define FFX_DOF_RING_MERGE_MIN_RADIUS_TEXELS 2.0f

// The MIP that merged rings read for a kernel at `baseMip`: FFX_DOF_RING_MERGE_LOG levels coarser, within
// the chain.
FFX_DOF_INLINE FfxUInt32 ffxDofCoarseMip(FfxUInt32 baseMip)
{
    return min(baseMip + FfxUInt32(FFX_DOF_RING_MERGE_LOG), FfxUInt32(FFX_DOF_OPTION_MAX_MIP - 1));
}

// Whether merged rings can stand for every radius the kernels of a tile read (`dilated`: its
// DILATED_TILES texel, footprint min and max in z and w): where those radii are flat (within
// FFX_DOF_RING_MERGE_NOT_FLAT_SPREAD), or where the smallest of them spans
// FFX_DOF_RING_MERGE_MIN_RADIUS_TEXELS texels of the coarse MIP. A disc not much larger than the texel
// moves by a large part of itself, and the texels of its own radius, which gather it at their own MIP,
// no longer take the share of it they should (a light of radius 3 half-res px read from 4 px texels in
// front of a background of 16 gained up to 22% of its energy; with one texel per radius, lights of a few
// px were drawn up to 5 px from where they are). In-focus and near-field radii in the footprint count as 0.
FFX_DOF_INLINE FfxBoolean ffxDofMergedRingsResolve(FfxFloat32x4 dilated, FfxUInt32 baseMip)
{
    FfxUInt32 coarseMip = ffxDofCoarseMip(baseMip);
    FfxFloat32 smallestRadius = dilated.w < -FFX_DOF_IN_FOCUS_RADIUS ? -dilated.w : 0.0f;
    return ffxDofFootprintFlat(dilated) ||
           smallestRadius >= FFX_DOF_RING_MERGE_MIN_RADIUS_TEXELS * FfxFloat32(1u << coarseMip);
}

// How much of the merged-ring path a texel takes (0: all rings at full resolution, 1: merged), from
// the largest difference between its own radius and those on its outermost ring. Continuous, so
// the result changes smoothly where the radii stop being flat.
FFX_DOF_INLINE FfxFloat32 ffxDofRingMergeAmount(FfxFloat32 cocSpread)
{
    return ffxDofSaturate((FFX_DOF_RING_MERGE_NOT_FLAT_SPREAD - cocSpread) /
                          (FFX_DOF_RING_MERGE_NOT_FLAT_SPREAD - FFX_DOF_RING_MERGE_FLAT_SPREAD));
}

// A weighted sum of far-field samples.
struct FfxDofBucket
{
    FfxFloat32x3 color;  // sum of color * weight (32-bit: hundreds of HDR samples overflow 16 bits)
    FfxFloat32 weight;   // sum of reach * area weight * texel area
};

FFX_DOF_INLINE FfxDofBucket ffxDofEmptyBucket()
{
    FfxDofBucket bucket;
    bucket.color = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    bucket.weight = 0.0f;
    return bucket;
}

// Far-field color of a texel from its two layers, composed front to back. Every far sample spreads its
// light over its own disc, so the front layer's summed weights over pi are the share of the texel it
// covers (a solid surface of any radius sums to pi: opacity 1); the background shows through the rest.
// Without this, the ring occlusion of the technique let a small light nearer than its background
// occlude the whole kernel at its own position: its centre kept the input's brightness on top of its
// disc. Returns false when neither layer has weight (no far-field sample reaches the texel).
FFX_DOF_INLINE FfxBoolean ffxDofComposeFarLayers(FfxDofBucket front, FfxDofBucket back, FFX_DOF_OUT(FfxFloat32x3) color)
{
    color = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    if (front.weight <= 0.0f && back.weight <= 0.0f)
        return false;
    if (back.weight <= 0.0f)
    {
        color = front.color / front.weight;
        return true;
    }
    FfxFloat32 frontOpacity = ffxDofSaturate(front.weight * (1.0f / FFX_DOF_PI));
    FfxFloat32x3 frontColor = front.weight > 0.0f ? front.color / front.weight : FfxFloat32x3(0.0f, 0.0f, 0.0f);
    color = frontColor * frontOpacity + (back.color / back.weight) * (1.0f - frontOpacity);
    return true;
}

// Near-field opacity from the weights of the near samples that reach the pixel (scatter as gather).
// A sample weighs reach * ffxDofAreaWeight(radius) * the area of the texel read (4^mip half-res
// px^2), so the sum is the area the near field covers in the kernel over its discs' areas / pi: a
// solid near region of the kernel's radius R sums to pi R^2 / R^2 = pi, opacity 1.
FFX_DOF_INLINE FfxFloat32 ffxDofNearOpacity(FfxFloat32 nearWeight)
{
    return ffxDofSaturate(nearWeight * (1.0f / FFX_DOF_PI));
}

// Below this |radius| (half-res px) a near disc's area on the texel grid is not pi radius^2
// (ffxDofPixelDiscArea): from it, within 1.8%.
#define FFX_DOF_NEAR_GRID_AREA_RADIUS 3.0f
// What scales the near weights of a texel whose near samples have the mean |radius| `meanRadius` so that
// a disc sums to pi over the texel grid, as it does over the plane: a near speck of 1.25 half-res px added
// 1.13 times its light to the near layer (1.27 at 1), of 2 px 1.04 (tests/shaders, "An isolated near pixel
// over an in-focus wall"). Taken at the mean radius, as ffxDofFinishSmallSources does: exact for one radius,
// and where a kernel holds near samples of several, the larger ones weigh least and are the nearest pi r^2.
FFX_DOF_INLINE FfxFloat32 ffxDofNearGridAreaScale(FfxFloat32 meanRadius)
{
    if (meanRadius >= FFX_DOF_NEAR_GRID_AREA_RADIUS)
        return 1.0f;
    return FFX_DOF_PI * max(meanRadius * meanRadius, 0.25f) / ffxDofPixelDiscArea(meanRadius);
}

// Weight of a background sample in the hole fill of a near texel, by its distance (half-res px):
// the inverse square, so the fill extrapolates the background from just around the near object rather
// than averaging the whole kernel. Behind a thin near object over a sharp surface the hidden part is
// best told by the surface right beside it (fence's near field +0.8 dB, above the circular gather); a
// steeper falloff gained more there but let the anti-aliased pixels at a large object's silhouette,
// part foreground, speak for its whole rim (near-object's near field -0.3 dB at 1 / d^4; docs/quality.md).
FFX_DOF_INLINE FfxFloat32 ffxDofFillProximity(FfxFloat32 distance) { return 1.0f / max(distance * distance, 0.25f); }

// How much of a far texel's own surface that a near sample of |radius| `nearAbsRadius` hides in the texel's
// disc (|radius| `farAbsRadius`) the far layer takes from the texel's own surface around, weighed by
// proximity (FfxDofGather::ownFill), instead of leaving it out and normalising what the pinhole sees. The thin
// lens sees behind a small near object, so the truth's far field there is the whole disc's mean. Where the
// near radius is at least the far one, the kernel, as wide as the near radius, reaches the background on the
// occluder's far side, as the hole fill of the near texels across the silhouette does; the far layer beside
// such an object was the visible side's mean alone, unlike the fill its own texels take, and the object's
// pinhole silhouette showed through its faint veil as a hard-edged ghost (docs/quality.md, near-and-far:
// +0.25 dB, its far field +0.39). Below (the front of an object at the focus, busy-background's sphere) the
// kernel is no wider than the texel's disc, and the fill, weighed by proximity to the texel, is mostly the
// visible side's nearest samples: a sharper far layer (busy-background 0.36 dB lower where every near sample
// counted).
FFX_DOF_INLINE FfxFloat32 ffxDofVeilShare(FfxFloat32 nearAbsRadius, FfxFloat32 farAbsRadius)
{
    return ffxDofSaturate(nearAbsRadius - farAbsRadius + 1.0f);
}

struct FfxDofBlurResult
{
    FfxDofFloat3 nearColor;
    FfxDofFloat3 farColor;
    FfxFloat32x2 alpha;  // near opacity, far validity
};

// Running sums of the gather of one texel: near sum and weights, hole fill, far buckets.
struct FfxDofGather
{
    FfxFloat32x3 nearSum;
    FfxFloat32 nearWeight;
    FfxFloat32 nearRadiusSum;  // |radius| * near weight
    FfxFloat32x3 fillSum;      // hole fill: color * proximity * texel area
    FfxFloat32 fillProximity;  // hole fill: proximity * texel area
    FfxFloat32 veiledArea;     // far texels: texel area of their own disc that near samples hide (ffxDofVeilShare)
    // Far texels: their own surface by proximity (rgb: color * weight, w: weight), what the veiled area takes.
    // Not the hole fill's samples: in-focus ones among them would bleed an object at the focus into the far
    // layer behind the near one.
    FfxFloat32x4 ownFill;
    FfxDofBucket farNearer;  // far-field samples nearer than the texel's own surface
    FfxDofBucket farFront;   // far-field samples of the texel's own surface
    FfxDofBucket farBack;    // far-field samples behind it
    FfxFloat32 cocSpread;    // largest |radius - own radius| among the samples seen
};

// What every ring of one texel's kernel shares.
struct FfxDofKernel
{
    FfxFloat32x2 center;
    FfxFloat32x2 origin;
    FfxFloat32 centerCoc;
    FfxFloat32 spacing;
    FfxFloat32 rimInset;      // how far the rim border moves in where coarse texels judge it (ffxDofWalkBorderRadius)
    FfxFloat32 behindRadius;  // how far beyond the kernel far samples may reach the texel (ffxDofGatherBehind); 0: none
    FfxBoolean mergeResolved;  // the tile's radii allow merged rings (ffxDofMergedRingsResolve)
    FfxUInt32 baseMip;
    FfxUInt32 rings;
    FfxBoolean centerIsNear;
    FfxDofPixelAperture aperture;  // the bokeh shape this texel sees
    FfxFloat32 ownGatherShare;     // ffxDofOwnGatherShare of the texel's own radius, where the tile draws
                                   // small sources at full resolution (FFX_DOF_LISTED_TILE_SMALL_SOURCES), else 0
    FfxFloat32 smallSourceCut;     // 1 where ffxDofSmallSourceShare leaves small sources out, else 0
};

// Which parts of the gather a tile class needs; literals at every call, so what a path leaves out
// compiles away.
struct FfxDofGatherParts
{
    FfxBoolean nearField;     // near sums (scatter-as-gather near layer)
    FfxBoolean farField;      // far buckets
    FfxBoolean equalWeights;  // every radius read is the texel's own: no CoC reads
    FfxBoolean shaped;        // the aperture is not round (ffx_dof_aperture.h); round discs run the circle's code
};

// What a ring walk shares with its sample loop (ffxDofGatherRing, ffxDofWalkSamples).
struct FfxDofRingWalk
{
    FfxUInt32 mip;
    FfxFloat32 texelSize;         // half-res px per texel of `mip`
    FfxFloat32 sampleWeight;      // the texel's area (4^mip half-res px^2) x the ring's presence
    FfxFloat32x2 centerToCorner;  // the kernel centre less half a texel, in texels of `mip`
    FfxFloat32x2 lastTexel;       // the last texel of `mip`
    FfxBoolean trackSpread;       // literal at every call: record the radius spread
    // Leave out a coarse sample whose light lies in a texel of the kernel's MIP that the kernel's outermost
    // ring read: where ffxDofGatherBehind walks coarser than the kernel (false at every other call).
    FfxBoolean skipKernelTexels;
    FfxFloat32 kernelTexelsPerTexel;   // texels of the kernel's MIP per texel of `mip`, per side
    FfxDofAnnulusBorder kernelBorder;  // the outer border of the kernel's outermost ring, at the kernel's MIP
};

// One step of a ring walk: the texel read, where its light lies from the kernel centre, and whether it
// counts (0 for a step past a row's end, or, where the walk leaves them out, a light the kernel's own MIP
// read). `coarse` is a literal at both calls: MIP 0 reads HALF_COLOR and HALF_COC, MIPs 1 and up read
// COARSE_MIPS, colour, radius and light offset in one fetch.
struct FfxDofWalkedSample
{
    FfxFloat32x3 color;
    FfxFloat32 coc;
    FfxFloat32x2 toTexel;
    FfxFloat32 valid;
};
FFX_DOF_INLINE FfxDofWalkedSample ffxDofFetchWalkedSample(FfxDofKernel kernel, FfxDofRingWalk ring,
                                                          FfxDofAnnulusWalk walk, FfxBoolean inAnnulus,
                                                          FfxBoolean coarse, FfxDofGatherParts parts)
{
    FfxDofWalkedSample step;
    FfxFloat32x2 sampleTexel = clamp(walk.texel, FfxFloat32x2(0.0f, 0.0f), ring.lastTexel);
    step.valid = inAnnulus && ffxDofAnnulusValid(walk) ? 1.0f : 0.0f;
    // Reach is judged from where the light of the texel lies: its centre at MIP 0, its light offset
    // above. Beyond the image border the image is taken as its edge texels repeated, each copy at
    // the position walked: judged from the clamped texel instead, every read past the border counted
    // the edge texel again at its own place, so a near object within a kernel of the border grew
    // opaque there (near-object's near field 0.59 dB lower, docs/quality.md).
    step.toTexel = walk.texel - ring.centerToCorner;
    step.coc = kernel.centerCoc;
    if (coarse)
    {
        FfxUInt32x2 packed = ffxDofLoadCoarseMip(FfxInt32x2(sampleTexel), ring.mip);
        step.color = ffxDofCoarseTexelColor(packed);
        if (!parts.equalWeights)
            step.coc = ffxDofCoarseTexelCoc(packed);
        FfxFloat32x2 lightOffset = ffxDofCoarseTexelLightOffset(packed);
        step.toTexel += lightOffset;
        if (ring.skipKernelTexels)
        {
            // The texel of the kernel's MIP that holds the light, judged by the kernel's own border
            // figures (ffxDofBorderSpan), so that a light the kernel read is not read again.
            FfxFloat32x2 kernelTexel =
                floor((walk.texel + FfxFloat32x2(0.5f, 0.5f) + lightOffset) * ring.kernelTexelsPerTexel);
            step.valid = ffxDofBorderHolds(ring.kernelBorder, kernelTexel) ? 0.0f : step.valid;
        }
    }
    else
    {
        step.color = ffxDofToFloat32x3(ffxDofLoadHalfColor(FfxInt32x2(sampleTexel)));
        if (!parts.equalWeights)
            step.coc = ffxDofLoadHalfCoc(FfxInt32x2(sampleTexel));
    }
    return step;
}

// Adds one step of a ring walk to the gather (its hole fill to ringFillSum / ringFillProximity). Written
// for devices that run both sides of every branch (lavapipe): near and far samples are added with 0/1
// shares instead of a branch, and a step that counts 0 (`valid`) is added with weight 0.
FFX_DOF_INLINE void ffxDofAddWalkedSample(FFX_DOF_INOUT(FfxDofGather) gather, FFX_DOF_INOUT(FfxFloat32x3) ringFillSum,
                                          FFX_DOF_INOUT(FfxFloat32) ringFillProximity, FfxDofKernel kernel,
                                          FfxDofRingWalk ring, FfxDofWalkedSample step, FfxBoolean coarse,
                                          FfxDofGatherParts parts)
{
    FfxBoolean holeFill = parts.nearField && parts.farField;
    FfxFloat32 centerAbsCoc = abs(kernel.centerCoc);
    FfxFloat32x3 color = step.color;
    FfxFloat32 coc = step.coc;
    FfxFloat32 valid = step.valid;
    if (ring.trackSpread)
        gather.cocSpread = max(gather.cocSpread, abs(coc - kernel.centerCoc) * valid);
    FfxBoolean nearSample = coc >= FFX_DOF_NEAR_THRESHOLD;
    FfxFloat32 gauge = sqrt(dot(step.toTexel, step.toTexel));
    if (parts.shaped)
        gauge = ffxDofApertureDistance(kernel.aperture, step.toTexel, nearSample);
    FfxFloat32 distance = gauge * ring.texelSize;
    // Near and far samples weigh alike (reach times inverse area).
    FfxFloat32 absCoc = abs(coc);
    FfxFloat32 areaWeight =
        parts.shaped ? ffxDofApertureAreaWeight(kernel.aperture, absCoc) : ffxDofRoundAreaWeight(absCoc);
    FfxFloat32 reach = ffxDofReach(absCoc, distance);
    reach *= valid;
    FfxFloat32 weight = reach * areaWeight * ring.sampleWeight;
    FfxFloat32 farShare = nearSample ? 0.0f : valid;
    if (!parts.nearField)
        farShare = valid;
    if (!parts.farField)
        farShare = 0.0f;
    FfxFloat32 farWeight = weight * farShare;
    FfxFloat32 ownShare = 0.0f;
    if (parts.nearField)
    {
        // A texel the near field covers in part carries that share, in quarters at MIP 0 and sixteenths
        // above (Near coverage, ffx_dof_common.h); equal-weight tiles hold none (their tiles are all near
        // or all far).
        FfxFloat32 coverage = parts.equalWeights ? 1.0f
                              : coarse           ? ffxDofCoarseNearCoverage(coc)
                                                 : ffxDofNearCoverage(coc);
        FfxFloat32 nearWeight = (weight - farWeight) * coverage;
        gather.nearSum += color * nearWeight;
        gather.nearWeight += nearWeight;
        gather.nearRadiusSum += absCoc * nearWeight;
        if (holeFill)
            gather.veiledArea += ffxDofReach(centerAbsCoc, distance) * (valid - farShare) * coverage *
                                 ffxDofVeilShare(absCoc, centerAbsCoc) * ring.sampleWeight;
    }
    if (parts.farField)
    {
        // On an equal-weight path every step has the texel's own radius, so all of it is the texel's
        // own surface: literals, so that the other buckets' sums compile away.
        FfxFloat32 frontShare = parts.equalWeights    ? 1.0f
                                : kernel.centerIsNear ? 0.0f
                                                      : ffxDofFarFrontShare(absCoc, centerAbsCoc);
        FfxFloat32 nearerShare =
            parts.equalWeights || kernel.centerIsNear ? 0.0f : ffxDofFarNearerShare(absCoc, centerAbsCoc);
        ownShare = frontShare - nearerShare;
        FfxFloat32 frontWeight = farWeight * frontShare;
        FfxFloat32 nearerWeight = farWeight * nearerShare;
        // The texel's own surface, where the composite gathers it at full resolution, stays out of
        // the far layer, which then holds only what lies in front and behind (ffxDofOwnGatherShare).
        FfxFloat32 frontKept = (frontWeight - nearerWeight) * (1.0f - kernel.ownGatherShare);
        // Small sources in front of a texel that the composite draws from the half-res layers are
        // drawn there at full resolution instead (ffxDofSmallSourceShare).
        FfxFloat32 nearerKept =
            nearerWeight * (1.0f - kernel.smallSourceCut * ffxDofSmallSourceShare(absCoc, centerAbsCoc));
        gather.farNearer.color += color * nearerKept;
        gather.farNearer.weight += nearerKept;
        gather.farFront.color += color * frontKept;
        gather.farFront.weight += frontKept;
        gather.farBack.color += color * (farWeight - frontWeight);
        gather.farBack.weight += farWeight - frontWeight;
    }
    if (holeFill)
    {
        FfxFloat32 proximity = ffxDofFillProximity(distance) * farShare;
        ringFillSum += color * proximity;
        ringFillProximity += proximity;
        FfxFloat32 ownProximity = proximity * ownShare * ring.sampleWeight;
        gather.ownFill += FfxFloat32x4(color * ownProximity, ownProximity);
    }
}

// Steps of a ring walk fetched before any of them is added (ffxDofWalkSamples): 3 and 4 took no less time than 2
// on lavapipe (docs/performance.md, "Two walk steps an iteration").
#define FFX_DOF_WALK_STEPS 2

// The sample loop of one ring walk: every texel of `annulus` at the walk's MIP, once, added to the
// gather. Two loops (`coarse` a literal at both calls) rather than a choice per sample, because on
// devices that run both sides of every branch (lavapipe) a per-sample choice fetches from both images; a
// loop no lane enters costs at most one pass. A step of the walk that lands on an empty row counts with
// weight 0 rather than looping on to the next row. FFX_DOF_WALK_STEPS steps an iteration, all fetched
// before any is added: on lavapipe a fetch is a call that saves no vector register, so the sums live
// across it were stored and reloaded around every fetch (the blur 0.92 to 0.95 times as long at 1080p); a
// GPU has the fetches in flight together. The steps are added in the walk's order, so the sums are the same
// to the bit. (Written as two named steps instead of this array's loop, lavapipe's compiler rounded a few
// far-field sums of four scenes differently, 98 to 116 dB from the image before.)
FFX_DOF_INLINE void ffxDofWalkSamples(FFX_DOF_INOUT(FfxDofGather) gather, FFX_DOF_INOUT(FfxFloat32x3) ringFillSum,
                                      FFX_DOF_INOUT(FfxFloat32) ringFillProximity, FfxDofKernel kernel,
                                      FfxDofRingWalk ring, FfxDofAnnulus annulus, FfxBoolean coarse,
                                      FfxDofGatherParts parts)
{
    FfxDofAnnulusWalk walk = ffxDofAnnulusBegin(annulus);
    FFX_DOF_LOOP
    while (ffxDofAnnulusRowsLeft(annulus, walk))
    {
        FfxDofWalkedSample steps[FFX_DOF_WALK_STEPS];
        FFX_DOF_UNROLL
        for (FfxUInt32 k = 0u; k < FfxUInt32(FFX_DOF_WALK_STEPS); ++k)
        {
            // Past the annulus's last row a step counts 0 (its texel, clamped, is still read).
            steps[k] = ffxDofFetchWalkedSample(kernel, ring, walk, k == 0u || ffxDofAnnulusRowsLeft(annulus, walk),
                                               coarse, parts);
            walk = ffxDofAnnulusNext(annulus, walk);
        }
        FFX_DOF_UNROLL
        for (FfxUInt32 k = 0u; k < FfxUInt32(FFX_DOF_WALK_STEPS); ++k)
            ffxDofAddWalkedSample(gather, ringFillSum, ringFillProximity, kernel, ring, steps[k], coarse, parts);
    }
}

// What a walk at MIP `mip` shares with its samples; `presence` (0..1): how much the walk counts.
FFX_DOF_INLINE FfxDofRingWalk ffxDofMakeRingWalk(FfxDofKernel kernel, FfxUInt32 mip, FfxFloat32 presence,
                                                 FfxBoolean trackSpread, FfxDofConstants constants)
{
    FfxDofRingWalk ring;
    ring.mip = mip;
    ring.texelSize = FfxFloat32(1u << mip);
    ring.sampleWeight = ring.texelSize * ring.texelSize * presence;
    ring.trackSpread = trackSpread;
    FfxFloat32 mipScale = 1.0f / ring.texelSize;
    // In units of MIP texels: the kernel centre less half a texel, so that (texel - centre) is the
    // offset of the texel's centre.
    ring.centerToCorner = kernel.center * mipScale - FfxFloat32x2(0.5f, 0.5f);
    ring.lastTexel = FfxFloat32x2(ffxDofMipSize(constants.halfSize, mip) - FfxUInt32x2(1u, 1u));
    ring.skipKernelTexels = false;
    ring.kernelTexelsPerTexel = 1.0f;
    ring.kernelBorder = ffxDofMakeAnnulusBorder(FfxFloat32x2(0.0f, 0.0f), 0.0f, 1.0f, 1.0f);
    return ring;
}

// The annulus from `innerRadius` to `outerRadius` (texels of MIP `mip`) around the kernel origin, its
// borders judged in blocks of `innerBlock` and `outerBlock` texels (FfxDofAnnulus); squeezed by the
// aperture's anamorphic ratio where the kernel is shaped.
FFX_DOF_INLINE FfxDofAnnulus ffxDofKernelAnnulus(FfxDofKernel kernel, FfxUInt32 mip, FfxFloat32 innerRadius,
                                                 FfxFloat32 outerRadius, FfxFloat32 innerBlock, FfxFloat32 outerBlock,
                                                 FfxBoolean shaped)
{
    return ffxDofMakeAnnulus(kernel.origin * (1.0f / FfxFloat32(1u << mip)), innerRadius, outerRadius, innerBlock,
                             outerBlock, shaped ? 1.0f / kernel.aperture.anamorphicRatio : 1.0f);
}

// Walks `annulus` at the walk's MIP (ffxDofWalkSamples, with `coarse` a literal at each call).
FFX_DOF_INLINE void ffxDofWalkAnnulus(FFX_DOF_INOUT(FfxDofGather) gather, FFX_DOF_INOUT(FfxFloat32x3) ringFillSum,
                                      FFX_DOF_INOUT(FfxFloat32) ringFillProximity, FfxDofKernel kernel,
                                      FfxDofRingWalk ring, FfxDofAnnulus annulus, FfxDofGatherParts parts)
{
    if (ring.mip == 0u)
        ffxDofWalkSamples(gather, ringFillSum, ringFillProximity, kernel, ring, annulus, false, parts);
    else
        ffxDofWalkSamples(gather, ringFillSum, ringFillProximity, kernel, ring, annulus, true, parts);
}

// The annulus of rings firstRing..lastRing at MIP `mip` around the kernel origin, in texels of that MIP;
// each border judged by the texels of its own MIP (FfxDofAnnulus): a border shared with a walk at a
// coarser MIP is judged by that walk's texels, so that the two read no fine texel twice and miss none.
FFX_DOF_INLINE FfxDofAnnulus ffxDofRingsAnnulus(FfxDofKernel kernel, FfxUInt32 firstRing, FfxUInt32 lastRing,
                                                FfxUInt32 mip, FfxUInt32 innerBorderMip, FfxUInt32 outerBorderMip,
                                                FfxBoolean shaped)
{
    FfxFloat32 mipScale = 1.0f / FfxFloat32(1u << mip);
    FfxFloat32 spacing = kernel.spacing * mipScale;
    FfxFloat32 rimInset = kernel.rimInset * mipScale;
    FfxFloat32 innerRadius =
        ffxDofWalkBorderRadius(firstRing, spacing, kernel.rings, innerBorderMip != kernel.baseMip, rimInset);
    FfxFloat32 outerRadius =
        lastRing == kernel.rings
            ? ffxDofKernelOuterRadius(kernel.rings, spacing, mip)
            : ffxDofWalkBorderRadius(lastRing + 1u, spacing, kernel.rings, outerBorderMip != kernel.baseMip, rimInset);
    return ffxDofKernelAnnulus(kernel, mip, innerRadius, outerRadius, FfxFloat32(1u << (innerBorderMip - mip)),
                               FfxFloat32(1u << (outerBorderMip - mip)), shaped);
}

// Gathers rings firstRing..lastRing from MIP `mip`: every texel of that MIP whose centre lies in
// the rings' annulus around the kernel origin, once (ffxDofRingsAnnulus). A sample weighs the texel's
// area (4^mip half-res px^2), so rings from different MIPs add up, and the whole ring counts `presence`
// (0..1) times. trackSpread (a literal at every call, so it compiles away) records the radius spread of
// the samples for the ring-merge decision: only the outermost ring needs it. Hole filling needs both
// fields (a near texel with background samples around it): only the mixed path has it.
FFX_DOF_INLINE void ffxDofGatherRing(FFX_DOF_INOUT(FfxDofGather) gather, FfxDofKernel kernel, FfxUInt32 firstRing,
                                     FfxUInt32 lastRing, FfxUInt32 mip, FfxUInt32 innerBorderMip,
                                     FfxUInt32 outerBorderMip, FfxFloat32 presence, FfxBoolean trackSpread,
                                     FfxDofGatherParts parts, FfxDofConstants constants)
{
    FfxDofRingWalk ring = ffxDofMakeRingWalk(kernel, mip, presence, trackSpread, constants);
    FfxDofAnnulus annulus =
        ffxDofRingsAnnulus(kernel, firstRing, lastRing, mip, innerBorderMip, outerBorderMip, parts.shaped);
    FfxFloat32x3 ringFillSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 ringFillProximity = 0.0f;
    ffxDofWalkAnnulus(gather, ringFillSum, ringFillProximity, kernel, ring, annulus, parts);
    gather.fillSum += ringFillSum * ring.sampleWeight;
    gather.fillProximity += ringFillProximity * ring.sampleWeight;
}

// The walks over the rings inside the outermost one. Rings 1 .. rings - 1 form groups of
// 2^FFX_DOF_RING_MERGE_LOG; a group is gathered either at the kernel's MIP (full) or from a MIP that
// much coarser (merged). A border between the two levels is judged by the coarse texels on both sides
// (FfxDofAnnulus), so that a one-texel source is read once (docs/technique.md, Kernel shape and walk).
// mergeAmount (0..1) merges the groups one after the other, from the outside in, and mixes the one group
// it is part-way through: that group merged with presence f and full with presence 1 - f. So the result
// is continuous in mergeAmount, and a texel walks at most one group more than the full path.
// Rings walked at the same MIP, with the same presence and next to each other, are walked as one
// annulus: the rings tile it exactly (ffxDofRingInnerRadius), and a walk costs its set-up and, on
// devices that run groups of lanes in lock step (lavapipe: 8), the steps its slowest lane takes, many of
// them on rows a thin ring leaves empty (one walk per ring: the blur about 1.12 times as long,
// docs/performance.md). So there are at most five walks, outside in: the rim rings of a shaped disc
// (never merged), the merged groups, the part-merged group merged, the same full, and every ring below
// them with ring 0; `pending` holds one bit for each still to take.
struct FfxDofInnerRingPlan
{
    FfxUInt32 pending;
    FfxUInt32 rings;
    FfxUInt32 mergeableRings;
    FfxUInt32 baseMip;
    FfxUInt32 coarseMip;
    FfxUInt32 topOfPartMerged;  // top ring of the part-merged group (the top ring below the merged ones)
    FfxUInt32 topOfUnmerged;    // top ring of the first group not merged at all; 0: ring 0 alone is left
    FfxFloat32 partMerged;      // the part-merged group's presence merged
};

// One walk of an FfxDofInnerRingPlan (ffxDofGatherRing's arguments).
struct FfxDofInnerWalk
{
    FfxUInt32 firstRing;
    FfxUInt32 lastRing;
    FfxUInt32 mip;
    FfxFloat32 presence;
};

// The plan of a kernel of `rings` rings at MIP `baseMip` whose rings 1 .. mergeableRings merge by
// mergeAmount (ffxDofGatherKernel makes one where rings may merge at all). The rings above
// mergeableRings (the rim of a shaped disc, ffxDofGatherInnerRings) are walked at the kernel's MIP.
// Every border between two walks is judged at the coarse MIP by both (ffxDofNextInnerWalk), the
// outermost ring's included (ffxDofGatherKernel judges it so on that ring's side): a fine border less
// than a coarse texel's reach (0.71 fine texels) inside a coarse one let a fine texel lie inside the
// first and outside the second, read by the walks on both sides (a shaped disc's rim rings, narrowed by
// the rim inset, over unmerged rings).
FFX_DOF_INLINE FfxDofInnerRingPlan ffxDofPlanInnerRings(FfxUInt32 rings, FfxUInt32 mergeableRings, FfxUInt32 baseMip,
                                                        FfxFloat32 mergeAmount)
{
    FfxUInt32 groupSize = 1u << FfxUInt32(FFX_DOF_RING_MERGE_LOG);
    FfxDofInnerRingPlan plan;
    plan.rings = rings;
    plan.mergeableRings = mergeableRings;
    plan.baseMip = baseMip;
    plan.coarseMip = ffxDofCoarseMip(baseMip);
    FfxBoolean rimRings = mergeableRings + 1u < rings;
    FfxUInt32 groupCount = (mergeableRings + groupSize - 1u) / groupSize;
    FfxFloat32 mergedGroups = mergeAmount * FfxFloat32(groupCount);
    FfxUInt32 fullyMerged = min(FfxUInt32(mergedGroups), groupCount);
    plan.partMerged = fullyMerged < groupCount ? mergedGroups - FfxFloat32(fullyMerged) : 0.0f;
    FfxUInt32 unmerged = fullyMerged + (plan.partMerged > 0.0f ? 1u : 0u);  // the first group merged not at all
    // The top ring of group g is mergeableRings - g * groupSize.
    plan.topOfPartMerged = fullyMerged < groupCount ? mergeableRings - fullyMerged * groupSize : 0u;
    plan.topOfUnmerged = unmerged < groupCount ? mergeableRings - unmerged * groupSize : 0u;
    plan.pending = (rimRings ? 1u : 0u) | (fullyMerged > 0u ? 2u : 0u) | (plan.partMerged > 0.0f ? 12u : 0u) | 16u;
    return plan;
}

// The next walk of the plan, which it takes off `plan.pending` (call while that is not 0).
FFX_DOF_INLINE FfxDofInnerWalk ffxDofNextInnerWalk(FFX_DOF_INOUT(FfxDofInnerRingPlan) plan)
{
    FfxUInt32 pending = plan.pending;
    FfxUInt32 walk = (pending & 1u) != 0u   ? 0u
                     : (pending & 2u) != 0u ? 1u
                     : (pending & 4u) != 0u ? 2u
                     : (pending & 8u) != 0u ? 3u
                                            : 4u;
    plan.pending = pending & (pending - 1u);
    FfxDofInnerWalk next;
    next.firstRing = walk == 0u   ? plan.mergeableRings + 1u
                     : walk == 1u ? plan.topOfPartMerged + 1u
                     : walk == 4u ? 0u
                                  : plan.topOfUnmerged + 1u;
    next.lastRing = walk == 0u   ? plan.rings - 1u
                    : walk == 1u ? plan.mergeableRings
                    : walk == 4u ? plan.topOfUnmerged
                                 : plan.topOfPartMerged;
    next.mip = walk == 1u || walk == 2u ? plan.coarseMip : plan.baseMip;
    next.presence = walk == 2u ? plan.partMerged : walk == 3u ? 1.0f - plan.partMerged : 1.0f;
    return next;
}

// Gathers every ring inside the outermost one of a kernel whose rings may merge (FfxDofInnerRingPlan).
// One loop runs the walks, so that lanes with different plans share its passes.
FFX_DOF_INLINE void ffxDofGatherInnerRings(FFX_DOF_INOUT(FfxDofGather) gather, FfxDofKernel kernel,
                                           FfxFloat32 mergeAmount, FfxDofGatherParts parts, FfxDofConstants constants)
{
    // The rim of a bladed or cat's-eye disc lies inside the walk's circle, down to the circle inscribed in
    // the shape. Rings reaching beyond that circle are walked at the kernel's MIP, never merged: merged,
    // the surface weights that normalise a light are counted on the coarse texels' lattice, and a point's
    // triangle kept 0.96 to 0.97 of its energy, 0.056 from flat inside, against 1.01 and 0.006 (the CPU
    // test "A shaped far point through the passes"). None is needed where the outermost ring, widened
    // inward by the rim inset, already reaches the inscribed circle (on a flat far tile wherever that
    // circle lies within a ring of it: ffxDofBlurTexel): walking its empty rows anyway cost six blades'
    // blur and composite about 5% (docs/performance.md, "A gauge without loops").
    // Rings 1 .. mergeableRings form the groups. Round discs: every ring (their rim lies in the outermost one).
    FfxUInt32 mergeableRings = kernel.rings - 1u;
    FfxFloat32 inscribedRings = kernel.aperture.inscribedRadius * FfxFloat32(kernel.rings);
    FfxBoolean rimInBand = FfxFloat32(kernel.rings) - 0.5f - kernel.rimInset / kernel.spacing <= inscribedRings;
    if (parts.shaped && !rimInBand)
        mergeableRings = min(mergeableRings, FfxUInt32(max(floor(inscribedRings - 0.5f), 0.0f)));
    FfxDofInnerRingPlan plan = ffxDofPlanInnerRings(kernel.rings, mergeableRings, kernel.baseMip, mergeAmount);
    FFX_DOF_LOOP
    while (plan.pending != 0u)
    {
        FfxDofInnerWalk walk = ffxDofNextInnerWalk(plan);
        // Both borders at the coarse MIP (ring 0's inner border is the kernel's centre, whatever the MIP).
        ffxDofGatherRing(gather, kernel, walk.firstRing, walk.lastRing, walk.mip, plan.coarseMip, plan.coarseMip,
                         walk.presence, false, parts, constants);
    }
}

// The layers of one texel from its finished gather; `result` holds the defaults (texel itself).
// `ownAreaWeight`: the area weight of the texel's own radius (its veiled area weighs it); `parts`: the
// tile class's (literals, so that what a class never gathers compiles away, and with it the resources it reads).
FFX_DOF_INLINE FfxDofBlurResult ffxDofFinishGather(FfxDofGather gather, FfxDofKernel kernel, FfxDofGatherParts parts,
                                                   FfxFloat32 ownAreaWeight, FfxDofBlurResult result)
{
    // The hole fill is background to a near texel: it takes what the far samples that reach the texel leave
    // uncovered of its disc (their weights sum to pi where they cover it all), as a far texel's veiled area
    // takes its own surface around. Weighed instead by the far samples' share of the kernel (until 2026-12-01),
    // a near object over a far field still showed its silhouette: steps of 0.071 and 0.065 across it, 0.057 and
    // 0.044 now (tests/shaders, "A small near object over a blurred far field leaves no edge of its silhouette").
    FfxDofBucket back = gather.farBack;
    FfxDofBucket front = gather.farFront;
    if (kernel.centerIsNear && gather.fillProximity > 0.0f)
    {
        FfxFloat32 holeWeight = max(FFX_DOF_PI - gather.farBack.weight, 0.0f);
        back.color += gather.fillSum * (holeWeight / gather.fillProximity);
        back.weight += holeWeight;
    }
    // A far texel's own surface behind the near samples in its disc (ffxDofVeilShare), as much of it as the
    // texel's front layer keeps (ffxDofOwnGatherShare).
    if (parts.nearField && parts.farField && gather.ownFill.w > 0.0f && !kernel.centerIsNear)
    {
        FfxFloat32 veiledWeight = gather.veiledArea * ownAreaWeight * (1.0f - kernel.ownGatherShare);
        front.color +=
            FfxFloat32x3(gather.ownFill.x, gather.ownFill.y, gather.ownFill.z) * (veiledWeight / gather.ownFill.w);
        front.weight += veiledWeight;
    }
    FfxFloat32x3 farColor;
    if (ffxDofComposeFarLayers(front, back, farColor))
    {
        if (gather.farNearer.weight > 0.0f)
        {
            FfxFloat32 nearerOpacity = ffxDofSaturate(gather.farNearer.weight * (1.0f / FFX_DOF_PI));
            farColor = ffxDofLerp(farColor, gather.farNearer.color / gather.farNearer.weight, nearerOpacity);
        }
        result.farColor = ffxDofToDofFloat3(farColor);
    }
    else if (ffxDofComposeFarLayers(gather.farNearer, ffxDofEmptyBucket(), farColor))
        result.farColor = ffxDofToDofFloat3(farColor);
    else
        result.alpha.y = 0.0f;
    if (gather.nearWeight > 0.0f)
    {
        // LAYER_ALPHA keeps whole steps of the opacity (ffxDofStoredNearOpacity). The near colour makes up the
        // difference: over a background like this texel's far layer, the composite's blend with the stored opacity
        // gives what the gathered opacity would (at most the stored step's 2/127 of the far layer's difference
        // from what the pixel shows behind). Scaled alone, the near colour kept the near layer's light, but every
        // opacity rounded up to one step hid 1/127 of what lay behind: in-focus pixels at the rim of near discs
        // darkened (the floor scene's in-focus PSNR 0.26 dB lower).
        FfxFloat32 opacity = ffxDofNearOpacity(gather.nearWeight);
        opacity = ffxDofSaturate(opacity * ffxDofNearGridAreaScale(gather.nearRadiusSum / gather.nearWeight));
        result.alpha.x = ffxDofStoredNearOpacity(opacity);
        FfxFloat32x3 nearColor = gather.nearSum / gather.nearWeight;
        if (result.alpha.x > 0.0f)
        {
            FfxFloat32 keptShare = opacity / result.alpha.x;
            nearColor = max(ffxDofLerp(ffxDofToFloat32x3(result.farColor), nearColor, keptShare),
                            FfxFloat32x3(0.0f, 0.0f, 0.0f));
        }
        result.nearColor = ffxDofToDofFloat3(nearColor);
    }
    return result;
}

FFX_DOF_INLINE FfxDofGatherParts ffxDofMakeGatherParts(FfxBoolean nearField, FfxBoolean farField,
                                                       FfxBoolean equalWeights, FfxBoolean shaped)
{
    FfxDofGatherParts parts;
    parts.nearField = nearField;
    parts.farField = farField;
    parts.equalWeights = equalWeights;
    parts.shaped = shaped;
    return parts;
}

// Coverage of the layers in front (nearer and front, over pi) from which ffxDofGatherBehind is not walked.
// On a sloped surface the front layer (radii within 1.5 px of the texel's own) covers only a band of the
// kernel, so a threshold near 1 walked most of the benchmark's floor for what the floor itself hides: the
// blur 1.05 times as long; from 0.5, no measurable cost, and the same figures for every light of
// docs/quality.md (docs/performance.md, "What lies behind the kernel").
#define FFX_DOF_BEHIND_HIDDEN_COVERAGE 0.5f

// The MIP ffxDofGatherBehind walks for a kernel at `baseMip`: at least MIP 1, whose texels carry where their
// light lies (their light offsets), as the kernels of the larger radii around read it. Read at MIP 0, where
// a texel's light is taken at its centre, a small light up to 0.35 half-res px from it reached the texel
// by less or more than it reached the texels around that read it at MIP 1: a dim light on a bright light's
// rim cut the bright disc at its own texels by a quarter (it added 0.92 to 0.94 of its energy; docs/quality.md,
// a dim light beside a bright one). A quarter of the texels, too.
FFX_DOF_INLINE FfxUInt32 ffxDofBehindMip(FfxUInt32 baseMip)
{
    return min(max(baseMip, 1u), FfxUInt32(FFX_DOF_OPTION_MAX_MIP - 1));
}

// How far inside the kernel's outer border (in texels of the walk's MIP) a texel of a coarser walk may hold
// a light that lies in a texel of the kernel's MIP outside it: its light lies up to sqrt(1/2) of its own
// texel from its centre, and the finer texel holding it has its centre up to sqrt(1/2) of a finer texel
// farther (at most half a walk texel).
#define FFX_DOF_BEHIND_INNER_MARGIN 1.07f

// What ffxDofGatherBehind walks, at `mip` (ffxDofBehindMip): from the kernel's outer radius as its outermost
// ring sees it (ffxDofKernelOuterRadius) out to the farthest far radius that reaches the tile. At the
// kernel's MIP the two walks share that border; a coarser walk starts FFX_DOF_BEHIND_INNER_MARGIN inside it
// and leaves out the lights the kernel read (FfxDofRingWalk::skipKernelTexels).
FFX_DOF_INLINE FfxDofAnnulus ffxDofBehindAnnulus(FfxDofKernel kernel, FfxUInt32 mip, FfxBoolean shaped)
{
    FfxFloat32 mipScale = 1.0f / FfxFloat32(1u << mip);
    FfxFloat32 kernelTexelSize = FfxFloat32(1u << kernel.baseMip);
    FfxFloat32 kernelOuterRadius =
        ffxDofKernelOuterRadius(kernel.rings, kernel.spacing / kernelTexelSize, kernel.baseMip) * kernelTexelSize *
        mipScale;
    FfxFloat32 innerRadius =
        mip == kernel.baseMip ? kernelOuterRadius : max(kernelOuterRadius - FFX_DOF_BEHIND_INNER_MARGIN, 0.0f);
    FfxFloat32 outerRadius = max((kernel.behindRadius + 0.5f * kernel.spacing) * mipScale, innerRadius);
    return ffxDofKernelAnnulus(kernel, mip, innerRadius, outerRadius, 1.0f, 1.0f, shaped);
}

// Far samples beyond the kernel that still reach the texel. A far texel's kernel is its own radius, but
// a sample behind it of a larger radius reaches farther: where the texel's own surface covers only part
// of its disc (a small light, the rim of an object) what lies behind shows through, a light there
// included. Without this, a dim light on a bright light's disc cut the bright disc at its own texels as
// if opaque: it added 0.79 of its energy instead of 1.00 (docs/quality.md, a dim light beside a bright
// one). Walked from the kernel's outermost ring's outer border (ffxDofBehindAnnulus: the two read no light
// twice and miss none) out to the farthest far radius that reaches the tile (dilate's far end), at
// ffxDofBehindMip, only where the layers in front do not hide it already. Not on equal-weight tiles, whose
// samples are all taken at the texel's own radius.
FFX_DOF_INLINE void ffxDofGatherBehind(FFX_DOF_INOUT(FfxDofGather) gather, FfxDofKernel kernel, FfxDofGatherParts parts,
                                       FfxDofConstants constants)
{
    FfxFloat32 covered = (gather.farNearer.weight + gather.farFront.weight) * (1.0f / FFX_DOF_PI);
    if (kernel.behindRadius <= 0.0f || covered >= FFX_DOF_BEHIND_HIDDEN_COVERAGE)
        return;
    FfxUInt32 mip = ffxDofBehindMip(kernel.baseMip);
    FfxDofRingWalk ring = ffxDofMakeRingWalk(kernel, mip, 1.0f, false, constants);
    ring.skipKernelTexels = mip > kernel.baseMip;
    ring.kernelTexelsPerTexel = FfxFloat32(1u << (mip - kernel.baseMip));
    ring.kernelBorder = ffxDofRingsAnnulus(kernel, kernel.rings, kernel.rings, kernel.baseMip, kernel.baseMip,
                                           kernel.baseMip, parts.shaped)
                            .outer;
    FfxDofAnnulus annulus = ffxDofBehindAnnulus(kernel, mip, parts.shaped);
    // Far buckets only: near samples this far out cannot reach (the kernel covers the near radii).
    FfxDofGatherParts behindParts = ffxDofMakeGatherParts(false, true, false, parts.shaped);
    FfxFloat32x3 unusedFillSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    FfxFloat32 unusedFillProximity = 0.0f;
    ffxDofWalkAnnulus(gather, unusedFillSum, unusedFillProximity, kernel, ring, annulus, behindParts);
}

// Gathers the whole kernel with the parts of one tile class.
// The outermost ring is always gathered at full resolution (it keeps the circle), and it tells how
// flat the radii around the texel are: the merged path is taken by how flat, per texel, from the
// texel's own samples, never per tile (a per-tile switch shows as tile-shaped blocks). Equal-weight
// tiles are flat by construction: their far texels merge fully (near texels never merge, as on the
// mixed path: merging them cost near-field PSNR, docs/performance.md).
FFX_DOF_INLINE void ffxDofGatherKernel(FFX_DOF_INOUT(FfxDofGather) gather, FfxDofKernel kernel, FfxDofGatherParts parts,
                                       FfxDofConstants constants)
{
    FfxBoolean trackSpread = !parts.equalWeights;
    FfxBoolean mergeEligible = FFX_DOF_RING_MERGE_LOG > 0 && kernel.rings >= 2u &&
                               kernel.centerCoc <= -FFX_DOF_IN_FOCUS_RADIUS && kernel.mergeResolved;
    // Whether the inner rings merge is known only after this ring, so its inner border is judged at
    // the coarse MIP wherever they may.
    FfxUInt32 coarseMip = ffxDofCoarseMip(kernel.baseMip);
    // Where no ring can merge, the whole kernel is one walk at its MIP (the rings tile it exactly; near
    // texels, tiles whose radii the coarse MIP does not resolve, FFX_DOF_DISABLE_RING_MERGE).
    ffxDofGatherRing(gather, kernel, mergeEligible ? kernel.rings : 0u, kernel.rings, kernel.baseMip,
                     mergeEligible ? coarseMip : kernel.baseMip, kernel.baseMip, 1.0f, trackSpread, parts, constants);
    if (mergeEligible)
    {
        FfxFloat32 mergeAmount = parts.equalWeights ? 1.0f : ffxDofRingMergeAmount(gather.cocSpread);
        ffxDofGatherInnerRings(gather, kernel, mergeAmount, parts, constants);
    }
    if (parts.farField && !parts.equalWeights)
        ffxDofGatherBehind(gather, kernel, parts, constants);
}

// The parts of the gather a blur class needs (`shaped`: a literal at each call). The class is the
// pipeline's constant (FFX_DOF_OPTION_BLUR_CLASS), so each pipeline holds one path.
FFX_DOF_INLINE FfxDofGatherParts ffxDofBlurClassParts(FfxUInt32 blurClass, FfxBoolean shaped)
{
    if (blurClass == FfxUInt32(FFX_DOF_BLUR_CLASS_EQUAL_FAR))
        return ffxDofMakeGatherParts(false, true, true, shaped);
    if (blurClass == FfxUInt32(FFX_DOF_BLUR_CLASS_EQUAL_NEAR))
        return ffxDofMakeGatherParts(true, false, true, shaped);
    if (blurClass == FfxUInt32(FFX_DOF_BLUR_CLASS_FAR_ONLY))
        return ffxDofMakeGatherParts(false, true, false, shaped);
    if (blurClass == FfxUInt32(FFX_DOF_BLUR_CLASS_NEAR_ONLY))
        return ffxDofMakeGatherParts(true, false, false, shaped);
    return ffxDofMakeGatherParts(true, true, false, shaped);
}

// The blur of one half-res texel; `dilated` is its tile's DILATED_TILES texel from pass 3, `tileFlags` what dilate
// listed with the tile (FFX_DOF_LISTED_TILE_*), `blurClass` the path (ffxDofBlurTileClass; the CPU tests also force
// the mixed path to compare).
FFX_DOF_INLINE FfxDofBlurResult ffxDofBlurTexel(FfxUInt32x2 texel, FfxFloat32x4 dilated, FfxUInt32 tileFlags,
                                                FfxUInt32 blurClass, FfxDofConstants constants)
{
    FfxDofBlurResult result;
    result.nearColor = FfxDofFloat3(0.0f, 0.0f, 0.0f);
    result.farColor = ffxDofLoadHalfColor(FfxInt32x2(texel));
    result.alpha = FfxFloat32x2(0.0f, 1.0f);
    // A copy tile's kernels are all in focus (its dilated range, below the in-focus radius): its texels are
    // the far layer, as they were when every class shared one pipeline, and the copy pipeline holds no gather.
    if (blurClass == FfxUInt32(FFX_DOF_BLUR_CLASS_COPY))
        return result;

    FfxDofKernel kernel;
    kernel.centerCoc = ffxDofLoadHalfCoc(FfxInt32x2(texel));
    FfxFloat32 nearRadius = max(dilated.y, 0.0f);
    FfxFloat32 kernelRadius = max(nearRadius, abs(kernel.centerCoc));
    kernel.rings = ffxDofRingCount(kernelRadius, constants.maxRings);
    if (kernel.rings == 0u)
        return result;  // in focus: the far layer holds the texel itself

    kernel.centerIsNear = kernel.centerCoc >= FFX_DOF_NEAR_THRESHOLD;
    kernel.spacing = kernelRadius / FfxFloat32(kernel.rings);
    kernel.center = FfxFloat32x2(texel) + FfxFloat32x2(0.5f, 0.5f);
    FfxFloat32 mipSpacing = kernel.spacing * ffxDofApertureRingSpacingScale(constants);
    FfxFloat32 coarserMip = ffxDofCoarserMipForSpacing(mipSpacing);
    kernel.baseMip = FfxUInt32(ffxDofKernelTakesCoarserMip(kernel.center, kernel.centerCoc, kernelRadius, dilated,
                                                           tileFlags != 0u, coarserMip, constants)
                                   ? coarserMip
                                   : ffxDofMipForSpacing(mipSpacing));
    kernel.mergeResolved = ffxDofMergedRingsResolve(dilated, kernel.baseMip);
    // The rim border moves in only where every radius the tile's kernels read is far and flat
    // (ffxDofFootprintFlat), so the rims of the discs lie in the outermost ring. Where a light lies
    // farther in front of its background, its rim lies in the merged rings anyway, and moving the
    // border in changed which texels merge: such lights kept 0.92 to 1.06 of their energy instead of
    // 0.95 to 1.02, and a bright near patch over a far field gained 1.4% instead of 0.5%.
    FfxBoolean flatFarTile = dilated.w < FFX_DOF_NEAR_THRESHOLD && ffxDofFootprintFlat(dilated);
    kernel.rimInset = flatFarTile ? FFX_DOF_RING_MERGE_RIM_INSET * FfxFloat32(1u << kernel.baseMip) : 0.0f;
    // Far samples may reach a far texel from as far as the farthest radius that reaches its tile.
    FfxFloat32 farReach = -dilated.x;
    kernel.behindRadius = kernel.centerCoc <= -FFX_DOF_IN_FOCUS_RADIUS && farReach > kernelRadius ? farReach : 0.0f;
    kernel.aperture = ffxDofRoundAperture();
    kernel.origin = kernel.center + ffxDofKernelJitter(texel, constants.frameIndex);
    // Near texels have no layer in front of their own surface to leave small sources out of.
    FfxBoolean drawsSmallSources =
        !kernel.centerIsNear && (tileFlags & FfxUInt32(FFX_DOF_LISTED_TILE_SMALL_SOURCES)) != 0u;
    kernel.ownGatherShare = drawsSmallSources ? ffxDofOwnGatherShare(kernel.centerCoc) : 0.0f;
    kernel.smallSourceCut = drawsSmallSources ? 1.0f : 0.0f;

    FfxDofGather gather;
    gather.nearSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    gather.nearWeight = 0.0f;
    gather.nearRadiusSum = 0.0f;
    gather.fillSum = FfxFloat32x3(0.0f, 0.0f, 0.0f);
    gather.fillProximity = 0.0f;
    gather.farNearer = ffxDofEmptyBucket();
    gather.farFront = ffxDofEmptyBucket();
    gather.farBack = ffxDofEmptyBucket();
    gather.cocSpread = 0.0f;
    gather.veiledArea = 0.0f;
    gather.ownFill = FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);

    FfxFloat32 ownAreaWeight = ffxDofRoundAreaWeight(abs(kernel.centerCoc));
#if FFX_DOF_OPTION_APERTURE_SHAPES
    // The permutation of FFX_DOF_ENABLE_APERTURE_SHAPES: every dispatch takes the shaped path (a round
    // aperture there gives the circle up to rounding). The circle's own code is the other permutation:
    // a blur holding both paths, one chosen per dispatch, made the round aperture's blur 1.11 to 1.27
    // times as long on lavapipe even when the shaped path never ran (docs/aperture.md, Cost).
    kernel.aperture = ffxDofMakeAperture(constants, kernel.center, FfxFloat32x2(constants.halfSize));
    ownAreaWeight = ffxDofApertureAreaWeight(kernel.aperture, abs(kernel.centerCoc));
    // A coarse texel's centre lies farther off in the aperture's units where the disc is narrowed.
    kernel.rimInset /= ffxDofApertureRingSpacingScale(constants);
    // On a flat far tile the outermost ring reaches in to the shape's inscribed circle where that lies
    // within one ring spacing of the ring's inner border (six blades up to 11 rings, nine blades up to 24),
    // so that no rim ring is walked (ffxDofGatherInnerRings); the ring inside it keeps part of its width.
    FfxFloat32 toInscribed =
        (FfxFloat32(kernel.rings) * (1.0f - kernel.aperture.inscribedRadius) - 0.5f) * kernel.spacing;
    if (kernel.rimInset > 0.0f && toInscribed < kernel.spacing)
        kernel.rimInset = max(kernel.rimInset, toInscribed);
    FfxDofGatherParts parts = ffxDofBlurClassParts(blurClass, true);
#else
    FfxDofGatherParts parts = ffxDofBlurClassParts(blurClass, false);
#endif
    ffxDofGatherKernel(gather, kernel, parts, constants);
    return ffxDofFinishGather(gather, kernel, parts, ownAreaWeight, result);
}

// Blurs the tile of list entry `listedTile` (ffxDofPackListedTile) on the path of `blurClass` (FFX_DOF_BLUR_CLASS_*).
FFX_DOF_INLINE void ffxDofBlurTile(FfxUInt32 listedTile, FfxUInt32 localIndex, FfxUInt32 blurClass)
{
    FfxDofConstants constants = ffxDofGetConstants();
    FfxUInt32x2 tile = ffxDofUnpackListedTile(listedTile);
    // Dilate has read the global radius; the next dispatch's pass 1 needs it at 0. The workgroup of tile
    // (0, 0) resets it: every tile is in one list, and any list may be empty.
    if (tile.x == 0u && tile.y == 0u && localIndex == 0u)
        ffxDofResetGlobals();
    FfxUInt32x2 texel = tile * FfxUInt32(FFX_DOF_TILE_SIZE) + ffxDofLocalCoord(localIndex);
    if (texel.x >= constants.halfSize.x || texel.y >= constants.halfSize.y)
        return;
    FfxDofBlurResult result =
        ffxDofBlurTexel(texel, ffxDofLoadDilatedTile(tile), ffxDofListedTileFlags(listedTile), blurClass, constants);
    ffxDofStoreNearColor(texel, ffxDofRoundForPackedColor(result.nearColor));
    ffxDofStoreFarColor(texel, ffxDofRoundForPackedColor(result.farColor));
    ffxDofStoreLayerAlpha(texel, result.alpha);
}

// Blurs tile `listIndex` of the list of `blurClass` (FFX_DOF_BLUR_CLASS_*, which dilate chose for it). The
// class is the pipeline's constant (FFX_DOF_OPTION_BLUR_CLASS): each pipeline holds only its class's path.
FFX_DOF_INLINE void ffxDofBlur(FfxUInt32 blurClass, FfxUInt32 listIndex, FfxUInt32 localIndex)
{
    FfxUInt32x2 tileCount = ffxDofGetConstants().tileCount;
    ffxDofBlurTile(
        ffxDofListedTileWord(FfxUInt32(FFX_DOF_BLUR_TILE_LIST_FIRST) + blurClass, listIndex, tileCount.x * tileCount.y),
        localIndex, blurClass);
}

#endif  // FFX_DOF_BLUR_H
