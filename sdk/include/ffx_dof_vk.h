/*
 * ffx-dof Vulkan backend. Valid C99 and C++.
 *
 * The engine owns the instance, the device, the command buffers and its images. The backend owns
 * its pipelines; each context owns its internal images. Nothing is submitted by ffx-dof.
 */
#ifndef FFX_DOF_VK_H
#define FFX_DOF_VK_H

#include "ffx_dof.h"

#include <vulkan/vulkan.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Bits of FfxDofBackendDescriptionVK::flags. */
typedef enum FfxDofBackendFlagBitsVK {
    /** Never select the 16-bit (FFX_HALF) shaders even where the device supports them. */
    FFX_DOF_VK_DISABLE_FLOAT16 = (1 << 0),
    /** Never select the wave64 shaders even where the device supports 64-wide subgroups. */
    FFX_DOF_VK_DISABLE_WAVE64 = (1 << 1),
    /** Run the HLSL-compiled SPIR-V instead of the GLSL-compiled one (for cross-checking). */
    FFX_DOF_VK_USE_HLSL_SHADERS = (1 << 2)
} FfxDofBackendFlagBitsVK;

/** Bits of FfxDofResource::flags for Vulkan images. */
typedef enum FfxDofResourceFlagBitsVK {
    /** The image was created with VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT: an _SRGB output is then
     *  written through a _UNORM view with the sRGB encoding done in the shader. */
    FFX_DOF_VK_RESOURCE_MUTABLE_FORMAT = (1 << 0)
} FfxDofResourceFlagBitsVK;

typedef struct FfxDofBackendDescriptionVK {
    VkInstance instance; /**< the engine's; outlives the backend */
    VkPhysicalDevice physicalDevice;
    VkDevice device; /**< created with the features listed in docs/integration-vulkan.md */
    /** Required: the features the engine enabled on `device`, as the VkPhysicalDeviceFeatures2 chain
     *  it passed to vkCreateDevice in VkDeviceCreateInfo::pNext (VkPhysicalDeviceVulkan11/12/13Features
     *  or the individual structures such as VkPhysicalDevice16BitStorageFeatures,
     *  VkPhysicalDeviceShaderFloat16Int8Features, VkPhysicalDeviceSubgroupSizeControlFeatures in its
     *  pNext). Other structures are skipped; a feature counts as enabled when any structure in the
     *  chain enables it. Read only during ffxDofBackendCreateVK. The backend chooses the 16-bit
     *  shaders with shaderFloat16 and wave64 with subgroupSizeControl and computeFullSubgroups; a
     *  feature that the chosen shaders need and the chain does not enable (such as
     *  shaderStorageImageWriteWithoutFormat) makes ffxDofContextCreate fail with
     *  FFX_DOF_ERROR_UNSUPPORTED naming it. */
    const VkPhysicalDeviceFeatures2* pEnabledFeatures;
    PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr; /**< all other entry points are loaded from these */
    PFN_vkGetDeviceProcAddr vkGetDeviceProcAddr;
    const VkAllocationCallbacks* allocationCallbacks; /**< optional; used for every object the backend creates */
    VkPipelineCache pipelineCache;                    /**< optional; VK_NULL_HANDLE makes a private one */
    uint32_t maxFramesInFlight;                       /**< dispatches the GPU may still be executing when the
                                                           next is recorded; 0 means 3 */
    uint32_t flags;                                   /**< FfxDofBackendFlagBitsVK */
} FfxDofBackendDescriptionVK;

/** Creates a Vulkan backend. *pBackend is set to NULL on failure. */
FfxDofErrorCode ffxDofBackendCreateVK(const FfxDofBackendDescriptionVK* pDescription, FfxDofBackend* pBackend);

/** Wraps an engine image. layout is the layout the image is in before the dispatch and is left in after. */
FfxDofResource ffxDofGetResourceVK(VkImage image, VkFormat format, uint32_t width, uint32_t height,
                                   VkImageLayout layout, uint32_t resourceFlags);

/** Wraps the engine's command buffer, which must be recording and support compute. */
FfxDofCommandList ffxDofGetCommandListVK(VkCommandBuffer commandBuffer);

/** The engine is about to destroy image (after the GPU finished every dispatch that used it): the
 *  context destroys the views it keeps of it. The context keeps a view of each engine image it was
 *  given, per format and aspect, from dispatch to dispatch (no view is made per dispatch), so an image
 *  destroyed without this call would leave a view whose handle a new image could be mistaken for.
 *  Destroying the context releases every view. Images never given to the context are ignored. */
FfxDofErrorCode ffxDofContextReleaseImageVK(FfxDofContext* pContext, VkImage image);

/** Number of timestamps ffxDofContextSetTimestampQueriesVK writes per dispatch: one before the first
 *  pass and one after each of the six passes (autofocus, then the five of FidelityFX DoF; autofocus
 *  takes no time in a dispatch that does not ask for it). */
#define FFX_DOF_VK_TIMESTAMP_COUNT 7u

/** Profiling: later dispatches write FFX_DOF_VK_TIMESTAMP_COUNT timestamps into queryPool starting at
 *  firstQuery (and reset them first). VK_NULL_HANDLE stops it. The pool is the engine's. */
FfxDofErrorCode ffxDofContextSetTimestampQueriesVK(FfxDofContext* pContext, VkQueryPool queryPool, uint32_t firstQuery);

#ifdef __cplusplus
}
#endif

#endif /* FFX_DOF_VK_H */
