#include <simp/geometry/ConvexPolygon.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace simp::geometry {
namespace {

inline double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Sutherland-Hodgman: keeps the part of `subject` left of the directed edge a->b.
// Output capacity: a convex n-gon clipped by a half plane has at most n+1 vertices.
inline void clipByEdge(const ConvexPolygon& subject, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                       ConvexPolygon& out) {
    out.n = 0;
    if (subject.n == 0) return;
    const Eigen::Vector2d edge = b - a;
    auto side = [&](const Eigen::Vector2d& p) { return edge.x() * (p.y() - a.y()) - edge.y() * (p.x() - a.x()); };
    Eigen::Vector2d prev = subject.v[subject.n - 1];
    double prev_side = side(prev);
    for (std::size_t i = 0; i < subject.n; ++i) {
        const Eigen::Vector2d& cur = subject.v[i];
        const double cur_side = side(cur);
        if (cur_side >= 0) {
            if (prev_side < 0 && out.n < ConvexPolygon::kMaxVertices) {
                const double t = prev_side / (prev_side - cur_side);
                out.push(prev + t * (cur - prev));
            }
            if (out.n < ConvexPolygon::kMaxVertices) out.push(cur);
        } else if (prev_side >= 0 && out.n < ConvexPolygon::kMaxVertices) {
            const double t = prev_side / (prev_side - cur_side);
            out.push(prev + t * (cur - prev));
        }
        prev = cur;
        prev_side = cur_side;
    }
}

}  // namespace

double ConvexPolygon::area() const {
    if (n < 3) return 0.0;
    double twice = 0.0;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) twice += v[j].x() * v[i].y() - v[i].x() * v[j].y();
    return 0.5 * std::abs(twice);
}

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
    std::array<Eigen::Vector2d, ConvexPolygon::kMaxVertices> p{};
    count = std::min(count, ConvexPolygon::kMaxVertices);
    std::copy(points, points + count, p.begin());
    std::sort(p.begin(), p.begin() + count,
              [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    std::array<Eigen::Vector2d, 2 * ConvexPolygon::kMaxVertices> h{};
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
    const Eigen::Vector2d ax(c * lx / 2, s * lx / 2), ay(-s * ly / 2, c * ly / 2);
    ConvexPolygon r;
    r.push(center - ax - ay);
    r.push(center + ax - ay);
    r.push(center + ax + ay);
    r.push(center - ax + ay);
    return r;
}

double intersectionArea(const ConvexPolygon& a, const ConvexPolygon& b) {
    if (a.n < 3 || b.n < 3) return 0.0;
    ConvexPolygon buf1 = a, buf2;
    ConvexPolygon* cur = &buf1;
    ConvexPolygon* next = &buf2;
    for (std::size_t i = 0, j = b.n - 1; i < b.n; j = i++) {
        clipByEdge(*cur, b.v[j], b.v[i], *next);
        std::swap(cur, next);
        if (cur->n < 3) return 0.0;
    }
    return cur->area();
}

double iou(const ConvexPolygon& a, const ConvexPolygon& b) {
    const double area_a = a.area(), area_b = b.area();
    if (area_a <= 0.0 || area_b <= 0.0) return 0.0;
    const double inter = intersectionArea(a, b);
    const double uni = area_a + area_b - inter;
    return uni > 0.0 ? std::clamp(inter / uni, 0.0, 1.0) : 0.0;
}

}  // namespace simp::geometry
