// The context object behind the public FfxDofContext handle. Private to ffx-dof.
#pragma once

#include "ffx_dof_backend.h"

namespace ffxdof {

// The backend half of a live context, or nullptr when the handle is not a live context.
// Backend-specific entry points (e.g. ffxDofContextSetTimestampQueriesVK) reach their object through it.
BackendContext* backendContextOf(FfxDofContext context);

// The planning the core does for every dispatch, exposed for tests: constants and workgroup counts
// for a context configuration and per-frame values.
DispatchPlan planDispatch(const ContextConfig& config, const FfxDofDispatchDescription& dispatch, uint32_t frameIndex);

}  // namespace ffxdof
