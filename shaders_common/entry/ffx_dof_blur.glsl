#version 450
#extension GL_GOOGLE_include_directive : require
#define FFX_GLSL 1
#define FFX_DOF_PASS_BLUR 1
#include "../ffx_dof_callbacks_glsl.h"
#include "../ffx_dof_blur.h"

layout(local_size_x = FFX_DOF_GROUP_THREADS, local_size_y = 1, local_size_z = 1) in;
void main()
{
    ffxDofBlur(FFX_DOF_OPTION_BLUR_CLASS, gl_WorkGroupID.x, gl_LocalInvocationIndex);
}
