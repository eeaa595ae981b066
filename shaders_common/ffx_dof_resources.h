// The resource table of ffx-dof: every resource a pass touches, with its binding slot. Included by
// the per-API callback headers (which declare the bindings) and by the C++ backends (which bind).
//
// Slot classes (one binding macro per class; Vulkan binding = class base + index, set 0;
// D3D12 register = index in its own class, space 0):
//   sampled textures (SRV, t#)     base  0
//   storage images   (UAV, u#)     base 16
//   storage buffers  (UAV, u#)     base 40
//   samplers         (s#)          base 48
// Push/root constants carry FfxDofConstants (b0 on D3D12).
//
// Internal images (sizes at full resolution W x H; half = ceil(W/2) x ceil(H/2);
// tiles = ceil(half / FFX_DOF_TILE_SIZE)); see docs/technique.md for who writes and reads each:
//   COLOR_MIPS     half, FFX_DOF_OPTION_MAX_MIP levels, B10G11R11 float   bilateral color chain
//   COC_MIPS       half, FFX_DOF_OPTION_MAX_MIP levels, R16 float         CoC chain, signed half-res px
//   TILES          tiles, R16G16 float       (min, max) signed CoC per tile
//   DILATED_TILES  tiles, R16G16 float       dilated (near, far) radii per tile
//   NEAR_COLOR     half, B10G11R11 float     near-field color
//   FAR_COLOR      half, B10G11R11 float     far-field color
//   LAYER_ALPHA    half, R8G8 unorm          x: near-field opacity, y: far-field validity
//   GLOBALS        16-byte storage buffer    [0]: global max |radius| (float bits, atomic max)
#ifndef FFX_DOF_RESOURCES_H
#define FFX_DOF_RESOURCES_H

#define FFX_DOF_TILE_SIZE 8   // half-resolution pixels per tile side (16 full-resolution pixels)

// Dispatch geometry: the domain each pass covers and how many domain elements (per side) one workgroup
// covers. The host computes group counts as ceil(domain / extent); independent of FFX_DOF_OPTION_WAVE64.
#define FFX_DOF_DOWNSAMPLE_DEPTH_GROUP_EXTENT 16   // full-res pixels (one tile)
#define FFX_DOF_DOWNSAMPLE_COLOR_GROUP_EXTENT 16   // full-res pixels (one tile: MIPs 0..3 from groupshared)
#define FFX_DOF_DILATE_GROUP_EXTENT 8              // tiles
#define FFX_DOF_BLUR_GROUP_EXTENT 8                // half-res pixels
#define FFX_DOF_COMPOSITE_GROUP_EXTENT 8           // full-res pixels

#define FFX_DOF_SRV_BASE 0
#define FFX_DOF_UAV_IMAGE_BASE 16
#define FFX_DOF_UAV_BUFFER_BASE 40
#define FFX_DOF_SAMPLER_BASE 48

// Sampled textures
#define FFX_DOF_SRV_INPUT_COLOR     0
#define FFX_DOF_SRV_INPUT_DEPTH     1
#define FFX_DOF_SRV_COLOR_MIPS      2
#define FFX_DOF_SRV_COC_MIPS        3
#define FFX_DOF_SRV_TILES           4
#define FFX_DOF_SRV_DILATED_TILES   5
#define FFX_DOF_SRV_NEAR_COLOR      6
#define FFX_DOF_SRV_FAR_COLOR       7
#define FFX_DOF_SRV_LAYER_ALPHA     8

// Storage images (one slot per MIP level written)
#define FFX_DOF_UAV_COLOR_MIP0      0
#define FFX_DOF_UAV_COLOR_MIP1      1
#define FFX_DOF_UAV_COLOR_MIP2      2
#define FFX_DOF_UAV_COLOR_MIP3      3
#define FFX_DOF_UAV_COC_MIP0        4
#define FFX_DOF_UAV_COC_MIP1        5
#define FFX_DOF_UAV_COC_MIP2        6
#define FFX_DOF_UAV_COC_MIP3        7
#define FFX_DOF_UAV_TILES           8
#define FFX_DOF_UAV_DILATED_TILES   9
#define FFX_DOF_UAV_NEAR_COLOR      10
#define FFX_DOF_UAV_FAR_COLOR       11
#define FFX_DOF_UAV_LAYER_ALPHA     12
#define FFX_DOF_UAV_OUTPUT          13

// Storage buffers
#define FFX_DOF_UAV_BUFFER_GLOBALS  0

// Samplers
#define FFX_DOF_SAMPLER_LINEAR_CLAMP 0

#endif // FFX_DOF_RESOURCES_H
