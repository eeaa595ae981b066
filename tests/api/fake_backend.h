// A backend that records instead of drawing, so the API-neutral core can be tested without a GPU. It
// offers the real GLSL shader tables (reflection only: no device is involved).
#pragma once

#include "ffx_dof_backend.h"
#include "ffx_dof_vk_shaders_glsl.h"

#include <vector>

namespace ffxdof::testing {

// The capabilities of a backend that has the GLSL tables.
inline BackendCapabilities glslCapabilities(bool half = false) {
    BackendCapabilities capabilities;
    for (uint32_t pass = 0; pass < kPassCount; ++pass) {
        capabilities.tables[pass] = shaders::glsl::findPassTable(kPassNames[pass]);
    }
    capabilities.half = half;
    return capabilities;
}

class RecordingContext final : public BackendContext {
public:
    explicit RecordingContext(std::vector<DispatchPlan>* log) : log_(log) {}
    FfxDofErrorCode dispatch(const DispatchPlan& plan) override {
        log_->push_back(plan);
        return FFX_DOF_OK;
    }
    FfxDofMemoryUsage memoryUsage() const override { return {1234, 0}; }
    FfxDofErrorCode autofocusDistance(uint32_t, float*) const override {
        return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "the recording backend runs no autofocus");
    }

private:
    std::vector<DispatchPlan>* log_;
};

class RecordingBackend final : public FfxDofBackend_T {
public:
    BackendCapabilities capabilities() const override { return offered; }
    FfxDofErrorCode createContext(const ContextPlan& plan, std::unique_ptr<BackendContext>* out) override {
        plans.push_back(plan);
        if (failCreation) return fail(FFX_DOF_ERROR_UNSUPPORTED, "recording backend told to fail");
        *out = std::make_unique<RecordingContext>(&dispatches);
        return FFX_DOF_OK;
    }
    BackendCapabilities offered = glslCapabilities();
    bool failCreation = false;
    std::vector<ContextPlan> plans;
    std::vector<DispatchPlan> dispatches;
};

}  // namespace ffxdof::testing
