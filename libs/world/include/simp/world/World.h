#pragma once
/// \file World.h
/// A world directory: floor plan + room ids + object map (doc/formats.md).
///   floorplan.yaml + floorplan.png   ROS map_server format
///   rooms.png                        16-bit or 8-bit grey, room id per pixel, 0 = none (optional)
///   objects.json                     the object map file

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>
#include <simp/geometry/Box3D.h>
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
    /// The pixel (row, col) whose cell holds a world point, possibly outside the raster (so that a
    /// search around a point just outside still finds the pixels near it); false when not finite.
    bool pixelOf(double x_m, double y_m, int& row, int& col) const;
    /// Room id of pixel (row, col); 0 outside the raster.
    int roomAtPixel(int row, int col) const;
};

/// Room of a map object: the room at its centre; when the centre lies on no room (a board or
/// a door in a wall), the most frequent non-zero id under its footprint grown by one cell on
/// each side (ties: the smaller id); 0 when there is none.
int roomOfBox(const RoomMap& rooms, const geometry::Box3D& box);

struct World {
    mrpt::maps::COccupancyGridMap2D floorplan;
    RoomMap rooms;            ///< may be empty
    ObjectMapData objects;
};

/// The occupancy thresholds of the floor plans the project writes (floorplan.yaml, the authors'
/// Map.png entry; map_server's defaults): occupancy >= this is occupied ...
inline constexpr double kWrittenOccupiedThresh = 0.65;
/// ... and occupancy <= this is free; between them unknown.
inline constexpr double kWrittenFreeThresh = 0.196;

/// The keys of a ROS map_server yaml file (http://wiki.ros.org/map_server#YAML_format).
struct RosMapYaml {
    std::string image_path;        ///< resolved: relative paths are relative to the yaml's folder
    double resolution_m = 0.05;    ///< cell size (m)
    double origin_x_m = 0, origin_y_m = 0;  ///< world pose of the bottom-left corner of the image
    double origin_yaw_rad = 0;     ///< must be 0 (MRPT grids are axis-aligned)
    bool negate = false;
    double occupied_thresh = kWrittenOccupiedThresh;
    double free_thresh = kWrittenFreeThresh;
    std::string mode = "trinary";  ///< "trinary" or "scale" ("raw" is rejected)
};

/// Parses and checks a map_server yaml (required keys: image, resolution, origin,
/// occupied_thresh, free_thresh; negate and mode optional).
/// \throw std::runtime_error naming the file and the key.
RosMapYaml readRosMapYaml(const std::string& yaml_path);

/// Sets the grid's extent exactly (MRPT's setSize rounds the origin to a multiple of the
/// resolution, which would shift a map_server origin such as -13.9155 m by up to half a cell).
/// All cells are set to `default_occupancy`.
void setGridExactly(mrpt::maps::COccupancyGridMap2D& grid, double x_min_m, double y_min_m,
                    unsigned size_x, unsigned size_y, double resolution_m,
                    float default_occupancy = 0.5f);

/// Loads a ROS map_server yaml + image (negate, occupied_thresh, free_thresh, origin honoured).
/// Cell (cx, cy) of the grid = image pixel (column cx, row rows-1-cy); occupancy 1.0 for
/// p > occupied_thresh, 0.0 for p < free_thresh, else 0.5 (trinary) or the scaled value (scale),
/// p = (255 - v) / 255, or v / 255 with negate (v = mean of the colour channels).
/// \throw std::runtime_error naming the file and key on any bad input.
void loadRosMap(const std::string& yaml_path, mrpt::maps::COccupancyGridMap2D& grid);
/// Writes `grid` as yaml + png (trinary: 0 occupied, 254 free, 205 unknown), the image
/// named after the yaml (floorplan.yaml -> floorplan.png). Cells with occupancy >= 0.65 are
/// occupied, <= 0.196 free, others unknown.
void saveRosMap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& yaml_path);

/// Reads a room raster (8- or 16-bit single-channel PNG/PGM) aligned with a floor plan.
/// \throw std::runtime_error naming the file on a missing/unreadable/multi-channel image.
RoomMap loadRoomMap(const std::string& png_path, double resolution_m, double origin_x_m,
                    double origin_y_m);
/// Writes the room ids as a 16-bit PNG.
void saveRoomMap(const RoomMap& rooms, const std::string& png_path);

/// Reads a world directory: floorplan.yaml (+ its image) and objects.json required,
/// rooms.png optional (must have the floor plan's size).
/// \throw std::runtime_error naming the directory, file and key.
World loadWorld(const std::string& dir);
/// Writes a world directory (created when missing): floorplan.yaml/.png, objects.json and
/// rooms.png when `world.rooms` is not empty.
void saveWorld(const World& world, const std::string& dir);

}  // namespace simp::world
