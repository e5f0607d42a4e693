#pragma once
/// \file World.h
/// A world directory: floor plan + room ids + object map (doc/formats.md).
///   floorplan.yaml + floorplan.png   ROS map_server format
///   rooms.png                        16-bit or 8-bit grey, room id per pixel, 0 = none (optional)
///   objects.json                     the object map file

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>
#include <simp/world/ObjectMapData.h>

#include <string>

namespace simp::world {

/// Room id raster aligned with the floor plan (same size, resolution and origin).
struct RoomMap {
    cv::Mat1w ids;            ///< row 0 = top of the image (max y), as the PNG
    double resolution_m = 0.05;
    double origin_x_m = 0, origin_y_m = 0;  ///< world coordinates of the bottom-left pixel corner

    bool empty() const { return ids.empty(); }
    /// Room id at a world point (0 outside).
    int roomAt(double x_m, double y_m) const;
};

struct World {
    mrpt::maps::COccupancyGridMap2D floorplan;
    RoomMap rooms;            ///< may be empty
    ObjectMapData objects;
};

/// Loads a ROS map_server yaml + image (negate, occupied_thresh, free_thresh, origin honoured).
void loadRosMap(const std::string& yaml_path, mrpt::maps::COccupancyGridMap2D& grid);
/// Writes `grid` as yaml + png (trinary: 0 occupied, 254 free, 205 unknown).
void saveRosMap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& yaml_path);

World loadWorld(const std::string& dir);
void saveWorld(const World& world, const std::string& dir);

}  // namespace simp::world
