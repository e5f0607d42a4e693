#pragma once
/// \file StepRecord.h
/// One row of O/steps.csv: the filter's state after a frame.

#include <mrpt/math/TPose2D.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace simp::localization {

struct StepRecord {
    double t_s = 0;                  ///< frame time (s)
    mrpt::math::TPose2D estimate;    ///< reported pose (world; m, rad), the line of estimate.tum
    mrpt::math::TPose2D mean;        ///< weighted mean of all particles
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();  ///< weighted covariance of (x, y, phi)
    double cluster_weight = 1;       ///< weight fraction of the reported cluster, [0, 1]
    std::size_t particles = 0;       ///< particle count after the frame
    double ess = 0;                  ///< effective sample size (particles) after the update, before resampling
    std::size_t detections = 0;      ///< K of Eq. singw (0 when not updated)
    bool updated = false;            ///< the filter ran an update on this frame (motion trigger)
    std::size_t pruned = 0;          ///< particles redrawn off free space
    double seconds = 0;              ///< wall time spent on the frame (s)
};

/// The header line of steps.csv (no trailing newline).
std::string stepsCsvHeader();
/// Writes steps.csv; throws std::runtime_error naming the file on failure.
void writeStepsCsv(const std::string& path, const std::vector<StepRecord>& steps);

}  // namespace simp::localization
