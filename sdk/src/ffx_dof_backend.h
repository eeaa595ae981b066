// The contract between the API-neutral core and a graphics-API backend. Private to ffx-dof.
// The core validates every description and plans everything that is not specific to one API
// (ffx_dof_plan.h); a backend reports what its device can run, creates what the plan lists and
// records what the plan says. It never calls back into the core or re-derives what the plan holds.
#pragma once

#include "ffx_dof.h"
#include "ffx_dof_plan.h"

#include <atomic>
#include <memory>
#include <string>

namespace ffxdof {

// The per-context half of a backend: internal images, descriptors, and recording.
class BackendContext {
public:
    virtual ~BackendContext() = default;
    // Checks what is API-specific about the engine's resources (formats, states, flags) and records.
    virtual FfxDofErrorCode dispatch(const DispatchPlan& dispatch) = 0;
    virtual FfxDofMemoryUsage memoryUsage() const = 0;
    // The focus distance the autofocus pass of the dispatch `dispatchesAgo` before the latest chose
    // (the caller says the GPU finished it); FFX_DOF_ERROR_INVALID_ARGUMENT when not kept or not run.
    virtual FfxDofErrorCode autofocusDistance(uint32_t dispatchesAgo, float* distance) const = 0;
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
    // The shader tables and device axes contexts of this backend use (asked once per context).
    virtual ffxdof::BackendCapabilities capabilities() const = 0;
    // Creates what the plan lists; the plan outlives the returned context.
    virtual FfxDofErrorCode createContext(const ffxdof::ContextPlan& plan,
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
