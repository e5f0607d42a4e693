#pragma once
/// \file RoomSegmentation.h
/// Room segmentation of a floor plan (paper Sec. "3D Semantic Map Construction": morphological
/// operations and connected components): the free space is eroded so that doors close, the
/// remaining components are the room seeds, and their labels grow back over the free space.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/camera/FloorPlanThresholds.h>
#include <simp/world/World.h>

namespace simp::mapping {

struct RoomSegmentationParams {
    double door_width_m = 1.0;        ///< openings up to this width separate rooms (m)
    double min_room_area_m2 = 1.0;    ///< eroded components smaller than this are dropped (m^2)
    double min_free_prob = camera::floorplan::kFreeMinFree;  ///< a cell is free when MRPT getCell() >= this (1 = free)
};

/// Room ids 1..N (0 = wall / unknown / unreachable) aligned with `grid`: same size, resolution
/// and origin, row 0 = top (max y) as in world::RoomMap. Ids are numbered in the order the
/// components are found (row-major scan of the image from the top-left).
/// \throw std::invalid_argument when the grid is empty or a parameter is not positive / finite.
world::RoomMap segmentRooms(const mrpt::maps::COccupancyGridMap2D& grid, const RoomSegmentationParams& params = {});

/// Number of distinct non-zero ids of a room map.
int countRooms(const world::RoomMap& rooms);

}  // namespace simp::mapping
