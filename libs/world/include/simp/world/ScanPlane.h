#pragma once
/// \file ScanPlane.h
/// What a planar 2D LiDAR at a given height sees of the object map: the footprint cells of every object
/// whose box spans the scan plane, doors excepted (an open leaf stands in an open gap). One rule for the
/// simulated LiDAR (libs/sim, on the sequence's changed world) and the LiDAR likelihood of
/// `simp-localize --method simp+lidar` (libs/localization, on the map it is given); doc/lidar.md.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/geometry/Box3D.h>
#include <simp/world/ObjectMapData.h>

#include <utility>
#include <vector>

namespace simp::world {

/// Cells (cx, cy) of `grid` whose centre lies inside the ground footprint of `box`.
std::vector<std::pair<int, int>> footprintCells(const mrpt::maps::COccupancyGridMap2D& grid, const geometry::Box3D& box);

/// True when the box's vertical extent contains height_m (the scan plane hits it).
bool spansHeight(const geometry::Box3D& box, double height_m);

/// Marks as occupied (free probability 0) the footprint cells of every object of `objects` that spans
/// height_m, doors excepted. Returns the number of objects drawn.
std::size_t drawObjectsAtHeight(mrpt::maps::COccupancyGridMap2D& grid, const ObjectMapData& objects, double height_m);

}  // namespace simp::world
