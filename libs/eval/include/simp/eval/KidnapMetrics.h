#pragma once
/// \file KidnapMetrics.h
/// The kidnapped-robot metrics of the issue "Localization that holds" (doc/evaluation.md "Kidnapped
/// robot"): how soon the filter says it is lost after the teleport, how soon it says `localized`
/// again at the right place, and the estimate after the teleport evaluated as a new global
/// localization with the paper's metrics (evaluateTrajectory on the part from the teleport on).
/// tests/battery/analyze_runs.py computes the two times the same way.

#include <simp/eval/TrajectoryMetrics.h>
#include <simp/io/Tum.h>

#include <optional>
#include <vector>

namespace simp::eval {

/// One filter step: its time, its state and the reported pose.
struct StateSample {
    enum class State { Global, Localized, Lost };
    double t_s = 0;
    State state = State::Global;
    mrpt::math::TPose2D estimate;
};

struct KidnapParams {
    double lost_within_s = 5.0;          ///< `lost` (or `global`) this soon after the teleport (s)
    double relocalized_within_s = 20.0;  ///< `localized` within the bounds this soon after the teleport (s)
    TrajMetricsParams traj;              ///< the bounds and the metrics of the part after the teleport
};

struct KidnapMetrics {
    std::optional<double> lost_after_s;         ///< first step at/after the teleport not `localized`, - t_kidnap (s)
    std::optional<double> relocalized_after_s;  ///< first `localized` step after that within the bounds, - t_kidnap (s)
    std::optional<TrajMetrics> after;           ///< the estimate from the teleport on (none: no estimate there)
    /// lost within lost_within_s, relocalized within relocalized_within_s, and `after` a success
    bool success = false;
};

/// \throw std::invalid_argument when the ground truth does not span t_kidnap_s.
KidnapMetrics evaluateKidnap(const std::vector<io::StampedPose2D>& ground_truth, const std::vector<StateSample>& steps,
                             const std::vector<io::StampedPose2D>& estimate, double t_kidnap_s,
                             const KidnapParams& params = {});

}  // namespace simp::eval
