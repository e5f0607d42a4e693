#include <simp/camera/ZBufferVisibility.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace simp::camera {
namespace {

// Box faces as corner indices (Box3D numbering: bit0 = x, bit1 = y, bit2 = z sign).
constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};

/// Clips a polygon (camera frame) against z >= near; returns the vertex count (<= n + 1 per plane).
int clipNear(const Eigen::Vector3d* in, int n, double near, Eigen::Vector3d* out) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d& a = in[i];
        const Eigen::Vector3d& b = in[(i + 1) % n];
        const bool a_in = a.z() >= near, b_in = b.z() >= near;
        if (a_in) out[m++] = a;
        if (a_in != b_in) {
            const double t = (near - a.z()) / (b.z() - a.z());
            out[m++] = a + t * (b - a);
        }
    }
    return m;
}

/// The part of an open-below box that hides (Occluders.h): its top kOpenBelowTop_m, along the box
/// axis closest to the world's vertical.
geometry::Box3D occludingTopOf(const geometry::Box3D& box) {
    int up = 0;
    for (int a = 1; a < 3; ++a)
        if (std::abs(box.R(2, a)) > std::abs(box.R(2, up))) up = a;
    geometry::Box3D top = box;
    const double t = std::min(kOpenBelowTop_m, box.size[up]);
    top.size[up] = t;
    top.center += box.R.col(up) * (box.R(2, up) >= 0 ? 1.0 : -1.0) * 0.5 * (box.size[up] - t);
    return top;
}

}  // namespace

void ZBufferRenderer::rasterizePolygon(const Eigen::Vector3d* p, int n, int object) {
    // Fan triangulation; p[i] = (u, v, 1/z) in z-buffer pixel units.
    for (int t = 1; t + 1 < n; ++t) {
        const Eigen::Vector3d& a = p[0];
        const Eigen::Vector3d& b = p[t];
        const Eigen::Vector3d& c = p[t + 1];
        const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
        if (std::abs(area) < 1e-12) continue;
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}) - 0.5)));
        const int x1 = std::min(m_w - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}) - 0.5)));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}) - 0.5)));
        const int y1 = std::min(m_h - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}) - 0.5)));
        const double inv_area = 1.0 / area;
        for (int y = y0; y <= y1; ++y) {
            const double py = y + 0.5;
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5;
                // Barycentric weights (sign-normalized by the area: either winding works).
                const double w0 = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) * inv_area;
                const double w1 = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) * inv_area;
                const double w2 = 1.0 - w0 - w1;
                if (w0 < 0 || w1 < 0 || w2 < 0) continue;
                const double inv_z = w0 * a.z() + w1 * b.z() + w2 * c.z();  // 1/z is affine in screen space
                if (!(inv_z > 0)) continue;
                const float z = static_cast<float>(1.0 / inv_z);
                const int idx = y * m_w + x;
                if (m_depth_only) {  // the hiding part of an open-below box
                    if (z < m_depth[idx]) m_depth[idx] = z, m_id[idx] = object;
                    continue;
                }
                if (m_pass == 1) {  // visibility against the final z-buffer, own group transparent
                    if (m_stamp_visible[idx] == object) continue;
                    m_stamp_visible[idx] = object;
                    if (seeThrough(object)) {  // in front of every occluder and wall, or its own top in front
                        if (z < m_depth[idx] || m_id[idx] == object) ++(*m_out)[object].visible_px;
                        continue;
                    }
                    const int front = m_id[idx];
                    if (front == object) {
                        ++(*m_out)[object].visible_px;
                        continue;
                    }
                    if (front < 0) continue;
                    const auto o = static_cast<std::size_t>(object), f = static_cast<std::size_t>(front);
                    if (m_group != nullptr && (*m_group)[o] >= 0 && (*m_group)[f] == (*m_group)[o]) {
                        ++(*m_out)[object].visible_px;
                        continue;
                    }
                    if (m_unhidden_by != nullptr && z < m_wall_depth[idx] &&
                        std::binary_search((*m_unhidden_by)[o].begin(), (*m_unhidden_by)[o].end(), front)) {
                        ++(*m_out)[object].visible_px;
                        ++(*m_out)[object].unhidden_px;
                    }
                    continue;
                }
                if (m_stamp[idx] != object) {
                    m_stamp[idx] = object;
                    ++(*m_out)[object].covered_px;
                }
                if (z < m_wall_depth[idx] && m_stamp_unwalled[idx] != object) {
                    m_stamp_unwalled[idx] = object;
                    ++(*m_out)[object].unwalled_px;
                }
                if (z < m_depth[idx] && !seeThrough(object)) {
                    m_depth[idx] = z;
                    m_id[idx] = object;
                }
            }
        }
    }
}

void ZBufferRenderer::render(const PinholeCamera& cam, const std::vector<geometry::Box3D>& boxes,
                             const FloorPlanGrid* walls, const ZBufferParams& prm, std::vector<BoxView>& out) {
    int ds = std::max(1, prm.downscale);
    const auto pixelsAt = [&](int d) {
        return static_cast<long>((cam.widthPx() + d - 1) / d) * static_cast<long>((cam.heightPx() + d - 1) / d);
    };
    while (pixelsAt(ds) > kMaxRenderedPixels) ++ds;  // memory bounded whatever the image size
    m_w = (cam.widthPx() + ds - 1) / ds;
    m_h = (cam.heightPx() + ds - 1) / ds;
    const std::size_t npx = static_cast<std::size_t>(m_w) * m_h;
    m_depth.assign(npx, std::numeric_limits<float>::infinity());
    m_id.assign(npx, -1);
    m_stamp.assign(npx, -1);
    m_stamp_unwalled.assign(npx, -1);
    out.assign(boxes.size(), BoxView{});
    m_out = &out;

    const Eigen::Matrix3d R_wc = cam.world_T_camera.linear();
    const Eigen::Vector3d t_wc = cam.world_T_camera.translation();
    const Eigen::Isometry3d camera_T_world = cam.world_T_camera.inverse();

    // Walls: the horizontal distance to the first wall along each pixel's own ray
    // (walls_per_pixel), or along its column's ray at the principal row (one cast per column); per
    // pixel the camera depth at that horizontal distance.
    if (walls != nullptr && !walls->empty()) {
        for (int x = 0; x < m_w; ++x) {
            const double xn = ((x + 0.5) * ds - cam.cx()) / cam.fx();
            double r_column = 0;
            if (!prm.walls_per_pixel) {
                const Eigen::Vector2d h_col = (R_wc * Eigen::Vector3d(xn, 0.0, 1.0)).head<2>();
                if (h_col.norm() < 1e-9) continue;
                r_column = walls->castRay(t_wc.head<2>(), h_col, prm.max_distance_m);
                if (!std::isfinite(r_column)) continue;
            }
            for (int y = 0; y < m_h; ++y) {
                const double yn = ((y + 0.5) * ds - cam.cy()) / cam.fy();
                const Eigen::Vector3d d = R_wc * Eigen::Vector3d(xn, yn, 1.0);  // camera depth z = 1
                const double h = d.head<2>().norm();
                if (h < 1e-9) continue;
                const double r = prm.walls_per_pixel ? walls->castRay(t_wc.head<2>(), d.head<2>(), prm.max_distance_m) : r_column;
                if (std::isfinite(r)) m_depth[y * m_w + x] = static_cast<float>(r / h + prm.wall_depth_margin_m);
            }
        }
    }

    m_wall_depth = m_depth;  // walls only, before the boxes

    std::array<Eigen::Vector3d, 8> c_cam;
    std::array<Eigen::Vector3d, 8> face_in, face_clip, face_px;
    // Rasterizes the faces of `corners_cam` (camera frame) for box k; returns the projected 2D
    // bounding box (image pixels) through the u/v bounds.
    const auto rasterizeBox = [&](const std::array<Eigen::Vector3d, 8>& corners_cam, int k, double& u_min, double& u_max,
                                  double& v_min, double& v_max) {
        for (const auto& f : kFaces) {
            for (int i = 0; i < 4; ++i) face_in[i] = corners_cam[f[i]];
            const int n = clipNear(face_in.data(), 4, prm.near_plane_m, face_clip.data());
            for (int i = 0; i < n; ++i) {
                const Eigen::Vector3d& q = face_clip[i];
                const double u = cam.fx() * q.x() / q.z() + cam.cx();
                const double v = cam.fy() * q.y() / q.z() + cam.cy();
                u_min = std::min(u_min, u), u_max = std::max(u_max, u);
                v_min = std::min(v_min, v), v_max = std::max(v_max, v);
                face_px[i] = Eigen::Vector3d(u / ds, v / ds, 1.0 / q.z());
            }
            if (n >= 3) rasterizePolygon(face_px.data(), n, k);
        }
    };
    m_group = prm.group != nullptr && prm.group->size() == boxes.size() ? prm.group : nullptr;
    m_occludes = prm.occludes != nullptr && prm.occludes->size() == boxes.size() ? prm.occludes : nullptr;
    m_unhidden_by = prm.unhidden_by != nullptr && prm.unhidden_by->size() == boxes.size() ? prm.unhidden_by : nullptr;
    const bool per_box_pass = m_group != nullptr || m_unhidden_by != nullptr;  // every box in pass 1
    bool any_see_through = false;
    for (std::size_t k = 0; k < boxes.size() && !any_see_through; ++k) any_see_through = seeThrough(static_cast<int>(k));
    const int n_pass = per_box_pass || any_see_through ? 2 : 1;
    if (n_pass == 2) m_stamp_visible.assign(npx, -1);
    for (m_pass = 0; m_pass < n_pass; ++m_pass)
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        if (m_pass == 1 && !per_box_pass && !seeThrough(static_cast<int>(k))) continue;  // counted from m_id
        const geometry::Box3D& box = boxes[k];
        BoxView& view = out[k];
        view.distance_m = (box.center - t_wc).norm();
        if (view.distance_m - 0.5 * box.size.norm() > prm.max_distance_m) continue;
        const auto corners = box.corners();
        bool any_in_front = false;
        for (int i = 0; i < 8; ++i) {
            c_cam[i] = camera_T_world * corners[i];
            any_in_front |= c_cam[i].z() >= prm.near_plane_m;
        }
        if (!any_in_front) continue;
        double u_min = std::numeric_limits<double>::infinity(), v_min = u_min, u_max = -u_min, v_max = -u_min;
        rasterizeBox(c_cam, static_cast<int>(k), u_min, u_max, v_min, v_max);
        if (m_pass == 0 && m_occludes != nullptr && (*m_occludes)[k] == kOpenBelow) {
            const auto top = occludingTopOf(box).corners();
            for (int i = 0; i < 8; ++i) c_cam[i] = camera_T_world * top[i];
            double tu0 = u_min, tu1 = u_max, tv0 = v_min, tv1 = v_max;  // the top's bounds are not the box's
            m_depth_only = true;
            rasterizeBox(c_cam, static_cast<int>(k), tu0, tu1, tv0, tv1);
            m_depth_only = false;
        }
        // Truncation: fraction of the projected 2D bounding box outside the image.
        const double area = (u_max - u_min) * (v_max - v_min);
        const double iw = std::max(0.0, std::min(u_max, double(cam.widthPx())) - std::max(u_min, 0.0));
        const double ih = std::max(0.0, std::min(v_max, double(cam.heightPx())) - std::max(v_min, 0.0));
        view.truncated_fraction = area > 0 ? std::clamp(1.0 - iw * ih / area, 0.0, 1.0) : 1.0;
    }
    if (!per_box_pass)
        for (std::size_t i = 0; i < npx; ++i)
            if (m_id[i] >= 0 && !seeThrough(m_id[i])) ++out[m_id[i]].visible_px;  // an open-below box counted itself in pass 1
    m_pass = 0;
    m_out = nullptr;
    m_occludes = nullptr;
    m_unhidden_by = nullptr;
}

}  // namespace simp::camera
