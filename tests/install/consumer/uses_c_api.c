#include <ffx_dof.h>

unsigned consumer_version_from_c(void) { return ffxDofGetEffectVersion(); }
