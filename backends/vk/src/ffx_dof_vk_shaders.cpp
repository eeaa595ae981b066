#include "ffx_dof_vk_shaders.h"

#include "ffx_dof_vk_shaders_glsl.h"
#if FFX_DOF_VK_HAVE_HLSL
#include "ffx_dof_vk_shaders_hlsl.h"
#endif

namespace ffxdof::vk {

const shaders::PassTable* passTable(ShaderLanguage language, Pass pass) {
    const char* name = kPassNames[uint32_t(pass)];
    if (language == ShaderLanguage::Glsl) return shaders::glsl::findPassTable(name);
#if FFX_DOF_VK_HAVE_HLSL
    return shaders::hlsl::findPassTable(name);
#else
    return nullptr;  // this build has no HLSL-compiled shaders
#endif
}

}  // namespace ffxdof::vk
