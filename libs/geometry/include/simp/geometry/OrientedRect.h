#pragma once
/// \file OrientedRect.h
/// Rectangles in the plane (the footprints of upright boxes: most map objects) and the
/// exact intersection area of a convex polygon with one, computed in the rectangle's own
/// frame, where each of its four edges is one coordinate compare. This is the fast path of
/// the sensor model's IoU (Eq. iouscore); it equals intersectionArea() up to rounding.

#include <simp/geometry/ConvexPolygon.h>

#include <Eigen/Core>
#include <cmath>
#include <optional>

namespace simp::geometry {

/// The rectangle center + R(c, s) [-hx, hx] x [-hy, hy].
struct OrientedRect {
    Eigen::Vector2d center{Eigen::Vector2d::Zero()};  ///< (m)
    double c = 1, s = 0;                              ///< cos, sin of the angle of the rectangle's x axis
    double hx = 0, hy = 0;                            ///< half side lengths along its x and y axes (m)

    double area() const { return 4.0 * hx * hy; }
    /// A point of the frame expressed in the rectangle's frame (centred, axis-aligned).
    Eigen::Vector2d toLocal(const Eigen::Vector2d& p) const {
        const Eigen::Vector2d d = p - center;
        return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
    }
    /// Its four vertices, counter-clockwise.
    ConvexPolygon polygon() const;
};

/// The rectangle `p` is, when it is one: 4 vertices whose sides are perpendicular and whose
/// opposite sides are equal, within `rel_tol` times the longest side (either vertex order).
/// The tolerance is meant for rounding only, so that results computed through the rectangle
/// equal those computed through the polygon up to rounding.
std::optional<OrientedRect> asRectangle(const ConvexPolygon& p, double rel_tol = 1e-12);

/// Area (m^2) of the intersection of the convex polygon `p` (either vertex order), given in
/// the rectangle's frame, with [-hx, hx] x [-hy, hy]; hx, hy >= 0. Exact up to rounding:
/// 0 when the bounds of p are outside, area of p when inside, else Sutherland-Hodgman by
/// only the rectangle's edges that cut p's bounds. No heap.
double intersectionAreaWithAlignedRect(const ConvexPolygon& p, double hx, double hy);

/// The same for a rectangle `a` given in that frame (the sensor model's common case: an
/// upright detection box against an upright map box). The four separating axes are tested
/// first, from a's centre and axes alone, so disjoint pairs cost no vertex; an overlapping pair
/// is integrated along both boundaries (Green's theorem) without branches on where a's vertices
/// fall; an `a` within ~0.01 rad of the axes (where that is ill-conditioned) is clipped.
double intersectionAreaWithAlignedRect(const OrientedRect& a, double hx, double hy);

/// True when a separating axis exists (one of the four side normals): the interiors are
/// disjoint and the IoU is 0. Touching rectangles count as separated. Inline: it runs
/// per (particle x detection) before any clipping.
inline bool separated(const OrientedRect& a, const OrientedRect& b) {
    const double dx = b.center.x() - a.center.x(), dy = b.center.y() - a.center.y();
    // |cos| and |sin| of the angle between the two x axes: b's extent along a's axes and back.
    const double cc = std::abs(a.c * b.c + a.s * b.s), ss = std::abs(a.c * b.s - a.s * b.c);
    if (std::abs(a.c * dx + a.s * dy) >= a.hx + b.hx * cc + b.hy * ss) return true;
    if (std::abs(a.c * dy - a.s * dx) >= a.hy + b.hx * ss + b.hy * cc) return true;
    if (std::abs(b.c * dx + b.s * dy) >= b.hx + a.hx * cc + a.hy * ss) return true;
    return std::abs(b.c * dy - b.s * dx) >= b.hy + a.hx * ss + a.hy * cc;
}

}  // namespace simp::geometry
