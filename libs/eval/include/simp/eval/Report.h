#pragma once
/// \file Report.h
/// Text, Markdown and JSON renderings of the metrics. The JSON objects have exactly the
/// keys of the command-line contract (doc/evaluation.md, shared docs/interfaces.md).

#include <simp/eval/MapMetrics.h>
#include <simp/eval/TrajectoryMetrics.h>

#include <nlohmann/json.hpp>
#include <string>

namespace simp::eval {

/// `{"success", "converged", "convergence_time_s", "ate_trans_m", "ate_rot_rad", "duration_s"}`;
/// the optional values are null when not defined (never converged).
nlohmann::json toJson(const TrajMetrics& m);

/// Human-readable multi-line summary of a trajectory evaluation.
std::string trajSummaryText(const TrajMetrics& m, const TrajMetricsParams& params);

/// `{"iou", "precision", "recall", "per_class": {"<class>": {"iou", "precision", "recall"}}}`.
nlohmann::json toJson(const MapMetrics& m);

/// The paper's Table I layout: classes as columns (sorted by name), AVG last; rows IoU, Pr,
/// Rc, then the extra rows IoU3D and the object counts GT / pred / matched.
std::string mapMarkdownTable(const MapMetrics& m);

/// Fixed-point number with `decimals` digits (C locale).
std::string fmt(double value, int decimals);

}  // namespace simp::eval
