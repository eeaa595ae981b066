// API-neutral description of the five passes: their order, names, permutation options, dispatch
// sizes and the internal resources. Shared by the core and every backend; the shader side of the
// same facts is shaders_common/ffx_dof_resources.h.
#pragma once

#include "ffx_dof.h"

#define FFX_CPU 1
#include "ffx_dof_constants.h"
#include "ffx_dof_resources.h"

#include <cstdint>

namespace ffxdof {

// Pipeline order. The names are the shader header names (shaders_common/ffx_dof_<name>.h).
enum class Pass : uint32_t { DownsampleDepth = 0, DownsampleColor, Dilate, Blur, Composite };
constexpr uint32_t kPassCount = 5;
constexpr const char* kPassNames[kPassCount] = {"downsample_depth", "downsample_color", "dilate", "blur",
                                                "composite"};

struct PassGrid {
    uint32_t x = 1, y = 1, z = 1;  // workgroup counts
};

// Values of the FFX_DOF_OPTION_* axes chosen by the context flags. A backend adds the
// device-dependent axes (FFX_HALF, FFX_DOF_OPTION_WAVE64).
struct PermutationOptions {
    uint32_t reverseDepth = 0;     // FFX_DOF_OPTION_REVERSE_DEPTH
    uint32_t ringMergeLog = 1;     // FFX_DOF_OPTION_MAX_RING_MERGE_LOG
    uint32_t combineInPlace = 0;   // FFX_DOF_OPTION_COMBINE_IN_PLACE
};

// Number of MIP levels of COLOR_MIPS / COC_MIPS the SDK allocates (FFX_DOF_OPTION_MAX_MIP).
constexpr uint32_t kMipCount = 4;

}  // namespace ffxdof
