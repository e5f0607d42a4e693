#include <simp/camera/Occluders.h>
#include <simp/geometry/Footprint.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/Visibility.h>

#include <algorithm>
#include <cmath>

namespace simp::sim {
namespace {

constexpr double kMinDepth_m = 0.05;  ///< corners closer to the image plane are "behind"
/// A door stands in its wall gap: its rays ignore walls this much farther from its footprint (m).
constexpr double kSeeThroughExtraSelfMargin_m = 0.1;

bool insideConvex(const geometry::ConvexPolygon& poly, const Eigen::Vector2d& q) {
    if (poly.n < 3) return false;
    for (std::size_t i = 0; i < poly.n; ++i) {
        const Eigen::Vector2d e = poly.v[(i + 1) % poly.n] - poly.v[i], d = q - poly.v[i];
        if (e.x() * d.y() - e.y() * d.x() < 0) return false;
    }
    return true;
}

/// Per-class range limits resolved for the world's class list.
void rangeOf(const VisibilityParams& p, const std::string& name, double& lo, double& hi) {
    const int k = obs::classIndexOf(obs::defaultClassNames(), name);
    lo = 0;
    hi = p.default_max_range_m;
    if (k < 0) return;
    const auto ku = static_cast<std::size_t>(k);
    if (ku < p.min_range_m.size()) lo = p.min_range_m[ku];
    if (ku < p.max_range_m.size() && p.max_range_m[ku] > 0) hi = p.max_range_m[ku];
}

struct Candidate {
    std::size_t index;
    geometry::Box3D box_in_camera;
    obs::ImageBox2D box_2d;
    double depth_m, inside_fraction;
    bool see_through;  ///< seen through its gap, hides nothing (a door)
    bool wall_visible = false;
};

double coveredFraction(const obs::ImageBox2D& a, const std::vector<const obs::ImageBox2D*>& nearer) {
    constexpr int kSamples = 8;
    int covered = 0;
    for (int i = 0; i < kSamples; ++i)
        for (int j = 0; j < kSamples; ++j) {
            const double u = a.x_min + (a.x_max - a.x_min) * (i + 0.5) / kSamples;
            const double v = a.y_min + (a.y_max - a.y_min) * (j + 0.5) / kSamples;
            for (const auto* b : nearer)
                if (u >= b->x_min && u <= b->x_max && v >= b->y_min && v <= b->y_max) {
                    ++covered;
                    break;
                }
        }
    return covered / static_cast<double>(kSamples * kSamples);
}

}  // namespace

bool projectBox(const camera::PinholeCamera& view, const geometry::Box3D& box_in_camera, obs::ImageBox2D& box_2d,
                double& inside_fraction) {
    int in_front = 0, inside = 0;
    double u0 = 1e18, v0 = 1e18, u1 = -1e18, v1 = -1e18;
    for (const auto& c : box_in_camera.corners()) {
        if (c.z() < kMinDepth_m) continue;
        ++in_front;
        const Eigen::Vector2d px = view.project(c);
        if (view.inImage(px)) ++inside;
        u0 = std::min(u0, px.x());
        v0 = std::min(v0, px.y());
        u1 = std::max(u1, px.x());
        v1 = std::max(v1, px.y());
    }
    inside_fraction = inside / 8.0;
    if (in_front == 0) return false;
    const auto clampU = [&](double u) { return static_cast<float>(std::clamp(u, 0.0, static_cast<double>(view.widthPx()))); };
    const auto clampV = [&](double v) { return static_cast<float>(std::clamp(v, 0.0, static_cast<double>(view.heightPx()))); };
    box_2d = {clampU(u0), clampV(v0), clampU(u1), clampV(v1)};
    return box_2d.x_max > box_2d.x_min && box_2d.y_max > box_2d.y_min;
}

bool visibleThroughWalls(const camera::PinholeCamera& view, const world::MapObject& object, const Raster& walls,
                         const VisibilityParams& p, double extra_self_margin_m) {
    const Eigen::Vector2d cam = view.world_T_camera.translation().head<2>();
    const double yaw = geometry::yawOf(object.box);
    const double margin = p.self_margin_m + extra_self_margin_m;
    const auto self = geometry::makeRectangle(object.box.center.head<2>(), object.box.size.x() + 2 * margin,
                                              object.box.size.y() + 2 * margin, yaw);
    const auto fp = geometry::footprint(object.box);
    const Eigen::Vector2d c = object.box.center.head<2>();
    // targets: the centre, then footprint corners pulled 30 % towards the centre
    std::vector<Eigen::Vector2d> targets{c};
    for (std::size_t i = 0; static_cast<int>(targets.size()) < p.wall_rays && fp.n > 0; ++i)
        targets.push_back(c + 0.7 * (fp.v[i % fp.n] - c));
    int clear = 0;
    const double step = 0.5 * walls.resolution_m;
    for (const auto& t : targets) {
        const double len = (t - cam).norm();
        const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
        bool ok = true;
        for (int i = 0; i <= n && ok; ++i) {
            const Eigen::Vector2d q = cam + (t - cam) * (static_cast<double>(i) / n);
            if (walls.isBlockedAt(q.x(), q.y()) && !insideConvex(self, q)) ok = false;
        }
        if (ok) ++clear;
    }
    return clear >= p.min_visible_ray_fraction * static_cast<double>(targets.size()) && clear > 0;
}

std::vector<VisibleObject> visibleObjects(const camera::PinholeCamera& view, const std::vector<world::MapObject>& objects,
                                          const std::vector<std::string>& class_names, const Raster& walls,
                                          const VisibilityParams& p) {
    const Eigen::Isometry3d T_camera_world = view.world_T_camera.inverse();
    const Eigen::Vector2d cam = view.world_T_camera.translation().head<2>();
    double global_max = p.default_max_range_m;
    for (double m : p.max_range_m) global_max = std::max(global_max, m);
    std::vector<Candidate> in_view;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const auto& o = objects[i];
        const std::string& name =
            o.class_id >= 0 && static_cast<std::size_t>(o.class_id) < class_names.size() ? class_names[static_cast<std::size_t>(o.class_id)] : "";
        if ((o.box.center.head<2>() - cam).norm() > global_max) continue;  // neither seen nor occluding
        Candidate c{i, o.box.transformed(T_camera_world), {}, 0, 0, !camera::occludes(name)};
        c.depth_m = c.box_in_camera.center.z();
        if (c.depth_m < kMinDepth_m) continue;
        if (!projectBox(view, c.box_in_camera, c.box_2d, c.inside_fraction)) continue;
        c.wall_visible = visibleThroughWalls(view, o, walls, p, c.see_through ? kSeeThroughExtraSelfMargin_m : 0.0);
        if (c.wall_visible) in_view.push_back(c);  // objects behind walls neither show nor occlude
    }
    std::vector<VisibleObject> out;
    for (const auto& c : in_view) {
        const auto& o = objects[c.index];
        double lo, hi;
        rangeOf(p, class_names.at(static_cast<std::size_t>(o.class_id)), lo, hi);
        const double range = (o.box.center.head<2>() - cam).norm();
        if (range < lo || range > hi) continue;
        if (c.inside_fraction < p.min_inside_fraction) continue;
        std::vector<const obs::ImageBox2D*> nearer;
        for (const auto& d : in_view)
            if (d.index != c.index && !d.see_through && d.depth_m < c.depth_m) nearer.push_back(&d.box_2d);
        const double occluded = coveredFraction(c.box_2d, nearer);
        if (occluded > p.max_occluded_fraction) continue;
        out.push_back({c.index, c.box_2d, c.depth_m, c.inside_fraction, occluded});
    }
    return out;
}

}  // namespace simp::sim
