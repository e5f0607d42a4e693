#pragma once
/// \file LidarSimulator.h
/// A simulated planar 2D LiDAR: MRPT's own ray casting (COccupancyGridMap2D::laserScanSimulator) on a
/// rasterised world: the floor plan of the sequence's world (walls, closed doors blocked) plus the
/// footprints of every object whose box spans the scan plane (doors excepted: an open leaf) and of
/// the people walking at the time of the scan (doc/lidar.md).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <simp/sim/Random.h>
#include <simp/sim/SensorParams.h>
#include <simp/world/ScanPlane.h>
#include <simp/world/World.h>

#include <utility>
#include <vector>

namespace simp::sim {

class LidarSimulator {
   public:
    /// Rasterises `world` once: its floor plan, then every non-door object spanning params.height_m
    /// as occupied cells.
    LidarSimulator(const world::World& world, const LidarParams& params);

    /// One scan from the robot at `robot_pose` with `dynamic_obstacles` (e.g. people; those spanning
    /// the scan plane) in the world; range noise N(0, range_std_m) drawn from `rng`, clamped to
    /// [0, max_range_m]; rays without a hit are invalid. sensorLabel "LIDAR", timestamp t_s.
    mrpt::obs::CObservation2DRangeScan scan(const mrpt::math::TPose2D& robot_pose,
                                            const std::vector<world::MapObject>& dynamic_obstacles, double t_s,
                                            Rng& rng);

    const mrpt::maps::COccupancyGridMap2D& grid() const { return m_grid; }

   private:
    LidarParams m_params;
    mrpt::maps::COccupancyGridMap2D m_grid;
};

}  // namespace simp::sim
