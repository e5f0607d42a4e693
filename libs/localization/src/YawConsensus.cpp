#include <simp/localization/YawConsensus.h>

#include <simp/geometry/Box3D.h>

#include <algorithm>
#include <cmath>

namespace simp::localization {

std::vector<double> YawConsensus::weigh(const ManhattanHeading& heading, const simp::obs::CObservationObjects3D& obs,
                                        const std::vector<TrackedDetection>& tracked,
                                        const mrpt::poses::CPose2D& odometry_pose, double t_s) {
    const auto& o = heading.options();
    std::vector<double> weights(obs.size(), 0.0);
    if (tracked.size() != obs.size()) return weights;  // no tracks (DetectionNovelty off): no vote
    m_tracks.erase(std::remove_if(m_tracks.begin(), m_tracks.end(),
                                  [&](const TrackYaw& tr) { return t_s - tr.last_t_s > o.consensus_window_s; }),
                   m_tracks.end());
    // Indices, not pointers: later insertions may move the tracks.
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::vector<std::size_t> of(obs.size(), kNone);
    for (std::size_t k = 0; k < obs.size(); ++k) {
        if (tracked[k].track == 0 || heading.squareClassOf(obs, k) < 0) continue;
        const double yaw4 = 4.0 * (geometry::yawOf(obs.boxInRobot(k)) + odometry_pose.phi());
        auto it = std::find_if(m_tracks.begin(), m_tracks.end(), [&](const TrackYaw& tr) { return tr.track == tracked[k].track; });
        if (it == m_tracks.end()) it = m_tracks.insert(m_tracks.end(), TrackYaw{tracked[k].track});
        it->sum_cos4 += std::cos(yaw4);
        it->sum_sin4 += std::sin(yaw4);
        ++it->detections;
        it->last_t_s = t_s;
        of[k] = static_cast<std::size_t>(it - m_tracks.begin());
    }
    for (std::size_t k = 0; k < obs.size(); ++k) {
        if (of[k] == kNone) continue;
        const TrackYaw& own = m_tracks[of[k]];
        if (own.detections < o.consensus_min_detections) continue;
        // The other tracks vote with one unit vector each: an object seen often counts once.
        double c = 0.0, s = 0.0;
        std::size_t others = 0;
        for (const auto& tr : m_tracks) {
            if (&tr == &own || tr.detections < o.consensus_min_detections) continue;
            const double a = std::atan2(tr.sum_sin4, tr.sum_cos4);
            c += std::cos(a), s += std::sin(a), ++others;
        }
        if (others < o.consensus_min_tracks || others == 0) continue;
        const double mine = std::atan2(own.sum_sin4, own.sum_cos4);
        const double diff4 = std::remainder(mine - std::atan2(s, c), 2.0 * M_PI);  // 4 x the yaw difference
        if (std::abs(diff4) <= 4.0 * o.consensus_tolerance_rad) weights[k] = tracked[k].temper_weight;
    }
    return weights;
}

}  // namespace simp::localization
