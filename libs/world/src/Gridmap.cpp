/// \file Gridmap.cpp
/// MRPT's `.gridmap` file (Gridmap.h).

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/world/Gridmap.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace simp::world {

void saveGridmap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path) {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    mrpt::io::CFileGZOutputStream f;
    if (!f.open(path)) throw std::runtime_error(path + ": cannot be written (.gridmap)");
    try {
        mrpt::serialization::archiveFrom(f) << grid;
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": writing the .gridmap failed: " + e.what());
    }
}

double gridmapOriginShift(const mrpt::maps::COccupancyGridMap2D& grid) {
    mrpt::maps::COccupancyGridMap2D rounded;  // what deserialization does: setSize() with the same extent
    rounded.setSize(grid.getXMin(), grid.getXMax(), grid.getYMin(), grid.getYMax(), grid.getResolution());
    return std::hypot(rounded.getXMin() - grid.getXMin(), rounded.getYMin() - grid.getYMin());
}

mrpt::maps::COccupancyGridMap2D loadGridmap(const std::string& path) {
    if (!std::filesystem::is_regular_file(path)) throw std::runtime_error(path + ": .gridmap file not found");
    mrpt::io::CFileGZInputStream f;
    if (!f.open(path)) throw std::runtime_error(path + ": cannot be opened (.gridmap)");
    mrpt::maps::COccupancyGridMap2D grid;
    try {
        mrpt::serialization::archiveFrom(f) >> grid;
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": not a serialized mrpt::maps::COccupancyGridMap2D (.gridmap): " + e.what());
    }
    return grid;
}

}  // namespace simp::world
