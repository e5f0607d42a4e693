#pragma once
/// \file FloorPlanThresholds.h
/// The thresholds that read a floor plan, in one place. A floor plan is an
/// mrpt::maps::COccupancyGridMap2D whose cell value getCell() is P(free): 0 = occupied (wall),
/// 0.5 = unknown, 1 = free (ROS map_server: occupied_thresh 0.65 on occupancy = P(free) < 0.35).
/// Three questions are asked of it and they keep their own answers:
///  - "is this a wall?" (camera occlusion, wall alignment, label visibility): P(free) < kWallMaxFree;
///    unknown cells (furniture drawn grey, the outside) do not occlude;
///  - "may the robot (or the simulated camera's ray) pass?" (simulator planning and visibility):
///    only known free space, P(free) > kUnknownFree; unknown cells block (outside the building);
///  - "may a particle stand here?" (localization: uniform draws, pruning): P(free) >= kParticleMinFree.

namespace simp::camera::floorplan {

/// P(free) below this: a wall (occupancy above 0.65, map_server's occupied_thresh).
inline constexpr double kWallMaxFree = 0.35;
/// P(free) above this: known free floor (1 - kWallMaxFree; room segmentation, free-cell tests).
inline constexpr double kFreeMinFree = 0.65;
/// The unknown cell value. Simulator rasters block P(free) <= this (walls and unknown), LiDAR
/// occupied cells are those below it.
inline constexpr float kUnknownFree = 0.5f;
/// P(free) at or above this: a cell where the localizer places particles ([LocalizationExperiment]
/// free_cells_threshold's default; MRPT's resetUniformFreeSpace default). Stricter than
/// kFreeMinFree: cells blurred by a grid's edge stay out.
inline constexpr double kParticleMinFree = 0.7;

}  // namespace simp::camera::floorplan
