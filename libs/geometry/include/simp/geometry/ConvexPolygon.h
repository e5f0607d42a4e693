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

    /// Appends a vertex. \throw std::length_error when already holding kMaxVertices.
    void push(const Eigen::Vector2d& p) {
        if (n >= kMaxVertices) throwFull();
        v[n++] = p;
    }
    double area() const;            ///< m^2, >= 0
    Eigen::Vector2d centroid() const;
    /// Axis-aligned bounds (min, max).
    void bounds(Eigen::Vector2d& lo, Eigen::Vector2d& hi) const;
    /// Rigid 2D motion: rotate by (c, s) = (cos, sin) then translate by t.
    ConvexPolygon transformed(double c, double s, const Eigen::Vector2d& t) const;

private:
    [[noreturn]] static void throwFull();
};

/// Convex hull (counter-clockwise, no collinear points) of up to kMaxVertices points.
/// \throw std::length_error when count > kMaxVertices.
ConvexPolygon convexHull(const Eigen::Vector2d* points, std::size_t count);

/// Parallelogram centred at `center` with half-axes `ax`, `ay`: corners -ax-ay, +ax-ay, +ax+ay, -ax+ay
/// (counter-clockwise when ay is ax turned left).
ConvexPolygon parallelogram(const Eigen::Vector2d& center, const Eigen::Vector2d& ax, const Eigen::Vector2d& ay);

/// Rectangle centred at `center` with side lengths (lx, ly) rotated by yaw.
ConvexPolygon makeRectangle(const Eigen::Vector2d& center, double lx, double ly, double yaw_rad);

/// Area (m^2) of the intersection of two convex polygons, exact up to rounding, by
/// Sutherland-Hodgman clipping of a by the edges of b: O(n_a * n_b), no heap.
/// Either vertex order is accepted; 0 when either has fewer than 3 vertices.
double intersectionArea(const ConvexPolygon& a, const ConvexPolygon& b);

/// IoU of two convex polygons in [0, 1]; 0 when either is degenerate (zero area),
/// NaN when a vertex is NaN (callers check with MRPT_CHECK_NORMAL_NUMBER or std::isfinite).
/// Hot path of the sensor model (Eq. iouscore): no heap; about 45-50 ns for two overlapping
/// rectangles, 15 ns when disjoint (tests/benchmarks/geometry/bench_geometry.cpp).
double iou(const ConvexPolygon& a, const ConvexPolygon& b);

}  // namespace simp::geometry
