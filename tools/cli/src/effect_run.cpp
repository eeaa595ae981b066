#include "effect_run.h"

#include "cli_error.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace ffxdof::cli {

std::unique_ptr<vkrun::Device> openDevice(const EffectOptions& effect) {
    const int physicalDeviceIndex = effect.device;
    vkrun::DeviceOptions options;
    options.physicalDeviceIndex = physicalDeviceIndex;
    options.validation = effect.validate;
    try {
        return std::make_unique<vkrun::Device>(options);
    } catch (const vkrun::Error& error) {
        std::string message = std::string("cannot open the Vulkan device: ") + error.what();
        if (physicalDeviceIndex >= 0) {
            std::vector<std::string> names;
            try {
                names = vkrun::listPhysicalDevices();
            } catch (const vkrun::Error&) {
                // The first message already says why Vulkan is not usable.
            }
            message += "; devices:";
            for (size_t i = 0; i < names.size(); ++i) {
                message += " " + std::to_string(i) + "=" + names[i];
            }
            if (names.empty()) {
                message += " none";
            }
        }
        throw CliError(ExitCode::Device, message);
    }
}

vkrun::RunSettings makeRunSettings(const EffectOptions& effect, const CocParameters& coc, bool reversedDepth,
                                   const FfxDofAutofocus* autofocus) {
    vkrun::RunSettings settings;
    settings.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.outputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.depthFormat = VK_FORMAT_D32_SFLOAT;
    settings.quality = effect.quality;
    settings.cocLimitFactor = float(effect.cocLimit);
    settings.contextFlags = (reversedDepth ? uint32_t(FFX_DOF_REVERSE_DEPTH) : 0u) |
                            (effect.noRingMerge ? uint32_t(FFX_DOF_DISABLE_RING_MERGE) : 0u);
    settings.cocScale = coc.cocScale;
    settings.cocBias = coc.cocBias;
    settings.aperture = toDofAperture(effect.aperture);
    if (autofocus != nullptr) {
        settings.useAutofocus = true;
        settings.autofocus = *autofocus;
    }
    return settings;
}

namespace {

// Always silent unless the device was opened with --validate.
void throwOnValidationMessages(vkrun::Device& device) {
    const std::vector<std::string> messages = device.validationMessages();
    if (!messages.empty()) {
        std::string first = messages.front();
        std::replace(first.begin(), first.end(), '\n', ' ');
        throw CliError(ExitCode::Device, "the validation layer reported " + std::to_string(messages.size()) +
                                             " message(s); the first: " + first);
    }
}

}  // namespace

vkrun::RunResult runEffectOrThrow(vkrun::Device& device, const vkrun::HostImage& color, const vkrun::HostImage& depth,
                                  const vkrun::RunSettings& settings) {
    vkrun::RunResult result;
    try {
        result = vkrun::runEffect(device, color, depth, settings);
    } catch (const vkrun::Error& error) {
        throw CliError(ExitCode::Device, std::string("running the effect failed: ") + error.what());
    }
    throwOnValidationMessages(device);
    return result;
}

vkrun::HostImage runEffectOrThrow(vkrun::Device& device, vkrun::EffectSession& session, const vkrun::HostImage& color,
                                  const vkrun::HostImage& depth, const vkrun::RunSettings& settings,
                                  float* autofocusDistance) {
    vkrun::HostImage output;
    try {
        output = session.run(color, depth, settings, autofocusDistance);
    } catch (const vkrun::Error& error) {
        throw CliError(ExitCode::Device, std::string("running the effect failed: ") + error.what());
    }
    throwOnValidationMessages(device);
    return output;
}

vkrun::HostImage toHostImage(const io::ImageRGBA& image) {
    vkrun::HostImage host(image.width, image.height, 4);
    host.pixels = image.pixels;
    return host;
}

vkrun::HostImage toHostImage(uint32_t width, uint32_t height, const std::vector<float>& singleChannel) {
    vkrun::HostImage host(width, height, 1);
    host.pixels = singleChannel;
    return host;
}

io::ImageRGBA toImageRGBA(const vkrun::HostImage& image) {
    io::ImageRGBA rgba(image.width, image.height);
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            const float* source = image.at(x, y);
            float* target = rgba.at(x, y);
            for (uint32_t c = 0; c < 4; ++c) {
                target[c] = c < image.channels ? source[c] : (c == 3 ? 1.0f : source[0]);
            }
        }
    }
    return rgba;
}

void writeOutput(const std::string& path, const io::ImageRGBA& image, io::ExrPixelType exrType) {
    try {
        io::writeImage(path, image, exrType);
    } catch (const io::IoError& error) {
        throw CliError(ExitCode::OutputWrite, error.what());
    }
}

}  // namespace ffxdof::cli
