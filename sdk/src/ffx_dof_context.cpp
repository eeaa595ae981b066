// The API-neutral core: validates every description, owns context lifetime, builds each context's
// plan (ffx_dof_plan.cpp) and hands every checked dispatch to the backend to record.
#include "ffx_dof_context.h"
#include "ffx_dof_live_handles.h"

#include <cmath>
#include <new>

struct FfxDofContext_T {
    FfxDofBackend backend = nullptr;
    ffxdof::ContextPlan plan;
    std::unique_ptr<ffxdof::BackendContext> impl;
    uint32_t frameIndex = 0;
    bool resetAutofocus = false;  // ffxDofContextResetAutofocus: applies to the next autofocus dispatch
};

namespace ffxdof {
namespace {

// Handles of live contexts and backends, so that a stale handle (used after destroy) or a garbage
// one is an error, not a crash. Made on first use and never destroyed: backends register from their
// constructors and unregister from their destructors, which may run before this file's globals are
// initialised or after they would have been destroyed (a backend held by a static object).
LiveHandles<FfxDofContext_T>& liveContexts() {
    static auto* registry = new LiveHandles<FfxDofContext_T>;
    return *registry;
}
LiveHandles<FfxDofBackend_T>& liveBackends() {
    static auto* registry = new LiveHandles<FfxDofBackend_T>;
    return *registry;
}

bool isLive(const FfxDofContext_T* context) { return liveContexts().contains(context); }

FfxDofErrorCode notALiveBackend(const char* what, const void* backend) {
    return fail(FFX_DOF_ERROR_INVALID_ARGUMENT,
                "%s %p is not a live backend (destroyed already, or not made by ffxDofBackendCreateVK/DX12)", what,
                backend);
}

FfxDofErrorCode checkResource(const FfxDofResource& resource, const char* name, FfxDofDimensions2D size) {
    if (resource.handle == 0) return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s: the image handle is null", name);
    if (resource.width != size.width || resource.height != size.height)
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s is %ux%u but the context was created for %ux%u", name,
                    resource.width, resource.height, size.width, size.height);
    return FFX_DOF_OK;
}

FfxDofErrorCode lookUpLiveContext(FfxDofContext* pContext, FfxDofContext_T** out) {
    if (pContext == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pContext is NULL");
    if (*pContext == nullptr || !isLive(*pContext))
        return fail(FFX_DOF_ERROR_INVALID_CONTEXT, "the context handle is not a live context (destroyed?)");
    *out = *pContext;
    return FFX_DOF_OK;
}

}  // namespace

void registerLiveBackend(const FfxDofBackend_T* backend) { liveBackends().insert(backend); }
void unregisterLiveBackend(const FfxDofBackend_T* backend) { liveBackends().erase(backend); }

BackendContext* backendContextOf(FfxDofContext context) {
    if (context == nullptr || !isLive(context)) return nullptr;
    return context->impl.get();
}

}  // namespace ffxdof

using namespace ffxdof;

extern "C" FfxDofErrorCode ffxDofContextCreate(FfxDofContext* pContext,
                                               const FfxDofContextDescription* pContextDescription) {
    clearLastError();
    if (pContext == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pContext is NULL");
    *pContext = nullptr;
    if (pContextDescription == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pContextDescription is NULL");
    const FfxDofContextDescription& desc = *pContextDescription;
    if (desc.flags & ~FFX_DOF_ALL_FLAGS)
        return fail(FFX_DOF_ERROR_INVALID_FLAGS, "flags 0x%x contain unknown bits 0x%x", desc.flags,
                    desc.flags & ~FFX_DOF_ALL_FLAGS);
    if (desc.quality == 0 || desc.quality > FFX_DOF_MAX_QUALITY)
        return fail(FFX_DOF_ERROR_INVALID_QUALITY, "quality %u is outside 1..%u", desc.quality, FFX_DOF_MAX_QUALITY);
    const FfxDofDimensions2D size = desc.resolution;
    if (size.width == 0 || size.height == 0 || size.width > FFX_DOF_MAX_RESOLUTION ||
        size.height > FFX_DOF_MAX_RESOLUTION)
        return fail(FFX_DOF_ERROR_INVALID_RESOLUTION, "resolution %ux%u is outside 1..%u", size.width, size.height,
                    FFX_DOF_MAX_RESOLUTION);
    if (!std::isfinite(desc.cocLimitFactor) || desc.cocLimitFactor < 0.0f)
        return fail(FFX_DOF_ERROR_INVALID_COC_LIMIT, "cocLimitFactor %g must be finite and >= 0",
                    static_cast<double>(desc.cocLimitFactor));
    if (desc.backendInterface == nullptr)
        return fail(FFX_DOF_ERROR_INVALID_POINTER,
                    "backendInterface is NULL (create one with ffxDofBackendCreateVK/DX12)");
    // Counts the new context on the backend while the registry says it is live, so that a concurrent
    // ffxDofBackendDestroy either happens before (and this call fails) or refuses (BACKEND_IN_USE).
    FfxDofBackend backend = desc.backendInterface;
    if (!liveBackends().whileLive(backend, false, [&](auto) {
            ++backend->liveContexts;
            return true;
        })) {
        return notALiveBackend("backendInterface", backend);
    }
    // Undone unless the context is made.
    struct ContextCountReservation {
        FfxDofBackend backend;
        bool kept = false;
        ~ContextCountReservation() {
            if (!kept) --backend->liveContexts;
        }
    } reservation{backend};

    std::unique_ptr<FfxDofContext_T> context(new (std::nothrow) FfxDofContext_T);
    if (!context) return fail(FFX_DOF_ERROR_OUT_OF_MEMORY, "allocating the context failed");
    context->backend = desc.backendInterface;
    ContextConfig config;
    config.resolution = size;
    config.flags = desc.flags;
    config.quality = desc.quality;
    config.cocLimitFactor = desc.cocLimitFactor;

    try {
        FfxDofErrorCode status = buildContextPlan(config, backend->capabilities(), &context->plan);
        if (status != FFX_DOF_OK) return status;
        status = backend->createContext(context->plan, &context->impl);
        if (status != FFX_DOF_OK) return status;
        if (!context->impl) return fail(FFX_DOF_ERROR_BACKEND, "the backend returned no context");
        liveContexts().insert(context.get());
    } catch (const std::bad_alloc&) {
        return fail(FFX_DOF_ERROR_OUT_OF_MEMORY, "host allocation failed while creating the context");
    }
    reservation.kept = true;
    *pContext = context.release();
    return FFX_DOF_OK;
}

extern "C" FfxDofErrorCode ffxDofContextDispatch(FfxDofContext* pContext,
                                                 const FfxDofDispatchDescription* pDispatchDescription) {
    clearLastError();
    FfxDofContext_T* context = nullptr;
    if (const FfxDofErrorCode status = lookUpLiveContext(pContext, &context); status != FFX_DOF_OK) return status;
    if (pDispatchDescription == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pDispatchDescription is NULL");
    const FfxDofDispatchDescription& desc = *pDispatchDescription;
    if (desc.commandList == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "commandList is NULL");

    const ContextConfig& config = context->plan.config;
    const FfxDofDimensions2D size = config.resolution;
    for (const auto& [resource, name] :
         {std::pair{&desc.color, "color"}, std::pair{&desc.depth, "depth"}, std::pair{&desc.output, "output"}}) {
        if (const FfxDofErrorCode status = checkResource(*resource, name, size); status != FFX_DOF_OK) return status;
    }
    if (desc.output.handle == desc.depth.handle)
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "output is the depth image");
    if (desc.depth.handle == desc.color.handle)
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "depth and color are the same image");
    const bool inPlace = desc.output.handle == desc.color.handle;
    if (inPlace && !(config.flags & FFX_DOF_OUTPUT_PRE_INIT))
        return fail(FFX_DOF_ERROR_OUTPUT_ALIASES_INPUT,
                    "output is the color image; create the context with FFX_DOF_OUTPUT_PRE_INIT for in-place use");
    if (inPlace && (desc.output.format != desc.color.format || desc.output.state != desc.color.state ||
                    desc.output.flags != desc.color.flags))
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "output is the color image (in place) but its format, state or flags differ from color's");
    if (desc.pAutofocus != nullptr) {
        if (const FfxDofErrorCode status = checkAutofocus(*desc.pAutofocus); status != FFX_DOF_OK) return status;
    } else if (!std::isfinite(desc.cocScale) || !std::isfinite(desc.cocBias))
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT,
                    "cocScale %g / cocBias %g must be finite (ffxDofCalculateCocScale/Bias return NaN for "
                    "impossible lenses: |focus| <= focalLength)",
                    static_cast<double>(desc.cocScale), static_cast<double>(desc.cocBias));

    if (desc.pAperture != nullptr) {
        if (const FfxDofErrorCode status = checkAperture(*desc.pAperture); status != FFX_DOF_OK) return status;
        if (!isRoundAperture(*desc.pAperture) && !(config.flags & FFX_DOF_ENABLE_APERTURE_SHAPES))
            return fail(FFX_DOF_ERROR_INVALID_ARGUMENT,
                        "pAperture is not round; create the context with FFX_DOF_ENABLE_APERTURE_SHAPES to shape the "
                        "bokeh");
    }

    try {
        const DispatchPlan dispatch = planDispatch(context->plan, desc, context->frameIndex, context->resetAutofocus);
        const FfxDofErrorCode status = context->impl->dispatch(dispatch);
        if (status == FFX_DOF_OK) {
            ++context->frameIndex;
            if (desc.pAutofocus != nullptr) context->resetAutofocus = false;
        }
        return status;
    } catch (const std::bad_alloc&) {
        return fail(FFX_DOF_ERROR_OUT_OF_MEMORY, "host allocation failed while recording the dispatch");
    }
}

extern "C" FfxDofErrorCode ffxDofContextDestroy(FfxDofContext* pContext) {
    clearLastError();
    if (pContext == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pContext is NULL");
    if (*pContext == nullptr) return FFX_DOF_OK;
    FfxDofContext_T* context = *pContext;
    if (!liveContexts().erase(context))
        return fail(FFX_DOF_ERROR_INVALID_CONTEXT, "the context handle is not a live context (destroyed twice?)");
    FfxDofBackend backend = context->backend;
    delete context;
    --backend->liveContexts;
    *pContext = nullptr;
    return FFX_DOF_OK;
}

extern "C" FfxDofErrorCode ffxDofContextResetAutofocus(FfxDofContext* pContext) {
    clearLastError();
    FfxDofContext_T* context = nullptr;
    if (const FfxDofErrorCode status = lookUpLiveContext(pContext, &context); status != FFX_DOF_OK) return status;
    context->resetAutofocus = true;
    return FFX_DOF_OK;
}

extern "C" FfxDofErrorCode ffxDofContextGetAutofocusDistance(FfxDofContext* pContext, uint32_t dispatchesAgo,
                                                             float* pDistance) {
    clearLastError();
    FfxDofContext_T* context = nullptr;
    if (const FfxDofErrorCode status = lookUpLiveContext(pContext, &context); status != FFX_DOF_OK) return status;
    if (pDistance == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pDistance is NULL");
    return context->impl->autofocusDistance(dispatchesAgo, pDistance);
}

extern "C" FfxDofErrorCode ffxDofContextGetGpuMemoryUsage(FfxDofContext* pContext, FfxDofMemoryUsage* pVramUsage) {
    clearLastError();
    FfxDofContext_T* context = nullptr;
    if (const FfxDofErrorCode status = lookUpLiveContext(pContext, &context); status != FFX_DOF_OK) return status;
    if (pVramUsage == nullptr) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pVramUsage is NULL");
    *pVramUsage = context->impl->memoryUsage();
    return FFX_DOF_OK;
}

extern "C" FfxDofErrorCode ffxDofBackendDestroy(FfxDofBackend backend) {
    clearLastError();
    if (backend == nullptr) return FFX_DOF_OK;
    // The registry is consulted before the pointer is dereferenced: destroying twice, or a garbage
    // pointer, is an error and reads no memory.
    constexpr int kNotLive = -1;
    const int contextsAlive = liveBackends().whileLive(backend, kNotLive, [&](auto eraseFromRegistry) {
        const int alive = backend->liveContexts.load();
        if (alive == 0) eraseFromRegistry();
        return alive;
    });
    if (contextsAlive == kNotLive) return notALiveBackend("the backend", backend);
    if (contextsAlive != 0)
        return fail(FFX_DOF_ERROR_BACKEND_IN_USE, "%d contexts made with this backend are still alive", contextsAlive);
    delete backend;
    return FFX_DOF_OK;
}

extern "C" FfxDofVersionNumber ffxDofGetEffectVersion(void) {
    return FFX_DOF_MAKE_VERSION(FFX_DOF_VERSION_MAJOR, FFX_DOF_VERSION_MINOR, FFX_DOF_VERSION_PATCH);
}
