#include <opencv2/imgproc.hpp>
#include <simp/eval/Canvas.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace simp::eval {

cv::Point Canvas::toPixel(double x_m, double y_m) const {
    return {static_cast<int>(std::lround((x_m - x_min_m) * px_per_m)),
            static_cast<int>(std::lround((y_max_m - y_m) * px_per_m))};
}

void ensureStrip(Canvas& canvas, int strip_width_px, int height_px) {
    const int cols = std::max(canvas.image.cols, canvas.map_width_px + strip_width_px);
    const int rows = std::max(canvas.image.rows, height_px);
    if (cols == canvas.image.cols && rows == canvas.image.rows) return;
    cv::Mat3b grown(rows, cols, cv::Vec3b(255, 255, 255));
    if (!canvas.image.empty()) canvas.image.copyTo(grown(cv::Rect(0, 0, canvas.image.cols, canvas.image.rows)));
    canvas.image = grown;
}

Canvas makeFloorplanCanvas(const mrpt::maps::COccupancyGridMap2D& grid, int px_per_cell, int legend_width_px) {
    const int w = static_cast<int>(grid.getSizeX()), h = static_cast<int>(grid.getSizeY());
    if (w == 0 || h == 0) throw std::invalid_argument("floor plan grid has no cells");
    cv::Mat1b grey(h, w);
    for (int cy = 0; cy < h; ++cy)
        for (int cx = 0; cx < w; ++cx)
            grey(h - 1 - cy, cx) = static_cast<uchar>(std::lround(255.0 * grid.getCell(cx, cy)));
    cv::Mat1b scaled;
    cv::resize(grey, scaled, cv::Size(w * px_per_cell, h * px_per_cell), 0, 0, cv::INTER_NEAREST);
    Canvas c;
    c.map_width_px = scaled.cols;
    c.map_height_px = scaled.rows;
    c.image = cv::Mat3b(scaled.rows, scaled.cols + legend_width_px, cv::Vec3b(255, 255, 255));
    cv::Mat3b map_area = c.image(c.mapArea());
    cv::cvtColor(scaled, map_area, cv::COLOR_GRAY2BGR);
    c.px_per_m = px_per_cell / grid.getResolution();
    c.x_min_m = grid.getXMin();
    c.y_max_m = grid.getYMax();
    return c;
}

Canvas makeBlankCanvas(double x_min_m, double y_min_m, double x_max_m, double y_max_m, double px_per_m,
                       double margin_m, int legend_width_px) {
    Canvas c;
    c.px_per_m = px_per_m;
    c.x_min_m = x_min_m - margin_m;
    c.y_max_m = y_max_m + margin_m;
    c.map_width_px = std::max(50, static_cast<int>(std::ceil((x_max_m - x_min_m + 2 * margin_m) * px_per_m)));
    const int h = std::max(50, static_cast<int>(std::ceil((y_max_m - y_min_m + 2 * margin_m) * px_per_m)));
    c.map_height_px = h;
    c.image = cv::Mat3b(h, c.map_width_px + legend_width_px, cv::Vec3b(255, 255, 255));
    return c;
}

void WorldBounds::add(double x_m, double y_m) {
    x_min_m = std::min(x_min_m, x_m), y_min_m = std::min(y_min_m, y_m);
    x_max_m = std::max(x_max_m, x_m), y_max_m = std::max(y_max_m, y_m);
}

Canvas makeCanvasFor(const mrpt::maps::COccupancyGridMap2D* grid, const WorldBounds& bounds) {
    if (grid && grid->getSizeX() > 0 && grid->getSizeY() > 0) return makeFloorplanCanvas(*grid);
    WorldBounds b = bounds;
    if (b.empty()) b.add(0, 0), b.add(1, 1);
    const double extent = std::max({b.x_max_m - b.x_min_m, b.y_max_m - b.y_min_m, 1.0});
    return makeBlankCanvas(b.x_min_m, b.y_min_m, b.x_max_m, b.y_max_m, std::clamp(1000.0 / extent, 10.0, 200.0));
}

void drawPolygon(Canvas& canvas, const geometry::ConvexPolygon& poly, const cv::Scalar& color, int thickness,
                 double fill_alpha) {
    if (poly.n < 2) return;
    std::vector<cv::Point> pts;
    for (std::size_t i = 0; i < poly.n; ++i) pts.push_back(canvas.toPixel(poly.v[i].x(), poly.v[i].y()));
    cv::Mat3b map = canvas.map();
    if (fill_alpha > 0) {
        // Blended only about the polygon (its anti-aliased edge reaches a pixel beyond its bounds):
        // elsewhere the blend of a pixel with itself gives the pixel back, and blending the whole
        // map once per object was most of a trajectory picture's time.
        const cv::Rect bounds = cv::boundingRect(pts) + cv::Point(-3, -3) + cv::Size(6, 6);
        const cv::Rect roi = bounds & cv::Rect(0, 0, map.cols, map.rows);
        if (!roi.empty()) {
            std::vector<cv::Point> local(pts);
            for (auto& q : local) q -= roi.tl();
            cv::Mat3b area = map(roi);
            cv::Mat3b overlay = area.clone();
            cv::fillConvexPoly(overlay, local, color, cv::LINE_AA);
            cv::addWeighted(overlay, fill_alpha, area, 1.0 - fill_alpha, 0.0, area);
        }
    }
    cv::polylines(map, pts, true, color, thickness, cv::LINE_AA);
}

}  // namespace simp::eval
