#define FFX_HLSL 1
#define FFX_DOF_PASS_COMPOSITE 1
#include "../ffx_dof_callbacks_hlsl.h"
#include "../ffx_dof_composite.h"

FFX_DOF_WAVE_SIZE_ATTRIBUTE
[numthreads(FFX_DOF_GROUP_THREADS, 1, 1)]
void main(uint3 groupId : SV_GroupID, uint localIndex : SV_GroupIndex)
{
    ffxDofComposite(FFX_DOF_OPTION_COMPOSITE_CLASS, groupId.x, localIndex);
}
