#include <simp/geometry/Footprint.h>
#include <simp/mapping/MapRendering.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>
#include <vector>

namespace simp::mapping {
namespace {

cv::Scalar classColour(int class_id, int num_classes) {
    const int hue = num_classes > 0 ? (class_id * 180 / std::max(1, num_classes)) % 180 : 0;
    cv::Mat3b hsv(1, 1, cv::Vec3b(static_cast<uchar>(hue), 220, 200)), bgr;
    cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
    return cv::Scalar(bgr(0, 0)[0], bgr(0, 0)[1], bgr(0, 0)[2]);
}

}  // namespace

cv::Mat3b renderObjectMap(const mrpt::maps::COccupancyGridMap2D& grid, const world::ObjectMapData& map, int scale) {
    scale = std::max(1, scale);
    const int nx = static_cast<int>(grid.getSizeX()), ny = static_cast<int>(grid.getSizeY());
    cv::Mat3b img(ny * scale, nx * scale);
    for (int cy = 0; cy < ny; ++cy)
        for (int cx = 0; cx < nx; ++cx) {
            const uchar g = static_cast<uchar>(55 + 200 * grid.getCell(cx, cy));
            img(cv::Rect(cx * scale, (ny - 1 - cy) * scale, scale, scale)).setTo(cv::Vec3b(g, g, g));
        }
    const double res = grid.getResolution();
    auto toPx = [&](const Eigen::Vector2d& p) {
        return cv::Point(static_cast<int>((p.x() - grid.getXMin()) / res * scale),
                         static_cast<int>((ny - (p.y() - grid.getYMin()) / res) * scale));
    };
    const int nc = static_cast<int>(map.class_names.size());
    for (const auto& o : map.objects) {
        const geometry::ConvexPolygon fp = geometry::footprint(o.box);
        std::vector<cv::Point> pts;
        for (std::size_t i = 0; i < fp.n; ++i) pts.push_back(toPx(fp.v[i]));
        const cv::Scalar colour = classColour(o.class_id, nc);
        cv::polylines(img, pts, true, colour, std::max(1, scale / 2), cv::LINE_AA);
        cv::circle(img, toPx(o.box.center.head<2>()), std::max(1, scale), colour, cv::FILLED);
    }
    for (int c = 0; c < nc; ++c) {  // legend
        const cv::Point at(5, 15 + 14 * c);
        cv::rectangle(img, at + cv::Point(0, -9), at + cv::Point(10, 1), classColour(c, nc), cv::FILLED);
        cv::putText(img, map.class_names[c], at + cv::Point(14, 0), cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0), 1,
                    cv::LINE_AA);
    }
    return img;
}

void writeObjectMapPng(const mrpt::maps::COccupancyGridMap2D& grid, const world::ObjectMapData& map,
                       const std::string& png_path, int scale) {
    const cv::Mat3b img = renderObjectMap(grid, map, scale);
    bool ok = false;
    try {
        ok = !img.empty() && cv::imwrite(png_path, img);
    } catch (const cv::Exception& e) {
        throw std::runtime_error(png_path + ": cannot write the map picture: " + e.what());
    }
    if (!ok) throw std::runtime_error(png_path + ": cannot write the map picture");
}

}  // namespace simp::mapping
