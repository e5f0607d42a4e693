#pragma once
/// \file Visibility.h
/// Visibility of ground-truth boxes in a posed image: the fraction of an object's image pixels
/// where it is the first surface seen, i.e. not hidden by another box (z-buffer over the ray-box
/// intersections) or by a wall of the floor plan (ray casting through the occupancy grid).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/geometry/Box3D.h>
#include <simp/labels/CameraFrames.h>

#include <vector>

namespace simp::labels {

struct VisibilityOptions {
    int pixel_step = 4;                  ///< one ray every pixel_step px in u and v
    double occupied_threshold = 0.65;    ///< cells with occupancy (1 - MRPT's P(free) cell value) >= this are walls
    bool ignore_object_cells = true;     ///< cells under an object's footprint (+ margin) are not walls
    double object_cell_margin_m = 0.10;  ///< margin around the footprint for ignore_object_cells (m)
    double max_range_m = 30.0;           ///< rays stop here
};

/// Visibility in [0, 1] of every box (world frame) in `image`; 0 for a box with no ray hitting
/// it inside the image. `floorplan` may be null (no walls). Walls are treated as floor-to-ceiling.
std::vector<double> computeVisibility(const PosedImage& image, const std::vector<geometry::Box3D>& boxes_world,
                                      const mrpt::maps::COccupancyGridMap2D* floorplan,
                                      const VisibilityOptions& options = {});

/// Depth (camera z, m) at which the ray p(s) = origin + s * dir (s = camera depth when dir has
/// camera z = 1) enters `box`; +inf when it misses. Slab method in the box frame.
double rayBoxEntry(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, const geometry::Box3D& box);

}  // namespace simp::labels
