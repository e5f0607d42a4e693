#include <simp/eval/KidnapMetrics.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace simp::eval {

KidnapMetrics evaluateKidnap(const std::vector<io::StampedPose2D>& ground_truth, const std::vector<StateSample>& steps,
                             const std::vector<io::StampedPose2D>& estimate, double t_kidnap_s,
                             const KidnapParams& params) {
    if (ground_truth.size() < 2 || !(ground_truth.front().t_s <= t_kidnap_s && t_kidnap_s < ground_truth.back().t_s))
        throw std::invalid_argument("evaluateKidnap: the ground truth does not span the kidnap time " +
                                    std::to_string(t_kidnap_s) + " s");
    KidnapMetrics m;
    for (const auto& s : steps) {
        if (s.t_s < t_kidnap_s) continue;
        mrpt::math::TPose2D truth;
        if (!io::interpolatePose(ground_truth, s.t_s, truth)) continue;
        const bool within = std::hypot(s.estimate.x - truth.x, s.estimate.y - truth.y) <= params.traj.max_trans_m &&
                            std::abs(mrpt::math::wrapToPi(s.estimate.phi - truth.phi)) <= params.traj.max_rot_rad;
        if (!m.lost_after_s && s.state != StateSample::State::Localized) m.lost_after_s = s.t_s - t_kidnap_s;
        if (m.lost_after_s && !m.relocalized_after_s && s.state == StateSample::State::Localized && within) {
            m.relocalized_after_s = s.t_s - t_kidnap_s;
            break;
        }
    }
    // The part from the teleport on: a new global localization.
    std::vector<io::StampedPose2D> gt_after, est_after;
    for (const auto& p : ground_truth)
        if (p.t_s >= t_kidnap_s) gt_after.push_back(p);
    for (const auto& p : estimate)
        if (p.t_s >= t_kidnap_s) est_after.push_back(p);
    if (gt_after.size() >= 2 && !est_after.empty() && est_after.front().t_s <= gt_after.back().t_s)
        m.after = evaluateTrajectory(gt_after, est_after, params.traj);
    m.success = m.lost_after_s && *m.lost_after_s <= params.lost_within_s && m.relocalized_after_s &&
                *m.relocalized_after_s <= params.relocalized_within_s && m.after && m.after->success;
    return m;
}

}  // namespace simp::eval
