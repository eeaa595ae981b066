// The core's planning: permutations, image sizes, the slot-to-resource map and each pass's reads and
// writes, decided once per context from the backend's shader tables.
#include "ffx_dof_plan.h"

#include "ffx_dof_backend.h"

#include <cstring>
#include <string>
#include <vector>

namespace ffxdof {
namespace {

uint32_t divideRoundingUp(uint32_t value, uint32_t divisor) { return (value + divisor - 1) / divisor; }

// The class and index of a reflected binding. SPIR-V tables (GLSL or HLSL source) number bindings
// as class base + index in set 0; DXIL tables use the register number in the class of the kind, in
// space 0, except the storage buffers in space 1 (u# is shared with the storage images).
struct Slot {
    shaders::BindingKind kind;
    uint32_t index;
};

bool decodeSlot(const shaders::PassTable& table, const shaders::Binding& binding, Slot* slot) {
    const bool dxil = std::strcmp(table.language, "dxil") == 0;
    if (binding.arraySize > 1) return false;
    slot->kind = binding.kind;
    switch (binding.kind) {
        case shaders::BindingKind::SampledImage:
            slot->index = dxil ? binding.binding : binding.binding - FFX_DOF_SRV_BASE;
            return binding.set == 0 && (dxil || binding.binding < FFX_DOF_UAV_IMAGE_BASE) &&
                   slot->index < kSampledSlotCount;
        case shaders::BindingKind::StorageImage:
            slot->index = dxil ? binding.binding : binding.binding - FFX_DOF_UAV_IMAGE_BASE;
            return binding.set == 0 && (dxil || binding.binding >= FFX_DOF_UAV_IMAGE_BASE) &&
                   slot->index < kStorageImageSlotCount;
        case shaders::BindingKind::StorageBuffer:
            slot->index = dxil ? binding.binding : binding.binding - FFX_DOF_UAV_BUFFER_BASE;
            return binding.set == (dxil ? 1u : 0u) && (dxil || binding.binding >= FFX_DOF_UAV_BUFFER_BASE) &&
                   slot->index < kStorageBufferSlotCount;
        default:
            return false;  // samplers and uniform buffers have no slot in the resource table
    }
}

// The slot map: what every slot of every class is bound to (whether or not a pass declares it).
void mapSlots(ContextPlan* plan) {
    plan->sampledSlots[FFX_DOF_SRV_INPUT_COLOR].resource = Resource::InputColor;
    plan->sampledSlots[FFX_DOF_SRV_INPUT_DEPTH].resource = Resource::InputDepth;
    plan->storageImageSlots[FFX_DOF_UAV_OUTPUT].resource = Resource::Output;
    plan->storageBufferSlots[FFX_DOF_UAV_BUFFER_GLOBALS].resource = Resource::Globals;
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        const InternalImageSpec& spec = kInternalImages[i];
        const PlannedImage& image = plan->images[i];
        SlotTarget& sampled = plan->sampledSlots[spec.sampledSlot];
        sampled.resource = internalImageResource(i);
        sampled.mipCount = image.mipLevels;
        const uint32_t storageSlots = spec.mipChain ? kMipCount : 1;
        for (uint32_t level = 0; level < storageSlots; ++level) {
            SlotTarget& storage = plan->storageImageSlots[spec.storageSlot + level];
            storage.resource = internalImageResource(i);
            storage.firstMip = level < image.mipLevels ? level : image.mipLevels - 1;
        }
    }
}

FfxDofErrorCode planPass(const ContextPlan& context, Pass pass, const shaders::PassTable* table, PlannedPass* out) {
    const uint32_t p = uint32_t(pass);
    if (table == nullptr) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "the backend has no shaders for the pass %s", kPassNames[p]);
    }
    out->table = table;

    std::vector<shaders::Define> key;
    for (uint32_t a = 0; a < kPassAxisCount[p]; ++a) {
        const Axis axis = kPassAxes[p][a];
        key.emplace_back(kAxisMacros[uint32_t(axis)], axisValue(context.axes, axis));
    }
    std::string error;
    if (!shaders::findPermutationIndex(*table, key, &out->permutationIndex, &error)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "no %s permutation of the pass %s: %s", table->language, kPassNames[p],
                    error.c_str());
    }
    out->blob = &table->blobs[table->permutationToBlob[out->permutationIndex]];
    out->groups = passGroups(context.constants, pass);

    for (uint32_t b = 0; b < table->bindingCount; ++b) {
        const shaders::Binding& binding = table->bindings[b];
        if (binding.kind == shaders::BindingKind::PushConstants) {
            if (binding.size > sizeof(FfxDofConstants)) {
                return fail(FFX_DOF_ERROR_BACKEND, "the %s push constants are %u bytes; FfxDofConstants is %u",
                            kPassNames[p], binding.size, uint32_t(sizeof(FfxDofConstants)));
            }
            out->pushConstantBytes = binding.size;
            continue;
        }
        Slot slot{};
        if (!decodeSlot(*table, binding, &slot)) {
            return fail(FFX_DOF_ERROR_BACKEND,
                        "the %s %s shader declares %s (%s x%u, set/space %u, binding/register %u), which is no slot "
                        "of the resource table",
                        table->language, kPassNames[p], binding.name, shaders::bindingKindName(binding.kind),
                        binding.arraySize, binding.set, binding.binding);
        }
        switch (slot.kind) {
            case shaders::BindingKind::SampledImage:
                out->sampledSlots |= 1u << slot.index;
                out->reads |= resourceBit(context.sampledSlots[slot.index].resource);
                break;
            case shaders::BindingKind::StorageImage:
                out->storageSlots |= 1u << slot.index;
                out->writes |= resourceBit(context.storageImageSlots[slot.index].resource);
                break;
            default:
                out->bufferSlots |= 1u << slot.index;
                out->writes |= resourceBit(context.storageBufferSlots[slot.index].resource);
                break;
        }
    }
    return FFX_DOF_OK;
}

}  // namespace

FfxDofConstants contextConstants(const ContextConfig& config) {
    const uint32_t width = config.resolution.width;
    const uint32_t height = config.resolution.height;
    const uint32_t halfWidth = divideRoundingUp(width, 2);
    const uint32_t halfHeight = divideRoundingUp(height, 2);
    FfxDofConstants c{};
    // cocLimitFactor is relative to the full-resolution height; radii are in half-resolution pixels.
    c.cocLimit = config.cocLimitFactor * static_cast<float>(height) * 0.5f;
    c.maxRings = config.quality;
    c.fullSize = {width, height};
    c.halfSize = {halfWidth, halfHeight};
    c.tileCount = {divideRoundingUp(halfWidth, FFX_DOF_TILE_SIZE), divideRoundingUp(halfHeight, FFX_DOF_TILE_SIZE)};
    c.halfTexelSize = {1.0f / static_cast<float>(halfWidth), 1.0f / static_cast<float>(halfHeight)};
    c.fullTexelSize = {1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height)};
    c.outputFlags = 0;  // the backend adds FFX_DOF_OUTPUT_FLAG_ENCODE_SRGB where it writes through a UNORM view
    return c;
}

PassGrid passGroups(const FfxDofConstants& constants, Pass pass) {
    // Each pass covers a domain with groups of a fixed extent, both declared next to the resource
    // table (ffx_dof_resources.h), so shader and host cannot disagree.
    const uint32_t p = uint32_t(pass);
    FfxUInt32x2 domain = constants.fullSize;
    if (kPassDomain[p] == FFX_DOF_DOMAIN_HALF_RES) domain = constants.halfSize;
    if (kPassDomain[p] == FFX_DOF_DOMAIN_TILES) domain = constants.tileCount;
    return PassGrid{divideRoundingUp(domain.x, kPassGroupExtent[p]), divideRoundingUp(domain.y, kPassGroupExtent[p]),
                    1};
}

FfxDofErrorCode buildContextPlan(const ContextConfig& config, const BackendCapabilities& capabilities,
                                 ContextPlan* plan) {
    *plan = ContextPlan{};
    plan->config = config;
    plan->constants = contextConstants(config);
    setAxesFromContextFlags(config.flags, &plan->axes);
    plan->axes.half = capabilities.half ? 1u : 0u;
    plan->axes.wave64 = capabilities.wave64 ? 1u : 0u;

    const FfxDofConstants& c = plan->constants;
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        const InternalImageSpec& spec = kInternalImages[i];
        PlannedImage& image = plan->images[i];
        image.spec = &spec;
        image.width = spec.extent == ImageExtent::Half ? c.halfSize.x : c.tileCount.x;
        image.height = spec.extent == ImageExtent::Half ? c.halfSize.y : c.tileCount.y;
        image.mipLevels = mipLevelsFor(spec, image.width, image.height);
    }
    mapSlots(plan);

    for (uint32_t p = 0; p < kPassCount; ++p) {
        PlannedPass& pass = plan->passes[p];
        if (const FfxDofErrorCode status = planPass(*plan, Pass(p), capabilities.tables[p], &pass);
            status != FFX_DOF_OK) {
            return status;
        }
        for (uint32_t s = 0; s < kSampledSlotCount; ++s) plan->sampledSlots[s].used |= (pass.sampledSlots >> s) & 1u;
        for (uint32_t s = 0; s < kStorageImageSlotCount; ++s)
            plan->storageImageSlots[s].used |= (pass.storageSlots >> s) & 1u;
        for (uint32_t s = 0; s < kStorageBufferSlotCount; ++s)
            plan->storageBufferSlots[s].used |= (pass.bufferSlots >> s) & 1u;
        plan->touched |= pass.reads | pass.writes;
        plan->written |= pass.writes;
    }
    return FFX_DOF_OK;
}

DispatchPlan planDispatch(const ContextPlan& plan, const FfxDofDispatchDescription& dispatch, uint32_t frameIndex) {
    DispatchPlan out;
    out.commandList = dispatch.commandList;
    out.color = dispatch.color;
    out.depth = dispatch.depth;
    out.output = dispatch.output;
    out.outputIsColor = dispatch.output.handle == dispatch.color.handle;
    out.constants = plan.constants;
    out.constants.cocScale = dispatch.cocScale;
    out.constants.cocBias = dispatch.cocBias;
    out.constants.frameIndex = frameIndex;
    return out;
}

}  // namespace ffxdof
