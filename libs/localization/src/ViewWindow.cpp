#include <simp/camera/Occluders.h>
#include <simp/camera/PinholeCamera.h>
#include <simp/localization/ViewWindow.h>

#include <cmath>
#include <limits>
#include <utility>

namespace simp::localization {
namespace {

camera::PinholeCamera cameraOf(const simp::obs::CObservationObjects3D& obs, const mrpt::math::TPose2D& robot) {
    return camera::PinholeCamera::onRobot(robot, obs.cameraPose(),
                                          camera::imageIntrinsics(obs.intrinsics(), static_cast<int>(obs.imageWidth()),
                                                                  static_cast<int>(obs.imageHeight()),
                                                                  camera::defaultIntrinsics()));
}

}  // namespace

ViewWindow::ViewWindow(const ViewWindowParams& params, const mrpt::maps::COccupancyGridMap2D& floorplan)
    : m_params(params), m_walls(floorplan) {}

void ViewWindow::add(const maps::CObjectMap& map, const simp::obs::CObservationObjects3D::Ptr& obs,
                     const mrpt::poses::CPose2D& odometry_pose, double t_s) {
    if (!obs) return;
    const std::size_t classes = map.data().class_names.size();
    if (m_min_range_m.size() != classes) {
        m_min_range_m.assign(classes, std::numeric_limits<double>::infinity());
        m_max_range_m.assign(classes, 0.0);
    }
    const mrpt::poses::CPose3D& cam = obs->cameraPose();
    std::vector<Shown> shown;
    for (std::size_t k = 0; k < obs->size(); ++k) {
        const int c = map.usableClassOf(*obs, k);
        if (c < 0) continue;
        const Eigen::Vector3d& p = obs->boxInRobot(k).center;
        const double r = std::hypot(p.x() - cam.x(), p.y() - cam.y());
        m_min_range_m[c] = std::min(m_min_range_m[c], r);
        m_max_range_m[c] = std::max(m_max_range_m[c], r);
        shown.push_back({c, p.x(), p.y()});
    }
    m_frames.push_back({obs, odometry_pose, t_s, std::move(shown)});
    while (m_frames.size() > m_params.max_frames || (!m_frames.empty() && t_s - m_frames.front().t_s > m_params.max_age_s))
        m_frames.pop_front();
}

ViewWindow::Recall ViewWindow::recallAt(const maps::CObjectMap& map, const mrpt::poses::CPose2D& estimate,
                                        const mrpt::poses::CPose2D& odometry_now, double t_now_s) const {
    Recall out;
    const auto& objects = map.data().objects;
    const std::vector<char> class_occludes = camera::occludingClasses(map.data().class_names);
    const double seen_r2 = m_params.seen_radius_m * m_params.seen_radius_m;
    // Boxes farther than this from the camera can neither be expected nor hide an expected one.
    const double near_m = m_params.max_range_m + 2.0;
    camera::ZBufferParams zb;
    zb.occludes = &m_box_occludes;
    zb.max_distance_m = near_m;
    for (const auto& f : m_frames) {
        if (t_now_s - f.t_s > m_params.max_age_s) continue;
        const mrpt::poses::CPose2D robot = estimate + (f.odometry_pose - odometry_now);
        const camera::PinholeCamera view = cameraOf(*f.obs, robot.asTPose());
        const Eigen::Vector2d eye = view.world_T_camera.translation().head<2>();
        m_boxes.clear(), m_box_object.clear(), m_box_occludes.clear();
        for (std::size_t i = 0; i < objects.size(); ++i) {
            if ((objects[i].box.center.head<2>() - eye).norm() > near_m) continue;
            m_boxes.push_back(objects[i].box);
            m_box_object.push_back(i);
            m_box_occludes.push_back(camera::occlusionOfClassId(class_occludes, objects[i].class_id));
        }
        if (m_boxes.empty()) continue;
        m_renderer.render(view, m_boxes, &m_walls, zb, m_views);
        for (std::size_t b = 0; b < m_boxes.size(); ++b) {
            const auto& o = objects[m_box_object[b]];
            const int c = o.class_id;
            if (c < 0 || static_cast<std::size_t>(c) >= m_max_range_m.size() || m_min_range_m[c] > m_max_range_m[c])
                continue;  // a class the detector has not shown in this run
            const camera::BoxView& v = m_views[b];
            const double range = (o.box.center.head<2>() - eye).norm();
            if (range < m_min_range_m[c] || range > std::min(m_max_range_m[c], m_params.max_range_m) ||
                v.covered_px <= 0 || v.truncated_fraction > m_params.max_truncated_fraction ||
                v.occludedFraction() > m_params.max_occluded_fraction)
                continue;
            ++out.expected;
            bool seen = false;
            for (std::size_t k = 0; k < f.shown.size() && !seen; ++k) {
                if (f.shown[k].map_class != c) continue;
                double x = 0, y = 0;
                robot.composePoint(f.shown[k].x, f.shown[k].y, x, y);
                const double dx = x - o.box.center.x(), dy = y - o.box.center.y();
                seen = dx * dx + dy * dy <= seen_r2;
            }
            out.seen += seen;
        }
    }
    return out;
}

}  // namespace simp::localization
