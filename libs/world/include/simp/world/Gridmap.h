#pragma once
/// \file Gridmap.h
/// The floor plan as MRPT's `.gridmap`: a serialized mrpt::maps::COccupancyGridMap2D, gzip-compressed,
/// as MRPT's pf-localization loads it (`map_file = F.gridmap` in [LocalizationExperiment]: it reads the
/// file through mrpt::io::CFileGZInputStream into the first occupancy grid of the [MetricMap]).

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>

namespace simp::world {

/// Writes `grid` to `path` (gzip, MRPT's CArchive serialization; CFileGZInputStream also reads it
/// uncompressed). The extension is not checked, but pf-localization needs `.gridmap` (or
/// `.gridmap.gz`). Creates missing parent folders.
/// \throw std::runtime_error naming the file when it cannot be written.
void saveGridmap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path);

/// How far (m) MRPT moves the grid's origin when it reads the file back: its deserialization calls
/// COccupancyGridMap2D::setSize(), which rounds x_min and y_min to multiples of the resolution (a ROS
/// map_server origin such as -13.9155 m at 0.05 m becomes -13.9 m). 0 when the origin is on that lattice.
double gridmapOriginShift(const mrpt::maps::COccupancyGridMap2D& grid);

/// Reads a `.gridmap` (gzip or plain) exactly as pf-localization does.
/// \throw std::runtime_error naming the file when it is missing or is not a serialized grid.
mrpt::maps::COccupancyGridMap2D loadGridmap(const std::string& path);

}  // namespace simp::world
