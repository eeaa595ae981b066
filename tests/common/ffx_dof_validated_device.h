// The one Vulkan device of a test process, with VK_LAYER_KHRONOS_validation and synchronization
// validation on, and the rule every Vulkan test ends with: any validation message fails the test.
#pragma once

#include "ffx_dof_vkrun.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

namespace ffxdof::testing {

inline vkrun::Device& validatedDevice() {
    static std::unique_ptr<vkrun::Device> device = [] {
        vkrun::DeviceOptions options;
        options.validation = true;
        return std::make_unique<vkrun::Device>(options);
    }();
    return *device;
}

// `what` names the run that produced the messages, for the failure report.
inline void requireNoValidationMessages(vkrun::Device& device, const std::string& what = "") {
    const std::vector<std::string> messages = device.validationMessages();
    device.clearValidationMessages();
    for (const std::string& message : messages)
        UNSCOPED_INFO(what << (what.empty() ? "" : ": ") << "validation: " << message);
    REQUIRE(messages.empty());
}

}  // namespace ffxdof::testing
