#pragma once
/// \file WallDistance.h
/// Distance from every cell of an MRPT occupancy grid to its nearest obstacle cell (P(free) below a
/// threshold; kUnknownFree, MRPT's likelihood-field rule, by default), and its gradient: the wall
/// normal at a point near a wall. Used by the LiDAR's beam skipping (ScanLikelihood) and by the
/// scan matcher's constrained directions (IcpPoseTracker).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/camera/FloorPlanThresholds.h>
#include <opencv2/core.hpp>

#include <Eigen/Core>

namespace simp::camera {

class WallDistance {
   public:
    WallDistance() = default;
    explicit WallDistance(const mrpt::maps::COccupancyGridMap2D& grid, float max_free_prob_of_obstacle = floorplan::kUnknownFree);

    /// Distance (m) from the world point's cell to the nearest obstacle cell; +infinity outside the grid.
    double at(double x_m, double y_m) const;
    /// Central difference of the distance at the world point's cell (m per cell, not normalized):
    /// points away from the nearest obstacle; zero on the grid's border cells and outside.
    Eigen::Vector2d gradient(double x_m, double y_m) const;

   private:
    /// Cell (column, row) of a world point; false outside the grid.
    bool cellOf(double x_m, double y_m, int& cx, int& cy) const;

    cv::Mat1f m_distance_m;  ///< row = grid cy
    double m_x_min = 0, m_y_min = 0, m_res = 0.05;
};

}  // namespace simp::camera
