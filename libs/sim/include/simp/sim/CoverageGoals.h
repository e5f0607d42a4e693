#pragma once
/// \file CoverageGoals.h
/// Where a mapping (coverage) run stops to look around: besides each room's widest free spots,
/// spots that bring the rest of the room within the cameras' reach (corners, the far side of
/// furniture), chosen on the floor plan and the free space alone, as a real robot could.

#include <simp/sim/Raster.h>
#include <simp/world/World.h>

#include <Eigen/Core>
#include <vector>

namespace simp::sim {

/// The area a goal at cell (cx, cy) of `cspace` serves: its room id in `rooms`, or, without a
/// room map, a 5 m block of the raster; 0 = none (a wall, outside every room).
int goalAreaAt(const Raster& cspace, const world::RoomMap& rooms, int cx, int cy);

/// `goals` plus further goals, room by room: greedily the reachable free cell of `cspace` that
/// brings the largest part of the room not yet within `reach_m` of a goal (a straight line that
/// stays inside the room) within reach, while that part is at least `min_gain_m2`. The room is
/// sampled every `sample_m`. Deterministic; the given goals come first, in their order.
std::vector<Eigen::Vector2d> addReachGoals(const Raster& cspace, const world::RoomMap& rooms,
                                           std::vector<Eigen::Vector2d> goals, double reach_m,
                                           double min_gain_m2, double sample_m = 0.25);

/// The order in which a coverage run visits `goals`, starting at goals[start]: a closed tour
/// that is short in driving distance through `cspace` (nearest neighbour, then 2-opt moves
/// while one shortens it), so that a run sees every room once before it sees any twice.
/// Goals not connected to goals[start] come last, in their given order.
std::vector<std::size_t> coverageTour(const Raster& cspace, const std::vector<Eigen::Vector2d>& goals,
                                      std::size_t start);

}  // namespace simp::sim
