#pragma once
/// \file MapLayers.h
/// What a picture of a run shows over the floor plan: one struct for the 2D figure
/// (drawTrajectoryMap, Plots.h) and the 3D scene (buildScene, Scene3D.h), so both show the same.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <simp/io/Tum.h>
#include <simp/world/ObjectMapData.h>

#include <vector>

namespace simp::eval {

struct MapLayers {
    const mrpt::maps::COccupancyGridMap2D* floorplan = nullptr;  ///< may be null or empty: no floor plan drawn
    const world::ObjectMapData* objects = nullptr;               ///< may be null: no objects
    std::vector<io::StampedPose2D> ground_truth;                 ///< world frame (m, rad); may be empty
    /// > 0: the ground truth teleports into pose `ground_truth_jump` (a kidnap odometry does not
    /// see): no line into it; the figure marks where the robot was lifted and put down.
    std::size_t ground_truth_jump = 0;
    std::vector<io::StampedPose2D> estimate;                     ///< world frame; may be empty
    std::vector<mrpt::math::TPose2D> particles;                  ///< final particles; may be empty
};

}  // namespace simp::eval
