// A backend that records instead of drawing, so the API-neutral core can be tested without a GPU.
#pragma once

#include "ffx_dof_backend.h"

#include <vector>

namespace ffxdof::testing {

class RecordingBackend;

class RecordingContext final : public BackendContext {
public:
    explicit RecordingContext(std::vector<DispatchPlan>* log) : log_(log) {}
    FfxDofErrorCode dispatch(const DispatchPlan& plan) override {
        log_->push_back(plan);
        return FFX_DOF_OK;
    }
    FfxDofMemoryUsage memoryUsage() const override { return {1234, 0}; }

private:
    std::vector<DispatchPlan>* log_;
};

class RecordingBackend final : public FfxDofBackend_T {
public:
    FfxDofErrorCode createContext(const ContextConfig& config, std::unique_ptr<BackendContext>* out) override {
        configs.push_back(config);
        if (failCreation) return fail(FFX_DOF_ERROR_UNSUPPORTED, "recording backend told to fail");
        *out = std::make_unique<RecordingContext>(&dispatches);
        return FFX_DOF_OK;
    }
    bool failCreation = false;
    std::vector<ContextConfig> configs;
    std::vector<DispatchPlan> dispatches;
};

}  // namespace ffxdof::testing
