// API-neutral description of the passes and the internal resources. The pass list and the axes come
// from shaders_common/ffx_dof_permutations.json (the generated ffx_dof_pass_list.h); the internal
// images are listed here once. The shader side of the same facts is shaders_common/ffx_dof_resources.h.
#pragma once

#include "ffx_dof.h"

#define FFX_CPU 1
#include "ffx_dof_constants.h"
#include "ffx_dof_resources.h"
#include "ffx_dof_pass_list.h"

#include <cstdint>

namespace ffxdof {

struct PassGrid {
    uint32_t x = 1, y = 1, z = 1;  // workgroup counts
};

// Number of MIP levels of the half-res colour and CoC the SDK allocates (FFX_DOF_OPTION_MAX_MIP): MIP 0
// in HALF_COLOR and HALF_COC, the others in COARSE_MIPS.
constexpr uint32_t kMipCount = 4;

// The internal images, API-neutral: the one table both backends create from (each maps the format
// to its API's enum). Names, formats and slots follow shaders_common/ffx_dof_resources.h.
enum class InternalFormat : uint32_t { R11G11B10Float, R16Float, R16G16B16A16Float, R8Unorm, R32G32Uint };

// Bytes of one texel of the format (before any driver layout).
constexpr uint32_t internalFormatTexelBytes(InternalFormat format) {
    switch (format) {
        case InternalFormat::R11G11B10Float:
            return 4;
        case InternalFormat::R16Float:
            return 2;
        case InternalFormat::R16G16B16A16Float:
            return 8;
        case InternalFormat::R8Unorm:
            return 1;
        case InternalFormat::R32G32Uint:
            return 8;
    }
    return 0;
}

enum class ImageExtent : uint32_t {
    Half,     // ceil(W / 2) x ceil(H / 2)
    Quarter,  // MIP 1 of the half-resolution image: max(half / 2, 1), rounded down
    Tiles,    // ceil(half / FFX_DOF_TILE_SIZE)
};

struct InternalImageSpec {
    const char* name;
    InternalFormat format;
    ImageExtent extent;
    uint32_t levels;       // MIP levels (fewer where the image is too small for a full chain)
    uint32_t sampledSlot;  // FFX_DOF_SRV_*: all levels, sampled
    uint32_t storageSlot;  // FFX_DOF_UAV_*: level 0; a mip chain has one consecutive slot per level
};

constexpr InternalImageSpec kInternalImages[] = {
    {"HALF_COLOR", InternalFormat::R11G11B10Float, ImageExtent::Half, 1, FFX_DOF_SRV_HALF_COLOR,
     FFX_DOF_UAV_HALF_COLOR},
    {"HALF_COC", InternalFormat::R16Float, ImageExtent::Half, 1, FFX_DOF_SRV_HALF_COC, FFX_DOF_UAV_HALF_COC},
    // MIPs 1.. of the half-res colour and CoC, packed with their light offsets (ffxDofPackCoarseTexel).
    {"COARSE_MIPS", InternalFormat::R32G32Uint, ImageExtent::Quarter, kMipCount - 1, FFX_DOF_SRV_COARSE_MIPS,
     FFX_DOF_UAV_COARSE_MIP1},
    {"TILES", InternalFormat::R16G16B16A16Float, ImageExtent::Tiles, 1, FFX_DOF_SRV_TILES, FFX_DOF_UAV_TILES},
    {"DILATED_TILES", InternalFormat::R16G16B16A16Float, ImageExtent::Tiles, 1, FFX_DOF_SRV_DILATED_TILES,
     FFX_DOF_UAV_DILATED_TILES},
    {"NEAR_COLOR", InternalFormat::R11G11B10Float, ImageExtent::Half, 1, FFX_DOF_SRV_NEAR_COLOR,
     FFX_DOF_UAV_NEAR_COLOR},
    {"FAR_COLOR", InternalFormat::R11G11B10Float, ImageExtent::Half, 1, FFX_DOF_SRV_FAR_COLOR, FFX_DOF_UAV_FAR_COLOR},
    {"LAYER_ALPHA", InternalFormat::R8Unorm, ImageExtent::Half, 1, FFX_DOF_SRV_LAYER_ALPHA, FFX_DOF_UAV_LAYER_ALPHA},
};
constexpr uint32_t kInternalImageCount = sizeof(kInternalImages) / sizeof(kInternalImages[0]);

// Shader slots per class (ffx_dof_resources.h): sampled images, storage images, storage buffers.
constexpr uint32_t kSampledSlotCount = FFX_DOF_SRV_COARSE_MIPS + 1;
constexpr uint32_t kStorageImageSlotCount = FFX_DOF_UAV_OUTPUT + 1;
constexpr uint32_t kStorageBufferSlotCount = FFX_DOF_UAV_BUFFER_HIGHLIGHTS + 1;

// The GLOBALS storage buffer (FFX_DOF_UAV_BUFFER_GLOBALS): 32-bit words.
constexpr uint32_t kGlobalsWordCount = FFX_DOF_GLOBALS_WORD_COUNT;
constexpr uint32_t kGlobalsBufferBytes = kGlobalsWordCount * 4;
// TILE_LIST_ARGS (FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS): per tile list its indirect dispatch arguments, then those of
// pass 2's second run (FFX_DOF_COLOR_RANGE_RERUN_ARGS).
constexpr uint32_t kTileListArgsWordCount = FFX_DOF_TILE_LIST_ARGS_ENTRIES * FFX_DOF_TILE_LIST_ARGS_WORDS;
constexpr uint32_t kTileListArgsBytes = kTileListArgsWordCount * 4;
// The byte offset of a tile list's arguments in TILE_LIST_ARGS.
constexpr uint32_t tileListArgsOffset(uint32_t list) { return list * FFX_DOF_TILE_LIST_ARGS_WORDS * 4; }
// The pass dispatched a second time, indirectly from FFX_DOF_COLOR_RANGE_RERUN_ARGS with
// FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN, where its first run found a colour channel above the range limit.
constexpr Pass kColorRangeRerunPass = Pass::DownsampleColor;
constexpr uint32_t kColorRangeRerunArgsOffset = tileListArgsOffset(FFX_DOF_COLOR_RANGE_RERUN_ARGS);
// TILE_LISTS (FFX_DOF_UAV_BUFFER_TILE_LISTS): arrays of one word per tile, each shared by two lists of
// one pass (ffxDofTileListWord).
constexpr uint32_t tileListsWordCount(uint32_t tileCountX, uint32_t tileCountY) {
    return FFX_DOF_TILE_LIST_ARRAYS * tileCountX * tileCountY;
}
// Tiles each way of the largest image the context accepts: what a TILE_LISTS word must hold.
constexpr uint32_t kMaxTileCount = (FFX_DOF_MAX_RESOLUTION / 2 + FFX_DOF_TILE_SIZE - 1) / FFX_DOF_TILE_SIZE;
static_assert(kMaxTileCount <= FFX_DOF_LISTED_TILE_Y_LIMIT, "a TILE_LISTS word holds the largest image's tile rows");
// HIGHLIGHTS (FFX_DOF_UAV_BUFFER_HIGHLIGHTS): FFX_DOF_HIGHLIGHT_SLOTS highlights of FFX_DOF_HIGHLIGHT_WORDS
// words and the word of the two floors (far, near) per tile.
constexpr uint32_t highlightsWordCount(uint32_t tileCountX, uint32_t tileCountY) {
    return tileCountX * tileCountY * FFX_DOF_HIGHLIGHT_TILE_WORDS;
}

// Levels of an image of this size: the spec's, clamped to the full chain of a small image (a 4x3
// half-resolution image has 3 levels, its quarter-resolution image 2x1 has 2).
inline uint32_t mipLevelsFor(const InternalImageSpec& spec, uint32_t width, uint32_t height) {
    uint32_t levels = 1;
    for (uint32_t largest = width > height ? width : height; largest > 1 && levels < spec.levels; largest /= 2) {
        ++levels;
    }
    return levels;
}

}  // namespace ffxdof
