#include "ffx_dof_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ffxdof::ref {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Rows of the area integral: the midpoint rule's error, dominated by the square-root ends of the
// circular arcs, is then about 1e-6 of the area.
constexpr int kAreaRows = 4096;

bool inRange(double value, double lo, double hi) { return std::isfinite(value) && value >= lo && value <= hi; }

}  // namespace

void ApertureShape::validate() const {
    if (bladeCount != 0 && (bladeCount < 3 || bladeCount > 16)) {
        throw std::invalid_argument("aperture.bladeCount must be 0 (round) or 3 to 16, got " +
                                    std::to_string(bladeCount));
    }
    if (!std::isfinite(bladeRotationDegrees)) {
        throw std::invalid_argument("aperture.bladeRotationDegrees must be finite");
    }
    if (!inRange(roundness, 0.0, 1.0)) throw std::invalid_argument("aperture.roundness must be in [0, 1]");
    if (!inRange(anamorphicRatio, 0.5, 2.0)) {
        throw std::invalid_argument("aperture.anamorphicRatio must be in [0.5, 2]");
    }
    if (!inRange(catEye, 0.0, 1.0)) throw std::invalid_argument("aperture.catEye must be in [0, 1]");
}

UnitAperture::UnitAperture(const ApertureShape& shape) : shape_(shape) {
    shape_.validate();
    if (shape_.bladeCount == 0) return;
    const double n = shape_.bladeCount;
    const double polygonInradius = std::cos(kPi / n);
    inradius_ = polygonInradius + shape_.roundness * (1.0 - polygonInradius);
    const double rotation = shape_.bladeRotationDegrees * (kPi / 180.0);
    for (uint32_t k = 0; k < shape_.bladeCount; ++k) {
        const double angle = rotation + 2.0 * kPi * k / n;
        normals_.push_back({std::cos(angle), std::sin(angle)});
    }
}

bool UnitAperture::isDisc() const { return shape_.catEye == 0.0 && (normals_.empty() || inradius_ >= 1.0); }

glm::dvec2 UnitAperture::catEyeCenter(double px, double py, uint32_t width, uint32_t height) const {
    if (shape_.catEye == 0.0) return glm::dvec2(0.0);
    const double halfDiagonal = 0.5 * std::sqrt(double(width) * width + double(height) * height);
    return shape_.catEye * glm::dvec2(px - 0.5 * width, 0.5 * height - py) / halfDiagonal;
}

bool UnitAperture::contains(glm::dvec2 point, glm::dvec2 catEyeCenter, double radius) const {
    // Written as comparisons of the point with the radius-scaled shape rather than dividing by the
    // radius: for the round aperture this is exactly the test of the renderer before shapes.
    if (glm::dot(point, point) > radius * radius) return false;
    const double bound = inradius_ * radius;
    for (const glm::dvec2& normal : normals_) {
        if (glm::dot(normal, point) > bound) return false;
    }
    if (shape_.catEye > 0.0) {
        const glm::dvec2 offset = point - radius * catEyeCenter;
        if (glm::dot(offset, offset) > radius * radius) return false;
    }
    return true;
}

bool UnitAperture::rowInterval(double uy, glm::dvec2 catEyeCenter, double& left, double& right) const {
    if (std::abs(uy) > 1.0) return false;
    right = std::sqrt(1.0 - uy * uy);
    left = -right;
    for (const glm::dvec2& normal : normals_) {
        // nx ux <= a - ny uy bounds ux on the side the normal points to.
        const double rest = inradius_ - normal.y * uy;
        if (normal.x > 0.0) {
            right = std::min(right, rest / normal.x);
        } else if (normal.x < 0.0) {
            left = std::max(left, rest / normal.x);
        } else if (rest < 0.0) {
            return false;
        }
    }
    if (shape_.catEye > 0.0) {
        const double dy = uy - catEyeCenter.y;
        if (std::abs(dy) > 1.0) return false;
        const double halfWidth = std::sqrt(1.0 - dy * dy);
        left = std::max(left, catEyeCenter.x - halfWidth);
        right = std::min(right, catEyeCenter.x + halfWidth);
    }
    return left <= right;
}

double UnitAperture::area(glm::dvec2 catEyeCenter) const {
    const bool catEyeIsUnitDisc = shape_.catEye == 0.0 || (catEyeCenter.x == 0.0 && catEyeCenter.y == 0.0);
    if (catEyeIsUnitDisc) {
        // The blades cut N disjoint circular segments off the disc (a >= cos(pi / N) keeps them apart),
        // each of area acos(a) - a sqrt(1 - a^2).
        if (normals_.empty() || inradius_ >= 1.0) return kPi;
        const double segment = std::acos(inradius_) - inradius_ * std::sqrt(1.0 - inradius_ * inradius_);
        return kPi - double(normals_.size()) * segment;
    }
    const double lo = std::max(-1.0, catEyeCenter.y - 1.0), hi = std::min(1.0, catEyeCenter.y + 1.0);
    if (!(lo < hi)) return 0.0;
    const double step = (hi - lo) / kAreaRows;
    double sum = 0.0;
    for (int row = 0; row < kAreaRows; ++row) {
        double left, right;
        if (rowInterval(lo + (row + 0.5) * step, catEyeCenter, left, right)) sum += right - left;
    }
    return sum * step;
}

}  // namespace ffxdof::ref
