/// \file Visibility.cpp
#include <simp/geometry/Footprint.h>
#include <simp/labels/BoxProjection.h>
#include <simp/labels/Visibility.h>

#include <cmath>
#include <limits>

namespace simp::labels {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Grid of wall flags: occupied cells minus (optionally) the cells under the objects.
struct WallGrid {
    const mrpt::maps::COccupancyGridMap2D* grid = nullptr;
    std::vector<char> wall;  // size_x * size_y
    int nx = 0, ny = 0;

    bool isWall(int cx, int cy) const {
        return cx >= 0 && cy >= 0 && cx < nx && cy < ny && wall[static_cast<std::size_t>(cy) * nx + cx];
    }
};

WallGrid makeWallGrid(const mrpt::maps::COccupancyGridMap2D& g, const std::vector<geometry::Box3D>& boxes,
                      const VisibilityOptions& o) {
    WallGrid w;
    w.grid = &g;
    w.nx = static_cast<int>(g.getSizeX());
    w.ny = static_cast<int>(g.getSizeY());
    w.wall.assign(static_cast<std::size_t>(w.nx) * w.ny, 0);
    for (int cy = 0; cy < w.ny; ++cy)
        for (int cx = 0; cx < w.nx; ++cx)
            w.wall[static_cast<std::size_t>(cy) * w.nx + cx] = 1.0 - g.getCell(cx, cy) >= o.occupied_threshold ? 1 : 0;  // MRPT stores P(free)
    if (o.ignore_object_cells) {
        const double r = g.getResolution();
        for (const auto& b : boxes) {
            Eigen::Vector2d lo, hi;
            geometry::footprint(b).bounds(lo, hi);
            geometry::Box3D grown = b;  // the box grown by the margin on every side
            grown.size += Eigen::Vector3d::Constant(2.0 * o.object_cell_margin_m);
            const int m = static_cast<int>(std::ceil(o.object_cell_margin_m / r)) + 1;
            for (int cy = std::max(0, g.y2idx(lo.y()) - m); cy <= std::min(w.ny - 1, g.y2idx(hi.y()) + m); ++cy)
                for (int cx = std::max(0, g.x2idx(lo.x()) - m); cx <= std::min(w.nx - 1, g.x2idx(hi.x()) + m); ++cx)
                    if (geometry::containsPoint(grown, Eigen::Vector3d(g.idx2x(cx), g.idx2y(cy), b.center.z())))
                        w.wall[static_cast<std::size_t>(cy) * w.nx + cx] = 0;
        }
    }
    return w;
}

/// Horizontal distance along the ground direction d2 (unit) from o2 to the first wall cell, up to max_m
/// (DDA over the grid cells, Amanatides & Woo).
double wallDistance(const WallGrid& w, const Eigen::Vector2d& o2, const Eigen::Vector2d& d2, double max_m) {
    const auto& g = *w.grid;
    const double r = g.getResolution();
    int cx = g.x2idx(o2.x()), cy = g.y2idx(o2.y());
    const int sx = d2.x() > 0 ? 1 : -1, sy = d2.y() > 0 ? 1 : -1;
    const double x_edge = g.getXMin() + (cx + (sx > 0 ? 1 : 0)) * r, y_edge = g.getYMin() + (cy + (sy > 0 ? 1 : 0)) * r;
    double t_x = d2.x() != 0 ? (x_edge - o2.x()) / d2.x() : kInf, t_y = d2.y() != 0 ? (y_edge - o2.y()) / d2.y() : kInf;
    const double dt_x = d2.x() != 0 ? r / std::abs(d2.x()) : kInf, dt_y = d2.y() != 0 ? r / std::abs(d2.y()) : kInf;
    double t = 0;
    while (t <= max_m) {
        if (w.isWall(cx, cy)) return t;
        if (t_x < t_y) {
            t = t_x, t_x += dt_x, cx += sx;
        } else {
            t = t_y, t_y += dt_y, cy += sy;
        }
        if (cx < -1 || cy < -1 || cx > w.nx || cy > w.ny) break;
    }
    return kInf;
}

}  // namespace

double rayBoxEntry(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, const geometry::Box3D& box) {
    const Eigen::Vector3d o = box.R.transpose() * (origin - box.center), d = box.R.transpose() * dir;
    double t0 = 0, t1 = kInf;
    for (int k = 0; k < 3; ++k) {
        const double h = 0.5 * box.size(k);
        if (std::abs(d(k)) < 1e-15) {
            if (std::abs(o(k)) > h) return kInf;
            continue;
        }
        double a = (-h - o(k)) / d(k), b = (h - o(k)) / d(k);
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
        if (t0 > t1) return kInf;
    }
    return t0;
}

std::vector<double> computeVisibility(const PosedImage& image, const std::vector<geometry::Box3D>& boxes,
                                      const mrpt::maps::COccupancyGridMap2D* floorplan, const VisibilityOptions& o) {
    const std::size_t n = boxes.size();
    std::vector<double> hits(n, 0.0), seen(n, 0.0);
    std::vector<ImageBox> bb(n);
    std::vector<char> candidate(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const auto p = projectBox(image, boxes[i]);
        bb[i] = p.bbox_trunc;
        candidate[i] = p.visible_in_front && area(p.bbox_trunc) > 0;
    }
    WallGrid walls;
    if (floorplan) walls = makeWallGrid(*floorplan, boxes, o);
    const Eigen::Matrix3d Kinv = image.K.inverse();
    const Eigen::Matrix3d R = image.world_T_camera.linear();
    const Eigen::Vector3d origin = image.world_T_camera.translation();
    const int step = std::max(1, o.pixel_step);
    std::vector<double> depth(n);
    for (int v = step / 2; v < image.height; v += step)
        for (int u = step / 2; u < image.width; u += step) {
            const double pu = u + 0.5, pv = v + 0.5;  // pixel centre
            bool any = false;
            for (std::size_t i = 0; i < n; ++i) {
                depth[i] = kInf;
                if (!candidate[i] || pu < bb[i](0) || pu > bb[i](2) || pv < bb[i](1) || pv > bb[i](3)) continue;
                const Eigen::Vector3d dir = R * (Kinv * Eigen::Vector3d(pu, pv, 1.0));  // camera z = 1: s = depth
                depth[i] = rayBoxEntry(origin, dir, boxes[i]);
                any |= std::isfinite(depth[i]);
            }
            if (!any) continue;
            double nearest = kInf;
            for (std::size_t i = 0; i < n; ++i) nearest = std::min(nearest, depth[i]);
            double wall = kInf;
            if (floorplan) {
                const Eigen::Vector3d dir = R * (Kinv * Eigen::Vector3d(pu, pv, 1.0));
                const double horiz = dir.head<2>().norm();
                if (horiz > 1e-12) {
                    const double max_h = std::min(o.max_range_m, nearest * horiz);
                    wall = wallDistance(walls, origin.head<2>(), dir.head<2>() / horiz, max_h) / horiz;
                }
            }
            for (std::size_t i = 0; i < n; ++i) {
                if (!std::isfinite(depth[i])) continue;
                hits[i] += 1;
                if (depth[i] <= nearest && depth[i] < wall) seen[i] += 1;
            }
        }
    std::vector<double> vis(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) vis[i] = hits[i] > 0 ? seen[i] / hits[i] : 0.0;
    return vis;
}

}  // namespace simp::labels
