#include "ffx_dof_backend.h"

#include <cstdarg>
#include <cstdio>
#include <string>

namespace {
thread_local std::string t_lastError;
}

namespace ffxdof {

FfxDofErrorCode fail(FfxDofErrorCode code, const char* format, ...) {
    char buffer[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buffer, sizeof(buffer), format, args);
    va_end(args);
    t_lastError = buffer;
    return code;
}

void clearLastError() { t_lastError.clear(); }

}  // namespace ffxdof

extern "C" const char* ffxDofGetLastErrorMessage(void) { return t_lastError.c_str(); }

extern "C" const char* ffxDofGetErrorString(FfxDofErrorCode code) {
    switch (code) {
        case FFX_DOF_OK:
            return "success";
        case FFX_DOF_ERROR_INVALID_POINTER:
            return "a required pointer or handle is null";
        case FFX_DOF_ERROR_INVALID_RESOLUTION:
            return "width or height is 0 or above FFX_DOF_MAX_RESOLUTION";
        case FFX_DOF_ERROR_INVALID_QUALITY:
            return "quality is 0 or above FFX_DOF_MAX_QUALITY";
        case FFX_DOF_ERROR_INVALID_COC_LIMIT:
            return "cocLimitFactor is negative, NaN or infinite";
        case FFX_DOF_ERROR_INVALID_FLAGS:
            return "flags contain bits that are not FfxDofInitializationFlagBits";
        case FFX_DOF_ERROR_INVALID_RESOURCE:
            return "a resource is null, of an unsupported format or of the wrong size";
        case FFX_DOF_ERROR_OUTPUT_ALIASES_INPUT:
            return "output is the color image but FFX_DOF_OUTPUT_PRE_INIT is not set";
        case FFX_DOF_ERROR_INVALID_CONTEXT:
            return "the context was destroyed or never created";
        case FFX_DOF_ERROR_INVALID_ARGUMENT:
            return "an argument is out of range";
        case FFX_DOF_ERROR_UNSUPPORTED:
            return "the device or this build does not support a required feature";
        case FFX_DOF_ERROR_OUT_OF_MEMORY:
            return "an allocation failed";
        case FFX_DOF_ERROR_BACKEND:
            return "the graphics API returned an error";
        case FFX_DOF_ERROR_BACKEND_IN_USE:
            return "the backend still has live contexts";
    }
    return "unknown error code";
}
