// The Vulkan backend object: the engine's device, the loaded entry points, the pipeline cache, the
// device axes, and the pipelines and layouts of every context made with it. Private to ffx-dof.
#pragma once

#include "ffx_dof_backend.h"
#include "ffx_dof_backend_cache.h"
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

// Vulkan binding numbers of the slot classes (ffx_dof_resources.h): class base + slot, set 0.
struct SlotClass {
    VkDescriptorType type;
    uint32_t base;
    uint32_t PlannedPass::*slots;
};
constexpr SlotClass kSlotClasses[] = {
    {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, FFX_DOF_SRV_BASE, &PlannedPass::sampledSlots},
    {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, FFX_DOF_UAV_IMAGE_BASE, &PlannedPass::storageSlots},
    {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, FFX_DOF_UAV_BUFFER_BASE, &PlannedPass::bufferSlots},
};

class BackendVK final : public FfxDofBackend_T {
public:
    ~BackendVK() override;
    FfxDofErrorCode init(const FfxDofBackendDescriptionVK& description);

    BackendCapabilities capabilities() const override;
    FfxDofErrorCode createContext(const ContextPlan& plan, std::unique_ptr<BackendContext>* out) override;

    // A memory type allowed by typeBits with the `required` properties, device-local where possible.
    bool findMemoryType(uint32_t typeBits, uint32_t* index, VkMemoryPropertyFlags required = 0) const;
    VkFormatFeatureFlags optimalFeatures(VkFormat format) const;

    // A pass's descriptor set layout and pipeline layout, made for the first context that declares its
    // slots and kept for the others (ffx_dof_backend_cache.h); destroyed with the backend.
    struct PassLayout {
        VkDescriptorSetLayout set = VK_NULL_HANDLE;
        VkPipelineLayout pipeline = VK_NULL_HANDLE;
    };
    FfxDofErrorCode passLayout(const PlannedPass& pass, PassLayout* out);
    // A pass's pipeline for one blob on its layout, made once per backend the same way.
    FfxDofErrorCode passPipeline(const char* passName, const shaders::Blob& blob, VkPipelineLayout layout, bool wave64,
                                 VkPipeline* out);

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

    struct LayoutKey {
        uint32_t sampledSlots, storageSlots, bufferSlots;  // PlannedPass's: they alone decide the bindings
        bool operator==(const LayoutKey& o) const {
            return sampledSlots == o.sampledSlots && storageSlots == o.storageSlots && bufferSlots == o.bufferSlots;
        }
    };
    struct PipelineKey {
        const shaders::Blob* blob;  // static data of the shader tables: its address names the permutation
        VkPipelineLayout layout;
        bool wave64;
        bool operator==(const PipelineKey& o) const {
            return blob == o.blob && layout == o.layout && wave64 == o.wave64;
        }
    };
    BackendObjectCache<LayoutKey, PassLayout> layouts_;
    BackendObjectCache<PipelineKey, VkPipeline> pipelines_;

    VkPhysicalDeviceMemoryProperties memoryProperties_{};
    bool ownsPipelineCache_ = false;
    ShaderLanguage language_ = ShaderLanguage::Glsl;
    bool useHalf_ = false;
};

}  // namespace ffxdof::vk
