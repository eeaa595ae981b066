#define FFX_HLSL 1
#define FFX_DOF_PASS_BLUR 1
#include "../ffx_dof_callbacks_hlsl.h"
#include "../ffx_dof_blur.h"

FFX_DOF_WAVE_SIZE_ATTRIBUTE
[numthreads(FFX_DOF_GROUP_THREADS, 1, 1)]
void main(uint3 groupId : SV_GroupID, uint localIndex : SV_GroupIndex)
{
    ffxDofBlur(FFX_DOF_OPTION_BLUR_CLASS, groupId.x, localIndex);
}
