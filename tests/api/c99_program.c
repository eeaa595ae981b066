/* Uses the public API from strict C99: designated initialisers, the error strings, the CoC helpers. */
#include "ffx_dof.h"

#include <stdio.h>

int ffx_dof_c99_checks(void);

int ffx_dof_c99_checks(void) {
    FfxDofContextDescription description = {
        .flags = FFX_DOF_REVERSE_DEPTH,
        .quality = 10,
        .resolution = {.width = 1920, .height = 1080},
        .backendInterface = NULL,
        .cocLimitFactor = 0.05f,
    };
    FfxDofContext context = NULL;
    int failures = 0;
    if (ffxDofContextCreate(&context, &description) != FFX_DOF_ERROR_INVALID_POINTER) ++failures;
    if (context != NULL) ++failures;
    if (ffxDofContextDestroy(&context) != FFX_DOF_OK) ++failures;
    if (ffxDofGetEffectVersion() !=
        FFX_DOF_MAKE_VERSION(FFX_DOF_VERSION_MAJOR, FFX_DOF_VERSION_MINOR, FFX_DOF_VERSION_PATCH))
        ++failures;
    {
        const float scale = ffxDofCalculateCocScale(0.0125f, -2.0f, 0.05f, 1000.0f, -1.0001f, -0.10001f, -1.0f);
        const float bias = ffxDofCalculateCocBias(0.0125f, -2.0f, 0.05f, 1000.0f, -1.0001f, -0.10001f, -1.0f);
        if (!(scale == scale) || !(bias == bias)) ++failures; /* finite for a valid lens */
    }
    printf("C99: %s / %s\n", ffxDofGetErrorString(FFX_DOF_ERROR_INVALID_POINTER), ffxDofGetLastErrorMessage());
    return failures;
}

#if defined(FFX_DOF_C99_PROGRAM_MAIN)
int main(void) {
    const int failures = ffx_dof_c99_checks();
    printf("%d failed\n", failures);
    return failures == 0 ? 0 : 1;
}
#endif
