#include <simp/localization/ScanLikelihood.h>

#include <mrpt/poses/CPose3D.h>
#include <simp/world/ScanPlane.h>

#include <cmath>
#include <stdexcept>

namespace simp::localization {

const io::OptionTable<LidarModelOptions>& LidarModelOptions::table() {
    using O = LidarModelOptions;
    using io::ValueRange;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("LidarModel")
            .number("weight", &O::weight, "", ValueRange::between(0, 100), "exponent of the scan likelihood (relative to the object model's 1 in `simp+lidar`)")
            .integer("decimation", &O::decimation, ValueRange::between(1, 10000), "every n-th beam (1081 -> 109), `LF_decimation`")
            .number("sigma_m", &O::sigma_m, "m", ValueRange::aboveUpTo(0, 10), "std of a beam end around the nearest wall, `LF_stdHit`")
            .number("z_hit", &O::z_hit, "", ValueRange::fraction(), "weight of the hit model, `LF_zHit`")
            .number("z_random", &O::z_random, "", ValueRange::aboveUpTo(0, 1),
                    "weight of random returns, `LF_zRandom` (> 0: one stray beam stays possible)")
            .number("max_range_m", &O::max_range_m, "m", ValueRange::aboveUpTo(0, 1000), "beams beyond are not weighed, `LF_maxRange`")
            .number("max_corr_distance_m", &O::max_corr_distance_m, "m", ValueRange::aboveUpTo(0, 100),
                    "the distance to the nearest wall is capped here, `LF_maxCorrsDistance`")
            .flag("map_objects", &O::map_objects,
                  "`simp+lidar`: the map's objects spanning the scan plane are obstacles of the scan grid (`lidar` never uses them)");
    return t;
}

void LidarModelOptions::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }

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
