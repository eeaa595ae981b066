// The plan of a context: everything the core decides once, at context creation, for a backend to
// create and record without deciding anything itself. Private to ffx-dof.
//
//   backend  --BackendCapabilities-->  core (buildContextPlan)  --ContextPlan-->  backend context
//   engine   --dispatch description--> core (checks, planDispatch) --DispatchPlan--> backend records
#pragma once

#include "ffx_dof.h"
#include "ffx_dof_passes.h"
#include "ffx_dof_shader_table.h"

#include <cstdint>

namespace ffxdof {

// Everything fixed for the lifetime of a context (the FfxDofContextDescription, checked).
struct ContextConfig {
    FfxDofDimensions2D resolution{};
    uint32_t flags = 0;  // FfxDofInitializationFlagBits
    uint32_t quality = 0;
    float cocLimitFactor = 0.0f;
};

// Every resource a pass can bind. The internal images follow kInternalImages, in its order.
enum class Resource : uint32_t {
    InputColor,
    InputDepth,
    Output,
    Globals,
    TileListArgs,
    TileLists,
    Highlights,
    FirstInternalImage
};
constexpr uint32_t kResourceCount = uint32_t(Resource::FirstInternalImage) + kInternalImageCount;
constexpr Resource internalImageResource(uint32_t image) {
    return Resource(uint32_t(Resource::FirstInternalImage) + image);
}
constexpr bool isInternalImage(Resource resource) { return resource >= Resource::FirstInternalImage; }
constexpr uint32_t internalImageIndex(Resource resource) {
    return uint32_t(resource) - uint32_t(Resource::FirstInternalImage);
}

// A set of resources: bit i is Resource(i).
using ResourceSet = uint32_t;
constexpr ResourceSet resourceBit(Resource resource) { return 1u << uint32_t(resource); }
static_assert(kResourceCount <= 32, "ResourceSet holds one bit per resource");

// What one shader slot is bound to. A storage slot of a MIP level that a small image lacks is bound
// to its last level (aliased: the shaders write the same 1x1 value to both).
struct SlotTarget {
    Resource resource = Resource::InputColor;
    uint32_t firstMip = 0;
    uint32_t mipCount = 1;  // sampled slots of a MIP chain see every level; storage slots one
};

struct PlannedImage {
    const InternalImageSpec* spec = nullptr;
    uint32_t width = 0, height = 0, mipLevels = 1;
};

// One pipeline of a pass: the permutation it runs.
struct PassVariant {
    const shaders::Blob* blob = nullptr;
    uint32_t permutationIndex = 0;
    // The value of the pass's per-dispatch axis and of its tile-list axis (0 without one).
    uint32_t dispatchValue = 0;
    uint32_t tileListValue = 0;
    // With a tile-list axis, the list the variant is dispatched over (kAxisTileLists: first + value).
    uint32_t tileList = 0;
};

struct PlannedPass {
    const shaders::PassTable* table = nullptr;
    // One variant per value of the pass's per-dispatch axis (perDispatch in the permutations JSON)
    // where the context's flag sets it, each dispatch running one (DispatchPlan::variants); else one.
    // With a tile-list axis (kAxisRunsPerTileList) each of those is a group of tileListVariants
    // variants, one per list the context dispatches: a dispatch runs every variant of its group, each
    // dispatched indirectly over its tile list (`groups` unused).
    PassVariant variants[kMaxPassVariants];
    uint32_t variantCount = 1;
    uint32_t tileListVariants = 1;
    bool perTileList = false;
    PassGrid groups;            // workgroup counts
    uint32_t sampledSlots = 0;  // bit i: FFX_DOF_SRV_* slot i is declared (reflected)
    uint32_t storageSlots = 0;  // bit i: FFX_DOF_UAV_* image slot i
    uint32_t bufferSlots = 0;   // bit i: FFX_DOF_UAV_BUFFER_* slot i
    ResourceSet reads = 0;      // sampled
    ResourceSet writes = 0;     // storage images and buffers (which the pass may also read)
    ResourceSet indirect = 0;   // read as indirect dispatch arguments (TILE_LIST_ARGS where perTileList)
};

// What a backend's device can run, asked once per context.
struct BackendCapabilities {
    const shaders::PassTable* tables[kPassCount] = {};  // nullptr: no shaders for the pass
    bool half = false;                                  // FFX_HALF permutations usable
    bool wave64 = false;                                // FFX_DOF_OPTION_WAVE64 permutations usable
};

struct ContextPlan {
    ContextConfig config;
    PermutationAxes axes;
    PlannedImage images[kInternalImageCount];
    PlannedPass passes[kPassCount];
    SlotTarget sampledSlots[kSampledSlotCount];
    SlotTarget storageImageSlots[kStorageImageSlotCount];
    SlotTarget storageBufferSlots[kStorageBufferSlotCount];
    uint32_t tileListsBytes = 0;   // TILE_LISTS (TILE_LIST_ARGS: kTileListArgsBytes)
    uint32_t highlightsBytes = 0;  // HIGHLIGHTS
    // Every pass's reads | writes | indirect.
    ResourceSet touched = 0;
    // Every pass's indirect: what the backends' barriers also make visible to the indirect-argument stage.
    ResourceSet indirect = 0;
    FfxDofConstants constants{};  // the per-context part; planDispatch adds the per-frame values
};

// Builds the plan, or fails naming what the backend's tables lack (a pass, a permutation, a slot).
FfxDofErrorCode buildContextPlan(const ContextConfig& config, const BackendCapabilities& capabilities,
                                 ContextPlan* plan);

// One dispatch, checked and planned by the core. The resources are the engine's, checked for what is
// API-neutral (present, sized, not aliased wrongly); the backend checks formats and states.
struct DispatchPlan {
    FfxDofCommandList commandList = nullptr;
    FfxDofResource color{};
    FfxDofResource depth{};
    FfxDofResource output{};
    FfxDofConstants constants{};  // the backend may only add FFX_DOF_OUTPUT_FLAG_* bits
    bool outputIsColor = false;   // in place: output and color are the same image
    bool runs[kPassCount] = {};   // the passes to record (autofocus only when the dispatch asks for it)
    // The PlannedPass::variants entry each pass runs: with a tile-list axis, the first of its group.
    uint32_t variants[kPassCount] = {};
};

// Checks an autofocus description; FFX_DOF_ERROR_INVALID_ARGUMENT naming the field otherwise.
FfxDofErrorCode checkAutofocus(const FfxDofAutofocus& autofocus);

// Checks an aperture description; FFX_DOF_ERROR_INVALID_ARGUMENT naming the field otherwise.
FfxDofErrorCode checkAperture(const FfxDofAperture& aperture);
// Whether a checked aperture is the circle (what NULL gives): no blades (or fully round ones),
// anamorphic ratio 1, no cat's eye.
bool isRoundAperture(const FfxDofAperture& aperture);
// The aperture's constants (ffx_dof_aperture.h) for a checked description; the round aperture's
// are contextConstants' defaults.
void setApertureConstants(const FfxDofAperture& aperture, FfxDofConstants* constants);

// The value a per-dispatch axis takes for a dispatch of these constants: FFX_DOF_OPTION_APERTURE_SHAPES
// is FFX_DOF_APERTURE_SHAPES_COMPACT where the aperture's gauge fits it (ffxDofApertureGaugeIsCompact),
// else FFX_DOF_APERTURE_SHAPES_ANY. Axes without perDispatch values: 0.
uint32_t dispatchAxisValue(Axis axis, const FfxDofConstants& constants);

// Whether a context of these axes dispatches the list of value `value` of a tile-list axis (every list,
// except the composite's copy class in place, which has nothing to do there).
bool tileListRuns(Axis axis, uint32_t value, const PermutationAxes& axes);

// The per-frame values added to the context's constants. resetAutofocus: autofocus ignores its
// previous distance (ffxDofContextResetAutofocus).
DispatchPlan planDispatch(const ContextPlan& plan, const FfxDofDispatchDescription& dispatch, uint32_t frameIndex,
                          bool resetAutofocus = false);

// The grid, images and constants of a configuration without shader tables (for tests and tools).
FfxDofConstants contextConstants(const ContextConfig& config);
// The size of each internal image (kInternalImages' order) for a context of these constants.
void sizeInternalImages(const FfxDofConstants& constants, PlannedImage images[kInternalImageCount]);
// The bytes the internal resources of a context of this configuration hold before any driver layout: every
// image's texels at every level, and the buffers (docs/technique.md, Internal resources). What a backend
// reports (ffxDofContextGetGpuMemoryUsage) is at least this; a GPU's tiled layouts pad each image.
uint64_t internalResourceBytes(const ContextConfig& config);
PassGrid passGroups(const FfxDofConstants& constants, Pass pass);

}  // namespace ffxdof
