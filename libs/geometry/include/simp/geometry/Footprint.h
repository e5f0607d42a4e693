#pragma once
/// \file Footprint.h
/// The ground footprint of a 3D box: its corners dropped onto the xy plane, convex hull.

#include <simp/geometry/Box3D.h>
#include <simp/geometry/ConvexPolygon.h>

namespace simp::geometry {

/// Footprint of a box expressed in a frame whose z is vertical (robot or world).
ConvexPolygon footprint(const Box3D& box_in_frame);

}  // namespace simp::geometry
