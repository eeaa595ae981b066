// Shared by the HLSL tests on a Vulkan device: one validated device per test process, and the
// reference renderer's procedural scenes prepared as effect inputs (pinhole colour, device depth in
// the standard or the reversed convention, and the thin-lens CoC scale and bias for that depth).
#pragma once

#include "ffx_dof.h"
#include "ffx_dof_reference.h"
#include "ffx_dof_validated_device.h"
#include "ffx_dof_vkrun.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace ffxdof::hlsltest {

using ffxdof::testing::requireNoValidationMessages;
using ffxdof::testing::validatedDevice;

// FfxDofInitializationFlagBits for the option axes a context chooses (the in-place flag, with its
// separate handling in vkrun, is left to the caller).
inline uint32_t contextFlags(bool reversedDepth, bool ringMerge) {
    return (reversedDepth ? uint32_t(FFX_DOF_REVERSE_DEPTH) : 0u) |
           (ringMerge ? 0u : uint32_t(FFX_DOF_DISABLE_RING_MERGE));
}

struct EffectInput {
    std::string name;  // "near-object 96x64 reversed"
    vkrun::HostImage color;
    vkrun::HostImage depth;
    float cocScale = 0.0f;
    float cocBias = 0.0f;
    float cocLimitFactor = 0.0f;
};

// The inputs for both depth conventions of one reference scene (rendered once).
struct SceneInputs {
    EffectInput standard;
    EffectInput reversed;
};

inline EffectInput makeInput(const std::string& name, const ref::Camera& camera, const io::ImageRGBA& color,
                             const io::ImageR& deviceDepth, const ref::ProjectionTerms& projection,
                             float cocLimitFactor) {
    EffectInput input;
    input.name = name;
    input.color = vkrun::HostImage(color.width, color.height, 4);
    input.color.pixels = color.pixels;
    input.depth = vkrun::HostImage(deviceDepth.width, deviceDepth.height, 1);
    input.depth.pixels = deviceDepth.pixels;
    // The SDK's radius is in half-resolution pixels: conversion = 0.5 * width / sensorWidth.
    const float conversion = float(0.5 * camera.width / camera.sensorWidth);
    const float args[] = {
        float(camera.apertureRadius), float(camera.focusDistance), float(camera.focalLength), conversion,
        float(projection.proj33),     float(projection.proj34),    float(projection.proj43)};
    input.cocScale = ffxDofCalculateCocScale(args[0], args[1], args[2], args[3], args[4], args[5], args[6]);
    input.cocBias = ffxDofCalculateCocBias(args[0], args[1], args[2], args[3], args[4], args[5], args[6]);
    input.cocLimitFactor = cocLimitFactor;
    return input;
}

inline SceneInputs makeSceneInputs(const std::string& scene, uint32_t width, uint32_t height) {
    const ref::SceneSetup setup = ref::makeScene(scene, width, height);
    const ref::PinholeImages pinhole = ref::renderPinhole(setup.scene, setup.camera);
    // A limit that covers the scene's largest radius (a fraction of the full-resolution height), so
    // that every pixel's blur is the lens's and none is clipped.
    float largest = 0.0f;
    for (float z : pinhole.depth.pixels) largest = std::max(largest, float(std::abs(setup.camera.cocRadiusPixels(z))));
    const float cocLimitFactor = largest / float(height) * 1.02f + 1e-3f;
    const std::string name = scene + " " + std::to_string(width) + "x" + std::to_string(height);
    return {makeInput(name + " standard", setup.camera, pinhole.color, pinhole.deviceDepth, setup.camera.projection(),
                      cocLimitFactor),
            makeInput(name + " reversed", setup.camera, pinhole.color, pinhole.deviceDepthReversed,
                      setup.camera.reversedProjection(), cocLimitFactor)};
}

}  // namespace ffxdof::hlsltest
