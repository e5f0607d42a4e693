#pragma once
/// \file SimpPixels.h
/// Geometry of the authors' map files (PRBonn/SIMP `global_variance.json`, `floor.config`):
/// their pixel convention and the rectangle fit that turns 4 footprint corners into a box.

#include <Eigen/Core>

#include <array>

namespace simp::world {

/// The authors' pixel convention (their GMAP.world2map / map2world):
///   u = round((x - origin_x) / res),  v = rows - round((y - origin_y) / res)
/// (`rows`, not `rows - 1`; v grows downwards). Integer (u, v) is therefore the top-left
/// corner of ROS map_server pixel (u, v), half a pixel from that pixel's centre.
struct SimpPixelFrame {
    double resolution_m = 0.05;
    double origin_x_m = 0, origin_y_m = 0;  ///< map_server origin (bottom-left image corner)
    int rows = 0;                           ///< image height (px)

    /// Continuous (unrounded) pixel coordinates of a world point.
    Eigen::Vector2d toPixel(const Eigen::Vector2d& xy_m) const;
    /// Pixel coordinates as the authors write corners: rounded half to even (numpy.round).
    Eigen::Vector2i toPixelRounded(const Eigen::Vector2d& xy_m) const;
    /// World point of (possibly fractional) pixel coordinates; exact inverse of toPixel.
    Eigen::Vector2d toWorld(const Eigen::Vector2d& uv_px) const;
};

/// A rectangle fitted to 4 corners given in order around it (either direction).
struct RectangleFit {
    Eigen::Vector2d center_m{Eigen::Vector2d::Zero()};
    double yaw_rad = 0;        ///< direction of the side `length_x_m`, in (-pi/4, pi/4]
    double length_x_m = 0;     ///< side length along yaw
    double length_y_m = 0;     ///< side length across
};

/// Least-squares style rectangle fit to a quadrilateral whose corners were rounded to pixels:
/// centre = mean of the corners; direction = length-weighted circular mean of the 4 edge
/// directions modulo 90 deg (angles times 4); half sides = mean absolute projections of the
/// corners on the two axes. On the simp-office map every fitted corner lies within 0.48 px
/// of the published one, so rounding the fit reproduces the published corners.
/// \throw std::invalid_argument when a number is not finite or the rectangle is degenerate.
RectangleFit fitRectangle(const std::array<Eigen::Vector2d, 4>& corners_m);

}  // namespace simp::world
