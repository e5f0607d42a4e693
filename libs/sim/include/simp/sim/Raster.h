#pragma once
/// \file Raster.h
/// A plain blocked/free raster for planning and ray casting (row-major, cell (cx, cy) with
/// cy = 0 at the minimum y, as mrpt::maps::COccupancyGridMap2D).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/world/MapObject.h>
#include <simp/world/World.h>

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace simp::sim {

struct Raster {
    int nx = 0, ny = 0;
    double x_min_m = 0, y_min_m = 0, resolution_m = 0.05;
    std::vector<std::uint8_t> blocked;  ///< 1 = wall / obstacle / unknown, 0 = free

    bool inside(int cx, int cy) const { return cx >= 0 && cy >= 0 && cx < nx && cy < ny; }
    bool isBlocked(int cx, int cy) const { return !inside(cx, cy) || blocked[static_cast<std::size_t>(cy) * nx + cx] != 0; }
    void set(int cx, int cy, bool b) {
        if (inside(cx, cy)) blocked[static_cast<std::size_t>(cy) * nx + cx] = b ? 1 : 0;
    }
    int cellX(double x_m) const { return static_cast<int>(std::floor((x_m - x_min_m) / resolution_m)); }
    int cellY(double y_m) const { return static_cast<int>(std::floor((y_m - y_min_m) / resolution_m)); }
    double centreX(int cx) const { return x_min_m + (cx + 0.5) * resolution_m; }
    double centreY(int cy) const { return y_min_m + (cy + 0.5) * resolution_m; }
    bool isBlockedAt(double x_m, double y_m) const { return isBlocked(cellX(x_m), cellY(y_m)); }
};

/// Walls of a floor plan for driving and the simulator's wall rays: every cell not known free
/// (P(free) <= camera::floorplan::kUnknownFree: walls and unknown space) is blocked.
Raster wallRaster(const mrpt::maps::COccupancyGridMap2D& grid);

/// Marks the ground footprints of `objects` blocked (cells whose centre lies inside).
void addFootprints(Raster& raster, const std::vector<world::MapObject>& objects);

/// What a robot drives around in `world`: its walls and the footprints of every object but the
/// doors (a door object stands in an open gap).
Raster drivingObstacles(const world::World& world);

/// The raster with every cell closer than `radius_m` to a blocked cell blocked too
/// (configuration space of a disc robot).
Raster inflate(const Raster& raster, double radius_m);

/// Distance (m) of each free cell to the nearest blocked cell (0 on blocked cells).
std::vector<float> clearance(const Raster& raster);

/// Cells (index cy * nx + cx) of the largest 4-connected area of cells with clearance `dist` > 0:
/// the free space a robot can drive in (pockets walled in by furniture are left out).
std::vector<std::uint8_t> largestFreeArea(const Raster& cspace, const std::vector<float>& dist);

/// True when the straight segment a-b (m) crosses no blocked cell (sampled every resolution/2).
bool lineOfSight(const Raster& raster, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

}  // namespace simp::sim
