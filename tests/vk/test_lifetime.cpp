// Backend and context lifetime, leaks, and the errors for invalid engine resources, through the
// public API on a validated device.
#include "vk_test_support.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <vector>

using namespace ffxdof;
using namespace ffxdof::vktest;

namespace {

// Allocation callbacks that count live allocations: every object the backend creates goes
// through them, so a leak shows as a count that does not return to zero.
struct CountingAllocator {
    std::mutex mutex;
    std::unordered_map<void*, size_t> live;
    size_t total = 0;

    static void* VKAPI_CALL allocate(void* user, size_t size, size_t alignment, VkSystemAllocationScope) {
        void* p = std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
        if (p) {
            auto* self = static_cast<CountingAllocator*>(user);
            std::lock_guard<std::mutex> lock(self->mutex);
            self->live[p] = size;
            ++self->total;
        }
        return p;
    }
    static void* VKAPI_CALL reallocate(void* user, void* original, size_t size, size_t alignment,
                                       VkSystemAllocationScope scope) {
        if (!original) return allocate(user, size, alignment, scope);
        if (size == 0) {
            release(user, original);
            return nullptr;
        }
        auto* self = static_cast<CountingAllocator*>(user);
        size_t oldSize;
        {
            std::lock_guard<std::mutex> lock(self->mutex);
            oldSize = self->live.at(original);
        }
        void* p = allocate(user, size, alignment, scope);
        if (p) {
            std::memcpy(p, original, std::min(oldSize, size));
            release(user, original);
        }
        return p;
    }
    static void VKAPI_CALL release(void* user, void* memory) {
        if (!memory) return;
        auto* self = static_cast<CountingAllocator*>(user);
        {
            std::lock_guard<std::mutex> lock(self->mutex);
            self->live.erase(memory);
        }
        std::free(memory);
    }
    VkAllocationCallbacks callbacks() {
        VkAllocationCallbacks result{};
        result.pUserData = this;
        result.pfnAllocation = &allocate;
        result.pfnReallocation = &reallocate;
        result.pfnFree = &release;
        return result;
    }
    size_t liveCount() {
        std::lock_guard<std::mutex> lock(mutex);
        return live.size();
    }
};

// The engine side of a raw-API test: images in the layouts an engine would declare.
struct EngineImages {
    vkrun::GpuImage color, depth, output;
    EngineImages(vkrun::Device& device, const Scene& scene, VkFormat colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT)
        : color(device, scene.color.width, scene.color.height, colorFormat,
                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT),
          depth(device, scene.color.width, scene.color.height, VK_FORMAT_D32_SFLOAT,
                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT),
          output(device, scene.color.width, scene.color.height, VK_FORMAT_R16G16B16A16_SFLOAT,
                 VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT) {
        color.upload(scene.color, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        depth.upload(scene.depth, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
        output.upload(scene.color, VK_IMAGE_LAYOUT_GENERAL);
    }
    FfxDofDispatchDescription dispatch(const Scene& scene) const {
        FfxDofDispatchDescription d{};
        d.color = ffxDofGetResourceVK(color.image(), color.format(), color.width(), color.height(),
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, 0);
        d.depth = ffxDofGetResourceVK(depth.image(), depth.format(), depth.width(), depth.height(),
                                      VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, 0);
        d.output = ffxDofGetResourceVK(output.image(), output.format(), output.width(), output.height(),
                                       VK_IMAGE_LAYOUT_GENERAL, 0);
        d.cocScale = scene.cocScale;
        d.cocBias = scene.cocBias;
        return d;
    }
};

FfxDofContextDescription contextDescription(FfxDofBackend backend, uint32_t width, uint32_t height) {
    FfxDofContextDescription description{};
    description.quality = 3;
    description.resolution = {width, height};
    description.backendInterface = backend;
    description.cocLimitFactor = 0.05f;
    return description;
}

// Records one dispatch, submits it (even on failure, to free the command buffer) and returns its code.
FfxDofErrorCode dispatchOnce(vkrun::Device& device, FfxDofContext* context, FfxDofDispatchDescription description) {
    VkCommandBuffer commandBuffer = device.beginCommands();
    description.commandList = ffxDofGetCommandListVK(commandBuffer);
    const FfxDofErrorCode code = ffxDofContextDispatch(context, &description);
    device.endSubmitAndWait(commandBuffer);
    return code;
}

}  // namespace

// 60 cycles, or FFX_DOF_LIFETIME_CYCLES: the AddressSanitizer build runs 12 (tests/vk/CMakeLists.txt). Each cycle
// makes a backend and three contexts with it (two sizes, then ring merging off), so every cycle compiles the
// pipelines of two permutations again (the backend keeps them for its contexts) and a leak shows in the first
// cycle that makes it.
static int lifetimeCycles() {
    const char* text = std::getenv("FFX_DOF_LIFETIME_CYCLES");
    if (text == nullptr) return 60;
    char* end = nullptr;
    const long cycles = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || cycles < 4 || cycles > 100000)
        FAIL("FFX_DOF_LIFETIME_CYCLES must be a whole number from 4 to 100000, not '" << text << "'");
    return int(cycles);
}

TEST_CASE("create/dispatch/destroy cycles leak nothing", "[vulkan]") {
    const int cycles = lifetimeCycles();
    vkrun::Device& device = validatedDevice();
    const Scene scene = makeScene(24, 16, 3.0f);
    const Scene smaller = makeScene(13, 7, 3.0f);
    EngineImages images(device, scene), smallerImages(device, smaller);
    CountingAllocator counter;
    const VkAllocationCallbacks callbacks = counter.callbacks();

    for (int cycle = 0; cycle < cycles; ++cycle) {
        FfxDofBackendDescriptionVK description = device.backendDescription();
        description.allocationCallbacks = &callbacks;
        description.maxFramesInFlight = 2;
        FfxDofBackend backend = nullptr;
        REQUIRE(ffxDofBackendCreateVK(&description, &backend) == FFX_DOF_OK);
        for (int made = 0; made < 3; ++made) {
            const bool small = made == 1;
            FfxDofContextDescription contextInfo = contextDescription(backend, small ? 13 : 24, small ? 7 : 16);
            if (made == 2) contextInfo.flags |= FFX_DOF_DISABLE_RING_MERGE;
            FfxDofContext context = nullptr;
            REQUIRE(ffxDofContextCreate(&context, &contextInfo) == FFX_DOF_OK);
            // Three dispatches wrap the two-slot descriptor ring (views are destroyed and remade).
            for (int frame = 0; frame < (cycle % 4 == 0 ? 3 : 1); ++frame) {
                const FfxDofDispatchDescription dispatch =
                    small ? smallerImages.dispatch(smaller) : images.dispatch(scene);
                REQUIRE(dispatchOnce(device, &context, dispatch) == FFX_DOF_OK);
            }
            REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_ERROR_BACKEND_IN_USE);
            REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
            REQUIRE(context == nullptr);
        }
        REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
        REQUIRE(counter.liveCount() == 0);
    }
    CHECK(counter.total > 0);  // the callbacks were used at all
#if defined(__SANITIZE_ADDRESS__)
    // Host memory the cycles leaked, checked now, while the driver is still loaded: its own
    // process-lifetime allocations are then attributable and suppressed by module name
    // (tests/vk/lsan_driver.supp); at exit they would come from unloaded, unnamed modules.
    CHECK(__lsan_do_recoverable_leak_check() == 0);
#endif
    requireNoValidationMessages(device);
}

namespace {
// The backend's vkCreateComputePipelines and vkDestroyPipeline, counted (pipelineCountingGetDeviceProcAddr).
std::atomic<int> pipelinesCreated{0}, pipelinesDestroyed{0};
PFN_vkCreateComputePipelines realCreateComputePipelines = nullptr;
PFN_vkDestroyPipeline realDestroyPipeline = nullptr;

VKAPI_ATTR VkResult VKAPI_CALL countingCreateComputePipelines(VkDevice device, VkPipelineCache cache, uint32_t count,
                                                              const VkComputePipelineCreateInfo* infos,
                                                              const VkAllocationCallbacks* allocator,
                                                              VkPipeline* pipelines) {
    pipelinesCreated += int(count);
    return realCreateComputePipelines(device, cache, count, infos, allocator, pipelines);
}

VKAPI_ATTR void VKAPI_CALL countingDestroyPipeline(VkDevice device, VkPipeline pipeline,
                                                   const VkAllocationCallbacks* allocator) {
    if (pipeline != VK_NULL_HANDLE) ++pipelinesDestroyed;
    realDestroyPipeline(device, pipeline, allocator);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL pipelineCountingGetDeviceProcAddr(VkDevice device, const char* name) {
    if (std::strcmp(name, "vkCreateComputePipelines") == 0) {
        realCreateComputePipelines = reinterpret_cast<PFN_vkCreateComputePipelines>(vkGetDeviceProcAddr(device, name));
        return reinterpret_cast<PFN_vkVoidFunction>(&countingCreateComputePipelines);
    }
    if (std::strcmp(name, "vkDestroyPipeline") == 0) {
        realDestroyPipeline = reinterpret_cast<PFN_vkDestroyPipeline>(vkGetDeviceProcAddr(device, name));
        return reinterpret_cast<PFN_vkVoidFunction>(&countingDestroyPipeline);
    }
    return vkGetDeviceProcAddr(device, name);
}
}  // namespace

TEST_CASE("a backend compiles each pipeline once for all its contexts and frees them with itself", "[vulkan]") {
    vkrun::Device& device = validatedDevice();
    const Scene scene = makeScene(24, 16, 3.0f);
    EngineImages images(device, scene);
    pipelinesCreated = 0;
    pipelinesDestroyed = 0;
    FfxDofBackendDescriptionVK description = device.backendDescription();
    description.vkGetDeviceProcAddr = &pipelineCountingGetDeviceProcAddr;
    FfxDofBackend backend = nullptr;
    REQUIRE(ffxDofBackendCreateVK(&description, &backend) == FFX_DOF_OK);
    // Makes a context, dispatches it once, destroys it; returns the pipelines its creation compiled.
    const auto contextCompiles = [&](uint32_t width, uint32_t height, uint32_t flags) {
        const int before = pipelinesCreated;
        FfxDofContextDescription contextInfo = contextDescription(backend, width, height);
        contextInfo.flags = flags;
        FfxDofContext context = nullptr;
        REQUIRE(ffxDofContextCreate(&context, &contextInfo) == FFX_DOF_OK);
        const int compiled = pipelinesCreated - before;
        if (width == 24 && height == 16) CHECK(dispatchOnce(device, &context, images.dispatch(scene)) == FFX_DOF_OK);
        REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
        return compiled;
    };
    const int first = contextCompiles(24, 16, 0);
    CHECK(first >= int(vkrun::kPassCount));  // a pipeline per pass at least (the blur and composite one per tile list)
    CHECK(pipelinesDestroyed == 0);          // the context's destruction kept them for the backend
    // Another resolution (a resized window), then the first again: nothing compiled.
    CHECK(contextCompiles(1920, 1080, 0) == 0);
    CHECK(contextCompiles(24, 16, 0) == 0);
    // Ring merging off changes the blur's permutations only: those, and only once.
    const int ringMergeOff = contextCompiles(24, 16, FFX_DOF_DISABLE_RING_MERGE);
    CHECK(ringMergeOff > 0);
    CHECK(ringMergeOff < first);
    CHECK(contextCompiles(40, 30, FFX_DOF_DISABLE_RING_MERGE) == 0);
    CHECK(pipelinesDestroyed == 0);

    // Contexts made on several threads at once with one backend: each pipeline is still compiled once.
    const int beforeThreads = pipelinesCreated;
    std::array<FfxDofContext, 4> contexts{};
    std::array<FfxDofErrorCode, 4> made{};
    {
        std::vector<std::thread> threads;
        for (size_t i = 0; i < contexts.size(); ++i) {
            threads.emplace_back([&, i] {
                FfxDofContextDescription contextInfo = contextDescription(backend, 24 + uint32_t(i), 16);
                contextInfo.flags = FFX_DOF_REVERSE_DEPTH;  // permutations no context of this backend has made
                made[i] = ffxDofContextCreate(&contexts[i], &contextInfo);
            });
        }
        for (std::thread& thread : threads) thread.join();
    }
    for (size_t i = 0; i < contexts.size(); ++i) {
        CHECK(made[i] == FFX_DOF_OK);
        CHECK(ffxDofContextDestroy(&contexts[i]) == FFX_DOF_OK);
    }
    const int reversedDepth = pipelinesCreated - beforeThreads;
    CHECK(reversedDepth > 0);
    CHECK(reversedDepth < first);  // reversed depth changes the depth downsample's permutation only

    REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    CHECK(pipelinesDestroyed == pipelinesCreated);
    requireNoValidationMessages(device);
}

TEST_CASE("a dispatch recorded right after another in one command buffer depends on it by frame index only",
          "[vulkan]") {
    // Dilate lists the composite's tiles per class in every dispatch (TILE_LIST_ARGS, TILE_LISTS), pass 1
    // empties the lists first, and GLOBALS is reset within the dispatch. Two contexts record two
    // dispatches each in one command buffer: their second dispatches (frame index 1, the same blurred
    // scene) must give the same bits whether the first had every tile a copy (radius 0 everywhere) or
    // the same blurred scene. A list left over from the first dispatch would compose tiles of the wrong
    // class or twice; a missing barrier is a synchronization validation message.
    vkrun::Device& device = validatedDevice();
    const Scene blurred = makeScene(96, 64, 6.0f);
    Scene sharp = blurred;
    sharp.cocScale = 0.0f;
    sharp.cocBias = 0.0f;
    FfxDofBackendDescriptionVK backendDescription = device.backendDescription();
    FfxDofBackend backend = nullptr;
    REQUIRE(ffxDofBackendCreateVK(&backendDescription, &backend) == FFX_DOF_OK);
    const auto secondOutput = [&](const Scene& first) {
        EngineImages images(device, blurred);
        FfxDofContextDescription contextInfo = contextDescription(backend, 96, 64);
        FfxDofContext context = nullptr;
        REQUIRE(ffxDofContextCreate(&context, &contextInfo) == FFX_DOF_OK);
        VkCommandBuffer commandBuffer = device.beginCommands();
        for (const Scene* scene : {&first, &blurred}) {
            FfxDofDispatchDescription dispatch = images.dispatch(*scene);
            dispatch.commandList = ffxDofGetCommandListVK(commandBuffer);
            CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);
        }
        device.endSubmitAndWait(commandBuffer);
        vkrun::HostImage output = images.output.download(VK_IMAGE_LAYOUT_GENERAL);
        REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
        return output;
    };
    const vkrun::HostImage afterSharp = secondOutput(sharp);
    const vkrun::HostImage afterBlurred = secondOutput(blurred);
    CHECK(difference(afterSharp, afterBlurred).maxAbs == 0.0);
    // The scene is blurred at all (so the lists of the two first dispatches differed).
    CHECK(difference(afterBlurred, blurred.color).maxAbs > 0.1);
    REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    requireNoValidationMessages(device);
}

TEST_CASE("invalid engine resources give specific errors", "[vulkan]") {
    vkrun::Device& device = validatedDevice();
    const Scene scene = makeScene(32, 16, 3.0f);
    EngineImages images(device, scene);
    FfxDofBackendDescriptionVK backendInfo = device.backendDescription();
    FfxDofBackend backend = nullptr;
    REQUIRE(ffxDofBackendCreateVK(&backendInfo, &backend) == FFX_DOF_OK);
    FfxDofContextDescription contextInfo = contextDescription(backend, 32, 16);
    FfxDofContext context = nullptr;
    REQUIRE(ffxDofContextCreate(&context, &contextInfo) == FFX_DOF_OK);

    const auto expectError = [&](FfxDofDispatchDescription description, FfxDofErrorCode expected,
                                 const char* messagePart) {
        const FfxDofErrorCode code = dispatchOnce(device, &context, description);
        CAPTURE(ffxDofGetLastErrorMessage());
        CHECK(code == expected);
        CHECK(std::string(ffxDofGetLastErrorMessage()).find(messagePart) != std::string::npos);
    };
    const FfxDofDispatchDescription valid = images.dispatch(scene);

    SECTION("null image") {
        FfxDofDispatchDescription d = valid;
        d.depth.handle = 0;
        expectError(d, FFX_DOF_ERROR_INVALID_RESOURCE, "depth");
    }
    SECTION("wrong size") {
        FfxDofDispatchDescription d = valid;
        d.output.width = 31;
        expectError(d, FFX_DOF_ERROR_INVALID_RESOURCE, "output");
    }
    SECTION("unsupported color format") {
        FfxDofDispatchDescription d = valid;
        d.color.format = VK_FORMAT_R8_UNORM;
        expectError(d, FFX_DOF_ERROR_INVALID_RESOURCE, "VK_FORMAT_R8_UNORM");
    }
    SECTION("unsupported depth format") {
        FfxDofDispatchDescription d = valid;
        d.depth.format = VK_FORMAT_D32_SFLOAT_S8_UINT;
        expectError(d, FFX_DOF_ERROR_INVALID_RESOURCE, "depth format");
    }
    SECTION("sRGB output without a mutable image") {
        FfxDofDispatchDescription d = valid;
        d.output.format = VK_FORMAT_R8G8B8A8_SRGB;
        expectError(d, FFX_DOF_ERROR_INVALID_RESOURCE, "MUTABLE_FORMAT");
    }
    SECTION("undefined layout") {
        FfxDofDispatchDescription d = valid;
        d.color.state = VK_IMAGE_LAYOUT_UNDEFINED;
        expectError(d, FFX_DOF_ERROR_INVALID_RESOURCE, "VK_IMAGE_LAYOUT_UNDEFINED");
    }
    SECTION("a value that is no layout, or one of the wrong aspect, for each image") {
        // These once passed and recorded barriers the validation layer rejects.
        for (const uint32_t badLayout : {0x7fffffffu, 12345u, uint32_t(VK_IMAGE_LAYOUT_PREINITIALIZED)}) {
            for (FfxDofResource FfxDofDispatchDescription::*role :
                 {&FfxDofDispatchDescription::color, &FfxDofDispatchDescription::depth,
                  &FfxDofDispatchDescription::output}) {
                FfxDofDispatchDescription d = valid;
                const FfxDofResource& resource = d.*role;
                d.*role = ffxDofGetResourceVK(reinterpret_cast<VkImage>(uintptr_t(resource.handle)),
                                              VkFormat(resource.format), resource.width, resource.height,
                                              VkImageLayout(badLayout), 0);
                CAPTURE(badLayout);
                expectError(d, FFX_DOF_ERROR_INVALID_RESOURCE, "is declared in");
            }
        }
        FfxDofDispatchDescription depthAsColorAttachment = valid;
        depthAsColorAttachment.depth.state = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        expectError(depthAsColorAttachment, FFX_DOF_ERROR_INVALID_RESOURCE, "depth is declared in");
        FfxDofDispatchDescription colorAsDepthAttachment = valid;
        colorAsDepthAttachment.color.state = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        expectError(colorAsDepthAttachment, FFX_DOF_ERROR_INVALID_RESOURCE, "color is declared in");
    }
    SECTION("unknown resource flags") {
        FfxDofDispatchDescription d = valid;
        d.output.flags = 0x80;
        expectError(d, FFX_DOF_ERROR_INVALID_RESOURCE, "flags");
    }
    SECTION("output is color without PRE_INIT") {
        FfxDofDispatchDescription d = valid;
        d.output = d.color;
        const FfxDofErrorCode code = dispatchOnce(device, &context, d);
        CHECK(code == FFX_DOF_ERROR_OUTPUT_ALIASES_INPUT);
    }
    SECTION("the valid description still works after errors") {
        CHECK(dispatchOnce(device, &context, valid) == FFX_DOF_OK);
    }

    REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
    REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    requireNoValidationMessages(device);
}

TEST_CASE("backend creation checks its description", "[vulkan]") {
    vkrun::Device& device = validatedDevice();
    FfxDofBackend backend = reinterpret_cast<FfxDofBackend>(uintptr_t(1));
    CHECK(ffxDofBackendCreateVK(nullptr, &backend) == FFX_DOF_ERROR_INVALID_POINTER);
    CHECK(backend == nullptr);
    FfxDofBackendDescriptionVK description = device.backendDescription();
    CHECK(ffxDofBackendCreateVK(&description, nullptr) == FFX_DOF_ERROR_INVALID_POINTER);

    FfxDofBackendDescriptionVK noDevice = description;
    noDevice.device = VK_NULL_HANDLE;
    CHECK(ffxDofBackendCreateVK(&noDevice, &backend) == FFX_DOF_ERROR_INVALID_POINTER);
    FfxDofBackendDescriptionVK noLoader = description;
    noLoader.vkGetDeviceProcAddr = nullptr;
    CHECK(ffxDofBackendCreateVK(&noLoader, &backend) == FFX_DOF_ERROR_INVALID_POINTER);
    FfxDofBackendDescriptionVK badFlags = description;
    badFlags.flags = 0x100;
    CHECK(ffxDofBackendCreateVK(&badFlags, &backend) == FFX_DOF_ERROR_INVALID_FLAGS);
    FfxDofBackendDescriptionVK tooManyFrames = description;
    tooManyFrames.maxFramesInFlight = 1000;
    CHECK(ffxDofBackendCreateVK(&tooManyFrames, &backend) == FFX_DOF_ERROR_INVALID_ARGUMENT);
    CHECK(backend == nullptr);

    // A context on the engine's pipeline cache works too.
    VkPipelineCacheCreateInfo cacheInfo{};
    cacheInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO;
    VkPipelineCache cache = VK_NULL_HANDLE;
    REQUIRE(vkCreatePipelineCache(device.device(), &cacheInfo, nullptr, &cache) == VK_SUCCESS);
    description.pipelineCache = cache;
    REQUIRE(ffxDofBackendCreateVK(&description, &backend) == FFX_DOF_OK);
    FfxDofContextDescription contextInfo = contextDescription(backend, 16, 16);
    FfxDofContext context = nullptr;
    REQUIRE(ffxDofContextCreate(&context, &contextInfo) == FFX_DOF_OK);
    size_t cacheBytes = 0;
    REQUIRE(vkGetPipelineCacheData(device.device(), cache, &cacheBytes, nullptr) == VK_SUCCESS);
    CHECK(cacheBytes > 0);
    CHECK(ffxDofContextSetTimestampQueriesVK(nullptr, VK_NULL_HANDLE, 0) == FFX_DOF_ERROR_INVALID_POINTER);
    REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
    CHECK(ffxDofContextSetTimestampQueriesVK(&context, VK_NULL_HANDLE, 0) == FFX_DOF_ERROR_INVALID_CONTEXT);
    REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    vkDestroyPipelineCache(device.device(), cache, nullptr);
    requireNoValidationMessages(device);
}

namespace {

// Entry points that count the backend's view and descriptor work: the backend loads every device
// function through the vkGetDeviceProcAddr of its description, so handing it this one counts exactly
// what the effect does, without looking inside it.
struct DescriptorWorkCounter {
    static inline PFN_vkGetDeviceProcAddr real = nullptr;
    static inline PFN_vkCreateImageView realCreateView = nullptr;
    static inline PFN_vkDestroyImageView realDestroyView = nullptr;
    static inline PFN_vkUpdateDescriptorSets realUpdate = nullptr;
    static inline std::atomic<int> viewsCreated{0}, viewsDestroyed{0}, descriptorWrites{0};

    static VKAPI_ATTR VkResult VKAPI_CALL createView(VkDevice device, const VkImageViewCreateInfo* info,
                                                     const VkAllocationCallbacks* allocator, VkImageView* view) {
        ++viewsCreated;
        return realCreateView(device, info, allocator, view);
    }
    static VKAPI_ATTR void VKAPI_CALL destroyView(VkDevice device, VkImageView view,
                                                  const VkAllocationCallbacks* allocator) {
        if (view != VK_NULL_HANDLE) ++viewsDestroyed;
        realDestroyView(device, view, allocator);
    }
    static VKAPI_ATTR void VKAPI_CALL update(VkDevice device, uint32_t writeCount, const VkWriteDescriptorSet* writes,
                                             uint32_t copyCount, const VkCopyDescriptorSet* copies) {
        descriptorWrites += int(writeCount);
        realUpdate(device, writeCount, writes, copyCount, copies);
    }
    static VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getDeviceProcAddr(VkDevice device, const char* name) {
        const PFN_vkVoidFunction function = real(device, name);
        if (std::strcmp(name, "vkCreateImageView") == 0) {
            realCreateView = reinterpret_cast<PFN_vkCreateImageView>(function);
            return reinterpret_cast<PFN_vkVoidFunction>(&createView);
        }
        if (std::strcmp(name, "vkDestroyImageView") == 0) {
            realDestroyView = reinterpret_cast<PFN_vkDestroyImageView>(function);
            return reinterpret_cast<PFN_vkVoidFunction>(&destroyView);
        }
        if (std::strcmp(name, "vkUpdateDescriptorSets") == 0) {
            realUpdate = reinterpret_cast<PFN_vkUpdateDescriptorSets>(function);
            return reinterpret_cast<PFN_vkVoidFunction>(&update);
        }
        return function;
    }
    struct Counts {
        int created, destroyed, writes;
    };
    static Counts now() { return {viewsCreated.load(), viewsDestroyed.load(), descriptorWrites.load()}; }
};

}  // namespace

TEST_CASE("engine image views are made once and kept and descriptors rewritten only when images change", "[vulkan]") {
    vkrun::Device& device = validatedDevice();
    const Scene scene = makeScene(32, 24, 3.0f);
    EngineImages images(device, scene);
    vkrun::GpuImage otherOutput(
        device, 32, 24, VK_FORMAT_R16G16B16A16_SFLOAT,
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    otherOutput.upload(scene.color, VK_IMAGE_LAYOUT_GENERAL);

    FfxDofBackendDescriptionVK description = device.backendDescription();
    DescriptorWorkCounter::real = description.vkGetDeviceProcAddr;
    description.vkGetDeviceProcAddr = &DescriptorWorkCounter::getDeviceProcAddr;
    description.maxFramesInFlight = 2;
    FfxDofBackend backend = nullptr;
    REQUIRE(ffxDofBackendCreateVK(&description, &backend) == FFX_DOF_OK);
    FfxDofContextDescription contextInfo = contextDescription(backend, 32, 24);
    FfxDofContext context = nullptr;
    const DescriptorWorkCounter::Counts beforeContext = DescriptorWorkCounter::now();
    REQUIRE(ffxDofContextCreate(&context, &contextInfo) == FFX_DOF_OK);
    const DescriptorWorkCounter::Counts created = DescriptorWorkCounter::now();
    CHECK(created.writes > beforeContext.writes);  // the internal resources, once, at creation

    // The first dispatch makes the three views (color, depth, output); each of the two ring slots
    // gets the engine's descriptors once.
    const FfxDofDispatchDescription first = images.dispatch(scene);
    REQUIRE(dispatchOnce(device, &context, first) == FFX_DOF_OK);
    REQUIRE(dispatchOnce(device, &context, first) == FFX_DOF_OK);
    const DescriptorWorkCounter::Counts warm = DescriptorWorkCounter::now();
    CHECK(warm.created - created.created == 3);
    CHECK(warm.destroyed == created.destroyed);
    CHECK(warm.writes > created.writes);

    // The same images again: no view made or destroyed, no descriptor written.
    for (int frame = 0; frame < 6; ++frame) REQUIRE(dispatchOnce(device, &context, first) == FFX_DOF_OK);
    const DescriptorWorkCounter::Counts steady = DescriptorWorkCounter::now();
    CHECK(steady.created == warm.created);
    CHECK(steady.destroyed == warm.destroyed);
    CHECK(steady.writes == warm.writes);

    // Alternating two outputs: one more view, and the descriptors of a slot change with its output.
    FfxDofDispatchDescription second = first;
    second.output = ffxDofGetResourceVK(otherOutput.image(), otherOutput.format(), 32, 24, VK_IMAGE_LAYOUT_GENERAL, 0);
    for (int frame = 0; frame < 4; ++frame) {
        REQUIRE(dispatchOnce(device, &context, frame % 2 ? first : second) == FFX_DOF_OK);
    }
    const DescriptorWorkCounter::Counts alternating = DescriptorWorkCounter::now();
    CHECK(alternating.created == steady.created + 1);
    CHECK(alternating.destroyed == steady.destroyed);

    // Released before the engine destroys it: its one view goes, and it is made again if it returns.
    REQUIRE(ffxDofContextReleaseImageVK(&context, otherOutput.image()) == FFX_DOF_OK);
    const DescriptorWorkCounter::Counts released = DescriptorWorkCounter::now();
    CHECK(released.destroyed == alternating.destroyed + 1);
    REQUIRE(dispatchOnce(device, &context, second) == FFX_DOF_OK);
    CHECK(DescriptorWorkCounter::now().created == released.created + 1);
    CHECK(ffxDofContextReleaseImageVK(nullptr, otherOutput.image()) == FFX_DOF_ERROR_INVALID_POINTER);

    REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
    CHECK(ffxDofContextReleaseImageVK(&context, otherOutput.image()) == FFX_DOF_ERROR_INVALID_CONTEXT);
    const DescriptorWorkCounter::Counts end = DescriptorWorkCounter::now();
    CHECK(end.created - beforeContext.created == end.destroyed - beforeContext.destroyed);
    REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    requireNoValidationMessages(device);
}
