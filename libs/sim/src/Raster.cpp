#include <simp/camera/FloorPlanThresholds.h>
#include <simp/geometry/Footprint.h>
#include <simp/sim/Raster.h>

#include <opencv2/imgproc.hpp>
#include <algorithm>
#include <cmath>

namespace simp::sim {

Raster wallRaster(const mrpt::maps::COccupancyGridMap2D& grid) {
    Raster r;
    r.nx = static_cast<int>(grid.getSizeX());
    r.ny = static_cast<int>(grid.getSizeY());
    r.x_min_m = grid.getXMin();
    r.y_min_m = grid.getYMin();
    r.resolution_m = grid.getResolution();
    r.blocked.assign(static_cast<std::size_t>(r.nx) * r.ny, 0);
    for (int cy = 0; cy < r.ny; ++cy)
        for (int cx = 0; cx < r.nx; ++cx) r.set(cx, cy, grid.getCell(cx, cy) <= camera::floorplan::kUnknownFree);
    return r;
}

void addFootprints(Raster& raster, const std::vector<world::MapObject>& objects) {
    for (const auto& o : objects) {
        const auto fp = geometry::footprint(o.box);
        Eigen::Vector2d lo, hi;
        fp.bounds(lo, hi);
        for (int cy = raster.cellY(lo.y()); cy <= raster.cellY(hi.y()); ++cy)
            for (int cx = raster.cellX(lo.x()); cx <= raster.cellX(hi.x()); ++cx) {
                const Eigen::Vector2d c(raster.centreX(cx), raster.centreY(cy));
                bool in = fp.n >= 3;
                for (std::size_t i = 0; i < fp.n && in; ++i) {
                    const Eigen::Vector2d e = fp.v[(i + 1) % fp.n] - fp.v[i], d = c - fp.v[i];
                    in = e.x() * d.y() - e.y() * d.x() >= 0;  // counter-clockwise: inside is left
                }
                if (in) raster.set(cx, cy, true);
            }
    }
}

std::vector<float> clearance(const Raster& raster) {
    cv::Mat1b free_mask(raster.ny, raster.nx);
    for (int cy = 0; cy < raster.ny; ++cy)
        for (int cx = 0; cx < raster.nx; ++cx) free_mask(cy, cx) = raster.isBlocked(cx, cy) ? 0 : 255;
    cv::Mat1f dist;
    cv::distanceTransform(free_mask, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    std::vector<float> out(static_cast<std::size_t>(raster.nx) * raster.ny);
    for (int cy = 0; cy < raster.ny; ++cy)
        for (int cx = 0; cx < raster.nx; ++cx)
            out[static_cast<std::size_t>(cy) * raster.nx + cx] = dist(cy, cx) * static_cast<float>(raster.resolution_m);
    return out;
}

Raster drivingObstacles(const world::World& world) {
    Raster obstacles = wallRaster(world.floorplan);
    const int door_class = world.objects.classId("door");
    std::vector<world::MapObject> solid;
    for (const auto& o : world.objects.objects)
        if (o.class_id != door_class) solid.push_back(o);
    addFootprints(obstacles, solid);
    return obstacles;
}

std::vector<std::uint8_t> largestFreeArea(const Raster& cspace, const std::vector<float>& dist) {
    cv::Mat1b free(cspace.ny, cspace.nx);
    for (int cy = 0; cy < cspace.ny; ++cy)
        for (int cx = 0; cx < cspace.nx; ++cx)
            free(cy, cx) = dist[static_cast<std::size_t>(cy) * cspace.nx + cx] > 0 ? 255 : 0;
    cv::Mat1i labels, stats;
    cv::Mat centroids;
    const int n = cv::connectedComponentsWithStats(free, labels, stats, centroids, 4, CV_32S);
    int best = 0;  // label 0 = not free
    for (int l = 1; l < n; ++l)
        if (best == 0 || stats(l, cv::CC_STAT_AREA) > stats(best, cv::CC_STAT_AREA)) best = l;
    std::vector<std::uint8_t> in(dist.size(), 0);
    for (int cy = 0; cy < cspace.ny; ++cy)
        for (int cx = 0; cx < cspace.nx; ++cx)
            in[static_cast<std::size_t>(cy) * cspace.nx + cx] = best != 0 && labels(cy, cx) == best;
    return in;
}

Raster inflate(const Raster& raster, double radius_m) {
    const auto d = clearance(raster);
    Raster out = raster;
    for (std::size_t i = 0; i < d.size(); ++i)
        if (d[i] < radius_m) out.blocked[i] = 1;
    return out;
}

bool lineOfSight(const Raster& raster, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const double len = (b - a).norm();
    const int steps = std::max(1, static_cast<int>(std::ceil(len / (0.5 * raster.resolution_m))));
    for (int i = 0; i <= steps; ++i) {
        const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(i) / steps);
        if (raster.isBlockedAt(p.x(), p.y())) return false;
    }
    return true;
}

}  // namespace simp::sim
