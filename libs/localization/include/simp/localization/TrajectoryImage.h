#pragma once
/// \file TrajectoryImage.h
/// A PNG of the estimated trajectory over the floor plan (with the map's object footprints
/// and the final particles).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <simp/world/ObjectMapData.h>

#include <string>
#include <vector>

namespace simp::localization {

/// Floor plan in grey, object footprints in their class colour, particles as blue dots, the
/// trajectory in red (start: green circle, end: red circle with heading). The image is the
/// grid upscaled to at least ~1000 px wide. Throws std::runtime_error naming the file on failure.
void writeTrajectoryPng(const std::string& path, const mrpt::maps::COccupancyGridMap2D& floorplan,
                        const simp::world::ObjectMapData& objects, const std::vector<mrpt::math::TPose2D>& trajectory,
                        const std::vector<mrpt::math::TPose2D>& particles);

}  // namespace simp::localization
