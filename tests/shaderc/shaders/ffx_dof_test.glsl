#version 450
// Test pass for ffx-dof-shaderc: an include, a push constant block, a few bindings and axes.
// FFX_DOF_TEST_SCALE changes the code; FFX_DOF_TEST_UNUSED does not (it must deduplicate).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types : require
#extension GL_EXT_samplerless_texture_functions : require
#include "ffx_dof_test_common.h"

#if FFX_DOF_TEST_WIDE
layout(local_size_x = FFX_DOF_TEST_GROUP_SIZE * 8, local_size_y = 1) in;
#else
layout(local_size_x = FFX_DOF_TEST_GROUP_SIZE, local_size_y = FFX_DOF_TEST_GROUP_SIZE) in;
#endif

layout(push_constant) uniform FfxDofTestConstants {
    float scale;
    uint flags;
    uvec2 size;
    vec2 texelSize;
} ffxDofTestConstants;

layout(set = 0, binding = 0) uniform texture2D ffxDofTestInput;
layout(set = 0, binding = 16, rgba16f) uniform writeonly image2D ffxDofTestOutput;
layout(set = 0, binding = 40, std430) buffer FfxDofTestGlobals { uint maxValue; } ffxDofTestGlobals;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), ffxDofTestConstants.size))) return;
#if FFX_HALF
    f16vec4 color = f16vec4(texelFetch(ffxDofTestInput, pixel, 0)) * float16_t(FFX_DOF_TEST_SCALE);
#else
    vec4 color = texelFetch(ffxDofTestInput, pixel, 0) * float(FFX_DOF_TEST_SCALE);
#endif
    imageStore(ffxDofTestOutput, pixel, vec4(color) * ffxDofTestConstants.scale);
    atomicMax(ffxDofTestGlobals.maxValue, ffxDofTestConstants.flags + uint(FFX_DOF_TEST_SCALE));
}
