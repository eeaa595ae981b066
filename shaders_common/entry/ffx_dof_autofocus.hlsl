#define FFX_HLSL 1
#define FFX_DOF_PASS_AUTOFOCUS 1
#include "../ffx_dof_callbacks_hlsl.h"
#include "../ffx_dof_autofocus.h"

FFX_DOF_WAVE_SIZE_ATTRIBUTE
[numthreads(FFX_DOF_GROUP_THREADS, 1, 1)]
void main(uint localIndex : SV_GroupIndex)
{
    ffxDofAutofocus(localIndex);
}
