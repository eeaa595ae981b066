// Shared by the shaderc test shaders (GLSL and HLSL): the push constant layout under test.
#ifndef FFX_DOF_TEST_COMMON_H
#define FFX_DOF_TEST_COMMON_H

#define FFX_DOF_TEST_GROUP_SIZE 8

#endif
