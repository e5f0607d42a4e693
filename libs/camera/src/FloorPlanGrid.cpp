#include <simp/camera/FloorPlanGrid.h>
#include <simp/geometry/Footprint.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace simp::camera {

FloorPlanGrid::FloorPlanGrid(const mrpt::maps::COccupancyGridMap2D& grid, double max_free_prob_of_wall)
    : m_x_min(grid.getXMin()), m_y_min(grid.getYMin()), m_res(grid.getResolution()) {
    const int nx = static_cast<int>(grid.getSizeX()), ny = static_cast<int>(grid.getSizeY());
    m_wall = cv::Mat1b::zeros(ny, nx);
    m_free = cv::Mat1b::zeros(ny, nx);
    for (int cy = 0; cy < ny; ++cy)
        for (int cx = 0; cx < nx; ++cx) {
            const float p_free = grid.getCell(cx, cy);
            if (p_free < max_free_prob_of_wall) m_wall(cy, cx) = 255;
            else if (p_free > 1.0 - max_free_prob_of_wall) m_free(cy, cx) = 255;
        }
    // Outside = unknown cells connected (4-neighbours) to the grid's border through unknown cells.
    // Unknown islands enclosed by walls (furniture drawn grey in a floor plan) are inside.
    const cv::Mat1b unknown = ~(m_wall | m_free);
    cv::Mat1i labels;
    const int n_labels = cv::connectedComponents(unknown, labels, 4, CV_32S);
    std::vector<bool> reaches_border(static_cast<std::size_t>(n_labels), false);
    const auto mark = [&](int cx, int cy) {
        if (unknown(cy, cx)) reaches_border[static_cast<std::size_t>(labels(cy, cx))] = true;
    };
    for (int cx = 0; cx < nx; ++cx) mark(cx, 0), mark(cx, ny - 1);
    for (int cy = 0; cy < ny; ++cy) mark(0, cy), mark(nx - 1, cy);
    m_outside = cv::Mat1b::zeros(ny, nx);
    for (int cy = 0; cy < ny; ++cy)
        for (int cx = 0; cx < nx; ++cx)
            if (unknown(cy, cx) && reaches_border[static_cast<std::size_t>(labels(cy, cx))]) m_outside(cy, cx) = 255;
    m_enclosed_unknown_m2 = cv::countNonZero(unknown & ~m_outside) * m_res * m_res;
}

void FloorPlanGrid::clearWallsUnder(const std::vector<geometry::Box3D>& boxes, double margin_m) {
    if (m_wall.empty()) return;
    const int m = static_cast<int>(std::ceil(margin_m / m_res)) + 1;
    const auto cellOf = [&](double v, double v_min) { return static_cast<int>(std::floor((v - v_min) / m_res)); };
    for (const auto& b : boxes) {
        Eigen::Vector2d lo, hi;
        geometry::footprint(b).bounds(lo, hi);
        geometry::Box3D grown = b;  // the box grown by the margin on every side
        grown.size += Eigen::Vector3d::Constant(2.0 * margin_m);
        for (int cy = std::max(0, cellOf(lo.y(), m_y_min) - m); cy <= std::min(m_wall.rows - 1, cellOf(hi.y(), m_y_min) + m); ++cy)
            for (int cx = std::max(0, cellOf(lo.x(), m_x_min) - m); cx <= std::min(m_wall.cols - 1, cellOf(hi.x(), m_x_min) + m); ++cx)
                if (geometry::containsPoint(grown, Eigen::Vector3d(m_x_min + (cx + 0.5) * m_res, m_y_min + (cy + 0.5) * m_res, b.center.z())))
                    m_wall(cy, cx) = 0;
    }
}

bool FloorPlanGrid::cellIsSet(const cv::Mat1b& cells, double x_m, double y_m, bool beyond_grid) const {
    if (cells.empty()) return false;
    const int cx = static_cast<int>(std::floor((x_m - m_x_min) / m_res));
    const int cy = static_cast<int>(std::floor((y_m - m_y_min) / m_res));
    if (cx < 0 || cy < 0 || cx >= cells.cols || cy >= cells.rows) return beyond_grid;
    return cells(cy, cx) != 0;
}

bool FloorPlanGrid::isWall(double x_m, double y_m) const { return cellIsSet(m_wall, x_m, y_m, false); }

bool FloorPlanGrid::isFree(double x_m, double y_m) const { return cellIsSet(m_free, x_m, y_m, false); }

bool FloorPlanGrid::isOutside(double x_m, double y_m) const { return cellIsSet(m_outside, x_m, y_m, true); }

double FloorPlanGrid::castRay(const Eigen::Vector2d& origin_m, const Eigen::Vector2d& dir_in, double max_dist_m) const {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double len = dir_in.norm();
    if (m_wall.empty() || !(len > 0) || !origin_m.allFinite()) return kInf;
    const Eigen::Vector2d dir = dir_in / len;
    // Grid coordinates in cells.
    const double gx = (origin_m.x() - m_x_min) / m_res, gy = (origin_m.y() - m_y_min) / m_res;
    int cx = static_cast<int>(std::floor(gx)), cy = static_cast<int>(std::floor(gy));
    const int step_x = dir.x() >= 0 ? 1 : -1, step_y = dir.y() >= 0 ? 1 : -1;
    const double inv_dx = dir.x() != 0 ? std::abs(1.0 / dir.x()) : kInf;
    const double inv_dy = dir.y() != 0 ? std::abs(1.0 / dir.y()) : kInf;
    // Ray parameter (in cells) to the first vertical / horizontal cell boundary.
    double t_max_x = dir.x() != 0 ? ((step_x > 0 ? (cx + 1 - gx) : (gx - cx)) * inv_dx) : kInf;
    double t_max_y = dir.y() != 0 ? ((step_y > 0 ? (cy + 1 - gy) : (gy - cy)) * inv_dy) : kInf;
    const double t_end = max_dist_m / m_res;
    double t = 0.0;
    while (t <= t_end) {
        if (cx >= 0 && cy >= 0 && cx < m_wall.cols && cy < m_wall.rows) {
            if (m_wall(cy, cx)) return t * m_res;
        } else {
            // Outside the grid: stop once moving away from it.
            if ((cx < 0 && step_x < 0) || (cy < 0 && step_y < 0) || (cx >= m_wall.cols && step_x > 0) ||
                (cy >= m_wall.rows && step_y > 0))
                return kInf;
        }
        if (t_max_x < t_max_y) {
            t = t_max_x;
            t_max_x += inv_dx;
            cx += step_x;
        } else {
            t = t_max_y;
            t_max_y += inv_dy;
            cy += step_y;
        }
    }
    return kInf;
}

}  // namespace simp::camera
