#include <simp/localization/DetectionNovelty.h>

#include <algorithm>

namespace simp::localization {

std::vector<double> DetectionNovelty::weigh(const simp::obs::CObservationObjects3D& obs,
                                            const mrpt::poses::CPose2D& odometry_pose, double t_s) {
    std::vector<double> weights(obs.size(), 1.0);
    if (!(m_params.decorrelation_distance_m > 0.0)) return weights;
    m_tracks.erase(std::remove_if(m_tracks.begin(), m_tracks.end(),
                                  [&](const Track& tr) { return t_s - tr.last_t_s > m_params.track_timeout_s; }),
                   m_tracks.end());
    const Eigen::Vector2d viewpoint(odometry_pose.x(), odometry_pose.y());
    const double c = std::cos(odometry_pose.phi()), s = std::sin(odometry_pose.phi());
    const double r2 = m_params.track_radius_m * m_params.track_radius_m;
    for (std::size_t k = 0; k < obs.size(); ++k) {
        const Eigen::Vector3d& p = obs.boxInRobot(k).center;
        const Eigen::Vector2d centre(viewpoint.x() + c * p.x() - s * p.y(), viewpoint.y() + s * p.x() + c * p.y());
        const std::string& name = obs.classNameOf(obs.detections()[k]);
        Track* best = nullptr;
        double best_d2 = r2;
        for (auto& tr : m_tracks) {
            const double d2 = (tr.centre_odom_m - centre).squaredNorm();
            if (d2 <= best_d2 && tr.class_name == name) best = &tr, best_d2 = d2;
        }
        if (best == nullptr) {
            m_tracks.push_back({name, centre, viewpoint, t_s});
            continue;
        }
        const double moved = (viewpoint - best->viewpoint_odom_m).norm();
        weights[k] = std::clamp(moved / m_params.decorrelation_distance_m, m_params.min_weight, 1.0);
        best->centre_odom_m = centre;
        best->viewpoint_odom_m = viewpoint;
        best->last_t_s = t_s;
    }
    return weights;
}

}  // namespace simp::localization
