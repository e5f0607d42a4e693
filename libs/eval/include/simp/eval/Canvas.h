#pragma once
/// \file Canvas.h
/// A raster of a rectangle of the world's floor (x right, y up) for the plots: the floor
/// plan drawn in grey, a world -> pixel mapping, a legend panel on the right.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>
#include <simp/geometry/ConvexPolygon.h>

#include <string>
#include <utility>
#include <vector>

namespace simp::eval {

struct Canvas {
    cv::Mat3b image;          ///< BGR; the map area is columns [0, map_width_px), the legend is right of it
    int map_width_px = 0;     ///< width of the map area (px)
    double x_min_m = 0;       ///< world x of the image's left edge (m)
    double y_max_m = 0;       ///< world y of the image's top edge (m)
    double px_per_m = 40;     ///< scale (px / m)

    /// Pixel of a world point (x right, y up -> column right, row down).
    cv::Point toPixel(double x_m, double y_m) const;
};

/// Canvas showing the floor plan: grey level = probability of free space (white free, black
/// occupied), `px_per_cell` pixels per grid cell, `legend_width_px` white columns on the right.
Canvas makeFloorplanCanvas(const mrpt::maps::COccupancyGridMap2D& grid, int px_per_cell = 2,
                           int legend_width_px = 300);

/// White canvas covering [x_min, x_max] x [y_min, y_max] (m) plus `margin_m` on each side.
Canvas makeBlankCanvas(double x_min_m, double y_min_m, double x_max_m, double y_max_m, double px_per_m,
                       double margin_m = 1.0, int legend_width_px = 300);

/// Floor-plan canvas when `grid` is given and has cells, else a blank canvas over the given bounds
/// (m). Note: a default-constructed COccupancyGridMap2D is not empty (MRPT gives it 40 m x 40 m).
Canvas makeCanvasFor(const mrpt::maps::COccupancyGridMap2D* grid, double x_min_m, double y_min_m,
                     double x_max_m, double y_max_m);

/// Legend entries (label, BGR colour) listed top-down in the legend panel.
void drawLegend(Canvas& canvas, const std::vector<std::pair<std::string, cv::Scalar>>& items);

/// Outline of a polygon (world frame), with a translucent fill when fill_alpha > 0.
void drawPolygon(Canvas& canvas, const geometry::ConvexPolygon& poly, const cv::Scalar& color, int thickness,
                 double fill_alpha = 0.0);

/// A distinct BGR colour for class index i (a fixed 14-colour palette, repeating).
cv::Scalar classColor(int i);

/// Writes a PNG, creating the parent folders. \throw std::runtime_error naming the file.
void writePng(const std::string& path, const cv::Mat& image);

}  // namespace simp::eval
