#include <simp/mapping/WallAlignment.h>

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace simp::mapping {
namespace {

bool isUpright(const geometry::Box3D& b) { return std::abs(b.R(2, 2)) > 0.999; }

Eigen::Vector2d axisDir(const geometry::Box3D& b, int axis) { return b.R.col(axis).head<2>().normalized(); }

/// 2D cross product: sine of the angle from a to b (unit vectors).
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/// The best qualifying contact on each box axis (smallest |gap|).
std::optional<WallContact> bestOnAxis(const geometry::Box3D& box, int axis, const camera::FloorPlanGrid& walls,
                                      const WallAlignmentParams& p) {
    std::optional<WallContact> best;
    for (const int sign : {1, -1}) {
        const auto c = wallContact(box, axis, sign, walls, p);
        if (c && (!best || std::abs(c->gap_m) < std::abs(best->gap_m))) best = c;
    }
    return best;
}

}  // namespace

std::optional<WallContact> wallContact(const geometry::Box3D& box, int axis, int sign, const camera::FloorPlanGrid& walls,
                                       const WallAlignmentParams& p) {
    if (walls.empty() || !isUpright(box) || p.rays_per_side < 2) return std::nullopt;
    const Eigen::Vector2d n = sign * axisDir(box, axis);
    const Eigen::Vector2d t = axisDir(box, 1 - axis);
    const double half = 0.5 * box.size[axis];
    const double length = box.size[1 - axis];
    const Eigen::Vector2d mid = box.center.head<2>() + half * n;
    const double reach = p.max_penetration_m + p.max_gap_m;
    // The opposite side must face the room (known free space); otherwise the box lies in or
    // behind the wall, and this side would find the wall from the wrong side.
    const Eigen::Vector2d opposite = box.center.head<2>() - half * n;
    if (!walls.isFree(opposite.x(), opposite.y())) return std::nullopt;

    // Rays from points along the side, started max_penetration_m behind it (inside the box).
    std::vector<double> s, g;
    for (int k = 0; k < p.rays_per_side; ++k) {
        const double sk = length * (-0.4 + 0.8 * k / (p.rays_per_side - 1));
        const Eigen::Vector2d start = mid + sk * t - p.max_penetration_m * n;
        if (walls.isWall(start.x(), start.y())) continue;  // deeper in the wall than allowed
        const double d = walls.castRay(start, n, reach);
        if (!std::isfinite(d)) continue;
        s.push_back(sk);
        g.push_back(d - p.max_penetration_m);
    }
    // Most of the side must face the wall (a door gap may leave a few rays free).
    const int need = std::max(2, p.rays_per_side / 2 + 1);
    if (static_cast<int>(s.size()) < need) return std::nullopt;

    // Least-squares line gap(s) = g0 + slope * s.
    const auto m = static_cast<double>(s.size());
    double ms = 0, mg = 0;
    for (std::size_t i = 0; i < s.size(); ++i) ms += s[i] / m, mg += g[i] / m;
    double sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < s.size(); ++i) sxx += (s[i] - ms) * (s[i] - ms), sxy += (s[i] - ms) * (g[i] - mg);
    const double slope = sxx > 1e-12 ? sxy / sxx : 0.0;
    WallContact c;
    c.axis = axis;
    c.sign = sign;
    c.slope = slope;
    c.gap_m = mg - slope * ms;
    c.hits = static_cast<int>(s.size());
    if (std::atan(std::abs(slope)) > p.max_yaw_rad) return std::nullopt;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (std::abs(g[i] - (c.gap_m + slope * s[i])) > p.max_residual_m) return std::nullopt;
    if (c.gap_m > p.max_gap_m || c.gap_m < -p.max_penetration_m) return std::nullopt;
    return c;
}

geometry::Box3D alignToWalls(const geometry::Box3D& box_in, const camera::FloorPlanGrid& walls, const WallAlignmentParams& p) {
    if (walls.empty() || !isUpright(box_in)) return box_in;
    geometry::Box3D box = box_in;

    // 1. The nearest qualifying wall sets the heading: turn the box parallel to it.
    std::optional<WallContact> first;
    for (int axis = 0; axis < 2; ++axis) {
        const auto c = bestOnAxis(box, axis, walls, p);
        if (c && (!first || std::abs(c->gap_m) < std::abs(first->gap_m))) first = c;
    }
    if (!first) return box_in;
    const Eigen::Vector2d n = first->sign * axisDir(box, first->axis);
    const Eigen::Vector2d t = axisDir(box, 1 - first->axis);
    // The wall runs along t + slope * n; turning t onto it turns by atan(slope) with the sign of t x n.
    const double turn = std::atan(first->slope) * (cross(t, n) >= 0 ? 1.0 : -1.0);
    box.R = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix() * box.R;

    // 2. Touch the wall on each axis that has one (re-measured with the new heading).
    for (int axis = 0; axis < 2; ++axis) {
        const auto c = bestOnAxis(box, axis, walls, p);
        if (!c) continue;
        box.center.head<2>() += c->gap_m * (c->sign * axisDir(box, axis));
    }
    return box;
}

}  // namespace simp::mapping
