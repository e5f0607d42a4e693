/// \file RoomMap.cpp
/// The room raster: one room id per floor-plan pixel (0 = no room), row 0 = top of the image.

#include <opencv2/imgcodecs.hpp>
#include <simp/world/ImageLimits.h>
#include <simp/world/World.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>

namespace simp::world {

int RoomMap::roomAt(double x_m, double y_m) const {
    int row = 0, col = 0;
    return pixelOf(x_m, y_m, row, col) ? roomAtPixel(row, col) : 0;
}

bool RoomMap::pixelOf(double x_m, double y_m, int& row, int& col) const {
    if (!std::isfinite(x_m) || !std::isfinite(y_m)) return false;
    // Same cell geometry as the floor plan: column c covers [ox + c res, ox + (c+1) res). Far
    // points are clamped before the integer cast; they stay outside the raster.
    constexpr double kFar = 1 << 30;
    const double fc = std::clamp(std::floor((x_m - origin_x_m) / resolution_m), -kFar, kFar);
    const double fr_from_bottom = std::clamp(std::floor((y_m - origin_y_m) / resolution_m), -kFar, kFar);
    col = static_cast<int>(fc);
    row = ids.rows - 1 - static_cast<int>(fr_from_bottom);
    return true;
}

int RoomMap::roomAtPixel(int row, int col) const {
    if (row < 0 || col < 0 || row >= ids.rows || col >= ids.cols) return 0;
    return ids(row, col);
}

int roomOfBox(const RoomMap& rooms, const geometry::Box3D& box) {
    const int at_centre = rooms.roomAt(box.center.x(), box.center.y());
    if (at_centre != 0 || rooms.empty()) return at_centre;
    const geometry::Box3D up = geometry::canonicalizeUpright(box);
    const double yaw = geometry::yawOf(up);
    const Eigen::Vector2d ax(std::cos(yaw), std::sin(yaw)), ay(-ax.y(), ax.x());
    const double step = rooms.resolution_m / 2;
    const double hx = up.size.x() / 2 + rooms.resolution_m, hy = up.size.y() / 2 + rooms.resolution_m;
    std::map<int, int> votes;
    for (double a = -hx; a <= hx; a += step)
        for (double b = -hy; b <= hy; b += step) {
            const Eigen::Vector2d p = up.center.head<2>() + a * ax + b * ay;
            const int id = rooms.roomAt(p.x(), p.y());
            if (id != 0) ++votes[id];
        }
    int best = 0, best_votes = 0;
    for (const auto& [id, n] : votes)
        if (n > best_votes) {
            best = id;
            best_votes = n;
        }
    return best;
}

RoomMap loadRoomMap(const std::string& png_path, double resolution_m, double origin_x_m, double origin_y_m) {
    if (!std::filesystem::exists(png_path)) throw std::runtime_error(png_path + ": file not found");
    checkDeclaredRasterSize(png_path);  // before decoding: a small PNG can declare gigapixels
    const cv::Mat img = cv::imread(png_path, cv::IMREAD_UNCHANGED);
    if (img.empty()) throw std::runtime_error(png_path + ": cannot read the image");
    checkRasterSize(png_path, {static_cast<std::uint64_t>(img.cols), static_cast<std::uint64_t>(img.rows)});
    if (img.channels() != 1 || (img.depth() != CV_8U && img.depth() != CV_16U))
        throw std::runtime_error(png_path + ": expected a single-channel 8-bit or 16-bit image of room ids");
    RoomMap r;
    img.convertTo(r.ids, CV_16U);
    r.resolution_m = resolution_m;
    r.origin_x_m = origin_x_m;
    r.origin_y_m = origin_y_m;
    return r;
}

void saveRoomMap(const RoomMap& rooms, const std::string& png_path) {
    if (rooms.empty()) throw std::runtime_error(png_path + ": cannot save an empty room map");
    const std::filesystem::path p(png_path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    if (!cv::imwrite(png_path, rooms.ids)) throw std::runtime_error(png_path + ": cannot write the image");
}

}  // namespace simp::world
