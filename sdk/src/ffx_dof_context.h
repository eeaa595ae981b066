// The context object behind the public FfxDofContext handle. Private to ffx-dof.
#pragma once

#include "ffx_dof_backend.h"

namespace ffxdof {

// The backend half of a live context, or nullptr when the handle is not a live context.
// Backend-specific entry points (e.g. ffxDofContextSetTimestampQueriesVK) reach their object through it.
BackendContext* backendContextOf(FfxDofContext context);

}  // namespace ffxdof
