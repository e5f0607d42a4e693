#include <simp/localization/TrajectoryImage.h>

#include <simp/geometry/Footprint.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace simp::localization {
namespace {

cv::Scalar classColour(int class_id) {
    static const cv::Scalar palette[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44},   {214, 39, 40},
                                         {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127},
                                         {188, 189, 34},  {23, 190, 207}};
    const auto& c = palette[static_cast<std::size_t>(std::abs(class_id)) % 10];
    return {c[2], c[1], c[0]};  // RGB -> BGR
}

}  // namespace

void writeTrajectoryPng(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid,
                        const simp::world::ObjectMapData& objects, const std::vector<mrpt::math::TPose2D>& trajectory,
                        const std::vector<mrpt::math::TPose2D>& particles) {
    const int w = static_cast<int>(grid.getSizeX()), h = static_cast<int>(grid.getSizeY());
    if (w <= 0 || h <= 0) throw std::runtime_error("cannot draw '" + path + "': empty floor plan");
    const int scale = std::max(1, static_cast<int>(std::ceil(1000.0 / w)));
    cv::Mat1b grey(h, w);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            grey(h - 1 - y, x) = static_cast<std::uint8_t>(std::lround(255.0 * grid.getCell(x, y)));
    cv::Mat img;
    cv::resize(grey, grey, cv::Size(w * scale, h * scale), 0, 0, cv::INTER_NEAREST);
    cv::cvtColor(grey, img, cv::COLOR_GRAY2BGR);

    const double res = grid.getResolution(), x0 = grid.getXMin(), y0 = grid.getYMin();
    auto px = [&](double x, double y) {
        return cv::Point(static_cast<int>(std::lround((x - x0) / res * scale)),
                         static_cast<int>(std::lround((h - (y - y0) / res) * scale)));
    };
    for (const auto& o : objects.objects) {
        const auto fp = geometry::footprint(o.box);
        std::vector<cv::Point> poly;
        for (std::size_t i = 0; i < fp.n; ++i) poly.push_back(px(fp.v[i].x(), fp.v[i].y()));
        if (poly.size() >= 3) cv::polylines(img, poly, true, classColour(o.class_id), std::max(1, scale / 2));
    }
    for (const auto& p : particles) cv::circle(img, px(p.x, p.y), std::max(1, scale / 3), {200, 80, 0}, cv::FILLED);
    for (std::size_t i = 1; i < trajectory.size(); ++i)
        cv::line(img, px(trajectory[i - 1].x, trajectory[i - 1].y), px(trajectory[i].x, trajectory[i].y),
                 {0, 0, 230}, std::max(1, scale / 2), cv::LINE_AA);
    if (!trajectory.empty()) {
        const auto& a = trajectory.front();
        const auto& b = trajectory.back();
        cv::circle(img, px(a.x, a.y), 3 * scale, {0, 170, 0}, std::max(1, scale / 2));
        cv::circle(img, px(b.x, b.y), 3 * scale, {0, 0, 230}, std::max(1, scale / 2));
        cv::line(img, px(b.x, b.y), px(b.x + 0.5 * std::cos(b.phi), b.y + 0.5 * std::sin(b.phi)), {0, 0, 230},
                 std::max(1, scale / 2), cv::LINE_AA);
    }
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    if (!cv::imwrite(path, img)) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace simp::localization
