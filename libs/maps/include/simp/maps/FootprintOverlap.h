#pragma once
/// \file FootprintOverlap.h
/// IoU of a prepared detection, moved to one particle pose, with one map object's footprint
/// (Eq. iouscore's argument): shared by SimpSensorModel (with o_max) and OverlapSensorModel (with
/// every object of the class). Inline: it runs once per clipped (particle x detection) pair.

#include <simp/geometry/ConvexPolygon.h>
#include <simp/geometry/OrientedRect.h>
#include <simp/maps/MapFootprints.h>
#include <simp/maps/PreparedDetection.h>

#include <Eigen/Core>

namespace simp::maps {

/// Footprints moved per pair, reused for every pair of a call (no construction per pair).
struct OverlapScratch {
    geometry::ConvexPolygon world;  ///< the detection in the world (generic clipping)
    bool world_valid = false;       ///< `world` holds the current pair's pose
    geometry::ConvexPolygon local;  ///< the detection in a rectangular map object's frame
};

/// out = R(c, s) in + t, written into a caller's polygon (no construction per particle).
inline void transformInto(const geometry::ConvexPolygon& in, double c, double s, double tx, double ty,
                          geometry::ConvexPolygon& out) {
    out.n = in.n;
    for (std::size_t i = 0; i < in.n; ++i)
        out.v[i] = Eigen::Vector2d(c * in.v[i].x() - s * in.v[i].y() + tx, s * in.v[i].x() + c * in.v[i].y() + ty);
}

/// IoU (Eq. iouscore) of the detection, the robot at (c, s, tx, ty) = (cos phi, sin phi, x, y) and
/// the detection's centre at wc in the world, with one map footprint. Rectangular map objects
/// (most: upright boxes) are done in their own frame, where their edges are axis-aligned:
/// separating axes first (in the global case most pairs whose circles overlap do not intersect),
/// then clipping by coordinate compares. Other footprints: generic clipping in the world, the
/// moved footprint kept in `scratch.world` for the next object of the same pair (OverlapSensorModel).
inline double footprintIou(const PreparedDetection& det, double c, double s, double tx, double ty,
                           const Eigen::Vector2d& wc, const ObjectFootprint& of, OverlapScratch& scratch) {
    if (det.area_m2 <= 0.0 || of.area_m2 <= 0.0) return 0.0;
    double inter = 0.0;
    if (of.is_rect) {
        const geometry::OrientedRect& r = of.rect;
        // Robot -> object frame: rotation R_o^T R(phi) = (rc, rs); the detection centre R_o^T (wc - c_o).
        const double rc = r.c * c + r.s * s, rs = r.c * s - r.s * c;
        const Eigen::Vector2d lc = r.toLocal(wc);
        if (det.is_rect) {
            // The box centre is the footprint's centre of symmetry (up to rounding).
            geometry::OrientedRect d;
            d.center = lc;
            d.c = rc * det.rect_robot.c - rs * det.rect_robot.s;
            d.s = rs * det.rect_robot.c + rc * det.rect_robot.s;
            d.hx = det.rect_robot.hx;
            d.hy = det.rect_robot.hy;
            inter = geometry::intersectionAreaWithAlignedRect(d, r.hx, r.hy);
        } else {
            geometry::ConvexPolygon& fp = scratch.local;
            const geometry::ConvexPolygon& off = det.offsets_robot;
            fp.n = off.n;
            for (std::size_t i = 0; i < off.n; ++i)
                fp.v[i] = Eigen::Vector2d(rc * off.v[i].x() - rs * off.v[i].y() + lc.x(),
                                          rs * off.v[i].x() + rc * off.v[i].y() + lc.y());
            inter = geometry::intersectionAreaWithAlignedRect(fp, r.hx, r.hy);
        }
    } else {
        if (!scratch.world_valid) {
            transformInto(det.footprint_robot, c, s, tx, ty, scratch.world);
            scratch.world_valid = true;
        }
        inter = geometry::intersectionArea(scratch.world, of.polygon);
    }
    return iouFromIntersection(inter, det.area_m2, of.area_m2);
}

}  // namespace simp::maps
