#include <simp/geometry/Footprint.h>
#include <simp/sim/Sequence.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace simp::sim {

void writeOverviewPng(const world::World& world, const std::vector<io::StampedPose2D>& trajectory,
                      const std::string& png_path, std::size_t jump_step) {
    const auto& g = world.floorplan;
    const int nx = static_cast<int>(g.getSizeX()), ny = static_cast<int>(g.getSizeY());
    if (nx == 0 || ny == 0) throw std::runtime_error("writeOverviewPng: empty floor plan");
    const int scale = std::max(1, std::min(4, 1600 / std::max(nx, ny)));
    cv::Mat3b img(ny * scale, nx * scale);
    for (int cy = 0; cy < ny; ++cy)
        for (int cx = 0; cx < nx; ++cx) {
            const float v = g.getCell(cx, cy);
            const cv::Vec3b c = v > 0.55f ? cv::Vec3b(255, 255, 255) : (v < 0.45f ? cv::Vec3b(0, 0, 0) : cv::Vec3b(180, 180, 180));
            img(cv::Rect(cx * scale, (ny - 1 - cy) * scale, scale, scale)) = c;
        }
    const auto toPx = [&](double x, double y) {
        return cv::Point(static_cast<int>(std::lround((x - g.getXMin()) / g.getResolution() * scale)),
                         static_cast<int>(std::lround(ny * scale - (y - g.getYMin()) / g.getResolution() * scale)));
    };
    for (const auto& o : world.objects.objects) {
        const auto fp = geometry::footprint(o.box);
        std::vector<cv::Point> poly;
        for (std::size_t i = 0; i < fp.n; ++i) poly.push_back(toPx(fp.v[i].x(), fp.v[i].y()));
        // a fixed colour per class id (golden-angle hue steps)
        cv::Mat3b hsv(1, 1, cv::Vec3b(static_cast<uchar>((o.class_id * 47) % 180), 200, 200)), bgr;
        cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
        if (poly.size() >= 3) cv::polylines(img, poly, true, cv::Scalar(bgr(0, 0)[0], bgr(0, 0)[1], bgr(0, 0)[2]), 1 + scale / 2);
    }
    for (std::size_t k = 1; k < trajectory.size(); ++k)
        if (k != jump_step) cv::line(img, toPx(trajectory[k - 1].pose.x, trajectory[k - 1].pose.y), toPx(trajectory[k].pose.x, trajectory[k].pose.y),
                 cv::Scalar(0, 0, 255), 1);
    if (!trajectory.empty())
        cv::circle(img, toPx(trajectory.front().pose.x, trajectory.front().pose.y), 3 * scale, cv::Scalar(0, 160, 0), -1);
    if (jump_step > 0 && jump_step < trajectory.size()) {  // a teleport: no path between, but where from and to
        const auto& from = trajectory[jump_step - 1].pose;
        const auto& to = trajectory[jump_step].pose;
        cv::circle(img, toPx(from.x, from.y), 3 * scale, cv::Scalar(255, 0, 0), 1 + scale / 2);
        cv::circle(img, toPx(to.x, to.y), 3 * scale, cv::Scalar(0, 140, 255), -1);
    }
    if (!cv::imwrite(png_path, img)) throw std::runtime_error("cannot write '" + png_path + "'");
}

}  // namespace simp::sim
