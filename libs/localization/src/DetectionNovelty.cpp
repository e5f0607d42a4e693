#include <simp/localization/DetectionNovelty.h>

#include <algorithm>
#include <cmath>

namespace simp::localization {
namespace {

Eigen::Vector2d centreInOdometry(const simp::obs::CObservationObjects3D& obs, std::size_t k,
                                 const mrpt::poses::CPose2D& odometry_pose) {
    const Eigen::Vector3d& p = obs.boxInRobot(k).center;
    Eigen::Vector2d out;
    odometry_pose.composePoint(p.x(), p.y(), out.x(), out.y());
    return out;
}

}  // namespace

DetectionNovelty::Track* DetectionNovelty::nearest(const std::string& class_name, const Eigen::Vector2d& centre) {
    const double r2 = m_params.track_radius_m * m_params.track_radius_m;
    const auto closest = [&](bool unmapped_only) {
        Track* best = nullptr;
        double best_d2 = r2;
        for (auto& tr : m_tracks) {
            if (tr.class_name != class_name || (unmapped_only && !tr.unmapped)) continue;
            double d2 = (tr.centre_odom_m - centre).squaredNorm();
            if (unmapped_only) d2 = std::min(d2, (tr.sum_odom_m / static_cast<double>(tr.detected) - centre).squaredNorm());
            if (d2 <= best_d2) best = &tr, best_d2 = d2;
        }
        return best;
    };
    // An unmapped object first: its detections scatter by the detector's noise (along a cabinet,
    // +-0.7 m), and one that went to a track of its own would be scored again.
    if (m_params.unmapped_min_detections > 0)
        if (Track* tr = closest(true)) return tr;
    return closest(false);
}

std::vector<double> DetectionNovelty::weigh(const simp::obs::CObservationObjects3D& obs,
                                            const mrpt::poses::CPose2D& odometry_pose, double t_s,
                                            std::vector<TrackedDetection>* tracked) {
    std::vector<double> weights(obs.size(), 1.0);
    if (tracked) tracked->clear();
    const bool temper = m_params.decorrelation_distance_m > 0.0;
    if (!temper && m_params.unmapped_min_detections == 0) return weights;
    if (tracked) tracked->assign(obs.size(), TrackedDetection{});
    m_tracks.erase(std::remove_if(m_tracks.begin(), m_tracks.end(),
                                  [&](const Track& tr) { return t_s - tr.last_t_s > m_params.track_timeout_s; }),
                   m_tracks.end());
    const Eigen::Vector2d viewpoint(odometry_pose.x(), odometry_pose.y());
    const mrpt::poses::CPose3D camera = mrpt::poses::CPose3D(odometry_pose) + obs.cameraPose();
    for (std::size_t k = 0; k < obs.size(); ++k) {
        const Eigen::Vector2d centre = centreInOdometry(obs, k, odometry_pose);
        const std::string& name = obs.classNameOf(obs.detections()[k]);
        Track* best = nearest(name, centre);
        if (best == nullptr) {
            m_tracks.push_back({++m_last_id, name, centre, viewpoint, camera, t_s, centre, 1});
            if (tracked) (*tracked)[k].track = m_last_id;
            continue;
        }
        double moved = (viewpoint - best->viewpoint_odom_m).norm();
        if (m_params.view_change_weight > 0.0) {
            // The object's centre seen from the last detection's camera and from this one.
            const mrpt::math::TPoint3D c(centre.x(), centre.y(), obs.boxInRobot(k).center.z());
            const double shift = (camera.inverseComposePoint(c) - best->camera_odom.inverseComposePoint(c)).norm();
            moved = std::max(moved, m_params.view_change_weight * shift);
        }
        const double temper_weight = temper ? std::clamp(moved / m_params.decorrelation_distance_m, m_params.min_weight, 1.0) : 1.0;
        weights[k] = best->unmapped ? 0.0 : temper_weight;
        if (tracked) (*tracked)[k] = {best->id, temper_weight};
        best->centre_odom_m = centre;
        best->sum_odom_m += centre;
        ++best->detected;
        best->viewpoint_odom_m = viewpoint;
        best->camera_odom = camera;
        best->last_t_s = t_s;
    }
    return weights;
}

void DetectionNovelty::judge(const simp::obs::CObservationObjects3D& obs, std::size_t k,
                             const mrpt::poses::CPose2D& odometry_pose, bool explained, double t_s) {
    if (m_params.unmapped_min_detections == 0 || k >= obs.size()) return;
    Track* tr = nearest(obs.classNameOf(obs.detections()[k]), centreInOdometry(obs, k, odometry_pose));
    if (tr == nullptr || tr->unmapped) return;
    if (tr->judged == 0) tr->first_judged_t_s = t_s;
    ++tr->judged;
    if (explained) ++tr->explained;
    tr->unmapped = tr->judged >= m_params.unmapped_min_detections &&
                   t_s - tr->first_judged_t_s >= m_params.unmapped_min_span_s &&
                   static_cast<double>(tr->explained) <= m_params.unmapped_max_explained * static_cast<double>(tr->judged);
}

std::size_t DetectionNovelty::unmappedCount() const {
    return static_cast<std::size_t>(std::count_if(m_tracks.begin(), m_tracks.end(), [](const Track& t) { return t.unmapped; }));
}

void DetectionNovelty::clearUnmapped() {
    for (auto& t : m_tracks) t.unmapped = false, t.judged = 0, t.explained = 0;
}

}  // namespace simp::localization
