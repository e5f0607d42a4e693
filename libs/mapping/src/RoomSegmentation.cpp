#include <simp/mapping/RoomSegmentation.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <deque>
#include <set>
#include <stdexcept>
#include <string>

namespace simp::mapping {

world::RoomMap segmentRooms(const mrpt::maps::COccupancyGridMap2D& grid, const RoomSegmentationParams& p) {
    const int nx = static_cast<int>(grid.getSizeX()), ny = static_cast<int>(grid.getSizeY());
    if (nx == 0 || ny == 0) throw std::invalid_argument("segmentRooms: the floor plan grid is empty");
    if (!(p.door_width_m >= 0) || !std::isfinite(p.door_width_m))
        throw std::invalid_argument("segmentRooms: door_width_m must be finite and >= 0, got " + std::to_string(p.door_width_m));
    if (!(p.min_room_area_m2 >= 0) || !std::isfinite(p.min_room_area_m2))
        throw std::invalid_argument("segmentRooms: min_room_area_m2 must be finite and >= 0");
    const double res = grid.getResolution();

    // Free space, image orientation (row 0 = max y).
    cv::Mat1b free_space(ny, nx, uchar(0));
    for (int cy = 0; cy < ny; ++cy)
        for (int cx = 0; cx < nx; ++cx)
            if (grid.getCell(cx, cy) >= p.min_free_prob) free_space(ny - 1 - cy, cx) = 255;

    // Erode by a disk whose diameter is the door width: openings up to it close.
    const int radius = static_cast<int>(std::ceil(0.5 * p.door_width_m / res));
    cv::Mat1b eroded = free_space.clone();
    if (radius > 0) {
        const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
        cv::erode(free_space, eroded, kernel, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    }

    // Connected components of the eroded free space = room seeds.
    cv::Mat1i labels;
    cv::Mat stats, centroids;
    const int n = cv::connectedComponentsWithStats(eroded, labels, stats, centroids, 8, CV_32S);
    const double min_px = p.min_room_area_m2 / (res * res);
    std::vector<int> id_of(n, 0);
    int next = 1;
    for (int l = 1; l < n; ++l)
        if (stats.at<int>(l, cv::CC_STAT_AREA) >= min_px) id_of[l] = next++;

    // Grow the labels back over the free space (multi-source breadth-first = geodesic nearest seed).
    world::RoomMap rooms;
    rooms.ids = cv::Mat1w::zeros(ny, nx);
    rooms.resolution_m = res;
    rooms.origin_x_m = grid.getXMin();
    rooms.origin_y_m = grid.getYMin();
    std::deque<std::pair<int, int>> queue;
    for (int r = 0; r < ny; ++r)
        for (int c = 0; c < nx; ++c)
            if (const int id = id_of[labels(r, c)]; id > 0) {
                rooms.ids(r, c) = static_cast<ushort>(id);
                queue.emplace_back(r, c);
            }
    constexpr int dr[4] = {-1, 1, 0, 0}, dc[4] = {0, 0, -1, 1};
    while (!queue.empty()) {
        const auto [r, c] = queue.front();
        queue.pop_front();
        for (int k = 0; k < 4; ++k) {
            const int rr = r + dr[k], cc = c + dc[k];
            if (rr < 0 || cc < 0 || rr >= ny || cc >= nx) continue;
            if (!free_space(rr, cc) || rooms.ids(rr, cc)) continue;
            rooms.ids(rr, cc) = rooms.ids(r, c);
            queue.emplace_back(rr, cc);
        }
    }
    return rooms;
}

int countRooms(const world::RoomMap& rooms) {
    std::set<int> ids;
    for (int r = 0; r < rooms.ids.rows; ++r)
        for (int c = 0; c < rooms.ids.cols; ++c)
            if (rooms.ids(r, c)) ids.insert(rooms.ids(r, c));
    return static_cast<int>(ids.size());
}

}  // namespace simp::mapping
