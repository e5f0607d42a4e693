#include <simp/obs/Detection3D.h>
#include <simp/obs/InputLimits.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace simp::obs {
namespace {

[[noreturn]] void reject(const std::string& where, const std::string& field, const std::string& what) {
    throw std::invalid_argument(where + ": field '" + field + "' " + what);
}

std::string vec3(const Eigen::Vector3d& v) {
    std::ostringstream s;
    s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

}  // namespace

void validateDetection(const Detection3D& d, std::size_t num_classes, const std::string& where) {
    if (d.class_id >= num_classes)
        reject(where, "class_id", "= " + std::to_string(d.class_id) + " is out of range [0, " +
                                      std::to_string(num_classes) + ")");
    if (!std::isfinite(d.confidence) || d.confidence < 0.0f || d.confidence > 1.0f)
        reject(where, "confidence", "= " + std::to_string(d.confidence) + " must be a number in [0, 1]");
    const auto& b = d.box_in_camera;
    if (!b.center.allFinite()) reject(where, "center", "= " + vec3(b.center) + " is not finite");
    if (!b.size.allFinite()) reject(where, "size", "= " + vec3(b.size) + " is not finite");
    if ((b.size.array() <= 0.0).any()) reject(where, "size", "= " + vec3(b.size) + " must be > 0 (W, H, L in m)");
    // Limits of doc/formats.md: beyond them a file is corrupted, not an office.
    if (b.center.cwiseAbs().maxCoeff() > limits::kMaxCoordinate_m)
        reject(where, "center", "= " + vec3(b.center) + " m is beyond the maximum coordinate " +
                                    std::to_string(limits::kMaxCoordinate_m) + " m");
    if (b.size.maxCoeff() > limits::kMaxBoxSide_m)
        reject(where, "size", "= " + vec3(b.size) + " m exceeds the maximum box side " +
                                  std::to_string(limits::kMaxBoxSide_m) + " m");
    if (!b.R.allFinite()) reject(where, "rotation", "is not finite");
    if (!b.isValid(1e-4)) reject(where, "rotation", "is not a rotation matrix (R^T R = I, det R = +1)");
    if (d.box_2d) {
        const auto& r = *d.box_2d;
        if (!std::isfinite(r.x_min) || !std::isfinite(r.y_min) || !std::isfinite(r.x_max) || !std::isfinite(r.y_max))
            reject(where, "box_2d", "is not finite");
        if (r.x_min > r.x_max || r.y_min > r.y_max) reject(where, "box_2d", "has min > max");
    }
}

}  // namespace simp::obs
