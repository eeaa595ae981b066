// The D3D12 backend object and the public entry points of ffx_dof_dx12.h.
#include "ffx_dof_dx12_backend.h"

#include "ffx_dof_dx12_formats.h"
#include "ffx_dof_dx12_shaders.h"

#include <cstdio>
#include <new>
#include <string>
#include <utility>

namespace ffxdof::dx12 {
namespace {

constexpr uint32_t kAllBackendFlags = FFX_DOF_DX12_DISABLE_FLOAT16 | FFX_DOF_DX12_DISABLE_WAVE64;

// The shader models the backend uses. Older Windows SDKs (and mingw-w64) lack the enumerators, and
// the enumerator value is the model's number in hex, so spell them as values.
constexpr D3D_SHADER_MODEL shaderModel(uint32_t majorMinorHex) { return static_cast<D3D_SHADER_MODEL>(majorMinorHex); }
constexpr D3D_SHADER_MODEL kRequiredShaderModel = shaderModel(0x62);  // native 16-bit types, wave ops
constexpr D3D_SHADER_MODEL kWave64ShaderModel = shaderModel(0x66);    // [WaveSize(64)]

}  // namespace

const char* describeFormat(DXGI_FORMAT format, char (&buffer)[32]) {
    if (const char* name = formatName(format)) {
        std::snprintf(buffer, sizeof(buffer), "DXGI_FORMAT_%s", name);
    } else {
        std::snprintf(buffer, sizeof(buffer), "DXGI_FORMAT %u", static_cast<unsigned>(format));
    }
    return buffer;
}

FfxDofErrorCode Backend::pipeline(const char* passName, const PassVariant& variant,
                                  ComPtr<ID3D12PipelineState>* out) const {
    return pipelines_.findOrCreate(variant.blob, out, [&](ComPtr<ID3D12PipelineState>* made) {
        D3D12_COMPUTE_PIPELINE_STATE_DESC desc{};
        desc.pRootSignature = rootSignature_.Get();
        desc.CS = {variant.blob->words, variant.blob->wordCount * sizeof(uint32_t)};
        const HRESULT hr = device_->CreateComputePipelineState(&desc, IID_PPV_ARGS(made->GetAddressOf()));
        if (FAILED(hr))
            return fail(
                FFX_DOF_ERROR_BACKEND,
                "ID3D12Device::CreateComputePipelineState failed for pass '%s' permutation %u (HRESULT 0x%08lx)",
                passName, variant.permutationIndex, static_cast<unsigned long>(hr));
        return FFX_DOF_OK;
    });
}

FfxDofErrorCode Backend::init(const FfxDofBackendDescriptionDX12& description) {
    if (description.flags & ~kAllBackendFlags)
        return fail(FFX_DOF_ERROR_INVALID_FLAGS, "FfxDofBackendDescriptionDX12::flags 0x%x contain unknown bits 0x%x",
                    description.flags, description.flags & ~kAllBackendFlags);
    if (description.maxFramesInFlight > kMaxFramesInFlight)
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "maxFramesInFlight %u is above %u", description.maxFramesInFlight,
                    kMaxFramesInFlight);
    for (uint32_t p = 0; p < kPassCount; ++p) {
        tables_[p] = dxilPassTable(static_cast<Pass>(p));
        if (tables_[p] == nullptr)
            return fail(FFX_DOF_ERROR_UNSUPPORTED,
                        "this build of ffx-dof carries no DXIL for pass '%s': the permutation compiler emits DXIL only "
                        "where dxc is found (a Windows build); rebuild there to use the D3D12 backend",
                        kPassNames[p]);
    }
    device_ = description.device;
    framesInFlight_ = description.maxFramesInFlight != 0 ? description.maxFramesInFlight : kDefaultFramesInFlight;
    descriptorSize_ = device_->GetDescriptorHandleIncrementSize(D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV);

    if (const FfxDofErrorCode status = queryDevice(description.flags); status != FFX_DOF_OK) return status;
    if (const FfxDofErrorCode status = createRootSignature(); status != FFX_DOF_OK) return status;
    return createTileListSignature();
}

BackendCapabilities Backend::capabilities() const {
    BackendCapabilities capabilities;
    for (uint32_t p = 0; p < kPassCount; ++p) capabilities.tables[p] = tables_[p];
    capabilities.half = deviceOptions_.half;
    capabilities.wave64 = deviceOptions_.wave64;
    return capabilities;
}

FfxDofErrorCode Backend::queryDevice(uint32_t flags) {
    // The runtime rejects a HighestShaderModel it does not know, so ask from the highest we use down.
    D3D12_FEATURE_DATA_SHADER_MODEL model{};
    bool known = false;
    for (uint32_t hex = 0x66; hex >= 0x60 && !known; --hex) {
        model.HighestShaderModel = shaderModel(hex);
        known = SUCCEEDED(device_->CheckFeatureSupport(D3D12_FEATURE_SHADER_MODEL, &model, sizeof(model)));
    }
    if (!known || model.HighestShaderModel < kRequiredShaderModel) {
        const unsigned reported = known ? static_cast<unsigned>(model.HighestShaderModel) : 0x51u;
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device supports shader model %u.%u; ffx-dof needs 6.2",
                    reported >> 4, reported & 0xfu);
    }

    D3D12_FEATURE_DATA_D3D12_OPTIONS4 options4{};
    const bool native16 =
        SUCCEEDED(device_->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS4, &options4, sizeof(options4))) &&
        options4.Native16BitShaderOpsSupported;
    D3D12_FEATURE_DATA_D3D12_OPTIONS1 options1{};
    const bool waveOps =
        SUCCEEDED(device_->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS1, &options1, sizeof(options1))) &&
        options1.WaveOps;
    if (!waveOps) return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device does not support wave operations");

    deviceOptions_.half = native16 && !(flags & FFX_DOF_DX12_DISABLE_FLOAT16);
    // Only where every wave has 64 lanes: the wave64 shaders rely on it, and [WaveSize(64)] needs 6.6.
    deviceOptions_.wave64 = model.HighestShaderModel >= kWave64ShaderModel && options1.WaveLaneCountMin == 64 &&
                            !(flags & FFX_DOF_DX12_DISABLE_WAVE64);
    return FFX_DOF_OK;
}

FfxDofErrorCode Backend::createRootSignature() {
    const D3D12_DESCRIPTOR_RANGE ranges[] = {
        {D3D12_DESCRIPTOR_RANGE_TYPE_SRV, kSrvCount, 0, 0, kSrvTableOffset},
        {D3D12_DESCRIPTOR_RANGE_TYPE_UAV, kUavImageCount, 0, 0, kUavImageTableOffset},
        {D3D12_DESCRIPTOR_RANGE_TYPE_UAV, kUavBufferCount, 0, kUavBufferRegisterSpace, kUavBufferTableOffset},
    };
    D3D12_ROOT_PARAMETER parameters[2]{};
    parameters[kRootConstantsParameter].ParameterType = D3D12_ROOT_PARAMETER_TYPE_32BIT_CONSTANTS;
    parameters[kRootConstantsParameter].Constants = {0, 0, kRootConstantCount};
    parameters[kRootConstantsParameter].ShaderVisibility = D3D12_SHADER_VISIBILITY_ALL;
    parameters[kRootDescriptorTableParameter].ParameterType = D3D12_ROOT_PARAMETER_TYPE_DESCRIPTOR_TABLE;
    parameters[kRootDescriptorTableParameter].DescriptorTable = {sizeof(ranges) / sizeof(ranges[0]), ranges};
    parameters[kRootDescriptorTableParameter].ShaderVisibility = D3D12_SHADER_VISIBILITY_ALL;

    D3D12_ROOT_SIGNATURE_DESC desc{};
    desc.NumParameters = sizeof(parameters) / sizeof(parameters[0]);
    desc.pParameters = parameters;
    desc.NumStaticSamplers = 0;
    desc.Flags = D3D12_ROOT_SIGNATURE_FLAG_NONE;

    // Version 1.0: every descriptor volatile, which is what a ring of descriptors rewritten at record
    // time needs, and every D3D12 runtime accepts it.
    ComPtr<ID3DBlob> serialized;
    ComPtr<ID3DBlob> errors;
    HRESULT hr = D3D12SerializeRootSignature(&desc, D3D_ROOT_SIGNATURE_VERSION_1, &serialized, &errors);
    if (FAILED(hr)) {
        const char* detail = errors ? static_cast<const char*>(errors->GetBufferPointer()) : "";
        return fail(FFX_DOF_ERROR_BACKEND, "D3D12SerializeRootSignature failed (HRESULT 0x%08lx): %s",
                    static_cast<unsigned long>(hr), detail);
    }
    hr = device_->CreateRootSignature(0, serialized->GetBufferPointer(), serialized->GetBufferSize(),
                                      IID_PPV_ARGS(&rootSignature_));
    if (FAILED(hr))
        return fail(FFX_DOF_ERROR_BACKEND, "ID3D12Device::CreateRootSignature failed (HRESULT 0x%08lx)",
                    static_cast<unsigned long>(hr));
    return FFX_DOF_OK;
}

FfxDofErrorCode Backend::createTileListSignature() {
    D3D12_INDIRECT_ARGUMENT_DESC argument{};
    argument.Type = D3D12_INDIRECT_ARGUMENT_TYPE_DISPATCH;
    D3D12_COMMAND_SIGNATURE_DESC desc{};
    desc.ByteStride = FFX_DOF_TILE_LIST_ARGS_WORDS * sizeof(uint32_t);
    desc.NumArgumentDescs = 1;
    desc.pArgumentDescs = &argument;
    // A signature of dispatch arguments alone changes no root argument: no root signature.
    const HRESULT hr = device_->CreateCommandSignature(&desc, nullptr, IID_PPV_ARGS(&tileListSignature_));
    if (FAILED(hr))
        return fail(FFX_DOF_ERROR_BACKEND, "ID3D12Device::CreateCommandSignature failed (HRESULT 0x%08lx)",
                    static_cast<unsigned long>(hr));
    return FFX_DOF_OK;
}

}  // namespace ffxdof::dx12

using namespace ffxdof;

extern "C" FfxDofErrorCode ffxDofBackendCreateDX12(const FfxDofBackendDescriptionDX12* pDescription,
                                                   FfxDofBackend* pBackend) {
    clearLastError();
    if (pBackend == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pBackend is NULL");
    *pBackend = nullptr;
    if (pDescription == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pDescription is NULL");
    if (pDescription->device == nullptr)
        return fail(FFX_DOF_ERROR_INVALID_POINTER, "FfxDofBackendDescriptionDX12::device is NULL");
    try {
        std::unique_ptr<dx12::Backend> backend(new dx12::Backend);
        if (const FfxDofErrorCode status = backend->init(*pDescription); status != FFX_DOF_OK) return status;
        *pBackend = backend.release();
        return FFX_DOF_OK;
    } catch (const std::bad_alloc&) {
        return fail(FFX_DOF_ERROR_OUT_OF_MEMORY, "host allocation failed while creating the D3D12 backend");
    }
}

extern "C" FfxDofResource ffxDofGetResourceDX12(ID3D12Resource* resource, DXGI_FORMAT format, uint32_t width,
                                                uint32_t height, D3D12_RESOURCE_STATES state) {
    FfxDofResource wrapped{};
    wrapped.handle = static_cast<uint64_t>(reinterpret_cast<uintptr_t>(resource));
    wrapped.format = static_cast<uint32_t>(format);
    wrapped.width = width;
    wrapped.height = height;
    wrapped.state = static_cast<uint32_t>(state);
    return wrapped;
}

extern "C" FfxDofCommandList ffxDofGetCommandListDX12(ID3D12GraphicsCommandList* commandList) {
    return static_cast<FfxDofCommandList>(commandList);
}
