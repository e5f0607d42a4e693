#include <simp/sim/LidarSimulator.h>

#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>

namespace simp::sim {
namespace {

constexpr float kOccupied = 0.0f;  ///< free probability of an obstacle cell
/// laserScanSimulator's threshold: a ray stops at the first cell whose free probability is below it,
/// so occupied (0) and unknown (0.5) cells both stop it, as the planner's wallRaster() treats them.
constexpr float kHitThreshold = 0.6f;

}  // namespace

LidarSimulator::LidarSimulator(const world::World& world, const LidarParams& params)
    : m_params(params), m_grid(world.floorplan) {
    world::drawObjectsAtHeight(m_grid, world.objects, params.height_m);
}

mrpt::obs::CObservation2DRangeScan LidarSimulator::scan(const mrpt::math::TPose2D& robot_pose,
                                                        const std::vector<world::MapObject>& dynamic_obstacles,
                                                        double t_s, Rng& rng) {
    // people (and other moving things) go into the grid for this scan only
    std::vector<std::pair<std::pair<int, int>, float>> saved;
    for (const auto& o : dynamic_obstacles) {
        if (!world::spansHeight(o.box, m_params.height_m)) continue;
        for (const auto& c : world::footprintCells(m_grid, o.box)) {
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
