// Consumes the installed package: the C API, a backend entry point, and the shader headers compiled as C++.
#include <ffx_dof.h>
#if defined(CONSUMER_USES_VULKAN)
#include <ffx_dof_vk.h>
#endif
#include <ffx_dof_constants.h>

#include <cstdio>

extern "C" unsigned consumer_version_from_c(void);

int main() {
    FfxDofContext context = nullptr;
    FfxDofContextDescription description{};
    description.quality = 10;
    description.resolution = {64, 64};
    if (ffxDofContextCreate(&context, &description) != FFX_DOF_ERROR_INVALID_POINTER) return 1;
#if defined(CONSUMER_USES_VULKAN)
    FfxDofBackend backend = nullptr;
    if (ffxDofBackendCreateVK(nullptr, &backend) == FFX_DOF_OK) return 2;
    // The installed header has the features chain; the backend refuses a description without it.
    FfxDofBackendDescriptionVK vulkan{};
    vulkan.pEnabledFeatures = nullptr;
    if (ffxDofBackendCreateVK(&vulkan, &backend) != FFX_DOF_ERROR_INVALID_POINTER) return 2;
#endif
    if (sizeof(FfxDofConstants) != 120) return 3;
    if (consumer_version_from_c() != ffxDofGetEffectVersion()) return 4;
    std::printf("ffx-dof %u.%u.%u consumed\n", FFX_DOF_VERSION_MAJOR, FFX_DOF_VERSION_MINOR, FFX_DOF_VERSION_PATCH);
    return 0;
}
