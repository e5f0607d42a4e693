#pragma once
/// \file Box3DIoU.h
/// Exact intersection volume and IoU of two oriented 3D boxes (any rotations):
/// the 3D IoU of the association cost (Eq. costfunc, C_IoU = 1 - IoU) and of the
/// map evaluation. Algorithm and cost: doc/geometry.md.

#include <simp/geometry/Box3D.h>

namespace simp::geometry {

/// Volume (m^3) of the intersection of two boxes expressed in the same frame.
/// Exact up to rounding for general rotations. When the boxes share an axis
/// direction (both upright, the usual map case) it takes the fast path
/// footprint intersection area x overlap along that axis; otherwise it calls
/// intersectionVolumeByClipping(). No heap allocation.
/// \throw std::invalid_argument when a box is not isValid() (NaN, size <= 0, R not a rotation).
double intersectionVolume(const Box3D& a, const Box3D& b);

/// Intersection-over-union of two boxes in [0, 1] (same frame; see intersectionVolume()).
/// \throw std::invalid_argument when a box is not isValid().
double iou3D(const Box3D& a, const Box3D& b);

/// The general path of intersectionVolume() without the upright fast path: the
/// convex polyhedron of `a` is clipped by the 6 half-spaces of `b`, keeping every
/// face closed (each cut adds its cap polygon), then the volume follows from the
/// divergence theorem, V = 1/6 sum over faces of the fan triangles' p0 . (p1 x p2).
/// Exposed so tests can check that both paths agree. Does not validate its input.
double intersectionVolumeByClipping(const Box3D& a, const Box3D& b);

}  // namespace simp::geometry
