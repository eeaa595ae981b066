// A D3D12 context: the internal resources, the descriptor ring, and the recording of one dispatch
// (descriptors, barriers, the five passes) into the engine's command list.
#include "ffx_dof_context.h"
#include "ffx_dof_dx12_backend.h"
#include "ffx_dof_dx12_formats.h"
#include "ffx_dof_dx12_state_tracker.h"
#include "ffx_dof_readback_ring.h"

#include <cstddef>
#include <cstdint>
#include <new>

namespace ffxdof::dx12 {
namespace {

// DXGI formats of the internal images; the images themselves are listed once, API-neutral, in
// sdk/src/ffx_dof_passes.h (kInternalImages). B10G11R11 there is DXGI's R11G11B10_FLOAT: same bits.
constexpr DXGI_FORMAT toDxgiFormat(InternalFormat format) {
    switch (format) {
        case InternalFormat::R11G11B10Float:
            return DXGI_FORMAT_R11G11B10_FLOAT;
        case InternalFormat::R16Float:
            return DXGI_FORMAT_R16_FLOAT;
        case InternalFormat::R16G16B16A16Float:
            return DXGI_FORMAT_R16G16B16A16_FLOAT;
        case InternalFormat::R8Unorm:
            return DXGI_FORMAT_R8_UNORM;
        case InternalFormat::R32G32Uint:
            return DXGI_FORMAT_R32G32_UINT;
    }
    return DXGI_FORMAT_UNKNOWN;
}

D3D12_RESOURCE_DESC bufferDescription(UINT64 bytes, D3D12_RESOURCE_FLAGS flags) {
    D3D12_RESOURCE_DESC desc{};
    desc.Dimension = D3D12_RESOURCE_DIMENSION_BUFFER;
    desc.Width = bytes;
    desc.Height = 1;
    desc.DepthOrArraySize = 1;
    desc.MipLevels = 1;
    desc.Format = DXGI_FORMAT_UNKNOWN;
    desc.SampleDesc.Count = 1;
    desc.Layout = D3D12_TEXTURE_LAYOUT_ROW_MAJOR;
    desc.Flags = flags;
    return desc;
}

// The storage buffers (FFX_DOF_UAV_BUFFER_*) are RWStructuredBuffer<uint> in HLSL, so structured UAVs.
constexpr UINT kBufferElementBytes = 4;

// An engine image, checked and with the view format the backend uses for it.
struct EngineImage {
    ID3D12Resource* resource = nullptr;
    DXGI_FORMAT viewFormat = DXGI_FORMAT_UNKNOWN;
    bool srgb = false;
    D3D12_RESOURCE_STATES state = D3D12_RESOURCE_STATE_COMMON;
};

FfxDofErrorCode checkEngineImage(const FfxDofResource& image, ImageRole role, const char* name, EngineImage* out) {
    char declaredName[32];
    char resourceName[32];
    char familyName[32];
    const DXGI_FORMAT declared = static_cast<DXGI_FORMAT>(image.format);
    const FormatRule* rule = findFormatRule(declared, role);
    if (rule == nullptr)
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "%s: %s is not accepted for this image (docs/integration-d3d12.md "
                    "lists the formats)",
                    name, describeFormat(declared, declaredName));
    ID3D12Resource* resource = reinterpret_cast<ID3D12Resource*>(static_cast<uintptr_t>(image.handle));
    const D3D12_RESOURCE_DESC desc = resource->GetDesc();
    if (desc.Dimension != D3D12_RESOURCE_DIMENSION_TEXTURE2D || desc.DepthOrArraySize != 1)
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s: the resource is not a single 2D texture", name);
    if (desc.SampleDesc.Count != 1)
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s: the resource has %u samples; resolve it first", name,
                    desc.SampleDesc.Count);
    if (desc.Width != image.width || desc.Height != image.height)
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s: declared %ux%u but the resource is %llux%u", name, image.width,
                    image.height, static_cast<unsigned long long>(desc.Width), desc.Height);
    const DXGI_FORMAT view = role == ImageRole::Output ? rule->uav : rule->srv;
    if (!viewableOn(*rule, view, desc.Format))
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "%s: a %s view cannot be made on a resource created as %s; create the resource as %s", name,
                    describeFormat(view, declaredName), describeFormat(desc.Format, resourceName),
                    describeFormat(rule->family, familyName));
    if (role == ImageRole::Output && !(desc.Flags & D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS))
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s: the resource lacks D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS",
                    name);
    if (role != ImageRole::Output && (desc.Flags & D3D12_RESOURCE_FLAG_DENY_SHADER_RESOURCE))
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s: the resource has D3D12_RESOURCE_FLAG_DENY_SHADER_RESOURCE",
                    name);
    out->resource = resource;
    out->viewFormat = view;
    out->srgb = rule->srgb;
    out->state = static_cast<D3D12_RESOURCE_STATES>(image.state);
    return FFX_DOF_OK;
}

class Context final : public BackendContext {
public:
    Context(const Backend& backend, const ContextPlan& plan)
        : backend_(backend), plan_(plan), readbackRing_(backend.framesInFlight()) {}

    FfxDofErrorCode init();
    FfxDofErrorCode dispatch(const DispatchPlan& plan) override;
    FfxDofMemoryUsage memoryUsage() const override { return memory_; }
    FfxDofErrorCode autofocusDistance(uint32_t dispatchesAgo, float* distance) const override;

private:
    struct InternalImage {
        ComPtr<ID3D12Resource> resource;
        D3D12_RESOURCE_STATES rest = kReadState;  // every level, between dispatches
    };

    // Tracks the internal levels (always first, in a fixed order) and fills their slot targets.
    void trackInternalImages(StateTracker* tracker, SlotTargets* slots) const;
    // Runs the passes' barrier logic without a command list to find where each image ends up.
    void chooseRestStates();
    FfxDofErrorCode createPipelines();
    FfxDofErrorCode createResources();
    FfxDofErrorCode createReadback();
    void recordFocusReadback(ID3D12GraphicsCommandList* list, uint32_t slot) const;
    FfxDofErrorCode createDescriptorHeap();
    FfxDofErrorCode checkOutputFormatSupport(DXGI_FORMAT format);

    D3D12_CPU_DESCRIPTOR_HANDLE cpuDescriptor(uint32_t ringSlot, uint32_t offset) const {
        D3D12_CPU_DESCRIPTOR_HANDLE handle = heapCpuStart_;
        handle.ptr += static_cast<SIZE_T>(ringSlot * kDescriptorsPerDispatch + offset) * backend_.descriptorSize();
        return handle;
    }
    void writeSrv(ID3D12Resource* resource, DXGI_FORMAT format, UINT mipLevels, D3D12_CPU_DESCRIPTOR_HANDLE at) const;
    void writeUav(ID3D12Resource* resource, DXGI_FORMAT format, UINT mip, D3D12_CPU_DESCRIPTOR_HANDLE at) const;

    const Backend& backend_;
    const ContextPlan& plan_;
    ComPtr<ID3D12PipelineState> pipelines_[kPassCount][kMaxPassVariants];  // [pass][variant]
    InternalImage images_[kInternalImageCount];
    ComPtr<ID3D12Resource> buffers_[kUavBufferCount];  // [FFX_DOF_UAV_BUFFER_*]
    UINT bufferElements_[kUavBufferCount] = {};
    ID3D12Resource* globals() const { return buffers_[FFX_DOF_UAV_BUFFER_GLOBALS].Get(); }
    // The focus distances of the last autofocus dispatches (ffxDofContextGetAutofocusDistance): a
    // readback buffer, mapped for the context's life, one float per slot of the ring.
    AutofocusReadbackRing readbackRing_;
    ComPtr<ID3D12Resource> readback_;
    const float* readbackValues_ = nullptr;
    ComPtr<ID3D12DescriptorHeap> heap_;
    D3D12_CPU_DESCRIPTOR_HANDLE heapCpuStart_{};
    D3D12_GPU_DESCRIPTOR_HANDLE heapGpuStart_{};
    uint32_t nextRingSlot_ = 0;
    FfxDofMemoryUsage memory_{};
    DXGI_FORMAT supportedOutputFormat_ = DXGI_FORMAT_UNKNOWN;  // last output format found usable
};

FfxDofErrorCode Context::init() {
    if (const FfxDofErrorCode status = createPipelines(); status != FFX_DOF_OK) return status;
    chooseRestStates();
    if (const FfxDofErrorCode status = createResources(); status != FFX_DOF_OK) return status;
    if (const FfxDofErrorCode status = createReadback(); status != FFX_DOF_OK) return status;
    return createDescriptorHeap();
}

FfxDofErrorCode Context::createPipelines() {
    for (uint32_t p = 0; p < kPassCount; ++p) {
        for (uint32_t v = 0; v < plan_.passes[p].variantCount; ++v) {
            if (const FfxDofErrorCode status =
                    backend_.pipeline(kPassNames[p], plan_.passes[p].variants[v], &pipelines_[p][v]);
                status != FFX_DOF_OK)
                return status;
        }
    }
    return FFX_DOF_OK;
}

void Context::trackInternalImages(StateTracker* tracker, SlotTargets* slots) const {
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        const InternalImageSpec& spec = kInternalImages[i];
        const InternalImage& image = images_[i];
        const uint32_t levels = plan_.images[i].mipLevels;
        uint8_t levelEntries[kMipCount] = {};
        for (uint32_t mip = 0; mip < levels; ++mip) {
            levelEntries[mip] = tracker->track(image.resource.Get(), mip, image.rest, image.rest);
        }
        slots->srv[spec.sampledSlot] = {levelEntries[0], static_cast<uint8_t>(levels)};
    }
    // TILE_LIST_ARGS changes state (UAV, then the composite's indirect arguments); it rests in COMMON,
    // the state a buffer is created in.
    const uint8_t args =
        tracker->track(buffers_[FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS].Get(), D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES,
                       D3D12_RESOURCE_STATE_COMMON, D3D12_RESOURCE_STATE_COMMON);
    slots->uavBuffer[FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS] = args;
    slots->indirectArgs = args;
    // Storage slots as the plan maps them (a level a small image lacks aliases its last level).
    for (uint32_t slot = 0; slot < kUavImageCount; ++slot) {
        const SlotTarget& target = plan_.storageImageSlots[slot];
        if (!isInternalImage(target.resource)) continue;
        const uint32_t image = internalImageIndex(target.resource);
        slots->uavImage[slot] =
            static_cast<uint8_t>(slots->srv[kInternalImages[image].sampledSlot].first + target.firstMip);
    }
}

void Context::chooseRestStates() {
    // Rest in the state each image's level 0 has after the last pass, so that the end of a dispatch
    // needs no barrier for it and the next dispatch starts from a known state whatever order the
    // engine records command lists in. (Levels that end elsewhere are moved back at the end.)
    StateTracker tracker;
    SlotTargets slots;
    trackInternalImages(&tracker, &slots);
    for (const PlannedPass& pass : plan_.passes) {
        tracker.beforePass(slots, pass, nullptr);  // no barrier is recorded
        tracker.afterPass(pass);
        tracker.flush(nullptr);
    }
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        images_[i].rest = tracker.entry(slots.srv[kInternalImages[i].sampledSlot].first).state;
    }
}

FfxDofErrorCode Context::createResources() {
    ID3D12Device* device = backend_.device();
    D3D12_HEAP_PROPERTIES heap{};
    heap.Type = D3D12_HEAP_TYPE_DEFAULT;
    for (uint32_t i = 0; i < kInternalImageCount; ++i) {
        InternalImage& image = images_[i];
        const PlannedImage& planned = plan_.images[i];
        D3D12_RESOURCE_DESC desc{};
        desc.Dimension = D3D12_RESOURCE_DIMENSION_TEXTURE2D;
        desc.Width = planned.width;
        desc.Height = planned.height;
        desc.DepthOrArraySize = 1;
        desc.MipLevels = static_cast<UINT16>(planned.mipLevels);
        desc.Format = toDxgiFormat(kInternalImages[i].format);
        desc.SampleDesc.Count = 1;
        desc.Layout = D3D12_TEXTURE_LAYOUT_UNKNOWN;
        desc.Flags = D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS;
        const HRESULT hr = device->CreateCommittedResource(&heap, D3D12_HEAP_FLAG_NONE, &desc, image.rest, nullptr,
                                                           IID_PPV_ARGS(&image.resource));
        if (FAILED(hr))
            return fail(hr == E_OUTOFMEMORY ? FFX_DOF_ERROR_OUT_OF_MEMORY : FFX_DOF_ERROR_BACKEND,
                        "creating internal image %s (%ux%u, %u levels) failed (HRESULT 0x%08lx)",
                        kInternalImages[i].name, planned.width, planned.height, planned.mipLevels,
                        static_cast<unsigned long>(hr));
        const D3D12_RESOURCE_ALLOCATION_INFO info = device->GetResourceAllocationInfo(0, 1, &desc);
        memory_.totalUsageInBytes += info.SizeInBytes;
        memory_.aliasableUsageInBytes += info.SizeInBytes;  // rewritten by every dispatch before it is read
    }

    // A committed resource in a default heap starts zeroed (no D3D12_HEAP_FLAG_CREATE_NOT_ZEROED),
    // which is the "zero before the first dispatch" that GLOBALS needs. Not aliasable: it carries the
    // zeros the passes write back into the next dispatch. TILE_LIST_ARGS, TILE_LISTS and HIGHLIGHTS are
    // rewritten by every dispatch before they are read.
    bufferElements_[FFX_DOF_UAV_BUFFER_GLOBALS] = kGlobalsWordCount;
    bufferElements_[FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS] = kTileListArgsWordCount;
    bufferElements_[FFX_DOF_UAV_BUFFER_TILE_LISTS] = plan_.tileListsBytes / kBufferElementBytes;
    bufferElements_[FFX_DOF_UAV_BUFFER_HIGHLIGHTS] = plan_.highlightsBytes / kBufferElementBytes;
    const char* const names[kUavBufferCount] = {"GLOBALS", "TILE_LIST_ARGS", "TILE_LISTS", "HIGHLIGHTS"};
    static_assert(FFX_DOF_UAV_BUFFER_GLOBALS == 0 && FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS == 1 &&
                      FFX_DOF_UAV_BUFFER_TILE_LISTS == 2 && FFX_DOF_UAV_BUFFER_HIGHLIGHTS == 3 && kUavBufferCount == 4,
                  "elements and names are listed by storage buffer slot");
    for (uint32_t slot = 0; slot < kUavBufferCount; ++slot) {
        const D3D12_RESOURCE_DESC desc = bufferDescription(UINT64(kBufferElementBytes) * bufferElements_[slot],
                                                           D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS);
        const HRESULT hr = device->CreateCommittedResource(
            &heap, D3D12_HEAP_FLAG_NONE, &desc, D3D12_RESOURCE_STATE_COMMON, nullptr, IID_PPV_ARGS(&buffers_[slot]));
        if (FAILED(hr))
            return fail(hr == E_OUTOFMEMORY ? FFX_DOF_ERROR_OUT_OF_MEMORY : FFX_DOF_ERROR_BACKEND,
                        "creating the %s buffer failed (HRESULT 0x%08lx)", names[slot], static_cast<unsigned long>(hr));
        const UINT64 bytes = device->GetResourceAllocationInfo(0, 1, &desc).SizeInBytes;
        memory_.totalUsageInBytes += bytes;
        if (slot != FFX_DOF_UAV_BUFFER_GLOBALS) memory_.aliasableUsageInBytes += bytes;
    }
    return FFX_DOF_OK;
}

FfxDofErrorCode Context::createReadback() {
    const uint32_t slots = readbackRing_.slotCount();
    D3D12_HEAP_PROPERTIES heap{};
    heap.Type = D3D12_HEAP_TYPE_READBACK;
    const D3D12_RESOURCE_DESC desc = bufferDescription(slots * sizeof(float), D3D12_RESOURCE_FLAG_NONE);
    HRESULT hr = backend_.device()->CreateCommittedResource(
        &heap, D3D12_HEAP_FLAG_NONE, &desc, D3D12_RESOURCE_STATE_COPY_DEST, nullptr, IID_PPV_ARGS(&readback_));
    if (FAILED(hr))
        return fail(hr == E_OUTOFMEMORY ? FFX_DOF_ERROR_OUT_OF_MEMORY : FFX_DOF_ERROR_BACKEND,
                    "creating the autofocus readback buffer failed (HRESULT 0x%08lx)", static_cast<unsigned long>(hr));
    memory_.totalUsageInBytes += backend_.device()->GetResourceAllocationInfo(0, 1, &desc).SizeInBytes;
    void* mapped = nullptr;
    hr = readback_->Map(0, nullptr, &mapped);
    if (FAILED(hr))
        return fail(FFX_DOF_ERROR_BACKEND, "mapping the autofocus readback buffer failed (HRESULT 0x%08lx)",
                    static_cast<unsigned long>(hr));
    readbackValues_ = static_cast<const float*>(mapped);
    return FFX_DOF_OK;
}

void Context::recordFocusReadback(ID3D12GraphicsCommandList* list, uint32_t slot) const {
    // GLOBALS is a UAV during the passes; the copy reads it, then it is a UAV again for whatever the
    // list records next (another dispatch of this context).
    D3D12_RESOURCE_BARRIER barrier{};
    barrier.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
    barrier.Transition.pResource = globals();
    barrier.Transition.Subresource = D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES;
    barrier.Transition.StateBefore = D3D12_RESOURCE_STATE_UNORDERED_ACCESS;
    barrier.Transition.StateAfter = D3D12_RESOURCE_STATE_COPY_SOURCE;
    list->ResourceBarrier(1, &barrier);
    list->CopyBufferRegion(readback_.Get(), slot * sizeof(float), globals(),
                           FFX_DOF_GLOBALS_FOCUS_DISTANCE * kBufferElementBytes, sizeof(float));
    barrier.Transition.StateBefore = D3D12_RESOURCE_STATE_COPY_SOURCE;
    barrier.Transition.StateAfter = D3D12_RESOURCE_STATE_UNORDERED_ACCESS;
    list->ResourceBarrier(1, &barrier);
}

FfxDofErrorCode Context::autofocusDistance(uint32_t dispatchesAgo, float* distance) const {
    return readbackRing_.read(dispatchesAgo, readbackValues_, distance);
}

void Context::writeSrv(ID3D12Resource* resource, DXGI_FORMAT format, UINT mipLevels,
                       D3D12_CPU_DESCRIPTOR_HANDLE at) const {
    D3D12_SHADER_RESOURCE_VIEW_DESC desc{};
    desc.Format = format;
    desc.ViewDimension = D3D12_SRV_DIMENSION_TEXTURE2D;
    desc.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
    desc.Texture2D.MipLevels = mipLevels;
    desc.Texture2D.PlaneSlice = 0;  // the depth plane of a depth-stencil format
    backend_.device()->CreateShaderResourceView(resource, &desc, at);
}

void Context::writeUav(ID3D12Resource* resource, DXGI_FORMAT format, UINT mip, D3D12_CPU_DESCRIPTOR_HANDLE at) const {
    D3D12_UNORDERED_ACCESS_VIEW_DESC desc{};
    desc.Format = format;
    desc.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE2D;
    desc.Texture2D.MipSlice = mip;
    backend_.device()->CreateUnorderedAccessView(resource, nullptr, &desc, at);
}

FfxDofErrorCode Context::createDescriptorHeap() {
    D3D12_DESCRIPTOR_HEAP_DESC desc{};
    desc.Type = D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV;
    desc.NumDescriptors = kDescriptorsPerDispatch * backend_.framesInFlight();
    desc.Flags = D3D12_DESCRIPTOR_HEAP_FLAG_SHADER_VISIBLE;
    const HRESULT hr = backend_.device()->CreateDescriptorHeap(&desc, IID_PPV_ARGS(&heap_));
    if (FAILED(hr))
        return fail(FFX_DOF_ERROR_BACKEND,
                    "creating a shader-visible descriptor heap of %u descriptors failed (HRESULT "
                    "0x%08lx)",
                    desc.NumDescriptors, static_cast<unsigned long>(hr));
    heapCpuStart_ = heap_->GetCPUDescriptorHandleForHeapStart();
    heapGpuStart_ = heap_->GetGPUDescriptorHandleForHeapStart();

    // The internal descriptors are the same in every ring slot; a dispatch writes only the engine's.
    for (uint32_t slot = 0; slot < backend_.framesInFlight(); ++slot) {
        for (uint32_t s = 0; s < kSrvCount; ++s) {
            const SlotTarget& target = plan_.sampledSlots[s];
            if (!isInternalImage(target.resource)) continue;
            const uint32_t i = internalImageIndex(target.resource);
            writeSrv(images_[i].resource.Get(), toDxgiFormat(kInternalImages[i].format), target.mipCount,
                     cpuDescriptor(slot, kSrvTableOffset + s));
        }
        for (uint32_t s = 0; s < kUavImageCount; ++s) {
            const SlotTarget& target = plan_.storageImageSlots[s];
            if (!isInternalImage(target.resource)) continue;
            const uint32_t i = internalImageIndex(target.resource);
            writeUav(images_[i].resource.Get(), toDxgiFormat(kInternalImages[i].format), target.firstMip,
                     cpuDescriptor(slot, kUavImageTableOffset + s));
        }
        for (uint32_t b = 0; b < kUavBufferCount; ++b) {
            D3D12_UNORDERED_ACCESS_VIEW_DESC view{};
            view.Format = DXGI_FORMAT_UNKNOWN;
            view.ViewDimension = D3D12_UAV_DIMENSION_BUFFER;
            view.Buffer.NumElements = bufferElements_[b];
            view.Buffer.StructureByteStride = kBufferElementBytes;
            backend_.device()->CreateUnorderedAccessView(buffers_[b].Get(), nullptr, &view,
                                                         cpuDescriptor(slot, kUavBufferTableOffset + b));
        }
    }
    return FFX_DOF_OK;
}

FfxDofErrorCode Context::checkOutputFormatSupport(DXGI_FORMAT format) {
    if (format == supportedOutputFormat_) return FFX_DOF_OK;
    D3D12_FEATURE_DATA_FORMAT_SUPPORT support{};
    support.Format = format;
    // In place, the composite pass also loads the color through the output UAV.
    const UINT needed2 =
        D3D12_FORMAT_SUPPORT2_UAV_TYPED_STORE | (plan_.axes.outputPreInit ? D3D12_FORMAT_SUPPORT2_UAV_TYPED_LOAD : 0);
    char name[32];
    if (FAILED(backend_.device()->CheckFeatureSupport(D3D12_FEATURE_FORMAT_SUPPORT, &support, sizeof(support))) ||
        !(support.Support1 & D3D12_FORMAT_SUPPORT1_TYPED_UNORDERED_ACCESS_VIEW) ||
        (support.Support2 & needed2) != needed2)
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "output: the device cannot %s typed UAVs of %s",
                    plan_.axes.outputPreInit ? "load and store" : "store", describeFormat(format, name));
    supportedOutputFormat_ = format;
    return FFX_DOF_OK;
}

FfxDofErrorCode Context::dispatch(const DispatchPlan& plan) {
    ID3D12GraphicsCommandList* list = static_cast<ID3D12GraphicsCommandList*>(plan.commandList);
    const D3D12_COMMAND_LIST_TYPE listType = list->GetType();
    if (listType != D3D12_COMMAND_LIST_TYPE_DIRECT && listType != D3D12_COMMAND_LIST_TYPE_COMPUTE)
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "commandList is of type %d; it must be DIRECT or COMPUTE",
                    static_cast<int>(listType));

    EngineImage color, depth, output;
    if (const FfxDofErrorCode status = checkEngineImage(plan.color, ImageRole::Color, "color", &color);
        status != FFX_DOF_OK)
        return status;
    if (const FfxDofErrorCode status = checkEngineImage(plan.depth, ImageRole::Depth, "depth", &depth);
        status != FFX_DOF_OK)
        return status;
    if (const FfxDofErrorCode status = checkEngineImage(plan.output, ImageRole::Output, "output", &output);
        status != FFX_DOF_OK)
        return status;
    if (const FfxDofErrorCode status = checkOutputFormatSupport(output.viewFormat); status != FFX_DOF_OK) return status;

    // Descriptors: the ring slot the GPU finished with maxFramesInFlight dispatches ago.
    const uint32_t ringSlot = nextRingSlot_;
    nextRingSlot_ = (nextRingSlot_ + 1) % backend_.framesInFlight();
    writeSrv(color.resource, color.viewFormat, 1, cpuDescriptor(ringSlot, kSrvTableOffset + FFX_DOF_SRV_INPUT_COLOR));
    writeSrv(depth.resource, depth.viewFormat, 1, cpuDescriptor(ringSlot, kSrvTableOffset + FFX_DOF_SRV_INPUT_DEPTH));
    writeUav(output.resource, output.viewFormat, 0, cpuDescriptor(ringSlot, kUavImageTableOffset + FFX_DOF_UAV_OUTPUT));

    StateTracker tracker;
    SlotTargets slots;
    trackInternalImages(&tracker, &slots);
    const uint8_t colorEntry =
        tracker.track(color.resource, D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES, color.state, color.state);
    slots.srv[FFX_DOF_SRV_INPUT_COLOR] = {colorEntry, 1};
    slots.srv[FFX_DOF_SRV_INPUT_DEPTH] = {
        tracker.track(depth.resource, D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES, depth.state, depth.state), 1};
    slots.uavImage[FFX_DOF_UAV_OUTPUT] =
        plan.outputIsColor
            ? colorEntry
            : tracker.track(output.resource, D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES, output.state, output.state);
    tracker.assumeBuffersWritten();

    FfxDofConstants constants = plan.constants;
    if (output.srgb) constants.outputFlags |= FFX_DOF_OUTPUT_FLAG_ENCODE_SRGB;

    // This replaces the engine's descriptor heaps, root signature and pipeline state on the list.
    ID3D12DescriptorHeap* heaps[] = {heap_.Get()};
    list->SetDescriptorHeaps(1, heaps);
    list->SetComputeRootSignature(backend_.rootSignature());
    list->SetComputeRoot32BitConstants(kRootConstantsParameter, kRootConstantCount, &constants, 0);
    D3D12_GPU_DESCRIPTOR_HANDLE table = heapGpuStart_;
    table.ptr += static_cast<UINT64>(ringSlot) * kDescriptorsPerDispatch * backend_.descriptorSize();
    list->SetComputeRootDescriptorTable(kRootDescriptorTableParameter, table);

    ID3D12Resource* uavBuffers[kUavBufferCount] = {};
    for (uint32_t b = 0; b < kUavBufferCount; ++b) uavBuffers[b] = buffers_[b].Get();
    for (uint32_t p = 0; p < kPassCount; ++p) {
        if (!plan.runs[p]) continue;  // autofocus, when the dispatch does not ask for it
        const PlannedPass& pass = plan_.passes[p];
        tracker.beforePass(slots, pass, uavBuffers);
        tracker.flush(list);
        if (pass.perTileList) {
            // Every variant of the dispatch's group, over the tiles dilate listed for it (ffx_dof_resources.h,
            // TILE_LISTS).
            for (uint32_t listed = 0; listed < pass.tileListVariants; ++listed) {
                const uint32_t v = plan.variants[p] + listed;
                if (listed > 0 && plan.outputIsColor && (pass.writes & resourceBit(Resource::Output)) != 0) {
                    // In place a composite workgroup reads the input only within its own tile, which no other
                    // workgroup writes; ordered all the same, as on Vulkan.
                    D3D12_RESOURCE_BARRIER written{};
                    written.Type = D3D12_RESOURCE_BARRIER_TYPE_UAV;
                    written.UAV.pResource = color.resource;
                    list->ResourceBarrier(1, &written);
                }
                list->SetPipelineState(pipelines_[p][v].Get());
                list->ExecuteIndirect(backend_.tileListSignature(), 1,
                                      buffers_[FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS].Get(),
                                      tileListArgsOffset(pass.variants[v].tileList), nullptr, 0);
            }
        } else {
            list->SetPipelineState(pipelines_[p][plan.variants[p]].Get());
            list->Dispatch(pass.groups.x, pass.groups.y, pass.groups.z);
        }
        tracker.afterPass(pass);
        if (p == static_cast<uint32_t>(kColorRangeRerunPass)) {
            // Its second run, over no workgroup unless the first found a colour channel above the range limit
            // (ffx_dof_downsample_color.h): from the arguments the first armed, which it does not touch (their
            // descriptor stays in the table, unused), with the flag that has it read the frame's peak.
            PlannedPass rerun = pass;
            rerun.bufferSlots &= ~(1u << FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS);
            rerun.indirect = resourceBit(Resource::TileListArgs);
            tracker.beforePass(slots, rerun, uavBuffers);
            tracker.flush(list);
            constexpr UINT kOutputFlagsIndex = offsetof(FfxDofConstants, outputFlags) / 4;
            list->SetComputeRoot32BitConstant(kRootConstantsParameter,
                                              constants.outputFlags | FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN,
                                              kOutputFlagsIndex);
            list->ExecuteIndirect(backend_.tileListSignature(), 1, buffers_[FFX_DOF_UAV_BUFFER_TILE_LIST_ARGS].Get(),
                                  kColorRangeRerunArgsOffset, nullptr, 0);
            list->SetComputeRoot32BitConstant(kRootConstantsParameter, constants.outputFlags, kOutputFlagsIndex);
            tracker.afterPass(rerun);
        }
    }
    tracker.restore();
    tracker.flush(list);
    const bool ranAutofocus = plan.runs[static_cast<uint32_t>(Pass::Autofocus)];
    const uint32_t readbackSlot = readbackRing_.record(ranAutofocus);
    if (ranAutofocus) recordFocusReadback(list, readbackSlot);
    return FFX_DOF_OK;
}

}  // namespace

FfxDofErrorCode Backend::createContext(const ContextPlan& plan, std::unique_ptr<BackendContext>* out) {
    std::unique_ptr<Context> context(new (std::nothrow) Context(*this, plan));
    if (!context) return fail(FFX_DOF_ERROR_OUT_OF_MEMORY, "allocating the D3D12 context failed");
    if (const FfxDofErrorCode status = context->init(); status != FFX_DOF_OK) return status;
    *out = std::move(context);
    return FFX_DOF_OK;
}

}  // namespace ffxdof::dx12
