#include <simp/geometry/OrientedRect.h>

#include "ClipBuffer.h"

#include <algorithm>
#include <cmath>

namespace simp::geometry {
namespace {

using detail::ClipBuffer;

/// Sutherland-Hodgman step against one edge of [-h, h] on one axis: keeps u <= h (kUpper)
/// or u >= -h, where u is x (kAlongX) or y. The same rule as clipByEdge in ConvexPolygon.cpp
/// (points on the line are kept), but the signed distance is one subtraction and a new
/// vertex lies exactly on the edge.
template <bool kAlongX, bool kUpper>
void clipAxis(const ClipBuffer& in, double h, ClipBuffer& out) {
    const double* u = kAlongX ? in.x : in.y;
    const double* w = kAlongX ? in.y : in.x;
    double* ou = kAlongX ? out.x : out.y;
    double* ow = kAlongX ? out.y : out.x;
    const double edge = kUpper ? h : -h;
    const std::size_t n = in.n;
    std::size_t m = 0;
    double pu = u[n - 1], pw = w[n - 1];
    double ps = kUpper ? h - pu : pu + h;
    for (std::size_t i = 0; i < n; ++i) {
        const double cu = u[i], cw = w[i];
        const double cs = kUpper ? h - cu : cu + h;
        if ((cs >= 0.0) != (ps >= 0.0)) {  // the edge crosses the line
            ou[m] = edge;
            ow[m] = pw + ps / (ps - cs) * (cw - pw);
            ++m;
        }
        if (cs >= 0.0) {
            ou[m] = cu;
            ow[m] = cw;
            ++m;
        }
        pu = cu;
        pw = cw;
        ps = cs;
    }
    out.n = m;
}

}  // namespace

ConvexPolygon OrientedRect::polygon() const {
    return parallelogram(center, Eigen::Vector2d(c * hx, s * hx), Eigen::Vector2d(-s * hy, c * hy));
}

std::optional<OrientedRect> asRectangle(const ConvexPolygon& p, double rel_tol) {
    if (p.n != 4) return std::nullopt;
    const Eigen::Vector2d e0 = p.v[1] - p.v[0], e1 = p.v[2] - p.v[1], e2 = p.v[3] - p.v[2], e3 = p.v[0] - p.v[3];
    const double l0 = e0.norm(), l1 = e1.norm(), l2 = e2.norm(), l3 = e3.norm();
    const double longest = std::max({l0, l1, l2, l3});
    if (!(std::min({l0, l1, l2, l3}) > 0.0) || !std::isfinite(longest)) return std::nullopt;  // degenerate: generic path
    const double tol = rel_tol * longest;
    if ((e0 + e2).norm() > tol || (e1 + e3).norm() > tol || std::abs(e0.dot(e1)) > tol * longest) return std::nullopt;
    OrientedRect r;
    r.center = 0.25 * (p.v[0] + p.v[1] + p.v[2] + p.v[3]);
    const Eigen::Vector2d axis = (e0 - e2).normalized();  // both sides along x, averaged
    r.c = axis.x();
    r.s = axis.y();
    r.hx = 0.25 * (l0 + l2);
    r.hy = 0.25 * (l1 + l3);
    return r;
}

namespace {

/// Clips `cur` (bounds x0..x1, y0..y1, overlapping the rectangle) to [-hx, hx] x [-hy, hy]
/// and returns the area. Only the edges that cut the bounds clip: a pass by an edge the
/// polygon lies inside of would return it unchanged, so skipping it changes nothing.
double clipToAlignedRect(ClipBuffer* cur, ClipBuffer* next, double x0, double x1, double y0, double y1, double hx,
                         double hy) {
    const auto pass = [&](auto clip) {
        if (cur->n > ClipBuffer::kCapacity / 2) return;  // unreachable for convex input
        clip(*cur, *next);
        std::swap(cur, next);
    };
    if (x1 > hx) pass([hx](const ClipBuffer& in, ClipBuffer& out) { clipAxis<true, true>(in, hx, out); });
    if (cur->n >= 3 && x0 < -hx) pass([hx](const ClipBuffer& in, ClipBuffer& out) { clipAxis<true, false>(in, hx, out); });
    if (cur->n >= 3 && y1 > hy) pass([hy](const ClipBuffer& in, ClipBuffer& out) { clipAxis<false, true>(in, hy, out); });
    if (cur->n >= 3 && y0 < -hy) pass([hy](const ClipBuffer& in, ClipBuffer& out) { clipAxis<false, false>(in, hy, out); });
    return cur->area();
}

}  // namespace

double intersectionAreaWithAlignedRect(const ConvexPolygon& p, double hx, double hy) {
    if (p.n < 3) return 0.0;
    double x0 = p.v[0].x(), x1 = x0, y0 = p.v[0].y(), y1 = y0;
    for (std::size_t i = 1; i < p.n; ++i) {
        x0 = std::min(x0, p.v[i].x());
        x1 = std::max(x1, p.v[i].x());
        y0 = std::min(y0, p.v[i].y());
        y1 = std::max(y1, p.v[i].y());
    }
    // Separating axis along x or y: the bounds are outside (touching gives area 0).
    if (x0 >= hx || x1 <= -hx || y0 >= hy || y1 <= -hy) return 0.0;
    ClipBuffer buf1, buf2;
    buf1.load(p);
    return clipToAlignedRect(&buf1, &buf2, x0, x1, y0, y1, hx, hy);
}

namespace {

/// Length of [lo, hi] (0 when empty).
inline double span(double lo, double hi) { return std::max(0.0, hi - lo); }

/// Area of a (centre (cx, cy), unit x axis (c, s) with c > 0, s > 0, half sides ax, ay) and
/// [-hx, hx] x [-hy, hy], by Green's theorem: the area is the integral of x dy counter-clockwise
/// around the intersection, whose boundary is the part of each rectangle's boundary inside the
/// other. The aligned rectangle's horizontal edges add nothing (dy = 0); its vertical ones add
/// hx times the length of a's cross-section at x = +-hx. Each of a's edges, as the centre of the
/// edge plus tau times its unit direction, is cut to the tau interval inside the aligned one:
/// products with 1/c and 1/s (shared by all four edges) and min / max: no branch on where the
/// vertices fall (the clipping's branches cost mispredictions in the sensor model's loop).
double alignedIntersectionByGreen(double cx, double cy, double c, double s, double ax, double ay, double hx,
                                  double hy) {
    const double rc = 1.0 / c, rs = 1.0 / s;
    const double ux = c * ax, uy = s * ax, vx = -s * ay, vy = c * ay;  // half axes
    double twice_area = 0.0;
    // Edges along (c, s), centred at centre -+ v (the first traversed along, the second against it).
    for (const double sign : {-1.0, 1.0}) {
        const double mx = cx + sign * vx, my = cy + sign * vy;
        const double lo = std::max({-ax, (-hx - mx) * rc, (-hy - my) * rs});
        const double hi = std::min({ax, (hx - mx) * rc, (hy - my) * rs});
        // integral of x dy along (c, s) over [lo, hi]: s (hi - lo) (mx + c (lo + hi) / 2)
        twice_area -= sign * s * span(lo, hi) * (2.0 * mx + c * (lo + hi));
    }
    // Edges along (-s, c), centred at centre +- u (the first traversed along, the second against it).
    for (const double sign : {1.0, -1.0}) {
        const double mx = cx + sign * ux, my = cy + sign * uy;
        const double lo = std::max({-ay, (mx - hx) * rs, (-hy - my) * rc});
        const double hi = std::min({ay, (mx + hx) * rs, (hy - my) * rc});
        // integral of x dy along (-s, c) over [lo, hi]: c (hi - lo) (mx - s (lo + hi) / 2)
        twice_area += sign * c * span(lo, hi) * (2.0 * mx - s * (lo + hi));
    }
    // The aligned rectangle's vertical edges: a's cross-section at x = X is y - cy within both slabs
    // |c dX + s w| <= ax and |-s dX + c w| <= ay (dX = X - cx, w = y - cy).
    const double half1 = ax * rs, half2 = ay * rc;
    for (const double x : {-hx, hx}) {
        const double dx = x - cx;
        const double mid1 = cy - c * dx * rs, mid2 = cy + s * dx * rc;
        const double lo = std::max({-hy, mid1 - half1, mid2 - half2});
        const double hi = std::min({hy, mid1 + half1, mid2 + half2});
        twice_area += 2.0 * hx * span(lo, hi);
    }
    return 0.5 * twice_area;
}

}  // namespace

double intersectionAreaWithAlignedRect(const OrientedRect& a, double hx, double hy) {
    // a's half axes; its bounds follow from them without visiting the vertices.
    const double ux = a.c * a.hx, uy = a.s * a.hx, vx = -a.s * a.hy, vy = a.c * a.hy;
    const double ex = std::abs(ux) + std::abs(vx), ey = std::abs(uy) + std::abs(vy);
    const double cx = a.center.x(), cy = a.center.y();
    const double x0 = cx - ex, x1 = cx + ex, y0 = cy - ey, y1 = cy + ey;
    // Separating axes: the aligned rectangle's are the bounds (the cheapest, tried first); then a's
    // two, where the aligned rectangle's extent is hx |c| + hy |s| along a's x axis (as separated()
    // computes it for an unrotated second rectangle, without the two axes the bounds tested).
    if (x0 >= hx || x1 <= -hx || y0 >= hy || y1 <= -hy) return 0.0;
    const double ac = std::abs(a.c), as = std::abs(a.s);
    if (std::abs(a.c * cx + a.s * cy) >= a.hx + hx * ac + hy * as) return 0.0;
    if (std::abs(a.c * cy - a.s * cx) >= a.hy + hx * as + hy * ac) return 0.0;
    // The same rectangle with its x axis in the first quadrant (turned by a multiple of pi / 2,
    // the half sides swapped for an odd one): c > 0, s >= 0.
    double c = a.c, s = a.s, ax = a.hx, ay = a.hy;
    if (c < 0.0) c = -c, s = -s;
    if (s < 0.0) {
        const double t = c;
        c = -s, s = t;
        std::swap(ax, ay);
    }
    // Green's theorem divides by c and s: where the box is within ~0.01 rad of the axes (4-6 % of
    // the overlapping pairs of a localization run, measured: a detection is turned about as its
    // object), the crossings of its nearly axis-parallel edges would be off by rounding / sin, so
    // it is clipped.
    constexpr double kMinSinCos = 0.01;
    if (std::min(c, s) < kMinSinCos) {
        ClipBuffer buf1, buf2;
        buf1.n = 4;
        buf1.x[0] = cx - ux - vx;
        buf1.y[0] = cy - uy - vy;
        buf1.x[1] = cx + ux - vx;
        buf1.y[1] = cy + uy - vy;
        buf1.x[2] = cx + ux + vx;
        buf1.y[2] = cy + uy + vy;
        buf1.x[3] = cx - ux + vx;
        buf1.y[3] = cy - uy + vy;
        return clipToAlignedRect(&buf1, &buf2, x0, x1, y0, y1, hx, hy);
    }
    return alignedIntersectionByGreen(cx, cy, c, s, ax, ay, hx, hy);
}

}  // namespace simp::geometry
