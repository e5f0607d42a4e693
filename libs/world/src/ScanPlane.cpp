#include <simp/geometry/Footprint.h>
#include <simp/world/ScanPlane.h>

#include <algorithm>
#include <limits>

namespace simp::world {

std::vector<std::pair<int, int>> footprintCells(const mrpt::maps::COccupancyGridMap2D& grid, const geometry::Box3D& box) {
    std::vector<std::pair<int, int>> cells;
    const auto fp = geometry::footprint(box);
    if (fp.n < 3) return cells;
    Eigen::Vector2d lo, hi;
    fp.bounds(lo, hi);
    const int nx = static_cast<int>(grid.getSizeX()), ny = static_cast<int>(grid.getSizeY());
    const int cx0 = std::max(0, grid.x2idx(lo.x())), cx1 = std::min(nx - 1, grid.x2idx(hi.x()));
    const int cy0 = std::max(0, grid.y2idx(lo.y())), cy1 = std::min(ny - 1, grid.y2idx(hi.y()));
    for (int cy = cy0; cy <= cy1; ++cy)
        for (int cx = cx0; cx <= cx1; ++cx) {
            const Eigen::Vector2d c(grid.idx2x(static_cast<std::size_t>(cx)), grid.idx2y(static_cast<std::size_t>(cy)));
            bool in = true;
            for (std::size_t i = 0; i < fp.n && in; ++i) {
                const Eigen::Vector2d e = fp.v[(i + 1) % fp.n] - fp.v[i], d = c - fp.v[i];
                in = e.x() * d.y() - e.y() * d.x() >= 0;  // counter-clockwise: inside is left
            }
            if (in) cells.emplace_back(cx, cy);
        }
    return cells;
}

bool spansHeight(const geometry::Box3D& box, double height_m) {
    double z_lo = std::numeric_limits<double>::infinity(), z_hi = -z_lo;
    for (const auto& c : box.corners()) {
        z_lo = std::min(z_lo, c.z());
        z_hi = std::max(z_hi, c.z());
    }
    return z_lo <= height_m && height_m <= z_hi;
}

std::size_t drawObjectsAtHeight(mrpt::maps::COccupancyGridMap2D& grid, const ObjectMapData& objects, double height_m) {
    const int door_class = objects.classId("door");
    std::size_t drawn = 0;
    for (const auto& o : objects.objects) {
        if (o.class_id == door_class || !spansHeight(o.box, height_m)) continue;
        for (const auto& [cx, cy] : footprintCells(grid, o.box)) grid.setCell(cx, cy, 0.0f);
        ++drawn;
    }
    return drawn;
}

}  // namespace simp::world
