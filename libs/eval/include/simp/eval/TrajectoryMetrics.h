#pragma once
/// \file TrajectoryMetrics.h
/// The paper's localization metrics ("Experimental Setup"): convergence, divergence,
/// success and ATE after convergence, for one planar estimate against ground truth.
///
/// Definitions (doc/evaluation.md):
///  - Only estimates whose time lies inside the ground-truth span [t_first, t_last] are
///    used; ground truth is interpolated at each estimate's time (simp::io::interpolatePose).
///  - Error of an estimate: translation |xy_est - xy_gt| (m) and rotation
///    |wrapToPi(phi_est - phi_gt)| (rad). An estimate is "within" when translation <=
///    max_trans_m and rotation <= max_rot_rad.
///  - Converged at the time of the first estimate that is within; convergence time =
///    that time - t_first (the start of the sequence).
///  - Each estimate holds until the next one (zero-order hold; the last holds 0 s). The
///    time spent outside after convergence is the sum of the hold times of the estimates
///    (from the converging one on) that are not within; the run diverged when that sum
///    exceeds (>) max_outside_s.
///  - Success = converged, convergence time <= convergence_fraction * duration, not diverged;
///    duration = t_last - t_first of the ground truth.
///  - ATE = RMSE of translation (m) and of rotation (rad) over the estimates from the
///    converging one on (those outside the bounds included).

#include <simp/io/Tum.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::eval {

/// Thresholds of the metrics; defaults are the paper's.
struct TrajMetricsParams {
    double max_trans_m = 0.3;                  ///< convergence radius (m)
    double max_rot_rad = 0.78539816339744831;  ///< convergence orientation bound (rad), pi/4
    double max_outside_s = 1.5;                ///< accumulated time outside the bounds that is a divergence (s)
    double convergence_fraction = 0.95;        ///< convergence must happen within this fraction of the duration
};

/// Error of one estimate against interpolated ground truth.
struct PoseErrorSample {
    double t_s = 0;        ///< estimate time (s)
    double trans_m = 0;    ///< planar translation error (m)
    double rot_rad = 0;    ///< absolute heading error (rad), in [0, pi]
    bool within = false;   ///< inside both convergence bounds
};

/// Result of evaluating one trajectory.
struct TrajMetrics {
    std::vector<PoseErrorSample> errors;        ///< per used estimate, time-ordered
    double start_s = 0;                         ///< first ground-truth time (s)
    double duration_s = 0;                      ///< ground-truth span (s)
    bool converged = false;
    std::optional<double> convergence_time_s;   ///< convergence instant - start_s (s)
    bool diverged = false;                      ///< accumulated time outside > max_outside_s after convergence
    std::optional<double> divergence_time_s;    ///< when the accumulated time first exceeded it, - start_s (s)
    double time_outside_s = 0;                  ///< accumulated time outside after convergence (s)
    bool success = false;
    std::optional<double> ate_trans_m;          ///< RMSE translation after convergence (m)
    std::optional<double> ate_rot_rad;          ///< RMSE rotation after convergence (rad)
    std::size_t n_estimates_used = 0;           ///< estimates inside the ground-truth span
    std::size_t n_estimates_ignored = 0;        ///< estimates outside it
};

/// Evaluates `estimate` against `ground_truth` (both time-ordered, as readTum returns).
/// \throw std::invalid_argument when the ground truth has fewer than 2 poses or a zero span,
///        when the estimate is empty, or when no estimate lies inside the ground-truth span.
TrajMetrics evaluateTrajectory(const std::vector<io::StampedPose2D>& ground_truth,
                               const std::vector<io::StampedPose2D>& estimate,
                               const TrajMetricsParams& params = {});

/// Ground truth and estimate as read from their TUM files.
struct TrajectoryFiles {
    std::string gt_path;                            ///< ground-truth TUM file
    std::string est_path;                           ///< estimate TUM file
    std::vector<io::StampedPose2D> ground_truth;    ///< time-ordered poses of gt_path
    std::vector<io::StampedPose2D> estimate;        ///< time-ordered poses of est_path
};

/// Reads both TUM files.
/// \throw std::invalid_argument naming the file when the ground truth has fewer than 2 poses or
///        the estimate none (and io::readTum's errors, which name the file and line).
TrajectoryFiles readTrajectoryFiles(const std::string& gt_path, const std::string& est_path);

/// evaluateTrajectory() on files read by readTrajectoryFiles(); its errors are prefixed with
/// "'<est_path>' vs '<gt_path>': ".
TrajMetrics evaluateTrajectory(const TrajectoryFiles& files, const TrajMetricsParams& params = {});

/// Reads both TUM files and evaluates; error messages name the offending file.
TrajMetrics evaluateTrajectoryFiles(const std::string& gt_path, const std::string& est_path,
                                    const TrajMetricsParams& params = {});

}  // namespace simp::eval
