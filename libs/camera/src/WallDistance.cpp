#include <simp/camera/WallDistance.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <limits>

namespace simp::camera {

WallDistance::WallDistance(const mrpt::maps::COccupancyGridMap2D& grid, float max_free_prob_of_obstacle)
    : m_x_min(grid.getXMin()), m_y_min(grid.getYMin()), m_res(grid.getResolution()) {
    cv::Mat1b free_cells(static_cast<int>(grid.getSizeY()), static_cast<int>(grid.getSizeX()));
    for (int cy = 0; cy < free_cells.rows; ++cy)
        for (int cx = 0; cx < free_cells.cols; ++cx)
            free_cells(cy, cx) = grid.getCell(cx, cy) < max_free_prob_of_obstacle ? 0 : 255;
    cv::distanceTransform(free_cells, m_distance_m, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    m_distance_m *= m_res;
}

bool WallDistance::cellOf(double x_m, double y_m, int& cx, int& cy) const {
    cx = static_cast<int>(std::floor((x_m - m_x_min) / m_res));
    cy = static_cast<int>(std::floor((y_m - m_y_min) / m_res));
    return cx >= 0 && cy >= 0 && cx < m_distance_m.cols && cy < m_distance_m.rows;
}

double WallDistance::at(double x_m, double y_m) const {
    int cx = 0, cy = 0;
    return cellOf(x_m, y_m, cx, cy) ? m_distance_m(cy, cx) : std::numeric_limits<double>::infinity();
}

Eigen::Vector2d WallDistance::gradient(double x_m, double y_m) const {
    int cx = 0, cy = 0;
    if (!cellOf(x_m, y_m, cx, cy) || cx < 1 || cy < 1 || cx >= m_distance_m.cols - 1 || cy >= m_distance_m.rows - 1)
        return Eigen::Vector2d::Zero();
    return {m_distance_m(cy, cx + 1) - m_distance_m(cy, cx - 1), m_distance_m(cy + 1, cx) - m_distance_m(cy - 1, cx)};
}

}  // namespace simp::camera
