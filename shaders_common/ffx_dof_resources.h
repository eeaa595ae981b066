// The resource table of ffx-dof: every resource a pass touches, with its binding slot. Included by
// the per-API callback headers (which declare the bindings) and by the C++ backends (which bind).
//
// Slot classes (one binding macro per class; Vulkan binding = class base + index, set 0;
// D3D12 register = index in its own class, space 0):
//   sampled textures (SRV, t#)     base  0
//   storage images   (UAV, u#)     base 16
//   storage buffers  (UAV, u#)     base 40   (D3D12: u<index> in space 1, since u# is shared
//                                            with the storage images)
// Push/root constants carry FfxDofConstants (b0 on D3D12).
//
// Internal images (sizes at full resolution W x H; half = ceil(W/2) x ceil(H/2);
// tiles = ceil(half / FFX_DOF_TILE_SIZE)); see docs/technique.md for who writes and reads each:
//   HALF_COLOR     half, B10G11R11 float     bilateral half-res color (MIP 0 of the color chain)
//   HALF_COC       half, R16 float           its CoC, signed half-res px; a near radius carries its texel's
//                                            coverage in its two lowest mantissa bits (ffxDofPackNearCoverage)
//   COARSE_MIPS    quarter (MIP 1 of half), FFX_DOF_OPTION_MAX_MIP - 1 levels, R32G32 uint: level l
//                                            is MIP l + 1 of the chain, each texel its color, CoC and
//                                            where in the texel its light lies (ffxDofPackCoarseTexel:
//                                            the blur reads a coarse sample in one fetch); a near radius
//                                            carries its coverage in sixteenths (ffxDofPackCoarseNearCoverage)
//   TILES          tiles, R16G16B16A16 float (min, max) signed CoC per tile; z, w: 0 (the tile's colour peak is
//                                            in HIGHLIGHTS, written by pass 2)
//   DILATED_TILES  tiles, R16G16B16A16 float dilated (far, near) radii per tile, and the (min, max)
//                                            radius of the tiles its blur kernels read
//   NEAR_COLOR     half, B10G11R11 float     near-field color
//   FAR_COLOR      half, B10G11R11 float     far-field color
//   LAYER_ALPHA    half, R8 unorm            near-field opacity (coverage of the pixel by near-field
//                                            blur, 0..1, its square root in 127ths) and far-field validity (top bit; 1:
//                                            FAR_COLOR holds gathered far-field color, 0: nothing was
//                                            gathered), packed by ffxDofPackLayerAlpha
//   GLOBALS        16-byte storage buffer    four uint words, all zero before the first dispatch:
//                  [0] (FFX_DOF_GLOBALS_MAX_RADIUS): global max |radius|, half-res px, as float bits
//                  (atomic max on uint: non-negative floats order like their bits); pass 1 writes,
//                  pass 3 reads, the blur writes 0 back, so it is zero before each dispatch.
//                  [1] (FFX_DOF_GLOBALS_COLOR_PEAK): the frame's largest finite colour channel as
//                  float bits, atomic max by pass 2's first run (only where it exceeds
//                  FFX_DOF_COLOR_RANGE_LIMIT, so 0 in most frames); its second run reads, pass 3 writes 0 back.
//                  [2] (FFX_DOF_GLOBALS_COLOR_SCALE): ffxDofColorRangeScale of the peak as float bits (1 in
//                  pass 2's first run), written by pass 2, read by the composite.
//                  [3] (FFX_DOF_GLOBALS_FOCUS_DISTANCE): the focus autofocus chose (signed like view
//                  z, 0 before the first autofocus dispatch), kept across dispatches for smoothing;
//                  [4], [5] (FFX_DOF_GLOBALS_FOCUS_COC_SCALE / _BIAS): its CoC line, which the passes
//                  read instead of the constants' when FFX_DOF_FOCUS_FLAG_AUTO is set. [6], [7]: unused.
//   TILE_LIST_ARGS storage buffer, (FFX_DOF_TILE_LIST_COUNT + 1) x 4 uint words: per list the indirect dispatch
//                  arguments (group counts x, y, z; the fourth word unused, so each starts 16-byte aligned).
//                  Pass 1 sets them to (0, 1, 1), dilate counts its listed tiles in x (atomic add), the
//                  blur and the composite are dispatched from them (one indirect dispatch per list of
//                  theirs), and never bind it. After the lists, FFX_DOF_COLOR_RANGE_RERUN_ARGS: pass 1 sets
//                  them to (0, 1, 1) too, pass 2's first run to the tile count (atomic max) where it finds a
//                  colour channel above FFX_DOF_COLOR_RANGE_LIMIT, and pass 2's second run, with
//                  FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN, is dispatched from them (docs/technique.md, HDR range).
//   TILE_LISTS     storage buffer, FFX_DOF_TILE_LIST_ARRAYS x tiles uint words: the tiles dilate put in
//                  each list (x | y << 16 | flags << 30, ffxDofPackListedTile: x below 65536, y below
//                  FFX_DOF_LISTED_TILE_Y_LIMIT), in no order; lists 2a and 2a + 1 share array a, one from each
//                  end (ffxDofTileListWord). The blur's or composite's workgroup i of a list works on the
//                  list's tile i.
//   HIGHLIGHTS     storage buffer, tiles x FFX_DOF_HIGHLIGHT_TILE_WORDS uint words: per tile the near and
//                  far highlights pass 2 took out of the half-res colour, for the composite to draw at full
//                  resolution (ffx_dof_highlights.h), FFX_DOF_HIGHLIGHT_SLOTS slots of FFX_DOF_HIGHLIGHT_WORDS
//                  words (a slot of zeros is empty), then the tile's far and near floors (two halves), from
//                  which the composite knows what pass 2 took of each pixel, then the tile's colour peak
//                  (FFX_DOF_HIGHLIGHT_PEAK_WORD: its largest finite channel, clamped to the half range, as
//                  float bits), which tells dilate and the composite where small sources and highlights may lie. Pass 2
//                  writes every word of every tile each dispatch, so it needs no initial value. Tile (x, y) starts at
//                  word (y * tileCount.x + x) * FFX_DOF_HIGHLIGHT_TILE_WORDS; slot s at s * FFX_DOF_HIGHLIGHT_WORDS
//                  from there, the floor at FFX_DOF_HIGHLIGHT_FLOOR_WORD.
#ifndef FFX_DOF_RESOURCES_H
#define FFX_DOF_RESOURCES_H

#define FFX_DOF_TILE_SIZE 8  // half-resolution pixels per tile side (16 full-resolution pixels)

#define FFX_DOF_SRV_BASE 0
#define FFX_DOF_UAV_IMAGE_BASE 16
#define FFX_DOF_UAV_BUFFER_BASE 40

// Sampled textures
#define FFX_DOF_SRV_INPUT_COLOR 0
#define FFX_DOF_SRV_INPUT_DEPTH 1
#define FFX_DOF_SRV_HALF_COLOR 2
#define FFX_DOF_SRV_HALF_COC 3
#define FFX_DOF_SRV_TILES 4
#define FFX_DOF_SRV_DILATED_TILES 5
#define FFX_DOF_SRV_NEAR_COLOR 6
#define FFX_DOF_SRV_FAR_COLOR 7
#define FFX_DOF_SRV_LAYER_ALPHA 8
#define FFX_DOF_SRV_COARSE_MIPS 9

// Storage images (one slot per MIP level written)
#define FFX_DOF_UAV_HALF_COLOR 0
#define FFX_DOF_UAV_HALF_COC 1
#define FFX_DOF_UAV_COARSE_MIP1 2  // level 0 of COARSE_MIPS
#define FFX_DOF_UAV_COARSE_MIP2 3
#define FFX_DOF_UAV_COARSE_MIP3 4
#define FFX_DOF_UAV_TILES 5
#define FFX_DOF_UAV_DILATED_TILES 6
#define FFX_DOF_UAV_NEAR_COLOR 7
#define FFX_DOF_UAV_FAR_COLOR 8
#define FFX_DOF_UAV_LAYER_ALPHA 9
#define FFX_DOF_UAV_OUTPUT 10

// Storage buffers
#define FFX_DOF_UAV_BUFFER_GLOBALS 0
#define FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS 1
#define FFX_DOF_UAV_BUFFER_TILE_LISTS 2
#define FFX_DOF_UAV_BUFFER_HIGHLIGHTS 3

// Words of GLOBALS
#define FFX_DOF_GLOBALS_MAX_RADIUS 0
#define FFX_DOF_GLOBALS_COLOR_PEAK 1
#define FFX_DOF_GLOBALS_COLOR_SCALE 2
#define FFX_DOF_GLOBALS_FOCUS_DISTANCE 3
#define FFX_DOF_GLOBALS_FOCUS_COC_SCALE 4
#define FFX_DOF_GLOBALS_FOCUS_COC_BIAS 5
#define FFX_DOF_GLOBALS_WORD_COUNT 8

// HIGHLIGHTS: highlights kept per tile, uint words per highlight, the word of the tile's floors (far and near, two
// halves) after its slots and uint words per tile.
#define FFX_DOF_HIGHLIGHT_SLOTS 4
#define FFX_DOF_HIGHLIGHT_WORDS 3
#define FFX_DOF_HIGHLIGHT_FLOOR_WORD (FFX_DOF_HIGHLIGHT_SLOTS * FFX_DOF_HIGHLIGHT_WORDS)
#define FFX_DOF_HIGHLIGHT_PEAK_WORD (FFX_DOF_HIGHLIGHT_FLOOR_WORD + 1)
#define FFX_DOF_HIGHLIGHT_TILE_WORDS (FFX_DOF_HIGHLIGHT_PEAK_WORD + 1)

// The tile lists (TILE_LIST_ARGS, TILE_LISTS): which work a tile needs in the blur and in the composite,
// decided by dilate (ffx_dof_tile_classes.h), so that each workgroup of those passes runs a pipeline
// with only that work. On a GPU a smaller pipeline needs fewer registers; on lavapipe every dispatched
// workgroup pays for the whole shader, early return or not (docs/performance.md).
#define FFX_DOF_BLUR_CLASS_COPY 0        // every kernel is in focus: the texel is the far layer
#define FFX_DOF_BLUR_CLASS_EQUAL_FAR 1   // all radii read are far and within FFX_DOF_EQUAL_WEIGHT_SPREAD
#define FFX_DOF_BLUR_CLASS_EQUAL_NEAR 2  // all radii read are near and within FFX_DOF_EQUAL_WEIGHT_SPREAD
#define FFX_DOF_BLUR_CLASS_FAR_ONLY 3    // no near-field radius reaches the tile
#define FFX_DOF_BLUR_CLASS_NEAR_ONLY 4   // every radius read is near-field: no far buckets, no fill
#define FFX_DOF_BLUR_CLASS_MIXED 5       // near and far field, hole filling
#define FFX_DOF_BLUR_CLASS_COUNT 6
#define FFX_DOF_COMPOSITE_CLASS_COPY 0      // in focus and no near field reaches it: the input, unchanged
#define FFX_DOF_COMPOSITE_CLASS_LAYERS 1    // the half-res layers and the fixed 3x3 blur
#define FFX_DOF_COMPOSITE_CLASS_FULL_RES 2  // and pixels whose own surface is gathered at full resolution
#define FFX_DOF_COMPOSITE_CLASS_LIGHTS 3    // and lights drawn at full resolution (small sources, highlights)
#define FFX_DOF_COMPOSITE_CLASS_COUNT 4
// List numbers: a pass's class c is list FIRST + c. Each pass's first list is even, since lists share
// storage in pairs (ffxDofTileListWord): the blur's six take lists 0 to 5, the composite's four 6 to 9.
#define FFX_DOF_BLUR_TILE_LIST_FIRST 0
#define FFX_DOF_COMPOSITE_TILE_LIST_FIRST 6
#define FFX_DOF_TILE_LIST_COUNT 10
// TILE_LIST_ARGS's entry after the lists': pass 2's second run (FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN).
#define FFX_DOF_COLOR_RANGE_RERUN_ARGS FFX_DOF_TILE_LIST_COUNT
#define FFX_DOF_TILE_LIST_ARGS_ENTRIES (FFX_DOF_TILE_LIST_COUNT + 1)
#define FFX_DOF_TILE_LIST_ARRAYS 5         // arrays of one word per tile in TILE_LISTS: ceil(lists / 2)
#define FFX_DOF_TILE_LIST_ARGS_WORDS 4     // words per list in TILE_LIST_ARGS
#define FFX_DOF_LISTED_TILE_Y_LIMIT 16384  // tile rows a TILE_LISTS word holds (14 bits)
#if FFX_DOF_BLUR_TILE_LIST_FIRST % 2 != 0 || FFX_DOF_COMPOSITE_TILE_LIST_FIRST % 2 != 0 ||          \
    FFX_DOF_COMPOSITE_TILE_LIST_FIRST < FFX_DOF_BLUR_TILE_LIST_FIRST + FFX_DOF_BLUR_CLASS_COUNT ||  \
    FFX_DOF_TILE_LIST_COUNT != FFX_DOF_COMPOSITE_TILE_LIST_FIRST + FFX_DOF_COMPOSITE_CLASS_COUNT || \
    FFX_DOF_TILE_LIST_ARRAYS * 2 < FFX_DOF_TILE_LIST_COUNT
#error "the tile lists must start even for each pass, not overlap, and fit their arrays"
#endif

// No samplers: every read is an integer texel fetch (texelFetch / Load), so no pass declares one and
// a reflected sampler is refused at context creation.

// Dispatch geometry. Every pass runs FFX_DOF_GROUP_THREADS threads per workgroup (8 x 8, in wave32
// and wave64 alike). Each pass covers a domain; one workgroup covers GROUP_EXTENT x GROUP_EXTENT
// elements of it, so the group count is ceil(domain size / GROUP_EXTENT) in x and y (z = 1):
//   FULL_RES  domain = fullSize  (FfxDofConstants::fullSize)
//   HALF_RES  domain = halfSize  (ceil(fullSize / 2))
//   TILES     domain = tileCount (ceil(halfSize / FFX_DOF_TILE_SIZE))
//   SINGLE    one workgroup (GROUP_EXTENT unused)
// The four tile-aligned passes give exactly tileCount groups: ceil(W / 16) == ceil(ceil(W / 2) / 8).
#define FFX_DOF_GROUP_THREADS 64
// Invocations per side of that square (ffxDofLocalCoord lays them out row by row).
#define FFX_DOF_GROUP_SIDE 8
#if FFX_DOF_GROUP_SIDE * FFX_DOF_GROUP_SIDE != FFX_DOF_GROUP_THREADS
#error "FFX_DOF_GROUP_THREADS must be FFX_DOF_GROUP_SIDE squared"
#endif
#define FFX_DOF_DOMAIN_FULL_RES 0
#define FFX_DOF_DOMAIN_HALF_RES 1
#define FFX_DOF_DOMAIN_TILES 2
#define FFX_DOF_DOMAIN_SINGLE 3

// Pass 0 (autofocus, when asked for): one workgroup samples the focus region.
#define FFX_DOF_AUTOFOCUS_DOMAIN FFX_DOF_DOMAIN_SINGLE
#define FFX_DOF_AUTOFOCUS_GROUP_EXTENT 1

// Pass 1: one workgroup = one tile (16 x 16 full-res px); a thread reduces a 2 x 2 px quad.
#define FFX_DOF_DOWNSAMPLE_DEPTH_DOMAIN FFX_DOF_DOMAIN_FULL_RES
#define FFX_DOF_DOWNSAMPLE_DEPTH_GROUP_EXTENT 16
// Pass 2: one workgroup = one tile; a thread makes one MIP-0 texel, then the group makes MIPs 1..3.
#define FFX_DOF_DOWNSAMPLE_COLOR_DOMAIN FFX_DOF_DOMAIN_FULL_RES
#define FFX_DOF_DOWNSAMPLE_COLOR_GROUP_EXTENT 16
// Pass 3: one thread per tile.
#define FFX_DOF_DILATE_DOMAIN FFX_DOF_DOMAIN_TILES
#define FFX_DOF_DILATE_GROUP_EXTENT 8
// Pass 4: one workgroup = one tile (8 x 8 half-res px), one thread per half-res px.
#define FFX_DOF_BLUR_DOMAIN FFX_DOF_DOMAIN_HALF_RES
#define FFX_DOF_BLUR_GROUP_EXTENT 8
// Pass 5: one workgroup = one tile (16 x 16 full-res px); a thread writes a 2 x 2 px quad.
#define FFX_DOF_COMPOSITE_DOMAIN FFX_DOF_DOMAIN_FULL_RES
#define FFX_DOF_COMPOSITE_GROUP_EXTENT 16

#endif  // FFX_DOF_RESOURCES_H
