// The harness's Vulkan instance and device, and images with host upload/read-back.
// It links the Vulkan loader directly: it is an application, not a library inside an engine.
#include "ffx_dof_pass_list.h"
#include "vkrun_internal.h"

#include <cstdio>
#include <cstring>
#include <mutex>
#include <utility>

namespace ffxdof::vkrun {

void check(VkResult result, const char* what) {
    if (result != VK_SUCCESS) throw Error(std::string(what) + " failed: VkResult " + std::to_string(int(result)));
}

void checkDof(FfxDofErrorCode code, const char* call) {
    if (code != FFX_DOF_OK) {
        throw Error(std::string(call) + ": " + ffxDofGetErrorString(code) + " (" + ffxDofGetLastErrorMessage() + ")",
                    code);
    }
}

const char* passName(uint32_t pass) { return pass < kPassCount ? ffxdof::kPassNames[pass] : "unknown pass"; }

struct Device::Impl {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    std::string name;
    DeviceFeatures features;
    // The chain given to vkCreateDevice (enabled -> enabled11 -> enabled12 -> enabled13); the
    // backend description points at it.
    VkPhysicalDeviceFeatures2 enabled{};
    VkPhysicalDeviceVulkan11Features enabled11{};
    VkPhysicalDeviceVulkan12Features enabled12{};
    VkPhysicalDeviceVulkan13Features enabled13{};
    double timestampPeriod = 1.0;

    mutable std::mutex messagesMutex;  // the layer may call back from driver threads
    std::vector<std::string> messages;

    struct SharedBackend {
        uint32_t flags, maxFramesInFlight;
        FfxDofBackend backend;
    };
    std::vector<SharedBackend> backends;

    ~Impl() {
        for (const SharedBackend& shared : backends) ffxDofBackendDestroy(shared.backend);
        if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);
        if (device) vkDestroyDevice(device, nullptr);
        if (messenger) {
            auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
            if (destroy) destroy(instance, messenger, nullptr);
        }
        if (instance) vkDestroyInstance(instance, nullptr);
    }

    static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                    VkDebugUtilsMessageTypeFlagsEXT,
                                                    const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData) {
        auto* impl = static_cast<Impl*>(userData);
        std::lock_guard<std::mutex> lock(impl->messagesMutex);
        impl->messages.emplace_back(data && data->pMessage ? data->pMessage : "(empty validation message)");
        return VK_FALSE;
    }
};

namespace {

bool hasLayer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const VkLayerProperties& layer : layers) {
        if (std::strcmp(layer.layerName, name) == 0) return true;
    }
    return false;
}

VkInstance createInstance(bool validation, Device::Impl* impl, VkDebugUtilsMessengerEXT* messenger) {
    auto app = makeInfo<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "ffx-dof";
    app.apiVersion = VK_API_VERSION_1_3;
    auto info = makeInfo<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.pApplicationInfo = &app;

    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    auto validationFeatures = makeInfo<VkValidationFeaturesEXT>(VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT);
    auto messengerInfo =
        makeInfo<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    if (validation) {
        if (!hasLayer(layer)) {
            throw Error(
                "validation was asked for but VK_LAYER_KHRONOS_validation is not installed "
                "(Debian: vulkan-validationlayers)");
        }
        validationFeatures.enabledValidationFeatureCount = 1;
        validationFeatures.pEnabledValidationFeatures = enables;
        messengerInfo.messageSeverity =
            VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
        messengerInfo.pfnUserCallback = &Device::Impl::onMessage;
        messengerInfo.pUserData = impl;
        // Chained into the instance info too, so instance creation and destruction are covered.
        validationFeatures.pNext = &messengerInfo;
        info.pNext = &validationFeatures;
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = &layer;
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = &extension;
    }
    VkInstance instance = VK_NULL_HANDLE;
    check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance (is a Vulkan driver installed?)");
    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) {
            vkDestroyInstance(instance, nullptr);
            throw Error("vkCreateDebugUtilsMessengerEXT is missing");
        }
        messengerInfo.pNext = nullptr;
        check(create(instance, &messengerInfo, nullptr, messenger), "vkCreateDebugUtilsMessengerEXT");
    }
    return instance;
}

std::vector<VkPhysicalDevice> physicalDevicesOf(VkInstance instance) {
    uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
    devices.resize(count);
    return devices;
}

}  // namespace

std::vector<std::string> listPhysicalDevices() {
    Device::Impl impl;
    impl.instance = createInstance(false, &impl, nullptr);
    std::vector<std::string> names;
    for (VkPhysicalDevice physicalDevice : physicalDevicesOf(impl.instance)) {
        VkPhysicalDeviceProperties properties{};
        vkGetPhysicalDeviceProperties(physicalDevice, &properties);
        names.emplace_back(properties.deviceName);
    }
    return names;
}

Device::Device(const DeviceOptions& options) : impl_(std::make_unique<Impl>()) {
    Impl& d = *impl_;
    d.instance = createInstance(options.validation, &d, &d.messenger);
    const std::vector<VkPhysicalDevice> devices = physicalDevicesOf(d.instance);
    if (devices.empty())
        throw Error("no Vulkan physical device found (on CPU-only machines install mesa-vulkan-drivers)");
    const int index = options.physicalDeviceIndex < 0 ? 0 : options.physicalDeviceIndex;
    if (size_t(index) >= devices.size()) {
        throw Error("device " + std::to_string(index) + " does not exist; there are " + std::to_string(devices.size()) +
                    " Vulkan devices (0.." + std::to_string(devices.size() - 1) + ")");
    }
    d.physicalDevice = devices[size_t(index)];

    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(d.physicalDevice, &properties);
    d.name = properties.deviceName;
    d.timestampPeriod = properties.limits.timestampPeriod;
    if (properties.apiVersion < VK_API_VERSION_1_3) {
        throw Error("device " + d.name + " supports Vulkan " +
                    std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
                    std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)) + "; the harness needs 1.3");
    }

    // What ffx-dof can use, where the device has it.
    auto supported13 =
        makeInfo<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    auto supported12 =
        makeInfo<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
    auto supported11 =
        makeInfo<VkPhysicalDeviceVulkan11Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
    auto supported = makeInfo<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
    supported.pNext = &supported11;
    supported11.pNext = &supported12;
    supported12.pNext = &supported13;
    vkGetPhysicalDeviceFeatures2(d.physicalDevice, &supported);

    VkPhysicalDeviceFeatures2& enable = d.enabled;
    VkPhysicalDeviceVulkan11Features& enable11 = d.enabled11;
    VkPhysicalDeviceVulkan12Features& enable12 = d.enabled12;
    VkPhysicalDeviceVulkan13Features& enable13 = d.enabled13;
    enable = makeInfo<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
    enable11 = makeInfo<VkPhysicalDeviceVulkan11Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
    enable12 = makeInfo<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
    enable13 = makeInfo<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    enable.pNext = &enable11;
    enable11.pNext = &enable12;
    enable12.pNext = &enable13;
    const std::pair<const char*, std::pair<VkBool32*, VkBool32>> wanted[] = {
        {"shaderStorageImageWriteWithoutFormat",
         {&enable.features.shaderStorageImageWriteWithoutFormat,
          supported.features.shaderStorageImageWriteWithoutFormat}},
        {"shaderStorageImageExtendedFormats",
         {&enable.features.shaderStorageImageExtendedFormats, supported.features.shaderStorageImageExtendedFormats}},
        {"storageBuffer16BitAccess", {&enable11.storageBuffer16BitAccess, supported11.storageBuffer16BitAccess}},
        {"shaderFloat16", {&enable12.shaderFloat16, supported12.shaderFloat16}},
        {"subgroupSizeControl", {&enable13.subgroupSizeControl, supported13.subgroupSizeControl}},
        {"computeFullSubgroups", {&enable13.computeFullSubgroups, supported13.computeFullSubgroups}},
    };
    for (const auto& [name, feature] : wanted) *feature.first = feature.second;
    for (const std::string& without : options.withoutFeatures) {
        bool known = false;
        for (const auto& [name, feature] : wanted) {
            if (without == name) {
                *feature.first = VK_FALSE;
                known = true;
            }
        }
        if (!known)
            throw Error("DeviceOptions::withoutFeatures: '" + without + "' is not a feature the harness enables");
    }
    d.features.shaderStorageImageWriteWithoutFormat = enable.features.shaderStorageImageWriteWithoutFormat;
    d.features.shaderStorageImageExtendedFormats = enable.features.shaderStorageImageExtendedFormats;
    d.features.storageBuffer16BitAccess = enable11.storageBuffer16BitAccess;
    d.features.shaderFloat16 = enable12.shaderFloat16;
    // wave64 needs full subgroups as well (VK_PIPELINE_SHADER_STAGE_CREATE_REQUIRE_FULL_SUBGROUPS_BIT).
    d.features.subgroupSizeControl = enable13.subgroupSizeControl && enable13.computeFullSubgroups;

    auto sizeControl = makeInfo<VkPhysicalDeviceSubgroupSizeControlProperties>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_SIZE_CONTROL_PROPERTIES);
    auto subgroup = makeInfo<VkPhysicalDeviceSubgroupProperties>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES);
    subgroup.pNext = &sizeControl;
    auto properties2 = makeInfo<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
    properties2.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(d.physicalDevice, &properties2);
    d.features.subgroupSize = subgroup.subgroupSize;
    d.features.minSubgroupSize = sizeControl.minSubgroupSize;
    d.features.maxSubgroupSize = sizeControl.maxSubgroupSize;

    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d.physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(d.physicalDevice, &familyCount, families.data());
    bool found = false;
    for (uint32_t i = 0; i < familyCount && !found; ++i) {
        if ((families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) && families[i].timestampValidBits > 0) {
            d.queueFamily = i;
            found = true;
        }
    }
    if (!found) throw Error("device " + d.name + " has no compute queue with timestamps");

    const float priority = 1.0f;
    auto queueInfo = makeInfo<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queueInfo.queueFamilyIndex = d.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    auto deviceInfo = makeInfo<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    deviceInfo.pNext = &enable;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    check(vkCreateDevice(d.physicalDevice, &deviceInfo, nullptr, &d.device), "vkCreateDevice");
    vkGetDeviceQueue(d.device, d.queueFamily, 0, &d.queue);

    auto poolInfo = makeInfo<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = d.queueFamily;
    check(vkCreateCommandPool(d.device, &poolInfo, nullptr, &d.commandPool), "vkCreateCommandPool");
}

Device::~Device() = default;

const std::string& Device::name() const { return impl_->name; }
const DeviceFeatures& Device::features() const { return impl_->features; }
VkInstance Device::instance() const { return impl_->instance; }
VkPhysicalDevice Device::physicalDevice() const { return impl_->physicalDevice; }
VkDevice Device::device() const { return impl_->device; }
VkQueue Device::queue() const { return impl_->queue; }
uint32_t Device::queueFamily() const { return impl_->queueFamily; }
VkCommandPool Device::commandPool() const { return impl_->commandPool; }
double Device::timestampPeriod() const { return impl_->timestampPeriod; }

FfxDofBackendDescriptionVK Device::backendDescription(uint32_t backendFlags) const {
    FfxDofBackendDescriptionVK description{};
    description.instance = impl_->instance;
    description.physicalDevice = impl_->physicalDevice;
    description.device = impl_->device;
    description.vkGetInstanceProcAddr = vkGetInstanceProcAddr;
    description.vkGetDeviceProcAddr = vkGetDeviceProcAddr;
    description.pEnabledFeatures = &impl_->enabled;
    description.flags = backendFlags;
    return description;
}

FfxDofBackend Device::sharedBackend(uint32_t backendFlags, uint32_t maxFramesInFlight) {
    for (const Impl::SharedBackend& shared : impl_->backends) {
        if (shared.flags == backendFlags && shared.maxFramesInFlight == maxFramesInFlight) return shared.backend;
    }
    FfxDofBackendDescriptionVK description = backendDescription(backendFlags);
    description.maxFramesInFlight = maxFramesInFlight;
    FfxDofBackend backend = nullptr;
    impl_->backends.reserve(impl_->backends.size() + 1);
    checkDof(ffxDofBackendCreateVK(&description, &backend), "ffxDofBackendCreateVK");
    impl_->backends.push_back({backendFlags, maxFramesInFlight, backend});
    return backend;
}

const VkPhysicalDeviceFeatures2& Device::enabledFeatures() const { return impl_->enabled; }

size_t Device::validationMessageCount() const {
    std::lock_guard<std::mutex> lock(impl_->messagesMutex);
    return impl_->messages.size();
}

std::vector<std::string> Device::validationMessages() const {
    std::lock_guard<std::mutex> lock(impl_->messagesMutex);
    return impl_->messages;
}

void Device::clearValidationMessages() {
    std::lock_guard<std::mutex> lock(impl_->messagesMutex);
    impl_->messages.clear();
}

VkCommandBuffer Device::beginCommands() {
    auto info = makeInfo<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    info.commandPool = impl_->commandPool;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(impl_->device, &info, &commandBuffer), "vkAllocateCommandBuffers");
    auto begin = makeInfo<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(commandBuffer, &begin), "vkBeginCommandBuffer");
    return commandBuffer;
}

void Device::endSubmitAndWait(VkCommandBuffer commandBuffer) {
    struct Free {
        Impl& d;
        VkCommandBuffer commandBuffer;
        ~Free() { vkFreeCommandBuffers(d.device, d.commandPool, 1, &commandBuffer); }
    } freeOnExit{*impl_, commandBuffer};
    check(vkEndCommandBuffer(commandBuffer), "vkEndCommandBuffer");
    auto submit = makeInfo<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commandBuffer;
    check(vkQueueSubmit(impl_->queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
    check(vkQueueWaitIdle(impl_->queue), "vkQueueWaitIdle");
}

// ---------------------------------------------------------------------------------------------
namespace {

uint32_t memoryTypeFor(VkPhysicalDevice physicalDevice, uint32_t typeBits, VkMemoryPropertyFlags wanted) {
    VkPhysicalDeviceMemoryProperties properties{};
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &properties);
    for (uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
        if ((typeBits & (1u << i)) && (properties.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    }
    throw Error("no Vulkan memory type with the needed properties");
}

// A host-visible, coherent buffer for one transfer.
struct StagingBuffer {
    Device& device;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;

    StagingBuffer(Device& d, VkDeviceSize size, VkBufferUsageFlags usage) : device(d) {
        auto info = makeInfo<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
        info.size = size;
        info.usage = usage;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        check(vkCreateBuffer(d.device(), &info, nullptr, &buffer), "vkCreateBuffer (staging)");
        VkMemoryRequirements requirements{};
        vkGetBufferMemoryRequirements(d.device(), buffer, &requirements);
        auto allocation = makeInfo<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        allocation.allocationSize = requirements.size;
        allocation.memoryTypeIndex =
            memoryTypeFor(d.physicalDevice(), requirements.memoryTypeBits,
                          VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        check(vkAllocateMemory(d.device(), &allocation, nullptr, &memory), "vkAllocateMemory (staging)");
        check(vkBindBufferMemory(d.device(), buffer, memory, 0), "vkBindBufferMemory (staging)");
        check(vkMapMemory(d.device(), memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    }
    ~StagingBuffer() {
        vkDestroyBuffer(device.device(), buffer, nullptr);
        vkFreeMemory(device.device(), memory, nullptr);  // unmaps
    }
};

void transition(VkCommandBuffer commandBuffer, VkImage image, VkImageAspectFlags aspects, VkImageLayout from,
                VkImageLayout to) {
    auto barrier = makeInfo<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspects, 0, 1, 0, 1};
    vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &barrier);
}

}  // namespace

GpuImage::GpuImage(Device& device, uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                   VkImageCreateFlags flags)
    : device_(device), format_(format), width_(width), height_(height) {
    auto info = makeInfo<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.flags = flags;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(device.device(), &info, nullptr, &image_),
          ("vkCreateImage (" + formatName(format) + ")").c_str());
    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(device.device(), image_, &requirements);
    auto allocation = makeInfo<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    allocation.allocationSize = requirements.size;
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    vkGetPhysicalDeviceMemoryProperties(device.physicalDevice(), &memoryProperties);
    allocation.memoryTypeIndex = vk::chooseMemoryType(memoryProperties, requirements.memoryTypeBits);
    if (allocation.memoryTypeIndex == UINT32_MAX) {
        vkDestroyImage(device.device(), image_, nullptr);
        throw Error("no Vulkan memory type can hold a " + formatName(format) + " image");
    }
    const VkResult allocated = vkAllocateMemory(device.device(), &allocation, nullptr, &memory_);
    if (allocated == VK_SUCCESS) {
        check(vkBindImageMemory(device.device(), image_, memory_, 0), "vkBindImageMemory");
    } else {
        vkDestroyImage(device.device(), image_, nullptr);
        check(allocated, "vkAllocateMemory (image)");
    }
}

GpuImage::~GpuImage() {
    vkDestroyImage(device_.device(), image_, nullptr);
    vkFreeMemory(device_.device(), memory_, nullptr);
}

VkImageAspectFlags GpuImage::aspects() const {
    if (format_ == VK_FORMAT_D24_UNORM_S8_UINT) return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    return isDepthAspectFormat(format_) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

void GpuImage::upload(const HostImage& pixels, VkImageLayout layout) {
    if (pixels.width != width_ || pixels.height != height_) throw Error("upload: the host image has another size");
    const std::vector<uint8_t> bytes = encodeTexels(pixels, format_);
    StagingBuffer staging(device_, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.mapped, bytes.data(), bytes.size());
    device_.submitAndWait([&](VkCommandBuffer commandBuffer) {
        transition(commandBuffer, image_, aspects(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkBufferImageCopy region{};
        // Only the depth aspect of a depth/stencil image carries data.
        region.imageSubresource = {isDepthAspectFormat(format_) ? VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT)
                                                                : VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT),
                                   0, 0, 1};
        region.imageExtent = {width_, height_, 1};
        vkCmdCopyBufferToImage(commandBuffer, staging.buffer, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        transition(commandBuffer, image_, aspects(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, layout);
    });
}

HostImage GpuImage::download(VkImageLayout layout) {
    const VkDeviceSize size = VkDeviceSize(width_) * height_ * bytesPerTexel(format_);
    StagingBuffer staging(device_, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    device_.submitAndWait([&](VkCommandBuffer commandBuffer) {
        transition(commandBuffer, image_, aspects(), layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width_, height_, 1};
        vkCmdCopyImageToBuffer(commandBuffer, image_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &region);
        transition(commandBuffer, image_, aspects(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
        auto toHost = makeInfo<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost,
                             0, nullptr, 0, nullptr);
    });
    return decodeColorTexels(static_cast<const uint8_t*>(staging.mapped), width_, height_, format_);
}

}  // namespace ffxdof::vkrun
