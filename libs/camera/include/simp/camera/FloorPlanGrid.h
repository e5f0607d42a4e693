#pragma once
/// \file FloorPlanGrid.h
/// The one view of a floor plan as walls / free / outside cells (thresholds: FloorPlanThresholds.h),
/// with 2D ray casting: the occluders of the occlusion renderer (walls extruded vertically
/// without limit), the contacts of wall alignment, the free floor of the mapper's tests.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/camera/FloorPlanThresholds.h>
#include <simp/geometry/Box3D.h>
#include <opencv2/core.hpp>

#include <Eigen/Core>
#include <vector>

namespace simp::camera {

class FloorPlanGrid {
   public:
    FloorPlanGrid() = default;
    /// Cells with free-probability < max_free_prob_of_wall (MRPT getCell(), 0 = occupied) are walls;
    /// unknown cells (0.5) do not block with the default floorplan::kWallMaxFree.
    explicit FloorPlanGrid(const mrpt::maps::COccupancyGridMap2D& grid, double max_free_prob_of_wall = floorplan::kWallMaxFree);

    /// Clears the wall cells whose centre lies in a box's footprint grown by `margin_m` on every side
    /// (at the box's centre height). A ground-truth floor plan that draws furniture outlines would
    /// otherwise hide every object behind its own footprint (labels' visibility_ignore_object_cells).
    void clearWallsUnder(const std::vector<geometry::Box3D>& boxes, double margin_m);

    bool empty() const { return m_wall.empty(); }
    /// True when the world point (m) falls in a wall cell (false outside the grid).
    bool isWall(double x_m, double y_m) const;

    /// True when the world point (m) falls in a known free cell (free-probability above
    /// 1 - max_free_prob_of_wall; false for walls, unknown cells and outside the grid).
    bool isFree(double x_m, double y_m) const;

    /// True when the world point (m) lies outside the building: in an unknown cell connected to
    /// the grid's border through unknown cells, or outside the grid (false without a grid).
    bool isOutside(double x_m, double y_m) const;

    /// Area (m^2) of the unknown cells enclosed by walls (not outside): furniture drawn into the plan.
    double enclosedUnknownArea_m2() const { return m_enclosed_unknown_m2; }

    /// Distance (m) along the horizontal ray from `origin_m` in direction `dir` (need not be unit;
    /// only xy used) to the boundary of the first wall cell, or +infinity when none within max_dist_m.
    /// A ray starting inside a wall cell returns 0. Amanatides-Woo grid traversal.
    double castRay(const Eigen::Vector2d& origin_m, const Eigen::Vector2d& dir, double max_dist_m) const;

    const cv::Mat1b& cells() const { return m_wall; }  ///< row = grid cy (y up), 255 = wall

   private:
    /// True when the world point falls in a non-zero cell of `cells`; `beyond_grid` outside the grid.
    bool cellIsSet(const cv::Mat1b& cells, double x_m, double y_m, bool beyond_grid) const;

    cv::Mat1b m_wall;
    cv::Mat1b m_free;     ///< 255 = known free space
    cv::Mat1b m_outside;  ///< 255 = unknown space connected to the border
    double m_enclosed_unknown_m2 = 0;  ///< computed with m_outside
    double m_x_min = 0, m_y_min = 0, m_res = 0.05;
};

}  // namespace simp::camera
