// The Vulkan-specific entry points of ffx_dof_vk.h that act on resources and contexts.
#include "ffx_dof_context.h"
#include "ffx_dof_vk_context.h"

#include <type_traits>

using namespace ffxdof;

namespace {

vk::ContextVK* vulkanContextOf(FfxDofContext* pContext) {
    return pContext ? dynamic_cast<vk::ContextVK*>(backendContextOf(*pContext)) : nullptr;
}

}  // namespace

extern "C" {

FfxDofResource ffxDofGetResourceVK(VkImage image, VkFormat format, uint32_t width, uint32_t height,
                                   VkImageLayout layout, uint32_t resourceFlags) {
    FfxDofResource resource{};
    if constexpr (std::is_pointer_v<VkImage>) {
        resource.handle = static_cast<uint64_t>(reinterpret_cast<uintptr_t>(image));
    } else {
        resource.handle = uint64_t(image);
    }
    resource.format = uint32_t(format);
    resource.width = width;
    resource.height = height;
    resource.state = uint32_t(layout);
    resource.flags = resourceFlags;
    return resource;
}

FfxDofCommandList ffxDofGetCommandListVK(VkCommandBuffer commandBuffer) { return commandBuffer; }

FfxDofErrorCode ffxDofContextSetTimestampQueriesVK(FfxDofContext* pContext, VkQueryPool queryPool,
                                                   uint32_t firstQuery) {
    clearLastError();
    if (!pContext) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pContext is null");
    vk::ContextVK* context = vulkanContextOf(pContext);
    if (!context) return fail(FFX_DOF_ERROR_INVALID_CONTEXT, "the context is not a live Vulkan context");
    context->setTimestampQueries(queryPool, firstQuery);
    return FFX_DOF_OK;
}

FfxDofErrorCode ffxDofContextReleaseImageVK(FfxDofContext* pContext, VkImage image) {
    clearLastError();
    if (!pContext) return fail(FFX_DOF_ERROR_INVALID_POINTER, "pContext is null");
    vk::ContextVK* context = vulkanContextOf(pContext);
    if (!context) return fail(FFX_DOF_ERROR_INVALID_CONTEXT, "the context is not a live Vulkan context");
    context->releaseImage(image);
    return FFX_DOF_OK;
}

}  // extern "C"
