#include <simp/localization/LocalizationState.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace simp::localization {
namespace {

/// Two detections (class, centre in the odometry frame) within sqrt(r2) of each other, of one class.
bool sameObject(int class_a, double xa, double ya, int class_b, double xb, double yb, double r2) {
    return class_a == class_b && (xa - xb) * (xa - xb) + (ya - yb) * (ya - yb) <= r2;
}

}  // namespace

std::string toString(LocalizationState s) {
    switch (s) {
        case LocalizationState::Global: return "global";
        case LocalizationState::Localized: return "localized";
        case LocalizationState::Lost: return "lost";
    }
    return "?";
}

void FitWindow::add(const maps::CObjectMap& map, const simp::obs::CObservationObjects3D::Ptr& obs,
                    const mrpt::poses::CPose2D& odometry_pose, double t_s, const std::vector<double>* weights) {
    for (std::size_t k = 0; k < obs->size(); ++k) {
        const int cls = map.usableClassOf(*obs, k);
        if (cls < 0 || (weights && k < weights->size() && (*weights)[k] == 0.0)) continue;
        const auto& c = obs->boxInRobot(k).center;
        double x = 0, y = 0;  // the centre in the odometry frame
        odometry_pose.composePoint(c.x(), c.y(), x, y);
        m_items.push_back({obs, k, odometry_pose, t_s, cls, x, y});
        if (m_items.size() > m_params.fit_window) m_items.pop_front();
    }
}

std::vector<FitWindow::Judged> FitWindow::judgeAt(const maps::CObjectMap& map, const mrpt::poses::CPose2D& estimate,
                                                  const mrpt::poses::CPose2D& odometry_now, double t_s,
                                                  double tolerance_m, double tolerance_rad) const {
    std::vector<Judged> out;
    const double log_explained = logExplained(map);
    for (auto it = m_items.rbegin(); it != m_items.rend() && it->t_s == t_s; ++it) {
        const auto explained = explainedNear(map, *it, estimate, odometry_now, tolerance_m, tolerance_rad, log_explained);
        if (!explained) continue;
        out.push_back({it->obs.get(), it->k, it->odometry_pose, *explained});
    }
    return out;
}

std::vector<FitWindow::Placed> FitWindow::placed() const {
    std::vector<Placed> out;
    out.reserve(m_items.size());
    for (const auto& it : m_items) out.push_back({it.map_class, it.odo_x, it.odo_y});
    return out;
}

std::optional<double> FitWindow::logLikelihoodAt(const maps::CObjectMap& map, const Item& it,
                                                 const mrpt::poses::CPose2D& estimate,
                                                 const mrpt::poses::CPose2D& odometry_now) {
    const mrpt::poses::CPose2D world_T_frame = estimate + (it.odometry_pose - odometry_now);
    return map.detectionLogLikelihood(*it.obs, it.k, world_T_frame.asTPose());
}

std::optional<bool> FitWindow::explainedNear(const maps::CObjectMap& map, const Item& it,
                                             const mrpt::poses::CPose2D& estimate,
                                             const mrpt::poses::CPose2D& odometry_now, double tolerance_m,
                                             double tolerance_rad, double log_explained) {
    const auto model = map.sensorModel();
    // Prepared once, scored at up to 27 poses (as scorePoses() does for the whole window).
    const auto prepared = model->prepare(it.map_class, it.obs->boxInRobot(it.k), it.obs->footprintInRobot(it.k));
    if (!prepared) return std::nullopt;
    const mrpt::poses::CPose2D rel = it.odometry_pose - odometry_now;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int h = -1; h <= 1; ++h) {
                const mrpt::poses::CPose2D pose(estimate.x() + i * tolerance_m, estimate.y() + j * tolerance_m,
                                                estimate.phi() + h * tolerance_rad);
                if (model->logLikelihood(*prepared, (pose + rel).asTPose()) >= log_explained) return true;
            }
    return false;
}

double FitWindow::logExplained(const maps::CObjectMap& map) const {
    return std::log(m_params.explained_ratio * map.likelihoodOptions.eta);
}

FitWindow::Fit FitWindow::evaluate(const maps::CObjectMap& map, const mrpt::poses::CPose2D& estimate,
                                   const mrpt::poses::CPose2D& odometry_now, double t_now_s) {
    while (!m_items.empty() && t_now_s - m_items.front().t_s > m_params.fit_max_age_s) m_items.pop_front();
    const double log_explained = logExplained(map);
    Fit fit;
    // Newest first. With object_radius_m > 0 a detection joins the (newest) object of its class
    // within the radius, and an object is explained when any of its detections is.
    struct Object {
        int map_class;
        double x, y;
        bool explained;
        bool near;  ///< explained within the lost test's tolerance (checked for the recent ones only)
    };
    const bool tolerant = m_params.lost_tolerance_m > 0 || m_params.lost_tolerance_rad > 0;
    std::vector<Object> objects;
    const double r2 = m_params.object_radius_m * m_params.object_radius_m;
    for (auto it = m_items.rbegin(); it != m_items.rend(); ++it) {
        const auto log_p = logLikelihoodAt(map, *it, estimate, odometry_now);
        if (!log_p) continue;
        const bool ok = *log_p >= log_explained;
        // Only detections that may enter the lost test's window pay for the grid.
        const bool near = !ok && tolerant && objects.size() <= m_params.lost_window &&
                          explainedNear(map, *it, estimate, odometry_now, m_params.lost_tolerance_m,
                                        m_params.lost_tolerance_rad, log_explained)
                                  .value_or(false);
        Object* same = nullptr;
        if (m_params.object_radius_m > 0)
            for (auto& o : objects)
                if (sameObject(o.map_class, o.x, o.y, it->map_class, it->odo_x, it->odo_y, r2)) {
                    same = &o;
                    break;
                }
        if (same)
            same->explained = same->explained || ok, same->near = same->near || near;
        else
            objects.push_back({it->map_class, it->odo_x, it->odo_y, ok, near});
    }
    std::size_t explained = 0, recent_explained = 0;
    for (const auto& o : objects) {
        ++fit.scored;
        explained += o.explained;
        if (fit.recent_scored < m_params.lost_window) ++fit.recent_scored, recent_explained += o.explained || o.near;
    }
    if (fit.scored > 0) fit.fraction = static_cast<double>(explained) / static_cast<double>(fit.scored);
    if (fit.recent_scored > 0)
        fit.recent_fraction = static_cast<double>(recent_explained) / static_cast<double>(fit.recent_scored);
    return fit;
}

std::size_t FitWindow::explainedObjects(const maps::CObjectMap& map, const mrpt::poses::CPose2D& estimate,
                                        const mrpt::poses::CPose2D& odometry_now, double radius_m) const {
    const double log_explained = logExplained(map), r2 = radius_m * radius_m;
    std::vector<Placed> objects;  // one explained detection per object
    for (const auto& it : m_items) {
        const auto log_p = logLikelihoodAt(map, it, estimate, odometry_now);
        if (!log_p || *log_p < log_explained) continue;
        const bool seen = std::any_of(objects.begin(), objects.end(), [&](const Placed& o) {
            return sameObject(o.map_class, o.x, o.y, it.map_class, it.odo_x, it.odo_y, r2);
        });
        if (!seen) objects.push_back({it.map_class, it.odo_x, it.odo_y});
    }
    return objects.size();
}

void FitWindow::scorePoses(const maps::CObjectMap& map, const std::vector<mrpt::math::TPose2D>& poses,
                           const mrpt::poses::CPose2D& odometry_now, std::vector<double>& log_lik) const {
    log_lik.assign(poses.size(), 0.0);
    if (poses.empty() || m_items.empty()) return;
    const auto model = map.sensorModel();
    // CPose2D caches its cos/sin: built once, each pose pays one sincos for all the window's items.
    const std::vector<mrpt::poses::CPose2D> now(poses.begin(), poses.end());
    std::vector<mrpt::math::TPose2D> item_poses(poses.size());
    for (const auto& it : m_items) {
        const int cls = map.usableClassOf(*it.obs, it.k);
        if (cls < 0) continue;
        const auto prepared = model->prepare(cls, it.obs->boxInRobot(it.k), it.obs->footprintInRobot(it.k));
        if (!prepared) continue;
        // The frame's robot pose for a robot at p now: p (+) (odometry_now^-1 (+) its odometry pose).
        const mrpt::poses::CPose2D rel = it.odometry_pose - odometry_now;
        for (std::size_t i = 0; i < poses.size(); ++i)
            item_poses[i] = (now[i] + rel).asTPose();
        model->accumulateLogLikelihoods(&*prepared, 1, item_poses.data(), item_poses.size(), log_lik.data());
    }
}

LocalizationState StateMonitor::update(double cluster_weight, double cluster_std_m, const FitWindow::Fit& fit,
                                       bool had_detections) {
    const bool fit_known = fit.scored >= m_params.fit_min_detections;
    if (m_state == LocalizationState::Localized) {
        const bool recent_known = fit.recent_scored >= m_params.lost_window;
        const bool rival_wins = fit.rival_advantage >= m_params.rival_lost_margin;  // false for NaN
        if ((recent_known && fit.recent_fraction <= m_params.lost_max_fit) || cluster_weight < m_params.lost_min_weight ||
            rival_wins) {
            m_state = LocalizationState::Lost;
            m_good_updates = 0;
        } else if (betterPoseNearby(fit, m_params.local_margin)) {
            m_state = LocalizationState::Global;
            m_good_updates = 0;
        }
        return m_state;
    }
    if (!had_detections) return m_state;  // nothing new to decide on
    const bool ambiguous = fit.rival_advantage > -m_params.rival_margin;  // false for NaN (not searched)
    const bool good = fit_known && !ambiguous && !betterPoseNearby(fit, m_params.local_margin) &&
                      !betterPoseApart(fit, m_params.local_entry_margin, m_params.local_entry_min_offset_m) && fit.fraction >= m_params.localized_min_fit &&
                      cluster_weight >= m_params.localized_min_weight && cluster_std_m <= m_params.localized_max_std_m;
    m_good_updates = good ? m_good_updates + 1 : 0;
    if (m_good_updates >= m_params.localized_min_updates) m_state = LocalizationState::Localized;
    return m_state;
}

}  // namespace simp::localization
