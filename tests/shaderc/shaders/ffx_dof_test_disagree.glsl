#version 450
// The storage image moves with FFX_DOF_TEST_SLOT: permutations disagree on bindings.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 16 + FFX_DOF_TEST_SLOT, rgba8) uniform writeonly image2D ffxDofTestOutput;
void main() { imageStore(ffxDofTestOutput, ivec2(gl_GlobalInvocationID.xy), vec4(1.0)); }
