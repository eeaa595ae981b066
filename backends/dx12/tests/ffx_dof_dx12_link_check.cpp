// Link and smoke check of the D3D12 backend.
//
// At compile time (every build, including the MinGW cross build in CI): the format rules and the
// descriptor layout, as static_asserts. At link time: every public entry point resolves in a
// Windows executable. At run time (on Windows only): the argument checks, and with a device (the
// default adapter, else WARP) the backend creation: FFX_DOF_ERROR_UNSUPPORTED in a build without
// DXIL, otherwise a context is created, sized and destroyed. Exit code 0 means every check passed.
#include "ffx_dof_dx12.h"
#include "ffx_dof_dx12_backend.h"
#include "ffx_dof_dx12_formats.h"

#include <dxgi1_4.h>

#include <cstdio>
#include <cstring>

namespace {

using ffxdof::dx12::ImageRole;
using ffxdof::dx12::viewFormat;

// Typeless depth resources are sampled through these SRV formats.
static_assert(viewFormat(DXGI_FORMAT_D32_FLOAT, ImageRole::Depth) == DXGI_FORMAT_R32_FLOAT);
static_assert(viewFormat(DXGI_FORMAT_R32_TYPELESS, ImageRole::Depth) == DXGI_FORMAT_R32_FLOAT);
static_assert(viewFormat(DXGI_FORMAT_D24_UNORM_S8_UINT, ImageRole::Depth) == DXGI_FORMAT_R24_UNORM_X8_TYPELESS);
static_assert(viewFormat(DXGI_FORMAT_R24G8_TYPELESS, ImageRole::Depth) == DXGI_FORMAT_R24_UNORM_X8_TYPELESS);
static_assert(viewFormat(DXGI_FORMAT_D16_UNORM, ImageRole::Depth) == DXGI_FORMAT_R16_UNORM);
static_assert(viewFormat(DXGI_FORMAT_D32_FLOAT_S8X24_UINT, ImageRole::Depth) == DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS);
// A depth format is no color, and a color format no depth.
static_assert(viewFormat(DXGI_FORMAT_D32_FLOAT, ImageRole::Color) == DXGI_FORMAT_UNKNOWN);
static_assert(viewFormat(DXGI_FORMAT_R16G16B16A16_FLOAT, ImageRole::Depth) == DXGI_FORMAT_UNKNOWN);
// sRGB output is written through the UNORM UAV (the shader encodes); shared-exponent cannot be stored.
static_assert(viewFormat(DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, ImageRole::Output) == DXGI_FORMAT_R8G8B8A8_UNORM);
static_assert(viewFormat(DXGI_FORMAT_B8G8R8A8_UNORM_SRGB, ImageRole::Output) == DXGI_FORMAT_B8G8R8A8_UNORM);
static_assert(viewFormat(DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, ImageRole::Color) == DXGI_FORMAT_R8G8B8A8_UNORM_SRGB);
static_assert(viewFormat(DXGI_FORMAT_R9G9B9E5_SHAREDEXP, ImageRole::Output) == DXGI_FORMAT_UNKNOWN);
static_assert(viewFormat(DXGI_FORMAT_R8G8B8A8_TYPELESS, ImageRole::Color) == DXGI_FORMAT_UNKNOWN);
// The view must be makeable on the resource: a D32_FLOAT resource cannot be sampled, R32_TYPELESS can;
// an sRGB output needs a typeless resource.
static_assert(!ffxdof::dx12::viewableOn(*ffxdof::dx12::findFormatRule(DXGI_FORMAT_D32_FLOAT, ImageRole::Depth),
                                        DXGI_FORMAT_R32_FLOAT, DXGI_FORMAT_D32_FLOAT));
static_assert(ffxdof::dx12::viewableOn(*ffxdof::dx12::findFormatRule(DXGI_FORMAT_D32_FLOAT, ImageRole::Depth),
                                       DXGI_FORMAT_R32_FLOAT, DXGI_FORMAT_R32_TYPELESS));
static_assert(!ffxdof::dx12::viewableOn(*ffxdof::dx12::findFormatRule(DXGI_FORMAT_R8G8B8A8_UNORM_SRGB,
                                                                      ImageRole::Output),
                                        DXGI_FORMAT_R8G8B8A8_UNORM, DXGI_FORMAT_R8G8B8A8_UNORM_SRGB));
static_assert(ffxdof::dx12::viewableOn(*ffxdof::dx12::findFormatRule(DXGI_FORMAT_R8G8B8A8_UNORM_SRGB,
                                                                     ImageRole::Output),
                                       DXGI_FORMAT_R8G8B8A8_UNORM, DXGI_FORMAT_R8G8B8A8_TYPELESS));

// Each declared format has at most one rule per role class (depth or not), so a lookup is unambiguous.
constexpr bool formatRulesAreUnique() {
    for (const auto& a : ffxdof::dx12::kFormatRules) {
        int matches = 0;
        for (const auto& b : ffxdof::dx12::kFormatRules) matches += (a.declared == b.declared && a.depth == b.depth);
        if (matches != 1) return false;
    }
    return true;
}
static_assert(formatRulesAreUnique());

// The descriptor table covers t0..t9, u0..u10 and the four buffers (GLOBALS, TILE_LIST_ARGS, TILE_LISTS,
// HIGHLIGHTS), and nothing overlaps.
static_assert(ffxdof::dx12::kDescriptorsPerDispatch == 10 + 11 + 4);
// FfxDofConstants as root constants: 30 DWORDs of the 64 a root signature holds.
static_assert(ffxdof::dx12::kRootConstantCount == 30);

int g_failures = 0;

void check(bool condition, const char* what) {
    std::printf("%s: %s\n", condition ? "ok  " : "FAIL", what);
    if (!condition) {
        std::printf("      last error: %s\n", ffxDofGetLastErrorMessage());
        ++g_failures;
    }
}

void checkArguments() {
    check(ffxDofBackendCreateDX12(nullptr, nullptr) == FFX_DOF_ERROR_INVALID_POINTER, "NULL pBackend is rejected");
    FfxDofBackend backend = reinterpret_cast<FfxDofBackend>(&g_failures);
    check(ffxDofBackendCreateDX12(nullptr, &backend) == FFX_DOF_ERROR_INVALID_POINTER && backend == nullptr,
          "NULL description is rejected and *pBackend set to NULL");
    FfxDofBackendDescriptionDX12 description{};
    check(ffxDofBackendCreateDX12(&description, &backend) == FFX_DOF_ERROR_INVALID_POINTER &&
              std::strstr(ffxDofGetLastErrorMessage(), "device") != nullptr,
          "NULL device is rejected, naming the field");

    ID3D12Resource* fake = reinterpret_cast<ID3D12Resource*>(static_cast<uintptr_t>(0x1000));
    const FfxDofResource wrapped = ffxDofGetResourceDX12(fake, DXGI_FORMAT_R16G16B16A16_FLOAT, 640, 360,
                                                         D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE);
    check(wrapped.handle == 0x1000 && wrapped.format == DXGI_FORMAT_R16G16B16A16_FLOAT && wrapped.width == 640 &&
              wrapped.height == 360 && wrapped.state == D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE &&
              wrapped.flags == 0,
          "ffxDofGetResourceDX12 keeps every field");
    ID3D12GraphicsCommandList* list = reinterpret_cast<ID3D12GraphicsCommandList*>(static_cast<uintptr_t>(0x2000));
    check(ffxDofGetCommandListDX12(list) == static_cast<void*>(list), "ffxDofGetCommandListDX12 keeps the pointer");
}

ID3D12Device* createDevice() {
    ID3D12Device* device = nullptr;
    if (SUCCEEDED(D3D12CreateDevice(nullptr, D3D_FEATURE_LEVEL_11_0, __uuidof(ID3D12Device),
                                    reinterpret_cast<void**>(&device))))
        return device;
    IDXGIFactory4* factory = nullptr;
    IDXGIAdapter* warp = nullptr;
    if (SUCCEEDED(CreateDXGIFactory1(__uuidof(IDXGIFactory4), reinterpret_cast<void**>(&factory))) &&
        SUCCEEDED(factory->EnumWarpAdapter(__uuidof(IDXGIAdapter), reinterpret_cast<void**>(&warp)))) {
        if (FAILED(D3D12CreateDevice(warp, D3D_FEATURE_LEVEL_11_0, __uuidof(ID3D12Device),
                                     reinterpret_cast<void**>(&device))))
            device = nullptr;
    }
    if (warp) warp->Release();
    if (factory) factory->Release();
    return device;
}

void checkDevice() {
    ID3D12Device* device = createDevice();
    if (device == nullptr) {
        std::printf("skip: no D3D12 device (neither an adapter nor WARP)\n");
        return;
    }
    FfxDofBackendDescriptionDX12 description{};
    description.device = device;
    description.flags = 0x80;
    FfxDofBackend backend = nullptr;
    check(ffxDofBackendCreateDX12(&description, &backend) == FFX_DOF_ERROR_INVALID_FLAGS, "unknown flags are rejected");
    description.flags = 0;
    const FfxDofErrorCode status = ffxDofBackendCreateDX12(&description, &backend);
#if FFX_DOF_DX12_EXPECT_DXIL
    const bool unsupportedDevice =
        status == FFX_DOF_ERROR_UNSUPPORTED && std::strstr(ffxDofGetLastErrorMessage(), "shader model") != nullptr;
    if (unsupportedDevice) {
        std::printf("skip: %s\n", ffxDofGetLastErrorMessage());
    } else {
        check(status == FFX_DOF_OK && backend != nullptr, "the backend is created");
        FfxDofContextDescription contextDescription{};
        contextDescription.quality = 10;
        contextDescription.resolution = {1280, 720};
        contextDescription.backendInterface = backend;
        contextDescription.cocLimitFactor = 0.02f;
        FfxDofContext context = nullptr;
        check(ffxDofContextCreate(&context, &contextDescription) == FFX_DOF_OK, "a 1280x720 context is created");
        FfxDofMemoryUsage usage{};
        check(ffxDofContextGetGpuMemoryUsage(&context, &usage) == FFX_DOF_OK && usage.totalUsageInBytes > 0 &&
                  usage.aliasableUsageInBytes < usage.totalUsageInBytes,
              "the context reports its GPU memory");
        std::printf("      GPU memory: %llu bytes, %llu aliasable\n",
                    static_cast<unsigned long long>(usage.totalUsageInBytes),
                    static_cast<unsigned long long>(usage.aliasableUsageInBytes));
        check(ffxDofBackendDestroy(backend) == FFX_DOF_ERROR_BACKEND_IN_USE, "a backend in use is not destroyed");
        check(ffxDofContextDestroy(&context) == FFX_DOF_OK && context == nullptr, "the context is destroyed");
        check(ffxDofBackendDestroy(backend) == FFX_DOF_OK, "the backend is destroyed");
    }
#else
    check(status == FFX_DOF_ERROR_UNSUPPORTED && backend == nullptr &&
              std::strstr(ffxDofGetLastErrorMessage(), "DXIL") != nullptr,
          "a build without DXIL reports FFX_DOF_ERROR_UNSUPPORTED, saying why");
#endif
    device->Release();
}

}  // namespace

int main() {
    checkArguments();
    checkDevice();
    std::printf("%s (%d failed)\n", g_failures == 0 ? "PASS" : "FAIL", g_failures);
    return g_failures == 0 ? 0 : 1;
}
