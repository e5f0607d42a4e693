#pragma once
/// \file Plots.h
/// PNG figures of the evaluation (OpenCV): trajectories over the floor plan with the error
/// over time, the object map over the floor plan, and a map evaluation's matches.

#include <simp/eval/MapLayers.h>
#include <simp/eval/MapMetrics.h>
#include <simp/eval/TrajectoryMetrics.h>
#include <simp/world/ChangesFile.h>
#include <simp/world/World.h>

#include <opencv2/core.hpp>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace simp::eval {

/// Top: ground truth (green) and estimate (orange dots before convergence, red line after)
/// over the floor plan of `world` (a blank canvas when null), convergence marked, a scale bar, a legend. Bottom:
/// translation (m) and rotation (rad) error over time since the sequence start, the
/// bounds dashed, the convergence (blue) and divergence (red) instants as vertical lines.
cv::Mat3b drawTrajectoryFigure(const std::vector<io::StampedPose2D>& ground_truth,
                               const std::vector<io::StampedPose2D>& estimate, const TrajMetrics& metrics,
                               const TrajMetricsParams& params, const world::World* world);

/// A run over the floor plan, without metrics: object footprints in their class colour, the
/// final particles (blue dots), the ground truth (green) when given, the estimate (red; start
/// o, end with its heading), a scale bar on the map and a legend (the layers drawn, then the
/// classes present) in a side panel.
cv::Mat3b drawTrajectoryMap(const MapLayers& layers);

/// The error-over-time panel alone (width x height px).
cv::Mat3b drawErrorPlot(const TrajMetrics& metrics, const TrajMetricsParams& params, int width, int height);

/// The object map over the floor plan: footprints coloured by class, a scale bar, the legend
/// of the classes in a side panel.
cv::Mat3b drawObjectMap(const world::World& world);
/// The same for a floor plan and an object map held apart (simp-map's M/map.png).
cv::Mat3b drawObjectMap(const mrpt::maps::COccupancyGridMap2D& floorplan, const world::ObjectMapData& objects);

/// A map evaluation: matched ground-truth/map objects green, missed ground-truth objects
/// blue, false map objects red, over the ground truth's floor plan, a scale bar.
cv::Mat3b drawMapEvaluation(const world::World& ground_truth, const world::World& map, const MapMetrics& metrics);

/// A change report over the floor plan (simp-map --update's M/changes.png): the updated map's
/// unchanged objects thin in grey, removed objects red and crossed out, moved objects orange (old
/// place outlined, new place filled, an arrow between), added objects green and filled; the objects of
/// `unseen_ids` (kept because the session never had them in view: the report says nothing of them)
/// purple instead of grey; counts in the legend.
cv::Mat3b drawChangeMap(const mrpt::maps::COccupancyGridMap2D& floorplan, const world::ObjectMapData& map,
                        const std::vector<world::ChangeRecord>& changes, const std::set<std::int64_t>& unseen_ids = {});

}  // namespace simp::eval
