#include <simp/camera/BoxProjection.h>

#include <algorithm>
#include <limits>
#include <array>
#include <vector>

namespace simp::camera {

double area(const ImageBox& b) { return std::max(0.0, b(2) - b(0)) * std::max(0.0, b(3) - b(1)); }

double iou2D(const ImageBox& a, const ImageBox& b) {
    const ImageBox i(std::max(a(0), b(0)), std::max(a(1), b(1)), std::min(a(2), b(2)), std::min(a(3), b(3)));
    const double inter = area(i), uni = area(a) + area(b) - inter;
    return uni > 0 ? inter / uni : 0.0;
}

Eigen::Vector2d projectPoint(const PinholeCamera& camera, const Eigen::Vector3d& X_world) {
    const Eigen::Vector3d Xc = camera.world_T_camera.inverse() * X_world;  // [R t] X
    const Eigen::Vector3d x = camera.K() * Xc;                               // K [R t] X
    return x.head<2>() / x.z();
}

ProjectedBox projectBox(const PinholeCamera& camera, const geometry::Box3D& box_world, double near_m) {
    // Corners in the camera frame; edges join corners differing in one bit (Box3D numbering).
    const Eigen::Isometry3d camera_T_world = camera.world_T_camera.inverse();
    const auto corners = box_world.corners();
    std::array<Eigen::Vector3d, 8> c;
    for (std::size_t i = 0; i < 8; ++i) c[i] = camera_T_world * corners[i];
    std::vector<Eigen::Vector3d> pts;
    for (std::size_t i = 0; i < 8; ++i) {
        if (c[i].z() >= near_m) pts.push_back(c[i]);
        for (std::size_t bit : {1u, 2u, 4u}) {
            const std::size_t j = i ^ bit;
            if (j < i) continue;
            const double zi = c[i].z() - near_m, zj = c[j].z() - near_m;
            if ((zi < 0) != (zj < 0)) pts.push_back(c[i] + (c[j] - c[i]) * (zi / (zi - zj)));
        }
    }
    ProjectedBox out;
    if (pts.empty()) return out;
    out.visible_in_front = true;
    const double inf = std::numeric_limits<double>::infinity();
    const Eigen::Matrix3d K = camera.K();
    ImageBox b(inf, inf, -inf, -inf);
    for (const Eigen::Vector3d& p : pts) {
        const Eigen::Vector3d x = K * p;
        const Eigen::Vector2d uv = x.head<2>() / x.z();
        b(0) = std::min(b(0), uv.x()), b(1) = std::min(b(1), uv.y());
        b(2) = std::max(b(2), uv.x()), b(3) = std::max(b(3), uv.y());
    }
    out.bbox_proj = b;
    out.bbox_trunc = ImageBox(std::clamp(b(0), 0.0, double(camera.widthPx())), std::clamp(b(1), 0.0, double(camera.heightPx())),
                              std::clamp(b(2), 0.0, double(camera.widthPx())), std::clamp(b(3), 0.0, double(camera.heightPx())));
    const double a = area(b);
    out.truncation = a > 0 ? 1.0 - area(out.bbox_trunc) / a : 1.0;
    return out;
}

}  // namespace simp::camera
