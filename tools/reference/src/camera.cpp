#include "ffx_dof_reference.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>

namespace ffxdof::ref {
namespace {

bool positiveFinite(double value) { return std::isfinite(value) && value > 0.0; }

nlohmann::json vectorToJson(const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

glm::dvec3 vectorFromJson(const nlohmann::json& json, const char* key) {
    const nlohmann::json& value = json.at(key);
    if (!value.is_array() || value.size() != 3) throw std::invalid_argument(std::string(key) + " must be [x, y, z]");
    return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
}

nlohmann::json projectionToJson(const ProjectionTerms& terms) {
    return {{"proj33", terms.proj33}, {"proj34", terms.proj34}, {"proj43", terms.proj43}};
}

nlohmann::json apertureToJson(const ApertureShape& shape) {
    return {{"bladeCount", shape.bladeCount},
            {"bladeRotationDegrees", shape.bladeRotationDegrees},
            {"roundness", shape.roundness},
            {"anamorphicRatio", shape.anamorphicRatio},
            {"catEye", shape.catEye}};
}

// Absent object or fields: the defaults (camera.json files from before shapes are round apertures).
// Present ones must have the right type; the ranges are checked by validate().
ApertureShape apertureFromJson(const nlohmann::json& camera) {
    ApertureShape shape;
    const auto found = camera.find("aperture");
    if (found == camera.end()) return shape;
    const nlohmann::json& json = *found;
    if (!json.is_object()) throw std::invalid_argument("camera JSON: aperture must be an object");
    const auto readNumber = [&](const char* key, double& value) {
        const auto field = json.find(key);
        if (field == json.end()) return;
        if (!field->is_number()) {
            throw std::invalid_argument(std::string("camera JSON: aperture.") + key + " must be a number");
        }
        value = field->get<double>();
    };
    if (const auto blades = json.find("bladeCount"); blades != json.end()) {
        if (!blades->is_number_integer()) {
            throw std::invalid_argument("camera JSON: aperture.bladeCount must be an integer (0 or 3 to 16)");
        }
        const int64_t count = blades->get<int64_t>();
        if (count < 0 || count > 16) {
            throw std::invalid_argument("aperture.bladeCount must be 0 (round) or 3 to 16, got " +
                                        std::to_string(count));
        }
        shape.bladeCount = uint32_t(count);
    }
    readNumber("bladeRotationDegrees", shape.bladeRotationDegrees);
    readNumber("roundness", shape.roundness);
    readNumber("anamorphicRatio", shape.anamorphicRatio);
    readNumber("catEye", shape.catEye);
    return shape;
}

}  // namespace

double Camera::verticalFovRadians() const { return 2.0 * std::atan(sensorHeight() / (2.0 * imageDistance())); }

void Camera::setVerticalFov(double fovRadians) {
    // From v = sensorHeight / (2 tan(fov / 2)) and v = f F / (F - f): f = v F / (F + v).
    const double v = sensorHeight() / (2.0 * std::tan(0.5 * fovRadians));
    focalLength = v * focusDistance / (focusDistance + v);
}

double Camera::cocRadiusPixels(double viewDepth) const {
    const double sensorRadius =
        apertureRadius * focalLength * (focusDistance - viewDepth) / (viewDepth * (focusDistance - focalLength));
    return sensorRadius * pixelsPerSensorUnit();
}

ProjectionTerms Camera::projection() const {
    // device = proj33 + proj34 / Z with device(near) = 0 and device(far) = 1.
    const double range = farPlane - nearPlane;
    return {farPlane / range, -nearPlane * farPlane / range, 1.0};
}

ProjectionTerms Camera::reversedProjection() const {
    // device(near) = 1 and device(far) = 0.
    const double range = farPlane - nearPlane;
    return {-nearPlane / range, nearPlane * farPlane / range, 1.0};
}

void Camera::validate() const {
    if (width == 0 || height == 0) throw std::invalid_argument("camera width and height must be at least 1");
    if (!positiveFinite(focalLength)) throw std::invalid_argument("focalLength must be positive and finite");
    if (!positiveFinite(sensorWidth)) throw std::invalid_argument("sensorWidth must be positive and finite");
    if (!std::isfinite(focusDistance) || focusDistance <= focalLength) {
        throw std::invalid_argument("focusDistance must be finite and greater than focalLength");
    }
    if (!std::isfinite(apertureRadius) || apertureRadius < 0.0) {
        throw std::invalid_argument("apertureRadius must be finite and not negative");
    }
    if (!positiveFinite(nearPlane) || !std::isfinite(farPlane) || farPlane <= nearPlane) {
        throw std::invalid_argument("near and far planes must satisfy 0 < near < far");
    }
    aperture.validate();
    const glm::dvec3 forward = target - position;
    if (!(glm::length(forward) > 0.0)) throw std::invalid_argument("camera target equals its position");
    if (!(glm::length(glm::cross(forward, up)) > 1e-9 * glm::length(forward) * glm::length(up))) {
        throw std::invalid_argument("camera up vector is parallel to the viewing direction");
    }
}

nlohmann::json cameraToJson(const Camera& camera) {
    return {
        {"width", camera.width},
        {"height", camera.height},
        {"position", vectorToJson(camera.position)},
        {"target", vectorToJson(camera.target)},
        {"up", vectorToJson(camera.up)},
        {"focalLength", camera.focalLength},
        {"sensorWidth", camera.sensorWidth},
        {"focusDistance", camera.focusDistance},
        {"apertureRadius", camera.apertureRadius},
        {"fstop", camera.fstop()},
        {"near", camera.nearPlane},
        {"far", camera.farPlane},
        {"aperture", apertureToJson(camera.aperture)},
        {"imageDistance", camera.imageDistance()},
        {"verticalFovDegrees", camera.verticalFovRadians() * 180.0 / M_PI},
        {"pixelsPerSensorUnit", camera.pixelsPerSensorUnit()},
        {"projection", projectionToJson(camera.projection())},
        {"projectionReversed", projectionToJson(camera.reversedProjection())},
        {"units",
         "metres; view space looks down +Z; CoC radius (sensor units) = "
         "apertureRadius * focalLength * |focusDistance - Z| / (Z * (focusDistance - focalLength))"},
    };
}

Camera cameraFromJson(const nlohmann::json& json) {
    Camera camera;
    try {
        camera.width = json.at("width").get<uint32_t>();
        camera.height = json.at("height").get<uint32_t>();
        camera.position = vectorFromJson(json, "position");
        camera.target = vectorFromJson(json, "target");
        camera.up = vectorFromJson(json, "up");
        camera.focalLength = json.at("focalLength").get<double>();
        camera.sensorWidth = json.at("sensorWidth").get<double>();
        camera.focusDistance = json.at("focusDistance").get<double>();
        camera.apertureRadius = json.at("apertureRadius").get<double>();
        camera.nearPlane = json.at("near").get<double>();
        camera.farPlane = json.at("far").get<double>();
    } catch (const nlohmann::json::exception& error) {
        throw std::invalid_argument(std::string("camera JSON: ") + error.what());
    }
    camera.aperture = apertureFromJson(json);
    camera.validate();
    return camera;
}

Camera readCameraJson(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw io::IoError(path + ": file not found");
    std::ifstream file(path);
    if (!file) throw io::IoError(path + ": cannot open for reading");
    try {
        return cameraFromJson(nlohmann::json::parse(file));
    } catch (const std::exception& error) {
        throw io::IoError(path + ": invalid camera: " + error.what());
    }
}

void writeCameraJson(const std::string& path, const Camera& camera) {
    io::writeFileReplacing(path, [&](std::ostream& stream) { stream << cameraToJson(camera).dump(2) << "\n"; });
}

}  // namespace ffxdof::ref
