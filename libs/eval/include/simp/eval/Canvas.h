#pragma once
/// \file Canvas.h
/// A raster of a rectangle of the world's floor (x right, y up) for the plots: the floor
/// plan drawn in grey, a world -> pixel mapping, a legend panel on the right.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/world/ObjectMapData.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace simp::eval {

struct Canvas {
    cv::Mat3b image;          ///< BGR; the map area is columns [0, map_width_px), the legend is right of it
    int map_width_px = 0;     ///< width of the map area (px)
    int map_height_px = 0;    ///< height of the map area (px); the image may be taller (a long legend)
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

/// Legend entries (label, BGR colour) listed top-down in the legend panel right of the map; the
/// image grows downwards (white) when the entries need more rows than the map has.
void drawLegend(Canvas& canvas, const std::vector<std::pair<std::string, cv::Scalar>>& items);

/// Legend entries of the classes `present` (ids), named from `objects.class_names`.
std::vector<std::pair<std::string, cv::Scalar>> classLegend(const world::ObjectMapData& objects,
                                                           const std::set<int>& present);

/// Outline of a polygon (world frame), with a translucent fill when fill_alpha > 0.
void drawPolygon(Canvas& canvas, const geometry::ConvexPolygon& poly, const cv::Scalar& color, int thickness,
                 double fill_alpha = 0.0);

/// BGR colour of class index i: simp::obs::classColorRgb (the palette of the 3D views too).
cv::Scalar classColor(int i);

/// Length (m) of a scale bar for a map `map_width_m` wide: the largest 1, 2 or 5 x 10^k m not
/// above a fifth of the width (0.1 m at least).
double scaleBarLength(double map_width_m);

/// A scale bar ("1 m", "5 m", ... scaleBarLength) in the map area's bottom-left corner, on a
/// white box so it reads over walls.
void drawScaleBar(Canvas& canvas);

/// Writes a PNG, creating the parent folders. \throw std::runtime_error naming the file.
void writePng(const std::string& path, const cv::Mat& image);

}  // namespace simp::eval
