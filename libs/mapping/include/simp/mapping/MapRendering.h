#pragma once
/// \file MapRendering.h
/// A picture of an object map over its floor plan (the M/map.png of simp-map).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>
#include <simp/world/ObjectMapData.h>

#include <string>

namespace simp::mapping {

/// The floor plan in grey (north up, one pixel per cell, scaled by `scale`) with the ground
/// footprint of every object drawn in its class colour and a class legend.
cv::Mat3b renderObjectMap(const mrpt::maps::COccupancyGridMap2D& floorplan, const world::ObjectMapData& map, int scale = 2);

/// Writes renderObjectMap() as a PNG. \throw std::runtime_error naming the file on failure.
void writeObjectMapPng(const mrpt::maps::COccupancyGridMap2D& floorplan, const world::ObjectMapData& map,
                       const std::string& png_path, int scale = 2);

}  // namespace simp::mapping
