// Shared by the Vulkan tests: one validated device per test process, a procedural scene, image
// comparisons. Every test ends with requireNoValidationMessages: any message fails it.
#pragma once

#include "ffx_dof_validated_device.h"
#include "ffx_dof_vkrun.h"
#include "vkrun_internal.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>

namespace ffxdof::vktest {

using ffxdof::testing::requireNoValidationMessages;
using ffxdof::testing::validatedDevice;

// A procedural scene: a textured background plane far behind the focus, a band in focus, and a
// bright near disc in front. Depth is device depth in [0, 1] (0 = near); the CoC is affine in it:
//   radius = (focusDepth - depth) * 2 * maxRadius  =>  cocScale = -2 R, cocBias = 2 R * focusDepth
// so depth 0 gives +R (near field) and depth 1 gives -R (far field), in half-resolution pixels.
struct Scene {
    vkrun::HostImage color;
    vkrun::HostImage depth;
    float cocScale = 0.0f;
    float cocBias = 0.0f;
};

constexpr float kFocusDepth = 0.5f;

inline Scene makeScene(uint32_t width, uint32_t height, float maxRadius, bool reversedDepth = false) {
    Scene scene{vkrun::HostImage(width, height, 4), vkrun::HostImage(width, height, 1)};
    const float cx = 0.5f * float(width), cy = 0.5f * float(height);
    const float discRadius = 0.2f * float(std::min(width, height)) + 0.5f;
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            float* c = scene.color.at(x, y);
            float d;
            const float dx = float(x) + 0.5f - cx, dy = float(y) + 0.5f - cy;
            if (dx * dx + dy * dy < discRadius * discRadius) {
                d = 0.15f;  // near disc: warm, bright
                c[0] = 1.6f, c[1] = 0.8f, c[2] = 0.2f;
            } else if (std::abs(float(y) + 0.5f - 0.25f * float(height)) < 0.08f * float(height) + 0.5f) {
                d = kFocusDepth;  // band in focus: fine stripes
                const float stripe = ((x / 2) % 2) ? 0.9f : 0.1f;
                c[0] = stripe, c[1] = stripe, c[2] = 0.5f;
            } else {
                d = 0.85f + 0.1f * float(x) / float(std::max(width, 1u));  // far plane, slightly tilted
                const bool checker = ((x / 6) + (y / 6)) % 2;
                c[0] = checker ? 0.2f : 0.05f;
                c[1] = checker ? 0.6f : 0.1f;
                c[2] = checker ? 0.9f : 0.3f;
                if ((x % 17 == 3) && (y % 13 == 5)) c[0] = c[1] = c[2] = 8.0f;  // highlights for bokeh
            }
            c[3] = 1.0f;
            scene.depth.at(x, y)[0] = reversedDepth ? 1.0f - d : d;
        }
    }
    if (reversedDepth) {
        // depth' = 1 - depth: radius = (depth' - (1 - focus)) * 2 R
        scene.cocScale = 2.0f * maxRadius;
        scene.cocBias = -2.0f * maxRadius * (1.0f - kFocusDepth);
    } else {
        scene.cocScale = -2.0f * maxRadius;
        scene.cocBias = 2.0f * maxRadius * kFocusDepth;
    }
    return scene;
}

struct Difference {
    double maxAbs = 0.0;
    double meanAbs = 0.0;
    double psnr = 0.0;  // dB over RGB, peak 1; infinity when identical
};

// RGB difference (alpha is not compared: the effect passes it through or ignores it).
inline Difference difference(const vkrun::HostImage& a, const vkrun::HostImage& b) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    Difference result;
    double squared = 0.0;
    const size_t count = size_t(a.width) * a.height;
    for (size_t i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double d = std::abs(double(a.pixels[i * 4 + c]) - double(b.pixels[i * 4 + c]));
            result.maxAbs = std::max(result.maxAbs, d);
            result.meanAbs += d;
            squared += d * d;
        }
    }
    result.meanAbs /= double(count * 3);
    const double mse = squared / double(count * 3);
    result.psnr = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : INFINITY;
    return result;
}

inline bool allFinite(const vkrun::HostImage& image) {
    for (float v : image.pixels) {
        if (!std::isfinite(v)) return false;
    }
    return true;
}

inline vkrun::RunSettings settingsFor(const Scene& scene) {
    vkrun::RunSettings settings;
    settings.cocScale = scene.cocScale;
    settings.cocBias = scene.cocBias;
    settings.colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.outputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    settings.quality = 4;
    settings.cocLimitFactor = 0.05f;
    return settings;
}

}  // namespace ffxdof::vktest
