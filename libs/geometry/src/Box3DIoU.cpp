#include <simp/geometry/Box3DIoU.h>
#include <simp/geometry/ConvexPolygon.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace simp::geometry {
namespace {

/// A face of the clipped polyhedron: vertices counter-clockwise seen from outside.
/// A face of the final solid (at most 12 faces) has at most 11 vertices; the
/// extra room absorbs near-duplicate vertices produced by rounding.
struct Face {
    static constexpr int kCapacity = 24;
    std::array<Eigen::Vector3d, kCapacity> p;
    int n = 0;
    void push(const Eigen::Vector3d& q) {
        if (n < kCapacity) p[n++] = q;
    }
};

/// The intersection of a box with k half-spaces has at most 6 + k faces.
struct Polyhedron {
    static constexpr int kCapacity = 12;
    std::array<Face, kCapacity> f;
    int n = 0;
};

/// Points where a cut meets the solid; their 2D convex hull is the cap face.
struct CapPoints {
    static constexpr int kCapacity = 2 * Polyhedron::kCapacity * Face::kCapacity;
    std::array<Eigen::Vector3d, kCapacity> p;
    int n = 0;
    void push(const Eigen::Vector3d& q) {
        if (n < kCapacity) p[n++] = q;
    }
};

/// The axis-aligned box [-half, half] as 6 outward-oriented quads.
Polyhedron makeBoxPolyhedron(const Eigen::Vector3d& half) {
    Polyhedron poly;
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // e_u x e_v = e_axis
        for (const double s : {-1.0, 1.0}) {
            Face& face = poly.f[poly.n++];
            // Corners of the face, counter-clockwise about s * e_axis.
            const double us[4] = {-1, 1, 1, -1};
            const double vs[4] = {-1, -1, 1, 1};
            for (int c = 0; c < 4; ++c) {
                Eigen::Vector3d q;
                q[axis] = s * half[axis];
                q[u] = us[c] * half[u];
                q[v] = s * vs[c] * half[v];  // mirror for the -axis face to keep it outward
                face.push(q);
            }
        }
    }
    return poly;
}

/// Keeps the part of `face` with normal . x <= d; the points where its edges cross the
/// plane go to `cap`. Only crossings: for a convex solid cut by a plane they are exactly
/// the vertices of the cross-section (a vertex on the plane whose edges all go inside
/// would be a maximum of normal . x, so nothing would be outside). Adding kept vertices
/// merely close to the plane would let the cap overlap a face nearly parallel to it.
void clipFace(const Face& face, const Eigen::Vector3d& normal, double d, Face& out, CapPoints& cap) {
    out.n = 0;
    Eigen::Vector3d prev = face.p[face.n - 1];
    double prev_d = normal.dot(prev) - d;
    for (int i = 0; i < face.n; ++i) {
        const Eigen::Vector3d& cur = face.p[i];
        const double cur_d = normal.dot(cur) - d;
        if ((cur_d <= 0.0) != (prev_d <= 0.0)) {
            const Eigen::Vector3d x = prev + (prev_d / (prev_d - cur_d)) * (cur - prev);
            out.push(x);
            cap.push(x);
        }
        if (cur_d <= 0.0) out.push(cur);
        prev = cur;
        prev_d = cur_d;
    }
}

/// The cap polygon: convex hull of the cut points in the plane, counter-clockwise seen from +normal.
void makeCap(const CapPoints& pts, const Eigen::Vector3d& normal, Face& cap) {
    cap.n = 0;
    if (pts.n < 3) return;
    // Basis (u, v) of the plane with u x v = normal.
    const Eigen::Vector3d u = normal.unitOrthogonal();
    const Eigen::Vector3d v = normal.cross(u);
    std::array<int, CapPoints::kCapacity> idx;
    std::array<Eigen::Vector2d, CapPoints::kCapacity> q;
    for (int i = 0; i < pts.n; ++i) {
        idx[i] = i;
        q[i] = Eigen::Vector2d(u.dot(pts.p[i]), v.dot(pts.p[i]));
    }
    std::sort(idx.begin(), idx.begin() + pts.n, [&](int a, int b) {
        return q[a].x() < q[b].x() || (q[a].x() == q[b].x() && q[a].y() < q[b].y());
    });
    auto turn = [&](int o, int a, int b) {
        return (q[a].x() - q[o].x()) * (q[b].y() - q[o].y()) - (q[a].y() - q[o].y()) * (q[b].x() - q[o].x());
    };
    // Andrew's monotone chain over indices.
    std::array<int, 2 * CapPoints::kCapacity> h;
    int k = 0;
    for (int i = 0; i < pts.n; ++i) {
        while (k >= 2 && turn(h[k - 2], h[k - 1], idx[i]) <= 0) --k;
        h[k++] = idx[i];
    }
    for (int i = pts.n - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && turn(h[k - 2], h[k - 1], idx[i]) <= 0) --k;
        h[k++] = idx[i];
    }
    for (int i = 0; i + 1 < k; ++i) cap.push(pts.p[h[i]]);
}

/// Volume by the divergence theorem over outward-oriented faces.
double volumeOf(const Polyhedron& poly) {
    double six_v = 0.0;
    for (int i = 0; i < poly.n; ++i) {
        const Face& face = poly.f[i];
        for (int j = 1; j + 1 < face.n; ++j) six_v += face.p[0].dot(face.p[j].cross(face.p[j + 1]));
    }
    return six_v / 6.0;
}

void requireValid(const Box3D& box, const char* which) {
    if (!box.isValid())
        throw std::invalid_argument(std::string("simp::geometry::intersectionVolume: ") + which +
                                    " box is invalid (non-finite number, size <= 0 or R not a rotation)");
}

/// Box b expressed in the frame of box a (a becomes axis-aligned at the origin).
void relativePose(const Box3D& a, const Box3D& b, Eigen::Vector3d& center_b, Eigen::Matrix3d& R_b) {
    center_b = a.R.transpose() * (b.center - a.center);
    R_b = a.R.transpose() * b.R;
}

}  // namespace

double intersectionVolumeByClipping(const Box3D& a, const Box3D& b) {
    Eigen::Vector3d cb;
    Eigen::Matrix3d Rb;
    relativePose(a, b, cb, Rb);
    const Eigen::Vector3d ha = 0.5 * a.size, hb = 0.5 * b.size;
    // Separated bounding spheres: nothing to clip.
    if (cb.norm() > ha.norm() + hb.norm()) return 0.0;
    const double eps = 1e-12 * (ha.maxCoeff() + hb.maxCoeff() + cb.norm());

    Polyhedron buf1 = makeBoxPolyhedron(ha), buf2;
    Polyhedron* cur = &buf1;
    Polyhedron* next = &buf2;
    CapPoints cap_points;
    for (int axis = 0; axis < 3; ++axis) {
        for (const double s : {-1.0, 1.0}) {
            // Half-space of b: normal . x <= d with the outward normal of b's face.
            const Eigen::Vector3d normal = s * Rb.col(axis);
            const double d = normal.dot(cb) + hb[axis];
            double max_d = -std::numeric_limits<double>::infinity(), min_d = -max_d;
            for (int i = 0; i < cur->n; ++i)
                for (int j = 0; j < cur->f[i].n; ++j) {
                    const double dist = normal.dot(cur->f[i].p[j]) - d;
                    max_d = std::max(max_d, dist);
                    min_d = std::min(min_d, dist);
                }
            if (max_d <= eps) continue;   // the whole solid is inside: no cut
            if (min_d >= -eps) return 0.0;  // the whole solid is outside (or touches)
            next->n = 0;
            cap_points.n = 0;
            for (int i = 0; i < cur->n; ++i) {
                Face& out = next->f[next->n];
                clipFace(cur->f[i], normal, d, out, cap_points);
                if (out.n >= 3 && next->n < Polyhedron::kCapacity - 1) ++next->n;
            }
            makeCap(cap_points, normal, next->f[next->n]);
            if (next->f[next->n].n >= 3) ++next->n;
            std::swap(cur, next);
        }
    }
    return std::max(0.0, volumeOf(*cur));
}

double intersectionVolume(const Box3D& a, const Box3D& b) {
    requireValid(a, "first");
    requireValid(b, "second");
    Eigen::Vector3d cb;
    Eigen::Matrix3d Rb;
    relativePose(a, b, cb, Rb);
    // Fast path: an axis kb of b parallel to an axis ka of a (both upright about the same axis).
    constexpr double kParallel = 1e-12;  // |sin| of the angle between the axes (rad)
    for (int ka = 0; ka < 3; ++ka) {
        for (int kb = 0; kb < 3; ++kb) {
            const int i = (ka + 1) % 3, j = (ka + 2) % 3;
            if (std::abs(Rb(i, kb)) > kParallel || std::abs(Rb(j, kb)) > kParallel) continue;
            // Overlap along the shared axis.
            const double ha = 0.5 * a.size[ka], hb = 0.5 * b.size[kb];
            const double overlap = std::min(ha, cb[ka] + hb) - std::max(-ha, cb[ka] - hb);
            if (overlap <= 0.0) return 0.0;
            // Footprints in the (i, j) plane: a is axis-aligned, b spanned by its two other axes.
            const ConvexPolygon fa = makeRectangle(Eigen::Vector2d::Zero(), a.size[i], a.size[j], 0.0);
            const int k1 = (kb + 1) % 3, k2 = (kb + 2) % 3;
            const Eigen::Vector2d c2(cb[i], cb[j]);
            const Eigen::Vector2d u1 = 0.5 * b.size[k1] * Eigen::Vector2d(Rb(i, k1), Rb(j, k1));
            const Eigen::Vector2d u2 = 0.5 * b.size[k2] * Eigen::Vector2d(Rb(i, k2), Rb(j, k2));
            ConvexPolygon fb;
            fb.push(c2 - u1 - u2);
            fb.push(c2 + u1 - u2);
            fb.push(c2 + u1 + u2);
            fb.push(c2 - u1 + u2);
            return intersectionArea(fa, fb) * overlap;
        }
    }
    return intersectionVolumeByClipping(a, b);
}

double iou3D(const Box3D& a, const Box3D& b) {
    const double inter = intersectionVolume(a, b);
    const double uni = a.volume() + b.volume() - inter;
    return uni > 0.0 ? std::clamp(inter / uni, 0.0, 1.0) : 0.0;
}

}  // namespace simp::geometry
