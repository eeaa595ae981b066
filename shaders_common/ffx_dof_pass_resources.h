// Which resources each pass touches: the per-API callback headers declare exactly these bindings
// for the pass named by FFX_DOF_PASS_<NAME> (docs/technique.md has the same table for people).
#ifndef FFX_DOF_PASS_RESOURCES_H
#define FFX_DOF_PASS_RESOURCES_H

#if defined(FFX_DOF_PASS_AUTOFOCUS)
#define FFX_DOF_USES_INPUT_DEPTH 1
#define FFX_DOF_USES_GLOBALS 1
#elif defined(FFX_DOF_PASS_DOWNSAMPLE_DEPTH)
#define FFX_DOF_USES_INPUT_DEPTH 1
#define FFX_DOF_USES_RW_TILES 1
#define FFX_DOF_USES_GLOBALS 1
#define FFX_DOF_USES_RW_TILE_LIST_ARGS 1  // resets them for dilate and pass 2's second run
#elif defined(FFX_DOF_PASS_DOWNSAMPLE_COLOR)
#define FFX_DOF_USES_INPUT_COLOR 1
#define FFX_DOF_USES_INPUT_DEPTH 1
#define FFX_DOF_USES_RW_MIPS 1  // HALF_COLOR, HALF_COC and COARSE_MIPS
#define FFX_DOF_USES_GLOBALS 1
#define FFX_DOF_USES_RW_HIGHLIGHTS 1
#define FFX_DOF_USES_RW_TILE_LIST_ARGS 1  // arms its second run (FFX_DOF_COLOR_RANGE_RERUN_ARGS)
#elif defined(FFX_DOF_PASS_DILATE)
#define FFX_DOF_USES_TILES 1
#define FFX_DOF_USES_HIGHLIGHTS 1  // which tiles gave light to them (FFX_DOF_HIGHLIGHT_GIVEN_BIT)
#define FFX_DOF_USES_RW_DILATED_TILES 1
#define FFX_DOF_USES_GLOBALS 1
#define FFX_DOF_USES_RW_TILE_LIST_ARGS 1
#define FFX_DOF_USES_RW_TILE_LISTS 1
#elif defined(FFX_DOF_PASS_BLUR)
#define FFX_DOF_USES_HALF_COLOR 1
#define FFX_DOF_USES_HALF_COC 1
#define FFX_DOF_USES_COARSE_MIPS 1
#define FFX_DOF_USES_DILATED_TILES 1
#define FFX_DOF_USES_RW_LAYERS 1
#define FFX_DOF_USES_GLOBALS 1
#define FFX_DOF_USES_TILE_LISTS 1  // and TILE_LIST_ARGS as its indirect dispatch arguments, unbound
#elif defined(FFX_DOF_PASS_COMPOSITE)
#define FFX_DOF_USES_INPUT_COLOR 1
#define FFX_DOF_USES_INPUT_DEPTH 1
#define FFX_DOF_USES_HALF_COC 1
#define FFX_DOF_USES_TILES 1
#define FFX_DOF_USES_LAYERS 1
#define FFX_DOF_USES_RW_OUTPUT 1
#define FFX_DOF_USES_GLOBALS 1
#define FFX_DOF_USES_TILE_LISTS 1  // and TILE_LIST_ARGS as its indirect dispatch arguments, unbound
#define FFX_DOF_USES_HIGHLIGHTS 1
#if FFX_DOF_OPTION_OUTPUT_PRE_INIT
// In place, the input pixels next to the tile are read from the half-res color (other workgroups
// write the full-res ones during the pass); see ffx_dof_composite.h.
#define FFX_DOF_USES_HALF_COLOR 1
#endif
#else
#error "define one FFX_DOF_PASS_<NAME> before including a callback header"
#endif

#ifndef FFX_DOF_USES_INPUT_COLOR
#define FFX_DOF_USES_INPUT_COLOR 0
#endif
#ifndef FFX_DOF_USES_INPUT_DEPTH
#define FFX_DOF_USES_INPUT_DEPTH 0
#endif
#ifndef FFX_DOF_USES_HALF_COLOR
#define FFX_DOF_USES_HALF_COLOR 0
#endif
#ifndef FFX_DOF_USES_HALF_COC
#define FFX_DOF_USES_HALF_COC 0
#endif
#ifndef FFX_DOF_USES_COARSE_MIPS
#define FFX_DOF_USES_COARSE_MIPS 0
#endif
#ifndef FFX_DOF_USES_TILES
#define FFX_DOF_USES_TILES 0
#endif
#ifndef FFX_DOF_USES_DILATED_TILES
#define FFX_DOF_USES_DILATED_TILES 0
#endif
#ifndef FFX_DOF_USES_LAYERS
#define FFX_DOF_USES_LAYERS 0
#endif
#ifndef FFX_DOF_USES_RW_MIPS
#define FFX_DOF_USES_RW_MIPS 0
#endif
#ifndef FFX_DOF_USES_RW_TILES
#define FFX_DOF_USES_RW_TILES 0
#endif
#ifndef FFX_DOF_USES_RW_DILATED_TILES
#define FFX_DOF_USES_RW_DILATED_TILES 0
#endif
#ifndef FFX_DOF_USES_RW_LAYERS
#define FFX_DOF_USES_RW_LAYERS 0
#endif
#ifndef FFX_DOF_USES_RW_OUTPUT
#define FFX_DOF_USES_RW_OUTPUT 0
#endif
#ifndef FFX_DOF_USES_GLOBALS
#define FFX_DOF_USES_GLOBALS 0
#endif
#ifndef FFX_DOF_USES_RW_TILE_LIST_ARGS
#define FFX_DOF_USES_RW_TILE_LIST_ARGS 0
#endif
#ifndef FFX_DOF_USES_RW_TILE_LISTS
#define FFX_DOF_USES_RW_TILE_LISTS 0
#endif
#ifndef FFX_DOF_USES_TILE_LISTS
#define FFX_DOF_USES_TILE_LISTS 0
#endif
#ifndef FFX_DOF_USES_RW_HIGHLIGHTS
#define FFX_DOF_USES_RW_HIGHLIGHTS 0
#endif
#ifndef FFX_DOF_USES_HIGHLIGHTS
#define FFX_DOF_USES_HIGHLIGHTS 0
#endif

#endif  // FFX_DOF_PASS_RESOURCES_H
