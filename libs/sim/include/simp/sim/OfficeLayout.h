#pragma once
/// \file OfficeLayout.h
/// The procedural office floor plan: corridors with rooms off them, one door per room,
/// walls of a given thickness; rasterized into a ROS-style occupancy grid and a room id map.

#include <mrpt/config/CConfigFileBase.h>
#include <simp/io/OptionTable.h>
#include <simp/sim/Random.h>
#include <simp/world/World.h>

#include <string>
#include <vector>

namespace simp::sim {

/// Axis-aligned rectangle in the world frame (m), x0 <= x1, y0 <= y1.
struct Rect {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
    double area() const { return width() * height(); }
    bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

enum class RoomType { Office, Meeting, Kitchen, Reception, Corridor };
const char* roomTypeName(RoomType t);

/// One room (or corridor) of the floor.
struct Room {
    int id = 0;                  ///< id written to rooms.png (1..), unique
    RoomType type = RoomType::Office;
    Rect interior;               ///< free space inside the walls (m, world frame)
    /// Door gap through the wall towards the corridor (m, world frame); empty for corridors.
    Rect door_gap;
    /// Outward normal of the door wall (0, +1) or (0, -1): the corridor lies that way.
    double door_side_y = 0;
};

/// Knobs of the office generator ([office] section of sim.ini).
struct OfficeParams {
    int rooms = 10;                    ///< number of rooms (used when size_m2 <= 0)
    double size_m2 = 0;                ///< target floor area (m^2); > 0 overrides `rooms`
    double resolution_m = 0.05;        ///< grid cell size (m)
    double wall_thickness_m = 0.15;    ///< wall thickness (m)
    double corridor_width_m = 2.0;     ///< corridor clear width (m)
    double door_width_m = 0.9;         ///< door gap width (m)
    double room_width_min_m = 3.5;     ///< room extent along the corridor (m)
    double room_width_max_m = 6.0;
    double room_depth_min_m = 4.0;     ///< room extent away from the corridor (m)
    double room_depth_max_m = 6.0;
    int max_rooms_per_side = 10;       ///< rooms along one side of one corridor
    double kitchen_every_n_rooms = 8;  ///< one kitchen per this many rooms (at least one from 4 rooms)
    double meeting_fraction = 0.2;     ///< fraction of the remaining rooms that are meeting rooms

    /// [office] keys, declared once (SimParams.cpp): loading, checks, dump, doc/simulator.md's table.
    static const io::OptionTable<OfficeParams>& table();
    /// Reads the keys (same names as the fields) of `section`; missing keys keep defaults.
    /// \throw std::invalid_argument "[section] key: must be ..." naming the key of a bad value.
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
    /// The checks of the table (after command-line overrides). \throw std::invalid_argument "[office] key: ..."
    void validate() const;
};

/// The geometry of a generated floor.
struct OfficeLayout {
    std::vector<Room> rooms;      ///< rooms first, then corridors
    Rect bounds;                  ///< outer wall boundary (m)
};

/// Draws the room rectangles, corridor(s) and doors. Several corridors ("bands" of two room
/// rows each) joined by a connecting corridor when the floor needs more than one.
OfficeLayout makeOfficeLayout(const OfficeParams& p, Rng& rng);

/// Rasterizes the layout: inside `bounds` everything is wall except room/corridor interiors and
/// door gaps; outside is unknown. Room ids go to `rooms`.
void rasterizeLayout(const OfficeLayout& layout, double resolution_m, mrpt::maps::COccupancyGridMap2D& grid,
                     world::RoomMap& rooms);

/// Marks a rectangle of the grid occupied (e.g. a closed door) or free.
void fillRect(mrpt::maps::COccupancyGridMap2D& grid, const Rect& r, bool occupied);

}  // namespace simp::sim
