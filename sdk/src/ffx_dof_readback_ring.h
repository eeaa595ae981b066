// The bookkeeping of a backend's autofocus readback ring: which dispatch each slot holds, and the
// checks of ffxDofContextGetAutofocusDistance. API-neutral; the backend owns the mapped memory (one
// float per slot) and records the copy of each autofocus dispatch into the slot `record` names.
// Private to ffx-dof.
#pragma once

#include "ffx_dof.h"
#include "ffx_dof_backend.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace ffxdof {

class AutofocusReadbackRing {
public:
    // maxFramesInFlight + 1 slots: the dispatch maxFramesInFlight back is finished (the backend's
    // contract) while the latest one writes its own slot.
    explicit AutofocusReadbackRing(uint32_t framesInFlight)
        : framesInFlight_(framesInFlight), written_(framesInFlight + 1, 0) {}

    uint32_t slotCount() const { return uint32_t(written_.size()); }

    // Called once for every dispatch recorded, in order: the slot its copy goes to.
    uint32_t record(bool ranAutofocus) {
        const uint32_t slot = uint32_t(dispatchCount_ % written_.size());
        written_[slot] = ranAutofocus ? dispatchCount_ + 1 : 0;
        ++dispatchCount_;
        return slot;
    }

    // The distance the dispatch `dispatchesAgo` before the latest copied into `values`.
    FfxDofErrorCode read(uint32_t dispatchesAgo, const float* values, float* distance) const {
        if (dispatchesAgo > framesInFlight_)
            return fail(FFX_DOF_ERROR_INVALID_ARGUMENT,
                        "dispatchesAgo %u: only the last maxFramesInFlight (%u) are kept", dispatchesAgo,
                        framesInFlight_);
        if (dispatchesAgo >= dispatchCount_)
            return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "dispatchesAgo %u: the context has recorded %llu dispatches",
                        dispatchesAgo, static_cast<unsigned long long>(dispatchCount_));
        const uint64_t index = dispatchCount_ - 1 - dispatchesAgo;
        const size_t slot = size_t(index % written_.size());
        if (written_[slot] != index + 1)
            return fail(FFX_DOF_ERROR_INVALID_ARGUMENT, "the dispatch %u before the latest did not run autofocus",
                        dispatchesAgo);
        *distance = std::fabs(values[slot]);  // the GPU keeps it signed like view z
        return FFX_DOF_OK;
    }

private:
    uint32_t framesInFlight_;
    std::vector<uint64_t> written_;  // per slot: 1 + the index of the dispatch that wrote it, 0: none
    uint64_t dispatchCount_ = 0;
};

}  // namespace ffxdof
