#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <simp/eval/Canvas.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace simp::eval {

cv::Point Canvas::toPixel(double x_m, double y_m) const {
    return {static_cast<int>(std::lround((x_m - x_min_m) * px_per_m)),
            static_cast<int>(std::lround((y_max_m - y_m) * px_per_m))};
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
    c.image = cv::Mat3b(scaled.rows, scaled.cols + legend_width_px, cv::Vec3b(255, 255, 255));
    cv::Mat3b map_area = c.image(cv::Rect(0, 0, scaled.cols, scaled.rows));
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
    c.image = cv::Mat3b(h, c.map_width_px + legend_width_px, cv::Vec3b(255, 255, 255));
    return c;
}

Canvas makeCanvasFor(const mrpt::maps::COccupancyGridMap2D* grid, double x_min_m, double y_min_m, double x_max_m,
                     double y_max_m) {
    if (grid && grid->getSizeX() > 0 && grid->getSizeY() > 0) return makeFloorplanCanvas(*grid);
    const double extent = std::max({x_max_m - x_min_m, y_max_m - y_min_m, 1.0});
    return makeBlankCanvas(x_min_m, y_min_m, x_max_m, y_max_m, std::clamp(1000.0 / extent, 10.0, 200.0));
}

void drawLegend(Canvas& canvas, const std::vector<std::pair<std::string, cv::Scalar>>& items) {
    const int x0 = canvas.map_width_px + 12;
    int y = 24;
    for (const auto& [label, color] : items) {
        cv::rectangle(canvas.image, cv::Rect(x0, y - 12, 22, 14), color, cv::FILLED);
        cv::putText(canvas.image, label, {x0 + 30, y}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1,
                    cv::LINE_AA);
        y += 24;
    }
}

void drawPolygon(Canvas& canvas, const geometry::ConvexPolygon& poly, const cv::Scalar& color, int thickness,
                 double fill_alpha) {
    if (poly.n < 2) return;
    std::vector<cv::Point> pts;
    for (std::size_t i = 0; i < poly.n; ++i) pts.push_back(canvas.toPixel(poly.v[i].x(), poly.v[i].y()));
    if (fill_alpha > 0) {
        cv::Mat3b overlay = canvas.image.clone();
        cv::fillConvexPoly(overlay, pts, color, cv::LINE_AA);
        cv::addWeighted(overlay, fill_alpha, canvas.image, 1.0 - fill_alpha, 0.0, canvas.image);
    }
    cv::polylines(canvas.image, pts, true, color, thickness, cv::LINE_AA);
}

cv::Scalar classColor(int i) {
    static const cv::Scalar kPalette[] = {
        {180, 119, 31}, {14, 127, 255}, {44, 160, 44},  {40, 39, 214},  {189, 103, 148}, {75, 86, 140},   {194, 119, 227},
        {127, 127, 127}, {34, 189, 188}, {207, 190, 23}, {0, 0, 128},   {128, 0, 128},   {0, 128, 128}, {255, 0, 255}};
    constexpr int n = sizeof(kPalette) / sizeof(kPalette[0]);
    return kPalette[((i % n) + n) % n];
}

void writePng(const std::string& path, const cv::Mat& image) {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    bool ok = false;
    try {
        ok = cv::imwrite(path, image);
    } catch (const cv::Exception& e) {
        throw std::runtime_error("cannot write image '" + path + "': " + e.what());
    }
    if (!ok) throw std::runtime_error("cannot write image '" + path + "' (is the extension .png?)");
}

}  // namespace simp::eval
