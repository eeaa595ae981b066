#include "ffx_dof_dx12_shaders.h"

// CMake defines FFX_DOF_DX12_DXIL_HEADER (the header ffx_dof_add_shader_library generated for the
// DXIL target) only when the permutation compiler produced DXIL; see backends/dx12/CMakeLists.txt.
#if defined(FFX_DOF_DX12_DXIL_HEADER)
#include FFX_DOF_DX12_DXIL_HEADER
#endif

namespace ffxdof::dx12 {

const shaders::PassTable* dxilPassTable(Pass pass) {
#if defined(FFX_DOF_DX12_DXIL_HEADER)
    return FFX_DOF_DX12_DXIL_NAMESPACE::findPassTable(kPassNames[static_cast<uint32_t>(pass)]);
#else
    (void)pass;
    return nullptr;
#endif
}

}  // namespace ffxdof::dx12
