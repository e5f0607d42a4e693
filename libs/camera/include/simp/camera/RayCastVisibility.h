#pragma once
/// \file RayCastVisibility.h
/// Visibility strategy of the label generator, exact rather than fast: the fraction of an object's
/// image pixels where it is the first surface seen, i.e. not hidden by another (occluding) box
/// (entry depth of the pixel's ray into every box) or by a wall of the floor plan (ray cast through
/// the grid along the ray's ground direction). One ray every `pixel_step` px.
/// (The mapper's z-buffer: ZBufferVisibility.h; doc/architecture.md "Camera and visibility".)

#include <simp/camera/FloorPlanGrid.h>
#include <simp/camera/PinholeCamera.h>
#include <simp/geometry/Box3D.h>

#include <vector>

namespace simp::camera {

struct RayCastParams {
    int pixel_step = 4;         ///< one ray every pixel_step px in u and v
    double max_range_m = 30.0;  ///< wall rays stop here (m, horizontal)
};

/// Visibility in [0, 1] of every box (world frame) in `camera`; 0 for a box no ray hits inside the
/// image. `walls` may be null (no walls; walls are floor-to-ceiling). `occludes` (optional, one
/// entry per box): 0 = the box is seen but hides nothing (a door, Occluders.h).
std::vector<double> rayCastVisibility(const PinholeCamera& camera, const std::vector<geometry::Box3D>& boxes_world,
                                      const FloorPlanGrid* walls, const RayCastParams& params,
                                      const std::vector<char>* occludes = nullptr);

/// Depth (camera z, m) at which the ray p(s) = origin + s * dir (s = camera depth when dir has
/// camera z = 1) enters `box`; +inf when it misses. Slab method in the box frame.
double rayBoxEntry(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, const geometry::Box3D& box);

}  // namespace simp::camera
