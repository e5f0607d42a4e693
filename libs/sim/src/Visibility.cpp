#include <simp/camera/BoxProjection.h>
#include <simp/camera/Occluders.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/Visibility.h>

#include <algorithm>

namespace simp::sim {
namespace {

constexpr double kNearPlane_m = 0.05;  ///< corners closer to the image plane are "behind"

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

}  // namespace

bool imageBoxOf(const camera::PinholeCamera& view, const geometry::Box3D& box_in_camera, obs::ImageBox2D& box_2d) {
    camera::PinholeCamera at_origin = view;
    at_origin.world_T_camera = Eigen::Isometry3d::Identity();
    const camera::ProjectedBox p = camera::projectBox(at_origin, box_in_camera, kNearPlane_m);
    if (!p.visible_in_front) return false;
    const camera::ImageBox& b = p.bbox_trunc;
    box_2d = {static_cast<float>(b(0)), static_cast<float>(b(1)), static_cast<float>(b(2)), static_cast<float>(b(3))};
    return box_2d.x_max > box_2d.x_min && box_2d.y_max > box_2d.y_min;
}

double insideCornerFraction(const camera::PinholeCamera& view, const geometry::Box3D& box_world) {
    const Eigen::Isometry3d camera_T_world = view.world_T_camera.inverse();
    int inside = 0;
    for (const auto& c : box_world.corners()) {
        const Eigen::Vector3d q = camera_T_world * c;
        if (q.z() >= kNearPlane_m && view.inImage(view.project(q))) ++inside;
    }
    return inside / 8.0;
}

camera::FloorPlanGrid cameraWalls(const mrpt::maps::COccupancyGridMap2D& floorplan, const std::vector<world::MapObject>& objects,
                                  const std::vector<std::string>& class_names, double self_margin_m) {
    camera::FloorPlanGrid walls(floorplan);
    const std::vector<char> class_occludes = camera::occludingClasses(class_names);
    std::vector<geometry::Box3D> furniture;
    for (const auto& o : objects)
        if (camera::occlusionOfClassId(class_occludes, o.class_id) != camera::kSeeThrough) furniture.push_back(o.box);
    walls.clearWallsUnder(furniture, self_margin_m);
    return walls;
}

std::vector<VisibleObject> SceneVisibility::visible(const camera::PinholeCamera& view, const std::vector<world::MapObject>& objects,
                                                    const std::vector<std::string>& class_names) {
    const VisibilityParams& p = m_params;
    const Eigen::Vector2d cam = view.world_T_camera.translation().head<2>();
    double global_max = p.default_max_range_m;
    for (double m : p.max_range_m) global_max = std::max(global_max, m);
    const std::vector<char> class_occludes = camera::occludingClasses(class_names);
    m_boxes.clear(), m_occludes.clear(), m_index.clear();
    for (std::size_t i = 0; i < objects.size(); ++i) {  // every box near enough to be seen or to hide one
        const auto& o = objects[i];
        if ((o.box.center.head<2>() - cam).norm() - 0.5 * o.box.size.head<2>().norm() > global_max) continue;
        m_boxes.push_back(o.box);
        m_occludes.push_back(camera::occlusionOfClassId(class_occludes, o.class_id));
        m_index.push_back(i);
    }
    camera::ZBufferParams z;
    z.downscale = p.render_downscale;
    z.near_plane_m = kNearPlane_m;
    z.wall_depth_margin_m = p.wall_depth_margin_m;
    z.max_distance_m = global_max;
    z.occludes = &m_occludes;
    m_renderer.render(view, m_boxes, &m_walls, z, m_views);

    const Eigen::Isometry3d camera_T_world = view.world_T_camera.inverse();
    std::vector<VisibleObject> out;
    for (std::size_t k = 0; k < m_boxes.size(); ++k) {
        const auto& o = objects[m_index[k]];
        const camera::BoxView& v = m_views[k];
        if ((camera_T_world * o.box.center).z() < kNearPlane_m || v.covered_px == 0) continue;  // centre behind, or no pixel
        double lo, hi;
        rangeOf(p, class_names.at(static_cast<std::size_t>(o.class_id)), lo, hi);
        const double range = (o.box.center.head<2>() - cam).norm();
        if (range < lo || range > hi) continue;
        const double inside = insideCornerFraction(view, o.box);
        if (inside < p.min_inside_fraction) continue;
        if (v.unwalled_px < p.min_unwalled_fraction * v.covered_px || v.unwalled_px == 0) continue;
        const double occluded = 1.0 - std::min(1.0, static_cast<double>(v.visible_px) / v.unwalled_px);
        if (occluded > p.max_occluded_fraction) continue;
        out.push_back({m_index[k], inside, occluded});
    }
    return out;
}

}  // namespace simp::sim
