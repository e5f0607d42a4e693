#pragma once
/// \file MapFootprints.h
/// Ground footprints of the map objects (world frame), with bounding circles and areas,
/// precomputed once so the per-particle IoU of Eq. iouscore does no setup work.

#include <simp/geometry/ConvexPolygon.h>
#include <simp/geometry/OrientedRect.h>
#include <simp/world/ObjectMapData.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace simp::maps {

struct ObjectFootprint {
    geometry::ConvexPolygon polygon;                         ///< world frame, counter-clockwise (m)
    Eigen::Vector2d circle_center_m{Eigen::Vector2d::Zero()};  ///< box centre on the ground (m)
    double circle_radius_m = 0;                              ///< max vertex distance to the centre (m)
    double area_m2 = 0;
    /// The polygon as a rectangle (upright boxes: most objects), when it is one; the IoU is
    /// then clipped in its frame (geometry::intersectionAreaWithAlignedRect), else generically.
    bool is_rect = false;
    geometry::OrientedRect rect;
};

struct MapFootprints {
    std::vector<ObjectFootprint> objects;                ///< per object index
    std::vector<std::vector<std::int32_t>> class_objects;  ///< per class id: its object indices
};

/// Footprints of every object; objects with a class id outside the class list throw
/// std::invalid_argument naming the object.
MapFootprints computeMapFootprints(const world::ObjectMapData& data);

/// IoU of two convex polygons whose areas are known (exact, convex clipping).
double iouWithAreas(const geometry::ConvexPolygon& a, double area_a, const geometry::ConvexPolygon& b, double area_b);

/// IoU from the intersection area and the two areas (> 0), clamped to [0, 1] against rounding.
inline double iouFromIntersection(double inter, double area_a, double area_b) {
    const double uni = area_a + area_b - inter;
    return uni > 0.0 ? std::clamp(inter / uni, 0.0, 1.0) : 0.0;
}

/// True when two discs overlap (strictly): otherwise the polygons they bound have IoU = 0.
inline bool circlesOverlap(const Eigen::Vector2d& ca, double ra, const Eigen::Vector2d& cb, double rb) {
    const double r = ra + rb;
    return (ca - cb).squaredNorm() < r * r;
}

}  // namespace simp::maps
