#include "ffx_dof_vk_functions.h"

namespace ffxdof::vk {

const char* loadFunctions(PFN_vkGetInstanceProcAddr getInstanceProcAddr, PFN_vkGetDeviceProcAddr getDeviceProcAddr,
                          VkInstance instance, VkDevice device, Functions* functions) {
#define FFX_DOF_VK_LOAD_INSTANCE(name)                                                    \
    functions->name = reinterpret_cast<PFN_##name>(getInstanceProcAddr(instance, #name)); \
    if (!functions->name) return #name;
#define FFX_DOF_VK_LOAD_OPTIONAL_INSTANCE(name) \
    functions->name = reinterpret_cast<PFN_##name>(getInstanceProcAddr(instance, #name));
#define FFX_DOF_VK_LOAD_DEVICE(name)                                                  \
    functions->name = reinterpret_cast<PFN_##name>(getDeviceProcAddr(device, #name)); \
    if (!functions->name) return #name;
    FFX_DOF_VK_INSTANCE_FUNCTIONS(FFX_DOF_VK_LOAD_INSTANCE)
    FFX_DOF_VK_OPTIONAL_INSTANCE_FUNCTIONS(FFX_DOF_VK_LOAD_OPTIONAL_INSTANCE)
    FFX_DOF_VK_DEVICE_FUNCTIONS(FFX_DOF_VK_LOAD_DEVICE)
#undef FFX_DOF_VK_LOAD_INSTANCE
#undef FFX_DOF_VK_LOAD_OPTIONAL_INSTANCE
#undef FFX_DOF_VK_LOAD_DEVICE
    return nullptr;
}

}  // namespace ffxdof::vk
