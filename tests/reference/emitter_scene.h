// The test scene the renderer's tests share: one small bright emitter on black.
#pragma once

#include "ffx_dof_reference.h"

#include <glm/vec3.hpp>

#include <cstdint>

namespace ffxdof::reftest {

// One small bright emitter on black at view depth z seen at pixel (px, py) of a size x size frame, the
// camera at the origin looking down +Z and focused at `focus`.
inline ref::SceneSetup emitterScene(uint32_t size, double focus, double z, double aperture, double px, double py,
                                    double imageRadiusPixels = 0.4) {
    ref::SceneSetup setup;
    ref::Camera& camera = setup.camera;
    camera.width = camera.height = size;
    camera.focalLength = 0.05;
    camera.sensorWidth = 0.036;
    camera.focusDistance = focus;
    camera.apertureRadius = aperture;
    const double metresPerPixel = z / (camera.pixelsPerSensorUnit() * camera.imageDistance());
    const glm::dvec3 center{(px - 0.5 * size) * metresPerPixel, (0.5 * size - py) * metresPerPixel, z};
    setup.scene.addEmitter(center, imageRadiusPixels * metresPerPixel, {1.0f, 1.0f, 1.0f}, 100.0f);
    return setup;
}

}  // namespace ffxdof::reftest
