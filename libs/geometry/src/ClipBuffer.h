#pragma once
/// \file ClipBuffer.h
/// Internal to libs/geometry: the working polygon shared by the two clippers
/// (ConvexPolygon.cpp: any convex polygon; OrientedRect.cpp: an axis-aligned rectangle).

#include <simp/geometry/ConvexPolygon.h>

#include <cmath>
#include <cstddef>

namespace simp::geometry::detail {

/// Working polygon of a clipper, structure of arrays, never zero-initialised.
/// The intersection of a convex n-gon and a convex m-gon has at most n + m <= 32
/// vertices, and so has every intermediate of Sutherland-Hodgman; a pass at most
/// doubles the count (rounding on near-degenerate input), so a pass only runs on
/// <= kCapacity / 2 vertices and never writes out of bounds.
struct ClipBuffer {
    static constexpr std::size_t kCapacity = 4 * ConvexPolygon::kMaxVertices;
    double x[kCapacity];
    double y[kCapacity];
    std::size_t n;

    void load(const ConvexPolygon& p) {
        n = p.n;
        for (std::size_t i = 0; i < p.n; ++i) {
            x[i] = p.v[i].x();
            y[i] = p.v[i].y();
        }
    }
    /// Area of the vertex loop (either order).
    double area() const {
        if (n < 3) return 0.0;
        double twice = 0.0;
        for (std::size_t i = 0, j = n - 1; i < n; j = i++) twice += x[j] * y[i] - x[i] * y[j];
        return 0.5 * std::abs(twice);
    }
};

}  // namespace simp::geometry::detail
