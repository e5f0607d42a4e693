#pragma once
/// \file StepRecord.h
/// One row of O/steps.csv: the filter's state after a frame.

#include <mrpt/math/TPose2D.h>
#include <simp/localization/LocalizationState.h>

#include <Eigen/Core>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace simp::localization {

struct StepRecord {
    double t_s = 0;                  ///< frame time (s)
    mrpt::math::TPose2D estimate;    ///< reported pose (world; m, rad), the line of estimate.tum
    mrpt::math::TPose2D mean;        ///< weighted mean of all particles
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();  ///< weighted covariance of (x, y, phi) of all particles
    Eigen::Matrix3d cluster_cov = Eigen::Matrix3d::Zero();  ///< ... of the reported cluster: the estimate's uncertainty
    double cluster_weight = 1;       ///< weight fraction of the reported cluster, [0, 1]
    std::size_t particles = 0;       ///< particle count after the frame
    double ess = 0;                  ///< effective sample size (particles) after the update, before resampling
    std::size_t detections = 0;      ///< K of Eq. singw (0 when not updated)
    bool updated = false;            ///< the filter ran an update on this frame (motion trigger)
    std::size_t pruned = 0;          ///< particles redrawn off free space
    std::size_t injected = 0;        ///< particles replaced by sensor resetting or recovery
    LocalizationState state = LocalizationState::Global;  ///< after the frame
    double fit = 0;                  ///< fraction of the last detections the estimate explains (FitWindow)
    std::size_t fit_detections = 0;  ///< detections behind `fit`
    /// Window log-likelihood of the best distinct place minus the estimate's (nats; HypothesisSearch);
    /// NaN when not searched at this frame (written empty).
    double rival_advantage = std::numeric_limits<double>::quiet_NaN();
    /// Window log-likelihood of the best pose near the estimate minus the estimate's (nats) and its
    /// distance (m) (HypothesisSearch::climb); NaN when not computed (written empty).
    double local_gain = std::numeric_limits<double>::quiet_NaN();
    double local_offset_m = std::numeric_limits<double>::quiet_NaN();
    std::size_t challenger_particles = 0;  ///< particles of the challenger searching while `lost` (0: none)
    /// The challenger after the frame (when there is one): its estimate, state, the fit of its
    /// estimate and its lead over the current estimate on the fit window (nats; NaN until it is
    /// `localized`, when the two are compared). Written empty without a challenger.
    mrpt::math::TPose2D challenger_estimate;
    LocalizationState challenger_state = LocalizationState::Global;
    double challenger_fit = std::numeric_limits<double>::quiet_NaN();
    double challenger_lead = std::numeric_limits<double>::quiet_NaN();
    std::size_t unmapped_objects = 0;  ///< tracks DetectionNovelty holds for objects the map does not hold there
    /// When a challenger elsewhere was judged on the camera frames since `lost` at this frame
    /// (ViewWindow): the views of map objects they should have shown at its estimate, and how many
    /// they showed; -1 (written empty) otherwise.
    long challenger_views_expected = -1;
    long challenger_views_seen = -1;
    double seconds = 0;              ///< wall time spent on the frame (s)
};

/// The header line of steps.csv (no trailing newline).
std::string stepsCsvHeader();
/// One data line of steps.csv (with the newline).
std::string stepsCsvLine(const StepRecord& s);
/// Writes steps.csv; throws std::runtime_error naming the file on failure.
void writeStepsCsv(const std::string& path, const std::vector<StepRecord>& steps);

}  // namespace simp::localization
