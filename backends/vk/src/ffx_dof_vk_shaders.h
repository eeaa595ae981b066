// Where the backend gets its SPIR-V: the tables the permutation compiler embeds (GLSL-compiled
// and HLSL-compiled), looked up by pass.
#pragma once

#include "ffx_dof_passes.h"
#include "ffx_dof_shader_table.h"

namespace ffxdof::vk {

enum class ShaderLanguage { Glsl, Hlsl };

// The table of one pass, or nullptr when the library has none for it.
const shaders::PassTable* passTable(ShaderLanguage language, Pass pass);

}  // namespace ffxdof::vk
