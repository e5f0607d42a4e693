#pragma once
/// \file WallAlignment.h
/// Floor-plan prior for map objects (project addition, not in the paper): cabinets, boards,
/// sinks and most office furniture stand flush against a wall. A detector's error across the
/// wall stays in the mean of its detections when it repeats from one viewpoint to the next, and
/// on a 0.15 m deep board a 0.1 m offset halves the footprint IoU. When one side of a map box
/// lies parallel to a wall of the floor plan, within a small gap or penetration, the box is
/// turned parallel to the wall and moved so that side touches the wall's face.

#include <simp/geometry/Box3D.h>
#include <simp/camera/FloorPlanGrid.h>

#include <optional>

namespace simp::mapping {

struct WallAlignmentParams {
    double max_gap_m = 0.3;          ///< a side at most this far in front of a wall face is aligned (m)
    double max_penetration_m = 0.3;  ///< ... or at most this far inside the wall (m)
    double max_yaw_rad = 0.2;        ///< the side must be within this angle of parallel to the wall (rad)
    double max_residual_m = 0.1;     ///< the wall face must be straight along the side to this tolerance (m)
    int rays_per_side = 5;           ///< rays cast from points spread along the side (>= 2)
};

/// The wall in front of one side of a box, fitted along the side: gap(s) = gap_m + slope * s,
/// s = position along the side from its midpoint (m); gap < 0 = the side is inside the wall.
struct WallContact {
    int axis = 0;               ///< box axis of the side's outward normal (0 = x, 1 = y)
    int sign = 1;               ///< +1 / -1: the side at +size/2 / -size/2 along that axis
    double gap_m = 0;           ///< distance side midpoint -> wall face along the normal (m)
    double slope = 0;           ///< d gap / d s (tan of the angle between side and wall)
    int hits = 0;               ///< rays that met the wall
};

/// The wall facing one side of an upright box, when the side qualifies (enough rays hit within
/// the gap / penetration limits, the face is straight and close to parallel); rays are cast from
/// points inside the box along the side's outward normal.
std::optional<WallContact> wallContact(const geometry::Box3D& upright_box, int axis, int sign, const camera::FloorPlanGrid& walls,
                                       const WallAlignmentParams& p);

/// The box aligned to the nearest qualifying wall: turned parallel to it, moved so the side
/// touches its face; a second wall on the other axis (a corner) moves it along that axis too.
/// Returns the box unchanged when no side qualifies (or `walls` is empty). Height, size and
/// vertical position are kept.
geometry::Box3D alignToWalls(const geometry::Box3D& upright_box, const camera::FloorPlanGrid& walls, const WallAlignmentParams& p);

}  // namespace simp::mapping
