#include <simp/camera/BoxProjection.h>
#include <simp/camera/RayCastVisibility.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace simp::camera {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

double rayBoxEntry(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, const geometry::Box3D& box) {
    const Eigen::Vector3d o = box.R.transpose() * (origin - box.center), d = box.R.transpose() * dir;
    double t0 = 0, t1 = kInf;
    for (int k = 0; k < 3; ++k) {
        const double h = 0.5 * box.size(k);
        if (std::abs(d(k)) < 1e-15) {
            if (std::abs(o(k)) > h) return kInf;
            continue;
        }
        double a = (-h - o(k)) / d(k), b = (h - o(k)) / d(k);
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
        if (t0 > t1) return kInf;
    }
    return t0;
}

std::vector<double> rayCastVisibility(const PinholeCamera& camera, const std::vector<geometry::Box3D>& boxes,
                                      const FloorPlanGrid* walls, const RayCastParams& o,
                                      const std::vector<char>* occludes) {
    const std::size_t n = boxes.size();
    if (occludes != nullptr && occludes->size() != n) occludes = nullptr;
    std::vector<double> hits(n, 0.0), seen(n, 0.0);
    std::vector<ImageBox> bb(n);
    std::vector<char> candidate(n, 0);
    for (std::size_t i = 0; i < n; ++i) {  // rays outside the clipped projected box cannot hit it
        const ProjectedBox p = projectBox(camera, boxes[i]);
        bb[i] = p.bbox_trunc;
        candidate[i] = p.visible_in_front && area(p.bbox_trunc) > 0;
    }
    const bool use_walls = walls != nullptr && !walls->empty();
    const Eigen::Matrix3d Kinv = camera.K().inverse();
    const Eigen::Matrix3d R = camera.world_T_camera.linear();
    const Eigen::Vector3d origin = camera.world_T_camera.translation();
    const int step = std::max(1, o.pixel_step);
    std::vector<double> depth(n);
    for (int v = step / 2; v < camera.heightPx(); v += step)
        for (int u = step / 2; u < camera.widthPx(); u += step) {
            const double pu = u + 0.5, pv = v + 0.5;  // pixel centre
            const Eigen::Vector3d dir = R * (Kinv * Eigen::Vector3d(pu, pv, 1.0));  // camera z = 1: s = depth
            bool any = false;
            for (std::size_t i = 0; i < n; ++i) {
                depth[i] = kInf;
                if (!candidate[i] || pu < bb[i](0) || pu > bb[i](2) || pv < bb[i](1) || pv > bb[i](3)) continue;
                depth[i] = rayBoxEntry(origin, dir, boxes[i]);
                any |= std::isfinite(depth[i]);
            }
            if (!any) continue;
            double nearest = kInf;  // the nearest occluding box
            for (std::size_t i = 0; i < n; ++i)
                if (occludes == nullptr || (*occludes)[i]) nearest = std::min(nearest, depth[i]);
            double wall = kInf;
            if (use_walls) {
                const double horiz = dir.head<2>().norm();
                if (horiz > 1e-12) {
                    const double max_h = std::min(o.max_range_m, nearest * horiz);
                    wall = walls->castRay(origin.head<2>(), dir.head<2>() / horiz, max_h) / horiz;
                }
            }
            for (std::size_t i = 0; i < n; ++i) {
                if (!std::isfinite(depth[i])) continue;
                hits[i] += 1;
                if (depth[i] <= nearest && depth[i] < wall) seen[i] += 1;
            }
        }
    std::vector<double> vis(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) vis[i] = hits[i] > 0 ? seen[i] / hits[i] : 0.0;
    return vis;
}

}  // namespace simp::camera
