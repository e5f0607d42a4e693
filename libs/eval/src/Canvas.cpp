#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <simp/eval/Canvas.h>
#include <simp/obs/ObjectStyle.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
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
    c.map_height_px = scaled.rows;
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
    c.map_height_px = h;
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
    const int needed_rows = 24 * static_cast<int>(items.size()) + 12;
    if (needed_rows > canvas.image.rows) {  // grow downwards: the legend never overlaps the map
        cv::Mat3b taller(needed_rows, canvas.image.cols, cv::Vec3b(255, 255, 255));
        canvas.image.copyTo(taller(cv::Rect(0, 0, canvas.image.cols, canvas.image.rows)));
        canvas.image = taller;
    }
    int y = 24;
    for (const auto& [label, color] : items) {
        cv::rectangle(canvas.image, cv::Rect(x0, y - 12, 22, 14), color, cv::FILLED);
        cv::putText(canvas.image, label, {x0 + 30, y}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1,
                    cv::LINE_AA);
        y += 24;
    }
}

std::vector<std::pair<std::string, cv::Scalar>> classLegend(const world::ObjectMapData& objects,
                                                           const std::set<int>& present) {
    std::vector<std::pair<std::string, cv::Scalar>> legend;
    for (int id : present) {
        const bool named = id >= 0 && id < static_cast<int>(objects.class_names.size());
        legend.emplace_back(named ? objects.class_names[static_cast<std::size_t>(id)] : "class " + std::to_string(id),
                            classColor(id));
    }
    return legend;
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
    const auto rgb = obs::classColorRgb(i);
    return {static_cast<double>(rgb[2]), static_cast<double>(rgb[1]), static_cast<double>(rgb[0])};
}

double scaleBarLength(double map_width_m) {
    const double target = std::max(map_width_m, 1e-6) / 5.0;  // about a fifth of the map's width
    double best = 0.1;
    for (double decade = 0.1; decade <= 1000.0; decade *= 10.0)
        for (double step : {1.0, 2.0, 5.0})
            if (step * decade <= target) best = step * decade;
    return best;
}

void drawScaleBar(Canvas& canvas) {
    const double width_m = canvas.map_width_px / canvas.px_per_m;
    const double len_m = scaleBarLength(width_m);
    const int len_px = static_cast<int>(std::lround(len_m * canvas.px_per_m));
    const int x0 = 12, y0 = canvas.map_height_px - 14;
    std::ostringstream label;
    label << len_m << " m";
    int baseline = 0;
    const cv::Size text = cv::getTextSize(label.str(), cv::FONT_HERSHEY_SIMPLEX, 0.5, 1, &baseline);
    // a white box keeps the bar readable over dark walls
    cv::rectangle(canvas.image, cv::Rect(x0 - 6, y0 - text.height - 14, std::max(len_px, text.width) + 12, text.height + 24),
                  cv::Scalar(255, 255, 255), cv::FILLED);
    cv::line(canvas.image, {x0, y0}, {x0 + len_px, y0}, cv::Scalar(0, 0, 0), 3);
    for (int x : {x0, x0 + len_px}) cv::line(canvas.image, {x, y0 - 5}, {x, y0 + 4}, cv::Scalar(0, 0, 0), 2);
    cv::putText(canvas.image, label.str(), {x0, y0 - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1,
                cv::LINE_AA);
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
