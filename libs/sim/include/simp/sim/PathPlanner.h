#pragma once
/// \file PathPlanner.h
/// A* on a (robot-radius inflated) raster, 8-connected, and line-of-sight shortcutting of the
/// resulting cell path into a few waypoints.

#include <simp/sim/Raster.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace simp::sim {

/// Shortest 8-connected path (cell centres, m) from `from` to `to` through free cells of
/// `cspace`, or nullopt when either end is blocked or they are not connected.
std::optional<std::vector<Eigen::Vector2d>> planPath(const Raster& cspace, const Eigen::Vector2d& from,
                                                     const Eigen::Vector2d& to);

/// Driving distance (m) from `from` to every cell of `cspace` along the 8-connected moves of
/// planPath (infinity where not connected or blocked; all infinity when `from` is blocked).
std::vector<float> drivingDistances(const Raster& cspace, const Eigen::Vector2d& from);

/// Keeps only the waypoints needed so that consecutive ones see each other in `cspace`.
std::vector<Eigen::Vector2d> shortcutPath(const Raster& cspace, const std::vector<Eigen::Vector2d>& path);

}  // namespace simp::sim
