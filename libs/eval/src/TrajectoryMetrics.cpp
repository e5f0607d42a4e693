#include <mrpt/math/wrap2pi.h>
#include <simp/eval/TrajectoryMetrics.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace simp::eval {

TrajMetrics evaluateTrajectory(const std::vector<io::StampedPose2D>& ground_truth,
                               const std::vector<io::StampedPose2D>& estimate, const TrajMetricsParams& params) {
    if (ground_truth.size() < 2)
        throw std::invalid_argument("ground truth has " + std::to_string(ground_truth.size()) +
                                    " poses; at least 2 are needed to define the sequence duration");
    TrajMetrics m;
    m.start_s = ground_truth.front().t_s;
    m.duration_s = ground_truth.back().t_s - m.start_s;
    if (!(m.duration_s > 0)) throw std::invalid_argument("ground truth spans zero time");
    // A localizer that never claimed a pose (simp-localize writes estimate.tum from its first
    // localized step) never converged: not an error, a failed run.
    if (estimate.empty()) return m;

    // Errors of the estimates inside the ground-truth span (ground truth interpolated).
    for (const auto& e : estimate) {
        mrpt::math::TPose2D gt;
        if (!io::interpolatePose(ground_truth, e.t_s, gt)) {
            ++m.n_estimates_ignored;
            continue;
        }
        PoseErrorSample s;
        s.t_s = e.t_s;
        s.trans_m = std::hypot(e.pose.x - gt.x, e.pose.y - gt.y);
        s.rot_rad = std::abs(mrpt::math::wrapToPi(e.pose.phi - gt.phi));
        s.within = s.trans_m <= params.max_trans_m && s.rot_rad <= params.max_rot_rad;
        m.errors.push_back(s);
    }
    m.n_estimates_used = m.errors.size();
    if (m.errors.empty())
        throw std::invalid_argument("no estimate lies inside the ground-truth time span [" +
                                    std::to_string(ground_truth.front().t_s) + ", " +
                                    std::to_string(ground_truth.back().t_s) + "] s (" +
                                    std::to_string(m.n_estimates_ignored) + " estimates ignored)");

    // Convergence: the first estimate within both bounds.
    std::size_t first = 0;
    while (first < m.errors.size() && !m.errors[first].within) ++first;
    if (first == m.errors.size()) return m;  // never converged: success false, metrics null
    m.converged = true;
    m.convergence_time_s = m.errors[first].t_s - m.start_s;

    // Divergence: accumulated (zero-order hold) time outside the bounds after convergence.
    double sum_t2 = 0, sum_r2 = 0;
    for (std::size_t i = first; i < m.errors.size(); ++i) {
        const auto& s = m.errors[i];
        sum_t2 += s.trans_m * s.trans_m;
        sum_r2 += s.rot_rad * s.rot_rad;
        if (s.within) continue;
        const double hold_s = (i + 1 < m.errors.size()) ? m.errors[i + 1].t_s - s.t_s : 0.0;
        m.time_outside_s += hold_s;
        if (!m.diverged && m.time_outside_s > params.max_outside_s) {
            m.diverged = true;
            // the instant inside this hold when the budget ran out
            m.divergence_time_s = s.t_s + hold_s - (m.time_outside_s - params.max_outside_s) - m.start_s;
        }
    }
    const double n = static_cast<double>(m.errors.size() - first);
    m.ate_trans_m = std::sqrt(sum_t2 / n);
    m.ate_rot_rad = std::sqrt(sum_r2 / n);
    m.success = *m.convergence_time_s <= params.convergence_fraction * m.duration_s && !m.diverged;
    return m;
}

TrajectoryFiles readTrajectoryFiles(const std::string& gt_path, const std::string& est_path) {
    TrajectoryFiles f{gt_path, est_path, io::readTum(gt_path), io::readTum(est_path)};
    if (f.ground_truth.size() < 2)
        throw std::invalid_argument("ground-truth file '" + gt_path + "': " + std::to_string(f.ground_truth.size()) +
                                    " poses, at least 2 are needed");
    return f;
}

TrajMetrics evaluateTrajectory(const TrajectoryFiles& files, const TrajMetricsParams& params) {
    try {
        return evaluateTrajectory(files.ground_truth, files.estimate, params);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("'" + files.est_path + "' vs '" + files.gt_path + "': " + e.what());
    }
}

TrajMetrics evaluateTrajectoryFiles(const std::string& gt_path, const std::string& est_path,
                                    const TrajMetricsParams& params) {
    return evaluateTrajectory(readTrajectoryFiles(gt_path, est_path), params);
}

}  // namespace simp::eval
