// The engine's images in one dispatch: what Vulkan-specific about them is accepted (formats, layouts,
// flags), how the dispatch uses them, and the cache of the views the effect reads and writes them by.
#pragma once

#include "ffx_dof_vk_backend.h"

#include <cstdint>
#include <vector>

namespace ffxdof::vk {

// How one dispatch uses an engine image: the layout it is declared in (and left in), the layout and
// the accesses of the effect's passes, and the view they see it through.
struct EngineImageUse {
    VkImage image = VK_NULL_HANDLE;
    VkImageAspectFlags barrierAspects = VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageLayout declared = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout during = VK_IMAGE_LAYOUT_UNDEFINED;
    VkAccessFlags access = 0;
    VkFormat viewFormat = VK_FORMAT_UNDEFINED;
    VkImageAspectFlags viewAspect = VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageUsageFlags viewUsage = VK_IMAGE_USAGE_SAMPLED_BIT;
};

struct EngineImages {
    EngineImageUse color, depth, output;  // in place, output describes the color image's storage view
    bool encodeSrgb = false;              // output is _SRGB, written through a _UNORM view
};

// Format capabilities of the physical device, asked once per format.
class FormatSupport {
public:
    explicit FormatSupport(const BackendVK& backend) : backend_(backend) {}
    VkFormatFeatureFlags optimalFeatures(VkFormat format);

private:
    const BackendVK& backend_;
    std::vector<std::pair<VkFormat, VkFormatFeatureFlags>> known_;
};

// Checks the Vulkan-specific properties of the engine's images (the core checked presence, sizes and
// aliasing) and says how the dispatch uses them. Records nothing.
FfxDofErrorCode checkEngineImages(const ContextPlan& plan, const DispatchPlan& dispatch, FormatSupport* formats,
                                  EngineImages* images);

// Views of the engine's images, per (image, format, aspect, usage), kept across dispatches.
//
// The rule for the engine (ffx_dof_vk.h, docs/integration-vulkan.md): before it destroys an image it
// gave a dispatch, it calls ffxDofContextReleaseImageVK once the GPU has finished those dispatches (or
// destroys the context). Views unused for longer than the frames in flight are also destroyed once more
// than kRetainedViews are cached, so an engine cycling through many images holds a bounded number.
class EngineViewCache {
public:
    static constexpr size_t kRetainedViews = 16;

    explicit EngineViewCache(const BackendVK& backend) : backend_(backend) {}
    ~EngineViewCache();
    EngineViewCache(const EngineViewCache&) = delete;
    EngineViewCache& operator=(const EngineViewCache&) = delete;

    // The view for `use`, made on its first use; marks it used by dispatch `dispatchIndex`.
    FfxDofErrorCode view(const EngineImageUse& use, uint64_t dispatchIndex, VkImageView* view);
    // Destroys the least recently used views beyond kRetainedViews that no dispatch in flight uses.
    // Appends the destroyed handles to `destroyed` (descriptors that name them must be rewritten).
    void trim(uint64_t dispatchIndex, std::vector<VkImageView>* destroyed);
    // Destroys every view of `image`.
    void release(VkImage image, std::vector<VkImageView>* destroyed);
    size_t size() const { return entries_.size(); }

private:
    struct Entry {
        VkImage image;
        VkFormat format;
        VkImageAspectFlags aspect;
        VkImageUsageFlags usage;
        VkImageView view;
        uint64_t lastUse;
    };
    const BackendVK& backend_;
    std::vector<Entry> entries_;
};

}  // namespace ffxdof::vk
