#pragma once
/// \file ScanPoints.h
/// The point clouds MRPT's ICP aligns: a 2D scan in the robot frame, the floor plan's walls.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstddef>

namespace simp::lidar {

/// Every `decimation`-th valid ray of `scan` with a range in [min_range_m, max_range_m] as a point (m)
/// in the ROBOT frame (the scan's sensorPose applied; rays right to left over the aperture as MRPT
/// defines them).
mrpt::maps::CSimplePointsMap scanToPoints(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t decimation,
                                          double min_range_m, double max_range_m);

/// Centres (m) of the occupied cells of `grid` (free probability < 0.5, camera::floorplan::kUnknownFree) that touch a free cell (free
/// probability > 0.5): the wall surfaces a scan can hit.
mrpt::maps::CSimplePointsMap wallSurfacePoints(const mrpt::maps::COccupancyGridMap2D& grid);

}  // namespace simp::lidar
