// ffx_dof_vkrun: the application side of ffx-dof on Vulkan, shared by the tests, the ffx-dof
// command line (apply, demo, bench) and the quality gates. It owns a Vulkan instance and device,
// uploads host float images into engine-like images of a chosen format, runs the effect through
// the public API (ffx_dof_vk.h), reads the output back, and times every pass with timestamps.
//
// Errors are reported as vkrun::Error exceptions whose what() is one specific line
// ("color format VK_FORMAT_R8_UNORM is not supported", "ffxDofContextCreate: quality is 0 ...").
#pragma once

#include "ffx_dof_vk.h"

#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ffxdof::vkrun {

// A failure with a one-line message. code is the ffx-dof error when the effect itself failed
// (FFX_DOF_OK when the failure is in the harness, e.g. no Vulkan device or a Vulkan error).
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message, FfxDofErrorCode code = FFX_DOF_OK)
        : std::runtime_error(message), code_(code) {}
    FfxDofErrorCode code() const { return code_; }

private:
    FfxDofErrorCode code_;
};

// Number of passes and their names, in pipeline order (the names of the per-pass timings).
constexpr uint32_t kPassCount = FFX_DOF_VK_TIMESTAMP_COUNT - 1;
const char* passName(uint32_t pass);

struct DeviceOptions {
    // Enables VK_LAYER_KHRONOS_validation with synchronization validation and records every
    // message it reports (see Device::validationMessages). Error if the layer is not installed.
    bool validation = false;
    // Which physical device (index in vkEnumeratePhysicalDevices order); -1 picks the first.
    int physicalDeviceIndex = -1;
    // Features to leave disabled although the device supports them (to test how ffx-dof copes):
    // any of "shaderStorageImageWriteWithoutFormat", "shaderStorageImageExtendedFormats",
    // "storageBuffer16BitAccess", "shaderFloat16", "subgroupSizeControl", "computeFullSubgroups".
    // Another name is an Error.
    std::vector<std::string> withoutFeatures;
};

// Features ffx-dof can use, as enabled on the created device (each only where supported).
struct DeviceFeatures {
    bool shaderFloat16 = false;
    bool storageBuffer16BitAccess = false;
    bool subgroupSizeControl = false;
    bool shaderStorageImageWriteWithoutFormat = false;
    bool shaderStorageImageExtendedFormats = false;
    uint32_t subgroupSize = 0;  // default subgroup size
    uint32_t minSubgroupSize = 0, maxSubgroupSize = 0;
};

// Names of the physical devices visible to a plain instance, in index order (for --device N).
std::vector<std::string> listPhysicalDevices();

// An instance, one device with a compute queue, and a command pool. Not copyable.
class Device {
public:
    explicit Device(const DeviceOptions& options = {});
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    const std::string& name() const;  // VkPhysicalDeviceProperties::deviceName
    const DeviceFeatures& features() const;

    VkInstance instance() const;
    VkPhysicalDevice physicalDevice() const;
    VkDevice device() const;
    VkQueue queue() const;
    uint32_t queueFamily() const;
    VkCommandPool commandPool() const;
    // Nanoseconds per timestamp tick.
    double timestampPeriod() const;

    // The backend description for this device; pEnabledFeatures is the very chain given to
    // vkCreateDevice (it lives as long as the Device).
    FfxDofBackendDescriptionVK backendDescription(uint32_t backendFlags = 0) const;
    // The backend of this device with backendFlags and maxFramesInFlight (0: the backend's default),
    // made on first use and kept until the Device is destroyed: runEffect and EffectSession make their
    // contexts with it, so they share its pipelines (a backend compiles each once, docs/api.md).
    FfxDofBackend sharedBackend(uint32_t backendFlags, uint32_t maxFramesInFlight = 0);
    const VkPhysicalDeviceFeatures2& enabledFeatures() const;

    // Messages of the validation layer (and any other debug-utils message of warning or error
    // severity) since creation or the last clear. Always empty without DeviceOptions::validation.
    size_t validationMessageCount() const;
    std::vector<std::string> validationMessages() const;
    void clearValidationMessages();

    // Records commands with record(), submits them and waits for the queue (for set-up and
    // read-back; the effect itself is recorded through runEffect).
    template <typename Recorder>
    void submitAndWait(Recorder&& record) {
        VkCommandBuffer commandBuffer = beginCommands();
        record(commandBuffer);
        endSubmitAndWait(commandBuffer);
    }
    VkCommandBuffer beginCommands();
    void endSubmitAndWait(VkCommandBuffer commandBuffer);

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

// A host image of 32-bit floats, row-major, top row first. channels is 4 (RGBA) for color and
// output, 1 for depth.
struct HostImage {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t channels = 4;
    std::vector<float> pixels;  // width * height * channels

    HostImage() = default;
    HostImage(uint32_t w, uint32_t h, uint32_t c) : width(w), height(h), channels(c), pixels(size_t(w) * h * c) {}
    float* at(uint32_t x, uint32_t y) { return &pixels[(size_t(y) * width + x) * channels]; }
    const float* at(uint32_t x, uint32_t y) const { return &pixels[(size_t(y) * width + x) * channels]; }
};

// Everything one run of the effect needs besides the images.
struct RunSettings {
    // Formats of the engine images the harness creates. Color: R16G16B16A16_SFLOAT,
    // R32G32B32A32_SFLOAT, B10G11R11_UFLOAT_PACK32, R8G8B8A8_UNORM, R8G8B8A8_SRGB. Depth:
    // D32_SFLOAT, D24_UNORM_S8_UINT, D16_UNORM, R32_SFLOAT. Output: a color format (an _SRGB
    // output is created mutable and written through a UNORM view). Host values are linear; the
    // harness converts them (sRGB encoding, UNORM clamping, packed floats) on upload and read-back.
    VkFormat colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    VkFormat depthFormat = VK_FORMAT_D32_SFLOAT;
    VkFormat outputFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

    // FfxDofContextDescription fields. FFX_DOF_OUTPUT_PRE_INIT is added when inPlace is set; when it
    // is set without inPlace, the output image is initialised with the color before the dispatch.
    uint32_t contextFlags = 0;
    uint32_t quality = 10;
    float cocLimitFactor = 0.05f;

    // FfxDofDispatchDescription fields: radius (half-res px) = depth * cocScale + cocBias.
    float cocScale = 0.0f;
    float cocBias = 0.0f;
    // Autofocus instead of cocScale / cocBias (FfxDofDispatchDescription::pAutofocus); the distance
    // it chose comes back in RunResult::autofocusDistance.
    bool useAutofocus = false;
    FfxDofAutofocus autofocus{};
    // FfxDofDispatchDescription::pAperture (the default is the round aperture, passed as NULL).
    FfxDofAperture aperture{0, 0.0f, 0.0f, 1.0f, 0.0f};

    // The output is the color image itself (needs FFX_DOF_OUTPUT_PRE_INIT, added automatically).
    bool inPlace = false;
    // Dispatches to record, each in its own submission; timings are the median over them. The
    // output read back is the last one's.
    uint32_t repeat = 1;
    // Backend flags: FFX_DOF_VK_DISABLE_FLOAT16, FFX_DOF_VK_USE_HLSL_SHADERS, FFX_DOF_VK_DISABLE_WAVE64.
    bool forceFloat32 = false;
    bool useHlsl = false;
    bool disableWave64 = false;
    // Also time a plain full-resolution copy pass (reads color and depth, writes output) in the
    // same run: the device's floor for the benchmark.
    bool measureCopyPass = false;
    // Frames in flight given to the backend (0 means its default of 3).
    uint32_t maxFramesInFlight = 0;
    // After the timed runs, the host CPU time of this many more ffxDofContextDispatch calls (0: none),
    // each recorded into its own command buffer that is never submitted and then freed, without
    // timestamps: the cost of recording the five passes (RunResult::hostRecordMicroseconds).
    uint32_t hostRecordCalls = 0;
};

struct RunResult {
    HostImage output;  // RGBA, linear, decoded from outputFormat (the color image when inPlace)
    std::array<double, kPassCount> passMilliseconds{};  // median over the repeats
    double totalMilliseconds = 0.0;                     // median of first to last timestamp
    double copyPassMilliseconds = -1.0;                 // median; -1 without measureCopyPass
    uint64_t internalMemoryBytes = 0;                   // ffxDofContextGetGpuMemoryUsage total
    uint64_t aliasableMemoryBytes = 0;
    double hostRecordMicroseconds = -1.0;  // median over hostRecordCalls; -1 without them
    float autofocusDistance = 0.0f;        // the last dispatch's, with useAutofocus; else 0
    // Host time of ffxDofContextCreate: with the pipeline compiles when the device's shared backend had not
    // made a context of these settings' permutations before (Device::sharedBackend), else without.
    double contextCreateMilliseconds = 0.0;
};

// Runs the effect once per repeat on color (RGBA) and depth (1 channel) of the same size and
// returns the output. Throws Error on any failure (invalid settings, an ffx-dof error with its
// code and ffxDofGetLastErrorMessage, a Vulkan error).
RunResult runEffect(Device& device, const HostImage& color, const HostImage& depth, const RunSettings& settings);

// Host milliseconds of one ffxDofContextCreate at width x height with the settings' flags, quality, cocLimitFactor
// and backend switches, on the device's shared backend (the context is destroyed again): a context made again, at a
// new resolution, once runEffect made one of the same permutations.
double timeContextCreate(Device& device, const RunSettings& settings, uint32_t width, uint32_t height);

// Runs the effect on frame after frame (ffx-dof apply over a sequence): the backend (its pipelines) is
// the device's shared one, the engine images made once per resolution and format, and the context for every frame,
// so each frame is dispatched as the first of its context (frame index 0, which seeds the kernel
// jitter): a frame's output never depends on which frames ran before it. Only the settings' formats,
// flags, quality, cocLimitFactor, cocScale/cocBias, aperture, autofocus and backend switches are used (no
// repeats, timings, in-place or copy pass). Not thread-safe: one thread submits.
class EffectSession {
public:
    explicit EffectSession(Device& device);
    ~EffectSession();
    EffectSession(const EffectSession&) = delete;
    EffectSession& operator=(const EffectSession&) = delete;

    // Throws Error as runEffect does. With settings.useAutofocus, *autofocusDistance (when not null)
    // receives the distance autofocus chose.
    HostImage run(const HostImage& color, const HostImage& depth, const RunSettings& settings,
                  float* autofocusDistance = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Which formats runEffect accepts (see RunSettings), and a format's name for messages.
bool isSupportedColorFormat(VkFormat format);
bool isSupportedDepthFormat(VkFormat format);
std::string formatName(VkFormat format);

}  // namespace ffxdof::vkrun
