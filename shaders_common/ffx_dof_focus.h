// The CoC line the passes use: the dispatch's own (FfxDofConstants::cocScale / cocBias), or the one
// the autofocus pass of the same dispatch wrote to GLOBALS. The passes that turn depth into a radius
// load their constants through ffxDofGetFocusedConstants instead of ffxDofGetConstants.
#ifndef FFX_DOF_FOCUS_H
#define FFX_DOF_FOCUS_H

#include "ffx_dof_common.h"

#if defined(FFX_CPU)
FfxDofConstants ffxDofGetConstants();
FfxFloat32x2 ffxDofLoadFocusCocLine();
#endif

FFX_DOF_INLINE FfxDofConstants ffxDofGetFocusedConstants()
{
    FfxDofConstants constants = ffxDofGetConstants();
    if ((constants.focusFlags & FFX_DOF_FOCUS_FLAG_AUTO) != 0u)
    {
        FfxFloat32x2 cocLine = ffxDofLoadFocusCocLine();
        constants.cocScale = cocLine.x;
        constants.cocBias = cocLine.y;
    }
    return constants;
}

#endif  // FFX_DOF_FOCUS_H
