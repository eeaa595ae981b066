// The Vulkan backend object: the engine's device, the loaded entry points, the pipeline cache and
// the device axes; shared by every context made with it. Private to ffx-dof.
#pragma once

#include "ffx_dof_backend.h"
#include "ffx_dof_vk.h"
#include "ffx_dof_vk_features.h"
#include "ffx_dof_vk_functions.h"
#include "ffx_dof_vk_shaders.h"

namespace ffxdof::vk {

// Records the VkResult of a failed call for ffxDofGetLastErrorMessage and maps it to an error code.
FfxDofErrorCode failVk(VkResult result, const char* what);

#define FFX_DOF_VK_CHECK(call, what)                                                       \
    do {                                                                                   \
        const VkResult checkedResult = (call);                                             \
        if (checkedResult != VK_SUCCESS) return ::ffxdof::vk::failVk(checkedResult, what); \
    } while (0)

class BackendVK final : public FfxDofBackend_T {
public:
    ~BackendVK() override;
    FfxDofErrorCode init(const FfxDofBackendDescriptionVK& description);

    BackendCapabilities capabilities() const override;
    FfxDofErrorCode createContext(const ContextPlan& plan, std::unique_ptr<BackendContext>* out) override;

    // A memory type allowed by typeBits with the `required` properties, device-local where possible.
    bool findMemoryType(uint32_t typeBits, uint32_t* index, VkMemoryPropertyFlags required = 0) const;
    VkFormatFeatureFlags optimalFeatures(VkFormat format) const;

    Functions fn;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    const VkAllocationCallbacks* allocator = nullptr;
    VkPipelineCache pipelineCache = VK_NULL_HANDLE;
    uint32_t framesInFlight = 0;
    EnabledFeatures features;  // what the engine enabled at vkCreateDevice (pEnabledFeatures)
    bool useWave64 = false;    // the pipelines require 64-wide full subgroups

private:
    bool deviceSupportsWave64() const;

    VkPhysicalDeviceMemoryProperties memoryProperties_{};
    bool ownsPipelineCache_ = false;
    ShaderLanguage language_ = ShaderLanguage::Glsl;
    bool useHalf_ = false;
};

}  // namespace ffxdof::vk
