#pragma once
/// \file Plots.h
/// PNG figures of the evaluation (OpenCV): trajectories over the floor plan with the error
/// over time, the object map over the floor plan, and a map evaluation's matches.

#include <simp/eval/MapMetrics.h>
#include <simp/eval/TrajectoryMetrics.h>
#include <simp/world/World.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace simp::eval {

/// Top: ground truth (green) and estimate (orange dots before convergence, red line after)
/// over the floor plan of `world` (a blank canvas when null), convergence marked. Bottom:
/// translation (m) and rotation (rad) error over time since the sequence start, the
/// bounds dashed, the convergence (blue) and divergence (red) instants as vertical lines.
cv::Mat3b drawTrajectoryFigure(const std::vector<io::StampedPose2D>& ground_truth,
                               const std::vector<io::StampedPose2D>& estimate, const TrajMetrics& metrics,
                               const TrajMetricsParams& params, const world::World* world);

/// The error-over-time panel alone (width x height px).
cv::Mat3b drawErrorPlot(const TrajMetrics& metrics, const TrajMetricsParams& params, int width, int height);

/// The object map over the floor plan: footprints coloured by class, legend of the classes.
cv::Mat3b drawObjectMap(const world::World& world);

/// A map evaluation: matched ground-truth/map objects green, missed ground-truth objects
/// blue, false map objects red, over the ground truth's floor plan.
cv::Mat3b drawMapEvaluation(const world::World& ground_truth, const world::World& map, const MapMetrics& metrics);

}  // namespace simp::eval
