#include "ffx_dof_vk_engine_images.h"

#include <algorithm>
#include <type_traits>

namespace ffxdof::vk {
namespace {

// FfxDofResource::handle <-> VkImage: a pointer on 64-bit platforms, a uint64_t on 32-bit ones.
VkImage imageOf(const FfxDofResource& resource) {
    if constexpr (std::is_pointer_v<VkImage>) {
        return reinterpret_cast<VkImage>(static_cast<uintptr_t>(resource.handle));
    } else {
        return VkImage(resource.handle);
    }
}

// The layouts an engine image may be declared in: valid for an image of its aspect and holding its
// contents, so the barriers into and out of the effect's layouts are valid. Anything else (UNDEFINED,
// PREINITIALIZED, an attachment layout of the other aspect, a value that is no VkImageLayout at all)
// is refused before any barrier is recorded.
bool isAcceptedLayout(VkImageLayout layout, bool depthAspect) {
    switch (layout) {
        case VK_IMAGE_LAYOUT_GENERAL:
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
        case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
            return true;
        case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
            return !depthAspect;
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL:
            return depthAspect;
        default:
            return false;
    }
}

// The layout a sampled image is read in: a read-only layout the engine already uses is kept.
VkImageLayout sampledLayout(VkImageLayout declared) {
    return declared == VK_IMAGE_LAYOUT_GENERAL ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

}  // namespace

VkFormatFeatureFlags FormatSupport::optimalFeatures(VkFormat format) {
    for (const auto& [known, features] : known_) {
        if (known == format) return features;
    }
    const VkFormatFeatureFlags features = backend_.optimalFeatures(format);
    known_.emplace_back(format, features);
    return features;
}

FfxDofErrorCode checkEngineImages(const ContextPlan& plan, const DispatchPlan& dispatch, FormatSupport* formats,
                                  EngineImages* images) {
    const struct {
        const char* name;
        const FfxDofResource& resource;
    } resources[] = {{"color", dispatch.color}, {"depth", dispatch.depth}, {"output", dispatch.output}};
    for (const auto& r : resources) {
        if (r.resource.flags & ~uint32_t(FFX_DOF_VK_RESOURCE_MUTABLE_FORMAT)) {
            return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "%s has flags 0x%x that are not FfxDofResourceFlagBitsVK",
                        r.name, r.resource.flags);
        }
    }
    const VkFormat colorFormat = VkFormat(dispatch.color.format);
    const VkFormat depthFormat = VkFormat(dispatch.depth.format);
    const VkFormat outputFormat = VkFormat(dispatch.output.format);
    if (!isColorFormat(colorFormat)) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "color format %s is not supported (R16G16B16A16_SFLOAT, R32G32B32A32_SFLOAT, "
                    "B10G11R11_UFLOAT_PACK32, R8G8B8A8_UNORM or R8G8B8A8_SRGB)",
                    formatName(colorFormat).c_str());
    }
    if (!isDepthFormat(depthFormat)) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "depth format %s is not supported (D32_SFLOAT, D24_UNORM_S8_UINT, D16_UNORM or R32_SFLOAT)",
                    formatName(depthFormat).c_str());
    }
    if (!isColorFormat(outputFormat)) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE, "output format %s is not supported (the color formats are)",
                    formatName(outputFormat).c_str());
    }
    const bool depthAspect = isDepthAspectFormat(depthFormat);
    for (const auto& r : resources) {
        const VkImageLayout layout = VkImageLayout(r.resource.state);
        const bool isDepthImage = &r.resource == &dispatch.depth && depthAspect;
        if (!isAcceptedLayout(layout, isDepthImage)) {
            return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                        "%s is declared in %s, which is not accepted: use GENERAL, SHADER_READ_ONLY_OPTIMAL, "
                        "TRANSFER_SRC/DST_OPTIMAL or %s (the image must hold its contents before and after)",
                        r.name, layoutName(layout).c_str(),
                        isDepthImage ? "DEPTH_STENCIL_ATTACHMENT/READ_ONLY_OPTIMAL, DEPTH_READ_ONLY_OPTIMAL"
                                     : "COLOR_ATTACHMENT_OPTIMAL");
        }
    }
    images->encodeSrgb = outputFormat == VK_FORMAT_R8G8B8A8_SRGB;
    if (images->encodeSrgb && !(dispatch.output.flags & FFX_DOF_VK_RESOURCE_MUTABLE_FORMAT)) {
        return fail(FFX_DOF_ERROR_INVALID_RESOURCE,
                    "output is VK_FORMAT_R8G8B8A8_SRGB, which cannot be a storage image: create it with "
                    "VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT and pass FFX_DOF_VK_RESOURCE_MUTABLE_FORMAT");
    }
    if (!(formats->optimalFeatures(colorFormat) & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device cannot sample color format %s",
                    formatName(colorFormat).c_str());
    }
    if (!(formats->optimalFeatures(depthFormat) & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device cannot sample depth format %s",
                    formatName(depthFormat).c_str());
    }
    const VkFormat outputViewFormat = images->encodeSrgb ? VK_FORMAT_R8G8B8A8_UNORM : outputFormat;
    if (!(formats->optimalFeatures(outputViewFormat) & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT)) {
        return fail(FFX_DOF_ERROR_UNSUPPORTED, "the device cannot write output format %s as a storage image",
                    formatName(outputViewFormat).c_str());
    }

    // The passes read color and depth (sampled) and write the output (storage, which they may read).
    const bool colorRead = plan.touched & resourceBit(Resource::InputColor);
    const VkAccessFlags storageAccess = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;

    EngineImageUse& color = images->color;
    color = EngineImageUse{};
    color.image = imageOf(dispatch.color);
    color.declared = VkImageLayout(dispatch.color.state);
    color.viewFormat = colorFormat;
    if (dispatch.outputIsColor) {
        // One image, sampled and stored: GENERAL for both.
        color.during = VK_IMAGE_LAYOUT_GENERAL;
        color.access = storageAccess;
    } else {
        color.during = sampledLayout(color.declared);
        color.access = colorRead ? VK_ACCESS_SHADER_READ_BIT : 0;
    }

    EngineImageUse& depth = images->depth;
    depth = EngineImageUse{};
    depth.image = imageOf(dispatch.depth);
    depth.declared = VkImageLayout(dispatch.depth.state);
    depth.access = VK_ACCESS_SHADER_READ_BIT;
    depth.viewFormat = depthFormat;
    if (depthAspect) {
        const bool keep = depth.declared == VK_IMAGE_LAYOUT_GENERAL ||
                          depth.declared == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL ||
                          depth.declared == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
        depth.during = keep ? depth.declared : VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
        // Without separate depth/stencil layouts both aspects change layout together.
        depth.barrierAspects = VK_IMAGE_ASPECT_DEPTH_BIT;
        if (depthFormat == VK_FORMAT_D24_UNORM_S8_UINT && depth.declared != VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL) {
            depth.barrierAspects |= VK_IMAGE_ASPECT_STENCIL_BIT;
        }
        depth.viewAspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    } else {
        depth.during = sampledLayout(depth.declared);  // R32_SFLOAT, through the color aspect
    }

    EngineImageUse& output = images->output;
    output = EngineImageUse{};
    output.image = imageOf(dispatch.output);
    output.declared = VkImageLayout(dispatch.output.state);
    output.during = VK_IMAGE_LAYOUT_GENERAL;
    output.access = storageAccess;
    // Each view is restricted to the usage it serves, so a view format that cannot be stored (an
    // _SRGB view of a mutable storage image) is still valid.
    output.viewFormat = outputViewFormat;
    output.viewUsage = VK_IMAGE_USAGE_STORAGE_BIT;
    return FFX_DOF_OK;
}

EngineViewCache::~EngineViewCache() {
    for (const Entry& entry : entries_) backend_.fn.vkDestroyImageView(backend_.device, entry.view, backend_.allocator);
}

FfxDofErrorCode EngineViewCache::view(const EngineImageUse& use, uint64_t dispatchIndex, VkImageView* view) {
    for (Entry& entry : entries_) {
        if (entry.image == use.image && entry.format == use.viewFormat && entry.aspect == use.viewAspect &&
            entry.usage == use.viewUsage) {
            entry.lastUse = dispatchIndex;
            *view = entry.view;
            return FFX_DOF_OK;
        }
    }
    auto usageInfo = makeInfo<VkImageViewUsageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_USAGE_CREATE_INFO);
    usageInfo.usage = use.viewUsage;
    auto info = makeInfo<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    info.pNext = &usageInfo;
    info.image = use.image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = use.viewFormat;
    info.subresourceRange = {use.viewAspect, 0, 1, 0, 1};
    VkImageView made = VK_NULL_HANDLE;
    FFX_DOF_VK_CHECK(backend_.fn.vkCreateImageView(backend_.device, &info, backend_.allocator, &made),
                     "vkCreateImageView (an engine image)");
    entries_.push_back({use.image, use.viewFormat, use.viewAspect, use.viewUsage, made, dispatchIndex});
    *view = made;
    return FFX_DOF_OK;
}

void EngineViewCache::trim(uint64_t dispatchIndex, std::vector<VkImageView>* destroyed) {
    if (entries_.size() <= kRetainedViews) return;
    // Oldest first; a view used by one of the last framesInFlight dispatches may still be in use.
    std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.lastUse < b.lastUse; });
    size_t excess = entries_.size() - kRetainedViews;
    auto end = entries_.begin();
    while (excess > 0 && end != entries_.end() && end->lastUse + backend_.framesInFlight <= dispatchIndex) {
        backend_.fn.vkDestroyImageView(backend_.device, end->view, backend_.allocator);
        destroyed->push_back(end->view);
        ++end;
        --excess;
    }
    entries_.erase(entries_.begin(), end);
}

void EngineViewCache::release(VkImage image, std::vector<VkImageView>* destroyed) {
    const auto kept = std::stable_partition(entries_.begin(), entries_.end(),
                                            [&](const Entry& entry) { return entry.image != image; });
    for (auto it = kept; it != entries_.end(); ++it) {
        backend_.fn.vkDestroyImageView(backend_.device, it->view, backend_.allocator);
        destroyed->push_back(it->view);
    }
    entries_.erase(kept, entries_.end());
}

}  // namespace ffxdof::vk
