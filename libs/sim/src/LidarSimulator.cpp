#include <simp/geometry/Footprint.h>
#include <simp/sim/LidarSimulator.h>

#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace simp::sim {
namespace {

constexpr float kOccupied = 0.0f;  ///< free probability of an obstacle cell
/// laserScanSimulator's threshold: a ray stops at the first cell whose free probability is below it,
/// so occupied (0) and unknown (0.5) cells both stop it, as the planner's wallRaster() treats them.
constexpr float kHitThreshold = 0.6f;

}  // namespace

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

LidarSimulator::LidarSimulator(const world::World& world, const LidarParams& params)
    : m_params(params), m_grid(world.floorplan) {
    const int door_class = world.objects.classId("door");
    for (const auto& o : world.objects.objects) {
        if (o.class_id == door_class || !spansHeight(o.box, params.height_m)) continue;
        for (const auto& [cx, cy] : footprintCells(m_grid, o.box)) m_grid.setCell(cx, cy, kOccupied);
    }
}

mrpt::obs::CObservation2DRangeScan LidarSimulator::scan(const mrpt::math::TPose2D& robot_pose,
                                                        const std::vector<world::MapObject>& dynamic_obstacles,
                                                        double t_s, Rng& rng) {
    // people (and other moving things) go into the grid for this scan only
    std::vector<std::pair<std::pair<int, int>, float>> saved;
    for (const auto& o : dynamic_obstacles) {
        if (!spansHeight(o.box, m_params.height_m)) continue;
        for (const auto& c : footprintCells(m_grid, o.box)) {
            saved.push_back({c, m_grid.getCell(c.first, c.second)});
            m_grid.setCell(c.first, c.second, kOccupied);
        }
    }
    mrpt::obs::CObservation2DRangeScan s;
    s.sensorLabel = "LIDAR";
    s.timestamp = mrpt::Clock::fromDouble(t_s);
    s.aperture = static_cast<float>(m_params.fov_deg * M_PI / 180.0);
    s.rightToLeft = true;
    s.maxRange = static_cast<float>(m_params.max_range_m);
    s.stdError = static_cast<float>(m_params.range_std_m);
    s.beamAperture = s.aperture / static_cast<float>(m_params.beams - 1);
    s.sensorPose = mrpt::poses::CPose3D(m_params.x_m, m_params.y_m, m_params.height_m, m_params.yaw_deg * M_PI / 180.0, 0, 0);
    // MRPT's ray casting, noise-free: the noise below comes from the sequence's own generator
    // (MRPT's global one would tie the rawlog to whatever else drew from it).
    m_grid.laserScanSimulator(s, mrpt::poses::CPose2D(robot_pose), kHitThreshold, static_cast<std::size_t>(m_params.beams));
    for (auto it = saved.rbegin(); it != saved.rend(); ++it) m_grid.setCell(it->first.first, it->first.second, it->second);
    for (std::size_t i = 0; i < s.getScanSize(); ++i) {
        const double noise = rng.normal(0.0, m_params.range_std_m);  // drawn for every ray: same count per scan
        if (!s.getScanRangeValidity(i)) continue;
        const double r = std::clamp(static_cast<double>(s.getScanRange(i)) + noise, 0.0, m_params.max_range_m);
        s.setScanRange(i, static_cast<float>(r));
        if (r >= m_params.max_range_m) s.setScanRangeValidity(i, false);
    }
    return s;
}

}  // namespace simp::sim
