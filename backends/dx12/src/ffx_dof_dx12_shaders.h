// Where the D3D12 backend gets its DXIL: tables of the same shape as the SPIR-V ones
// (sdk/src/shader_table/ffx_dof_shader_table.h), made by the permutation compiler when it finds dxc.
//
// The shape, as this backend reads it:
//   PassTable::language            "dxil"
//   Blob::words / wordCount        the DXIL container as 32-bit words (containers are 4-byte sized)
//   Binding::set / Binding::binding register space / register number; kind gives the class (t, u, s, b)
// This header is the one place that knows where the tables come from.
#pragma once

#include "ffx_dof_passes.h"
#include "ffx_dof_shader_table.h"

namespace ffxdof::dx12 {

// The DXIL table of one pass, or nullptr when this build embeds none (it was built without dxc).
const shaders::PassTable* dxilPassTable(Pass pass);

}  // namespace ffxdof::dx12
