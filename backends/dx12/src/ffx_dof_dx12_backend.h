// The D3D12 backend: the device, its axes, one root signature and one command signature, shared by every context made
// with it, and the pipeline states of their plans (each made once per backend). Private to ffx-dof.
#pragma once

#include "ffx_dof_backend.h"
#include "ffx_dof_backend_cache.h"
#include "ffx_dof_dx12.h"
#include "ffx_dof_shader_table.h"

#include <d3d12.h>
#include <wrl/client.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace ffxdof::dx12 {

using Microsoft::WRL::ComPtr;

// Every dispatch binds one contiguous block of descriptors through one descriptor table:
//   [0, 10)   SRVs t0..t9               (FFX_DOF_SRV_*)
//   [10, 21)  image UAVs u0..u10        (FFX_DOF_UAV_*)
//   [21, 25)  buffer UAVs u0..u3, space 1 (FFX_DOF_UAV_BUFFER_*)
// HLSL has one u# namespace for images and buffers, so the buffers take register space 1
// (shaders_common/ffx_dof_callbacks_hlsl.h declares them there).
constexpr uint32_t kSrvCount = kSampledSlotCount;
constexpr uint32_t kUavImageCount = kStorageImageSlotCount;
constexpr uint32_t kUavBufferCount = kStorageBufferSlotCount;
constexpr UINT kUavBufferRegisterSpace = 1;
constexpr uint32_t kSrvTableOffset = 0;
constexpr uint32_t kUavImageTableOffset = kSrvTableOffset + kSrvCount;
constexpr uint32_t kUavBufferTableOffset = kUavImageTableOffset + kUavImageCount;
constexpr uint32_t kDescriptorsPerDispatch = kUavBufferTableOffset + kUavBufferCount;

constexpr UINT kRootConstantsParameter = 0;  // b0: FfxDofConstants
constexpr UINT kRootDescriptorTableParameter = 1;
constexpr UINT kRootConstantCount = sizeof(FfxDofConstants) / 4;

constexpr uint32_t kDefaultFramesInFlight = 3;
constexpr uint32_t kMaxFramesInFlight = 16;

// Axes the backend chooses from the device (FFX_HALF, FFX_DOF_OPTION_WAVE64).
struct DeviceOptions {
    bool half = false;
    bool wave64 = false;
};

class Backend final : public FfxDofBackend_T {
public:
    FfxDofErrorCode init(const FfxDofBackendDescriptionDX12& description);
    BackendCapabilities capabilities() const override;
    FfxDofErrorCode createContext(const ContextPlan& plan, std::unique_ptr<BackendContext>* out) override;

    ID3D12Device* device() const { return device_.Get(); }
    ID3D12RootSignature* rootSignature() const { return rootSignature_.Get(); }
    // One dispatch whose arguments are a tile list's in TILE_LIST_ARGS (FFX_DOF_TILE_LIST_ARGS_WORDS apart).
    ID3D12CommandSignature* tileListSignature() const { return tileListSignature_.Get(); }
    uint32_t framesInFlight() const { return framesInFlight_; }
    // The pipeline state of one blob on the root signature, made for the first context that uses it and kept for the
    // others until the backend is destroyed (ffx_dof_backend_cache.h).
    FfxDofErrorCode pipeline(const char* passName, const PassVariant& variant, ComPtr<ID3D12PipelineState>* out) const;
    UINT descriptorSize() const { return descriptorSize_; }

private:
    FfxDofErrorCode queryDevice(uint32_t flags);
    FfxDofErrorCode createRootSignature();
    FfxDofErrorCode createTileListSignature();

    ComPtr<ID3D12Device> device_;
    ComPtr<ID3D12RootSignature> rootSignature_;
    ComPtr<ID3D12CommandSignature> tileListSignature_;
    // Keyed by the blob: static data of the shader tables, its address names the permutation.
    mutable BackendObjectCache<const shaders::Blob*, ComPtr<ID3D12PipelineState>> pipelines_;  // a cache: const
    uint32_t framesInFlight_ = kDefaultFramesInFlight;
    UINT descriptorSize_ = 0;
    DeviceOptions deviceOptions_;
    const shaders::PassTable* tables_[kPassCount] = {};
};

// "DXGI_FORMAT_R16G16B16A16_FLOAT" style name, or the number for formats outside the rule table.
const char* describeFormat(DXGI_FORMAT format, char (&buffer)[32]);

}  // namespace ffxdof::dx12
