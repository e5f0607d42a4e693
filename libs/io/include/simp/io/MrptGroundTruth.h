#pragma once
/// \file MrptGroundTruth.h
/// Ground truth in the format MRPT 2.5's pf-localization reads (`ground_truth_path_file` of
/// [LocalizationExperiment], mrpt::apps::MonteCarloLocalization_Base::prepareGT / getGroundTruth):
/// a numeric text matrix, '#' comment lines, one row `t x y phi` per pose (s, m, m, rad).
///
/// pf-localization decides that the first column is a time stamp (and not a rawlog entry index)
/// only when the first two rows' values are not whole numbers; a whole-second time stamp is
/// therefore written 1 us later (the interpolation it feeds tolerates 200 ms gaps).
/// pf-localization never advances its rawlog-entry counter in MRPT 2.5.8, so the time-stamped
/// form is the only one it can use.

#include <simp/io/Tum.h>

#include <string>
#include <vector>

namespace simp::io {

/// Time written for t_s: t_s itself, or t_s + 1e-6 when t_s is a whole number (see above).
double mrptGroundTruthTime(double t_s);

/// Writes `poses` as `t x y phi` rows (9 decimals) after a '#' header; creates parent folders.
/// \throw std::runtime_error naming the file when it cannot be written.
void writeMrptGroundTruth(const std::string& path, const std::vector<StampedPose2D>& poses);

}  // namespace simp::io
