#include <simp/localization/ScanLikelihood.h>

#include <mrpt/poses/CPose3D.h>
#include <simp/world/ScanPlane.h>

#include <cmath>
#include <stdexcept>

namespace simp::localization {

void LidarModelOptions::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    weight = cfg.read_double(s, "weight", weight);
    decimation = cfg.read_int(s, "decimation", decimation);
    sigma_m = cfg.read_double(s, "sigma_m", sigma_m);
    z_hit = cfg.read_double(s, "z_hit", z_hit);
    z_random = cfg.read_double(s, "z_random", z_random);
    max_range_m = cfg.read_double(s, "max_range_m", max_range_m);
    max_corr_distance_m = cfg.read_double(s, "max_corr_distance_m", max_corr_distance_m);
    map_objects = cfg.read_bool(s, "map_objects", map_objects);
    const auto check = [&](bool ok, const std::string& key, const std::string& what) {
        if (!ok) throw std::invalid_argument("[" + s + "] " + key + " " + what);
    };
    check(weight >= 0 && weight <= 100, "weight", "must be in [0, 100]");
    check(decimation >= 1 && decimation <= 10000, "decimation", "must be in [1, 10000]");
    check(sigma_m > 0 && sigma_m <= 10, "sigma_m", "must be in (0, 10]");
    check(z_hit >= 0 && z_hit <= 1, "z_hit", "must be in [0, 1]");
    check(z_random > 0 && z_random <= 1, "z_random", "must be in (0, 1] (0 makes one stray beam impossible)");
    check(max_range_m > 0 && max_range_m <= 1000, "max_range_m", "must be in (0, 1000]");
    check(max_corr_distance_m > 0 && max_corr_distance_m <= 100, "max_corr_distance_m", "must be in (0, 100]");
}

ScanLikelihood::ScanLikelihood(const mrpt::maps::COccupancyGridMap2D& floorplan, const LidarModelOptions& options,
                               const world::ObjectMapData* objects)
    : m_opts(options), m_floorplan(floorplan) {
    if (objects) m_objects = *objects;
}

mrpt::maps::COccupancyGridMap2D& ScanLikelihood::gridAt(double height_m) const {
    if (m_grid && (!m_objects || height_m == m_grid_height_m)) return *m_grid;
    m_grid = std::make_unique<mrpt::maps::COccupancyGridMap2D>(m_floorplan);
    m_grid_height_m = height_m;
    m_objects_drawn = m_objects ? world::drawObjectsAtHeight(*m_grid, *m_objects, height_m) : 0;
    auto& o = m_grid->likelihoodOptions;
    o.likelihoodMethod = mrpt::maps::COccupancyGridMap2D::lmLikelihoodField_Thrun;
    o.LF_decimation = static_cast<std::uint32_t>(m_opts.decimation);
    o.LF_stdHit = static_cast<float>(m_opts.sigma_m);
    o.LF_zHit = static_cast<float>(m_opts.z_hit);
    o.LF_zRandom = static_cast<float>(m_opts.z_random);
    o.LF_maxRange = static_cast<float>(m_opts.max_range_m);
    o.LF_maxCorrsDistance = static_cast<float>(m_opts.max_corr_distance_m);
    o.LF_useSquareDist = false;
    o.enableLikelihoodCache = true;
    return *m_grid;
}

void ScanLikelihood::logLikelihoods(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D* poses,
                                    std::size_t n, double* out_log) const {
    auto& grid = gridAt(scan.sensorPose.z());
    for (std::size_t i = 0; i < n; ++i) {
        const mrpt::poses::CPose3D pose(poses[i].x, poses[i].y, 0.0, poses[i].phi, 0.0, 0.0);
        const double l = grid.computeObservationLikelihood(scan, pose);
        if (!std::isfinite(l))
            throw std::runtime_error("LiDAR likelihood: non-finite value for pose (" + std::to_string(poses[i].x) + ", " +
                                     std::to_string(poses[i].y) + ", " + std::to_string(poses[i].phi) + ")");
        out_log[i] = m_opts.weight * l;
    }
}

mrpt::obs::CObservation2DRangeScan::Ptr lastScan(const mrpt::obs::CSensoryFrame& sf) {
    mrpt::obs::CObservation2DRangeScan::Ptr scan;
    for (const auto& o : sf)
        if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) scan = s;
    return scan;
}

}  // namespace simp::localization
