#include <simp/geometry/ConvexPolygon.h>

#include "ClipBuffer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace simp::geometry {
namespace {

inline double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

using detail::ClipBuffer;

/// Twice the signed area (> 0 counter-clockwise) of a polygon's vertex loop.
inline double twiceSignedArea(const ConvexPolygon& p) {
    if (p.n < 3) return 0.0;
    double twice = 0.0;
    for (std::size_t i = 0, j = p.n - 1; i < p.n; j = i++) twice += p.v[j].x() * p.v[i].y() - p.v[i].x() * p.v[j].y();
    return twice;
}

/// Sutherland-Hodgman step: keeps the part of `in` left of the directed line
/// (ax, ay) -> (ax + ex, ay + ey). Points on the line are kept. The count lives in a
/// register (a local), not in `out`, which the compiler could not keep there.
inline void clipByEdge(const ClipBuffer& in, double ax, double ay, double ex, double ey, ClipBuffer& out) {
    const std::size_t n = in.n;
    std::size_t m = 0;
    double px = in.x[n - 1], py = in.y[n - 1];
    double ps = ex * (py - ay) - ey * (px - ax);
    for (std::size_t i = 0; i < n; ++i) {
        const double cx = in.x[i], cy = in.y[i];
        const double cs = ex * (cy - ay) - ey * (cx - ax);
        if ((cs >= 0.0) != (ps >= 0.0)) {  // the edge crosses the line
            const double t = ps / (ps - cs);
            out.x[m] = px + t * (cx - px);
            out.y[m] = py + t * (cy - py);
            ++m;
        }
        if (cs >= 0.0) {
            out.x[m] = cx;
            out.y[m] = cy;
            ++m;
        }
        px = cx;
        py = cy;
        ps = cs;
    }
    out.n = m;
}

/// Exact intersection area of a with b; `b_ccw` tells b's vertex order (a's does not matter).
double clipArea(const ConvexPolygon& a, const ConvexPolygon& b, bool b_ccw) {
    ClipBuffer buf1, buf2;
    buf1.load(a);
    ClipBuffer* cur = &buf1;
    ClipBuffer* next = &buf2;
    for (std::size_t i = 0, j = b.n - 1; i < b.n; j = i++) {
        // Edge j -> i of b, reversed when b is clockwise, so b's inside is on its left.
        const Eigen::Vector2d& from = b_ccw ? b.v[j] : b.v[i];
        const Eigen::Vector2d& to = b_ccw ? b.v[i] : b.v[j];
        if (cur->n > ClipBuffer::kCapacity / 2) break;  // unreachable for convex input (<= 32)
        clipByEdge(*cur, from.x(), from.y(), to.x() - from.x(), to.y() - from.y(), *next);
        std::swap(cur, next);
        if (cur->n < 3) return 0.0;
    }
    return cur->area();
}

}  // namespace

void ConvexPolygon::throwFull() {
    throw std::length_error("simp::geometry::ConvexPolygon::push: more than kMaxVertices = " +
                            std::to_string(kMaxVertices) + " vertices");
}

double ConvexPolygon::area() const { return 0.5 * std::abs(twiceSignedArea(*this)); }

Eigen::Vector2d ConvexPolygon::centroid() const {
    if (n == 0) return Eigen::Vector2d::Zero();
    double twice = 0.0;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const double w = v[j].x() * v[i].y() - v[i].x() * v[j].y();
        twice += w;
        c += w * (v[j] + v[i]);
    }
    if (std::abs(twice) < 1e-15) {  // degenerate: mean of the vertices
        Eigen::Vector2d m = Eigen::Vector2d::Zero();
        for (std::size_t i = 0; i < n; ++i) m += v[i];
        return m / static_cast<double>(n);
    }
    return c / (3.0 * twice);
}

void ConvexPolygon::bounds(Eigen::Vector2d& lo, Eigen::Vector2d& hi) const {
    lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (std::size_t i = 0; i < n; ++i) {
        lo = lo.cwiseMin(v[i]);
        hi = hi.cwiseMax(v[i]);
    }
}

ConvexPolygon ConvexPolygon::transformed(double c, double s, const Eigen::Vector2d& t) const {
    ConvexPolygon out;
    out.n = n;
    for (std::size_t i = 0; i < n; ++i)
        out.v[i] = Eigen::Vector2d(c * v[i].x() - s * v[i].y() + t.x(), s * v[i].x() + c * v[i].y() + t.y());
    return out;
}

ConvexPolygon convexHull(const Eigen::Vector2d* points, std::size_t count) {
    // Andrew's monotone chain; count <= kMaxVertices keeps the output bounded.
    if (count > ConvexPolygon::kMaxVertices)
        throw std::length_error("simp::geometry::convexHull: " + std::to_string(count) +
                                " points, at most kMaxVertices = " + std::to_string(ConvexPolygon::kMaxVertices));
    std::array<Eigen::Vector2d, ConvexPolygon::kMaxVertices> p;
    std::copy(points, points + count, p.begin());
    std::sort(p.begin(), p.begin() + count, [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    std::array<Eigen::Vector2d, 2 * ConvexPolygon::kMaxVertices> h;
    std::size_t k = 0;
    for (std::size_t i = 0; i < count; ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = count, lower = k + 1; i-- > 1;) {
        while (k >= lower && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
        h[k++] = p[i - 1];
    }
    ConvexPolygon out;
    const std::size_t m = k > 1 ? k - 1 : k;
    for (std::size_t i = 0; i < m && i < ConvexPolygon::kMaxVertices; ++i) out.push(h[i]);
    return out;
}

ConvexPolygon makeRectangle(const Eigen::Vector2d& center, double lx, double ly, double yaw_rad) {
    const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
    return parallelogram(center, Eigen::Vector2d(c * lx / 2, s * lx / 2), Eigen::Vector2d(-s * ly / 2, c * ly / 2));
}

ConvexPolygon parallelogram(const Eigen::Vector2d& center, const Eigen::Vector2d& ax, const Eigen::Vector2d& ay) {
    ConvexPolygon r;
    r.push(center - ax - ay);
    r.push(center + ax - ay);
    r.push(center + ax + ay);
    r.push(center - ax + ay);
    return r;
}

double intersectionArea(const ConvexPolygon& a, const ConvexPolygon& b) {
    if (a.n < 3 || b.n < 3) return 0.0;
    return clipArea(a, b, twiceSignedArea(b) >= 0.0);
}

double iou(const ConvexPolygon& a, const ConvexPolygon& b) {
    if (a.n < 3 || b.n < 3) return 0.0;
    const double twice_b = twiceSignedArea(b);
    const double area_a = 0.5 * std::abs(twiceSignedArea(a)), area_b = 0.5 * std::abs(twice_b);
    if (std::isnan(area_a) || std::isnan(area_b)) return std::numeric_limits<double>::quiet_NaN();
    if (area_a <= 0.0 || area_b <= 0.0) return 0.0;
    const double inter = clipArea(a, b, twice_b >= 0.0);
    const double uni = area_a + area_b - inter;
    return uni > 0.0 ? std::clamp(inter / uni, 0.0, 1.0) : 0.0;
}

}  // namespace simp::geometry
