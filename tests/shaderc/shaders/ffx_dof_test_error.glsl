#version 450
// Compiles only when FFX_DOF_TEST_BROKEN is 0: the error must name the permutation and the line.
layout(local_size_x = 8) in;
layout(set = 0, binding = 40, std430) buffer FfxDofTestResult { uint value; } ffxDofTestResult;
void main() {
#if FFX_DOF_TEST_BROKEN
    ffxDofTestResult.value = ffxDofTestUndeclared;
#else
    ffxDofTestResult.value = 1u;
#endif
}
