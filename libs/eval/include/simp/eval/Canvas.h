#pragma once
/// \file Canvas.h
/// The one floor-plan renderer of the figures: a raster of a rectangle of the world's floor
/// (x right, y up) with the floor plan drawn in grey and a world -> pixel mapping, plus a strip
/// right of the map for what is not the map (scale bar, legend: ScaleBar.h, Legend.h), so nothing
/// covers the map. Every map figure starts here (doc/figures.md).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>
#include <simp/geometry/Box3D.h>
#include <simp/geometry/ConvexPolygon.h>

#include <limits>

namespace simp::eval {

struct Canvas {
    static constexpr int kStripMargin = 12;  ///< px between the map area and the strip's content

    cv::Mat3b image;          ///< BGR; the map area is columns [0, map_width_px), the strip is right of it
    int map_width_px = 0;     ///< width of the map area (px)
    int map_height_px = 0;    ///< height of the map area (px); the image may be taller (a long legend)
    double x_min_m = 0;       ///< world x of the image's left edge (m)
    double y_max_m = 0;       ///< world y of the image's top edge (m)
    double px_per_m = 40;     ///< scale (px / m)
    int strip_used_px = 0;    ///< rows [0, strip_used_px) of the strip are taken (scale bar, legend)

    /// Pixel of a world point (x right, y up -> column right, row down).
    cv::Point toPixel(double x_m, double y_m) const;
    /// The map area: image pixels [0, map_width_px) x [0, map_height_px).
    cv::Rect mapArea() const { return {0, 0, map_width_px, map_height_px}; }
    /// The map area of `image` (shares its pixels, same coordinates as toPixel): drawing here is
    /// clipped to the map, so what lies beyond the floor plan never reaches the strip.
    cv::Mat3b map() { return image(mapArea()); }
};

/// Grows `canvas.image` with white to the right and downwards until the strip right of the map
/// is at least `strip_width_px` wide and the image at least `height_px` tall; the map stays put.
void ensureStrip(Canvas& canvas, int strip_width_px, int height_px);

/// Canvas showing the floor plan: grey level = probability of free space (white free, black
/// occupied), `px_per_cell` pixels per grid cell, `legend_width_px` white columns on the right.
Canvas makeFloorplanCanvas(const mrpt::maps::COccupancyGridMap2D& grid, int px_per_cell = 2,
                           int legend_width_px = 300);

/// White canvas covering [x_min, x_max] x [y_min, y_max] (m) plus `margin_m` on each side.
Canvas makeBlankCanvas(double x_min_m, double y_min_m, double x_max_m, double y_max_m, double px_per_m,
                       double margin_m = 1.0, int legend_width_px = 300);

/// The extent (m) of what a figure shows; empty until a point is added.
struct WorldBounds {
    double x_min_m = std::numeric_limits<double>::max(), y_min_m = std::numeric_limits<double>::max();
    double x_max_m = -std::numeric_limits<double>::max(), y_max_m = -std::numeric_limits<double>::max();
    void add(double x_m, double y_m);
    /// Adds the centre of `box` (as the figures always have).
    void add(const geometry::Box3D& box) { add(box.center.x(), box.center.y()); }
    bool empty() const { return x_min_m > x_max_m; }
};

/// Floor-plan canvas when `grid` is given and has cells, else a blank canvas over `bounds`
/// ([0, 1] m x [0, 1] m when empty). Note: a default-constructed COccupancyGridMap2D is not empty
/// (MRPT gives it 40 m x 40 m).
Canvas makeCanvasFor(const mrpt::maps::COccupancyGridMap2D* grid, const WorldBounds& bounds);

/// Outline of a polygon (world frame), with a translucent fill when fill_alpha > 0.
void drawPolygon(Canvas& canvas, const geometry::ConvexPolygon& poly, const cv::Scalar& color, int thickness,
                 double fill_alpha = 0.0);

}  // namespace simp::eval
