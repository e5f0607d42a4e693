#pragma once
/// \file ConvexPolygon.h
/// Convex polygons in the plane (ground footprints), their area and the exact
/// intersection-over-union of two of them by convex clipping.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace simp::geometry {

/// A convex polygon with at most kMaxVertices vertices, counter-clockwise.
/// Fixed capacity, no heap: footprints are built and intersected per particle.
struct ConvexPolygon {
    static constexpr std::size_t kMaxVertices = 16;
    std::array<Eigen::Vector2d, kMaxVertices> v{};
    std::size_t n = 0;

    void push(const Eigen::Vector2d& p) { v[n++] = p; }
    double area() const;            ///< m^2, >= 0
    Eigen::Vector2d centroid() const;
    /// Axis-aligned bounds (min, max).
    void bounds(Eigen::Vector2d& lo, Eigen::Vector2d& hi) const;
    /// Rigid 2D motion: rotate by (c, s) = (cos, sin) then translate by t.
    ConvexPolygon transformed(double c, double s, const Eigen::Vector2d& t) const;
};

/// Convex hull (counter-clockwise, no collinear points) of up to kMaxVertices points.
ConvexPolygon convexHull(const Eigen::Vector2d* points, std::size_t count);

/// Rectangle centred at `center` with side lengths (lx, ly) rotated by yaw.
ConvexPolygon makeRectangle(const Eigen::Vector2d& center, double lx, double ly, double yaw_rad);

/// Area of the intersection of two convex counter-clockwise polygons (exact, by clipping).
double intersectionArea(const ConvexPolygon& a, const ConvexPolygon& b);

/// IoU of two convex polygons in [0, 1]; 0 when either is degenerate.
double iou(const ConvexPolygon& a, const ConvexPolygon& b);

}  // namespace simp::geometry
