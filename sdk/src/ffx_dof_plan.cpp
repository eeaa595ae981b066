// The core's planning: permutations, image sizes, the slot-to-resource map and each pass's reads and
// writes, decided once per context from the backend's shader tables.
#include "ffx_dof_plan.h"

#include "ffx_dof_backend.h"

#include "ffx_dof_aperture.h"

#include <cassert>
#include <cmath>
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
    plan->storageBufferSlots[FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS].resource = Resource::TileListArgs;
    plan->storageBufferSlots[FFX_DOF_UAV_BUFFER_TILE_LISTS].resource = Resource::TileLists;
    plan->storageBufferSlots[FFX_DOF_UAV_BUFFER_HIGHLIGHTS].resource = Resource::Highlights;
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        const InternalImageSpec& spec = kInternalImages[i];
        const PlannedImage& image = plan->images[i];
        SlotTarget& sampled = plan->sampledSlots[spec.sampledSlot];
        sampled.resource = internalImageResource(i);
        sampled.mipCount = image.mipLevels;
        for (uint32_t level = 0; level < spec.levels; ++level) {
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

    // The pass's per-dispatch axis, where the context's flag sets it, and its tile-list axis: one variant per
    // pair of their values, the tile-list values innermost (a dispatch runs one group of those).
    std::vector<uint32_t> dispatchValues;
    std::vector<uint32_t> listValues;
    constexpr uint32_t kNone = ~0u;
    uint32_t dispatchAxis = kNone;  // indices into kPassAxes[p]
    uint32_t listAxis = kNone;
    for (uint32_t a = 0; a < kPassAxisCount[p]; ++a) {
        const Axis axis = kPassAxes[p][a];
        const AxisDispatchValues& perDispatch = kAxisDispatchValues[uint32_t(axis)];
        if (perDispatch.count > 0 && axisValue(context.axes, axis) != 0) {
            dispatchValues.assign(perDispatch.values, perDispatch.values + perDispatch.count);
            dispatchAxis = a;
        } else if (kAxisRunsPerTileList[uint32_t(axis)]) {
            for (uint32_t value = 0; value < kAxisTileLists[uint32_t(axis)].count; ++value) {
                if (tileListRuns(axis, value, context.axes)) listValues.push_back(value);
            }
            listAxis = a;
        }
    }
    if (dispatchValues.empty()) dispatchValues.push_back(0);
    if (listValues.empty()) listValues.push_back(0);
    out->perTileList = listAxis != kNone;
    out->tileListVariants = uint32_t(listValues.size());
    out->variantCount = uint32_t(dispatchValues.size() * listValues.size());
    // The generated kMaxPassVariants is the largest product of a pass's per-dispatch values and lists, and
    // tileListRuns only leaves lists out: a pass with more is a generator fault, not a context's.
    assert(out->variantCount <= kMaxPassVariants && "more pipelines than kMaxPassVariants");
    for (uint32_t v = 0; v < out->variantCount; ++v) {
        PassVariant& variant = out->variants[v];
        variant.dispatchValue = dispatchAxis != kNone ? dispatchValues[v / out->tileListVariants] : 0;
        variant.tileListValue = listAxis != kNone ? listValues[v % out->tileListVariants] : 0;
        if (listAxis != kNone)
            variant.tileList = kAxisTileLists[uint32_t(kPassAxes[p][listAxis])].first + variant.tileListValue;
        std::vector<shaders::Define> key;
        for (uint32_t a = 0; a < kPassAxisCount[p]; ++a) {
            const Axis axis = kPassAxes[p][a];
            const uint32_t value = a == dispatchAxis ? variant.dispatchValue
                                   : a == listAxis   ? variant.tileListValue
                                                     : axisValue(context.axes, axis);
            key.emplace_back(kAxisMacros[uint32_t(axis)], value);
        }
        std::string error;
        if (!shaders::findPermutationIndex(*table, key, &variant.permutationIndex, &error)) {
            return fail(FFX_DOF_ERROR_UNSUPPORTED, "no %s permutation of the pass %s: %s", table->language,
                        kPassNames[p], error.c_str());
        }
        variant.blob = &table->blobs[table->permutationToBlob[variant.permutationIndex]];
    }
    if (out->perTileList) out->indirect = resourceBit(Resource::TileListArgs);
    out->groups = passGroups(context.constants, pass);

    for (uint32_t b = 0; b < table->bindingCount; ++b) {
        const shaders::Binding& binding = table->bindings[b];
        if (binding.kind == shaders::BindingKind::PushConstants) {
            if (binding.size > sizeof(FfxDofConstants)) {
                return fail(FFX_DOF_ERROR_BACKEND, "the %s push constants are %u bytes; FfxDofConstants is %u",
                            kPassNames[p], binding.size, uint32_t(sizeof(FfxDofConstants)));
            }
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

// A float field of a description, named for the error message.
struct NamedField {
    const char* name;
    float value;
};

// FFX_DOF_ERROR_INVALID_ARGUMENT naming the first field of `owner` that is not finite.
template <size_t N>
FfxDofErrorCode requireFinite(const char* owner, const NamedField (&fields)[N]) {
    for (const NamedField& field : fields) {
        if (!std::isfinite(field.value))
            return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "%s->%s is %g; it must be finite", owner, field.name,
                        double(field.value));
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
    c.outputFlags = 0;  // the backend adds FFX_DOF_OUTPUT_FLAG_ENCODE_SRGB where it writes through a UNORM view
    const FfxDofAperture round{0, 0.0f, 0.0f, 1.0f, 0.0f};
    setApertureConstants(round, &c);
    return c;
}

PassGrid passGroups(const FfxDofConstants& constants, Pass pass) {
    // Each pass covers a domain with groups of a fixed extent, both declared next to the resource
    // table (ffx_dof_resources.h), so shader and host cannot disagree.
    const uint32_t p = uint32_t(pass);
    if (kPassDomain[p] == FFX_DOF_DOMAIN_SINGLE) return PassGrid{1, 1, 1};
    FfxUInt32x2 domain = constants.fullSize;
    if (kPassDomain[p] == FFX_DOF_DOMAIN_HALF_RES) domain = constants.halfSize;
    if (kPassDomain[p] == FFX_DOF_DOMAIN_TILES) domain = constants.tileCount;
    return PassGrid{divideRoundingUp(domain.x, kPassGroupExtent[p]), divideRoundingUp(domain.y, kPassGroupExtent[p]),
                    1};
}

void sizeInternalImages(const FfxDofConstants& constants, PlannedImage images[kInternalImageCount]) {
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        const InternalImageSpec& spec = kInternalImages[i];
        PlannedImage& image = images[i];
        image.spec = &spec;
        switch (spec.extent) {
            case ImageExtent::Half:
                image.width = constants.halfSize.x;
                image.height = constants.halfSize.y;
                break;
            case ImageExtent::Quarter:
                image.width = constants.halfSize.x / 2 > 0 ? constants.halfSize.x / 2 : 1;
                image.height = constants.halfSize.y / 2 > 0 ? constants.halfSize.y / 2 : 1;
                break;
            case ImageExtent::Tiles:
                image.width = constants.tileCount.x;
                image.height = constants.tileCount.y;
                break;
        }
        image.mipLevels = mipLevelsFor(spec, image.width, image.height);
    }
}

uint64_t internalResourceBytes(const ContextConfig& config) {
    const FfxDofConstants constants = contextConstants(config);
    PlannedImage images[kInternalImageCount];
    sizeInternalImages(constants, images);
    uint64_t bytes = 0;
    for (const PlannedImage& image : images) {
        for (uint32_t level = 0; level < image.mipLevels; ++level) {
            const uint64_t width = image.width >> level > 0 ? image.width >> level : 1;
            const uint64_t height = image.height >> level > 0 ? image.height >> level : 1;
            bytes += width * height * internalFormatTexelBytes(image.spec->format);
        }
    }
    const FfxUInt32x2 tiles = constants.tileCount;
    return bytes + kGlobalsBufferBytes + kTileListArgsBytes + uint64_t(tileListsWordCount(tiles.x, tiles.y)) * 4 +
           uint64_t(highlightsWordCount(tiles.x, tiles.y)) * 4;
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
    sizeInternalImages(c, plan->images);
    mapSlots(plan);

    for (uint32_t p = 0; p < kPassCount; ++p) {
        PlannedPass& pass = plan->passes[p];
        if (const FfxDofErrorCode status = planPass(*plan, Pass(p), capabilities.tables[p], &pass);
            status != FFX_DOF_OK) {
            return status;
        }
        plan->touched |= pass.reads | pass.writes | pass.indirect;
        plan->indirect |= pass.indirect;
    }
    plan->tileListsBytes = tileListsWordCount(c.tileCount.x, c.tileCount.y) * 4;
    plan->highlightsBytes = highlightsWordCount(c.tileCount.x, c.tileCount.y) * 4;
    return FFX_DOF_OK;
}

FfxDofErrorCode checkAutofocus(const FfxDofAutofocus& a) {
    const NamedField fields[] = {{"regionCenter[0]", a.regionCenter[0]},
                                 {"regionCenter[1]", a.regionCenter[1]},
                                 {"regionSize[0]", a.regionSize[0]},
                                 {"regionSize[1]", a.regionSize[1]},
                                 {"aperture", a.aperture},
                                 {"focalLength", a.focalLength},
                                 {"conversion", a.conversion},
                                 {"proj33", a.proj33},
                                 {"proj34", a.proj34},
                                 {"proj43", a.proj43},
                                 {"minFocusDistance", a.minFocusDistance},
                                 {"maxFocusDistance", a.maxFocusDistance},
                                 {"timeConstant", a.timeConstant},
                                 {"deltaTime", a.deltaTime}};
    if (const FfxDofErrorCode status = requireFinite("pAutofocus", fields); status != FFX_DOF_OK) return status;
    for (int i = 0; i < 2; ++i) {
        if (a.regionCenter[i] < 0.0f || a.regionCenter[i] > 1.0f)
            return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "pAutofocus->regionCenter[%d] is %g; it must be in 0..1", i,
                        double(a.regionCenter[i]));
        if (!(a.regionSize[i] > 0.0f) || a.regionSize[i] > 1.0f)
            return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "pAutofocus->regionSize[%d] is %g; it must be in (0, 1]", i,
                        double(a.regionSize[i]));
    }
    if (a.aperture < 0.0f)
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "pAutofocus->aperture is %g; it must be >= 0", double(a.aperture));
    if (!(a.focalLength > 0.0f) || !(a.conversion > 0.0f))
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "pAutofocus->focalLength (%g) and conversion (%g) must be > 0",
                    double(a.focalLength), double(a.conversion));
    if (a.proj34 == 0.0f || a.proj43 == 0.0f)
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT,
                    "pAutofocus->proj34 (%g) and proj43 (%g) must not be 0 (a perspective projection)",
                    double(a.proj34), double(a.proj43));
    if (!(a.minFocusDistance > a.focalLength) || a.maxFocusDistance < a.minFocusDistance)
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT,
                    "pAutofocus: focus distances must satisfy focalLength (%g) < minFocusDistance (%g) <= "
                    "maxFocusDistance (%g)",
                    double(a.focalLength), double(a.minFocusDistance), double(a.maxFocusDistance));
    if (a.timeConstant < 0.0f || a.deltaTime < 0.0f)
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "pAutofocus->timeConstant (%g) and deltaTime (%g) must be >= 0",
                    double(a.timeConstant), double(a.deltaTime));
    return FFX_DOF_OK;
}

FfxDofErrorCode checkAperture(const FfxDofAperture& a) {
    const NamedField fields[] = {{"bladeRotation", a.bladeRotation},
                                 {"roundness", a.roundness},
                                 {"anamorphicRatio", a.anamorphicRatio},
                                 {"catEye", a.catEye}};
    if (const FfxDofErrorCode status = requireFinite("pAperture", fields); status != FFX_DOF_OK) return status;
    if (a.bladeCount != 0 && (a.bladeCount < 3 || a.bladeCount > FFX_DOF_MAX_APERTURE_BLADES))
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "pAperture->bladeCount is %u; it must be 0 (round) or 3..%u",
                    a.bladeCount, FFX_DOF_MAX_APERTURE_BLADES);
    if (a.roundness < 0.0f || a.roundness > 1.0f)
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "pAperture->roundness is %g; it must be in 0..1",
                    double(a.roundness));
    if (a.anamorphicRatio < FFX_DOF_MIN_ANAMORPHIC_RATIO || a.anamorphicRatio > FFX_DOF_MAX_ANAMORPHIC_RATIO)
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "pAperture->anamorphicRatio is %g; it must be in %g..%g",
                    double(a.anamorphicRatio), double(FFX_DOF_MIN_ANAMORPHIC_RATIO),
                    double(FFX_DOF_MAX_ANAMORPHIC_RATIO));
    if (a.catEye < 0.0f || a.catEye > 1.0f)
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "pAperture->catEye is %g; it must be in 0..1", double(a.catEye));
    return FFX_DOF_OK;
}

bool isRoundAperture(const FfxDofAperture& a) {
    return (a.bladeCount == 0 || a.roundness >= 1.0f) && a.anamorphicRatio == 1.0f && a.catEye == 0.0f;
}

void setApertureConstants(const FfxDofAperture& a, FfxDofConstants* c) {
    // Fully round blades are the circle: the blade loop is skipped rather than run to no effect.
    const bool blades = a.bladeCount >= 3 && a.roundness < 1.0f;
    float shapeArea = FFX_DOF_PI;
    c->bladeCount = 0;
    c->bladeNormal = {0.0f, 0.0f};
    if (blades) {
        const float inradius = ffxDofBladeInradius(a.bladeCount, a.roundness);
        c->bladeCount = a.bladeCount;
        c->bladeNormal = {std::cos(a.bladeRotation) / inradius, std::sin(a.bladeRotation) / inradius};
        shapeArea = ffxDofBladeShapeArea(a.bladeCount, inradius);
    }
    c->anamorphicRatio = a.anamorphicRatio;
    // The round disc's scale is the ratio itself, exactly (1 by default: the weights are unchanged).
    c->apertureAreaScale = (blades ? FFX_DOF_PI / shapeArea : 1.0f) * a.anamorphicRatio;
    c->catEye = a.catEye;
}

bool tileListRuns(Axis axis, uint32_t value, const PermutationAxes& axes) {
    // In place the output holds the input already: the composite's copy class has nothing to do.
    return !(axis == Axis::CompositeClass && value == FFX_DOF_COMPOSITE_CLASS_COPY && axes.outputPreInit != 0);
}

uint32_t dispatchAxisValue(Axis axis, const FfxDofConstants& constants) {
    if (axis == Axis::ApertureShapes) {
        return ffxDofApertureGaugeIsCompact(constants.bladeCount, constants.catEye) ? FFX_DOF_APERTURE_SHAPES_COMPACT
                                                                                    : FFX_DOF_APERTURE_SHAPES_ANY;
    }
    return 0;
}

DispatchPlan planDispatch(const ContextPlan& plan, const FfxDofDispatchDescription& dispatch, uint32_t frameIndex,
                          bool resetAutofocus) {
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
    for (uint32_t p = 0; p < kPassCount; ++p) out.runs[p] = Pass(p) != Pass::Autofocus;
    if (dispatch.pAperture) setApertureConstants(*dispatch.pAperture, &out.constants);
    if (const FfxDofAutofocus* a = dispatch.pAutofocus) {
        out.runs[uint32_t(Pass::Autofocus)] = true;
        FfxDofConstants& c = out.constants;
        c.focusRegionCenter = {a->regionCenter[0], a->regionCenter[1]};
        c.focusRegionSize = {a->regionSize[0], a->regionSize[1]};
        // 1 / z = depth * p43 / p34 - p33 / p34 (docs/coc.md).
        c.focusInvZScale = a->proj43 / a->proj34;
        c.focusInvZBias = a->proj33 / a->proj34;
        c.focusLensFactor = a->aperture * a->focalLength * a->conversion;
        c.focusFocalLength = a->focalLength;
        // In front of the camera clip w = p43 z is positive: z has the sign of p43.
        const float side = a->proj43 > 0.0f ? 1.0f : -1.0f;
        c.focusMinDistance = side * a->minFocusDistance;
        c.focusMaxDistance = side * a->maxFocusDistance;
        c.focusBlend = a->timeConstant > 0.0f ? float(1.0 - std::exp(-double(a->deltaTime) / a->timeConstant)) : 1.0f;
        c.focusFlags = FFX_DOF_FOCUS_FLAG_AUTO | (resetAutofocus ? FFX_DOF_FOCUS_FLAG_RESET : 0u);
    }
    for (uint32_t p = 0; p < kPassCount; ++p) {
        const PlannedPass& pass = plan.passes[p];
        if (pass.variantCount == pass.tileListVariants) continue;  // no per-dispatch axis
        for (uint32_t a = 0; a < kPassAxisCount[p]; ++a) {
            const Axis axis = kPassAxes[p][a];
            if (kAxisDispatchValues[uint32_t(axis)].count == 0) continue;
            const uint32_t value = dispatchAxisValue(axis, out.constants);
            bool planned = false;
            for (uint32_t v = 0; v < pass.variantCount && !planned; v += pass.tileListVariants) {
                if (pass.variants[v].dispatchValue == value) {
                    out.variants[p] = v;
                    planned = true;
                }
            }
            // dispatchAxisValue may only answer values of the JSON's "perDispatch" list, which planPass made
            // variants of: a value without one is a rule that forgot an axis value, not a user error.
            assert(planned && "dispatchAxisValue returned a value the pass has no variant for");
            (void)planned;
        }
    }
    return out;
}

}  // namespace ffxdof
