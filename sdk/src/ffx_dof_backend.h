// The contract between the API-neutral core (ffx_dof_context.cpp) and a graphics-API backend.
// Private to ffx-dof. The core validates every description, computes the constants and dispatch
// sizes; a backend only creates resources and pipelines and records what the core planned.
#pragma once

#include "ffx_dof.h"
#include "ffx_dof_passes.h"

#include <atomic>
#include <memory>
#include <string>

namespace ffxdof {

// Everything a backend needs to build one context.
struct ContextConfig {
    FfxDofDimensions2D resolution{};
    uint32_t flags = 0;  // FfxDofInitializationFlagBits
    uint32_t quality = 0;
    float cocLimitFactor = 0.0f;
};

// One recorded dispatch, fully planned by the core.
struct DispatchPlan {
    FfxDofCommandList commandList = nullptr;
    FfxDofResource color{};
    FfxDofResource depth{};
    FfxDofResource output{};
    FfxDofConstants constants{};
    PassGrid passes[kPassCount]{};  // workgroup counts, in pipeline order
    PermutationOptions options{};   // API-neutral option values; the backend adds half/wave64
    bool outputIsColor = false;     // in-place: output and color are the same image
};

// The per-context half of a backend: internal images, descriptors, and recording.
class BackendContext {
public:
    virtual ~BackendContext() = default;
    // Checks formats, sizes and states of the engine resources (API-specific) and records.
    virtual FfxDofErrorCode dispatch(const DispatchPlan& plan) = 0;
    virtual FfxDofMemoryUsage memoryUsage() const = 0;
};

}  // namespace ffxdof

namespace ffxdof {
// Every backend object is registered while it exists (see FfxDofBackend_T), so the core can refuse a
// destroyed or garbage FfxDofBackend before it dereferences it. Defined in ffx_dof_context.cpp.
void registerLiveBackend(const FfxDofBackend_T* backend);
void unregisterLiveBackend(const FfxDofBackend_T* backend);
}  // namespace ffxdof

// The public opaque handle is the backend object itself. Its constructor and destructor keep the
// registry of live backends, so every backend (Vulkan, D3D12, the tests' fakes) is covered.
struct FfxDofBackend_T {
    FfxDofBackend_T() { ffxdof::registerLiveBackend(this); }
    FfxDofBackend_T(const FfxDofBackend_T&) = delete;
    FfxDofBackend_T& operator=(const FfxDofBackend_T&) = delete;
    virtual ~FfxDofBackend_T() { ffxdof::unregisterLiveBackend(this); }
    virtual FfxDofErrorCode createContext(const ffxdof::ContextConfig& config,
                                          std::unique_ptr<ffxdof::BackendContext>* out) = 0;
    std::atomic<int> liveContexts{0};
};

namespace ffxdof {
// Records a detail for ffxDofGetLastErrorMessage and returns code, so a failure is one line:
//   return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "color format %u is not supported", format);
FfxDofErrorCode fail(FfxDofErrorCode code, const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void clearLastError();
}  // namespace ffxdof
