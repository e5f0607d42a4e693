#include <simp/localization/ScanLikelihood.h>

#include <mrpt/poses/CPose3D.h>
#include <simp/world/ScanPlane.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

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
            .number("min_range_m", &O::min_range_m, "m", ValueRange::between(0, 100),
                    "returns shorter than this are not weighed (inside the robot's footprint: a body touching it, not the map)")
            .number("beam_skip_distance_m", &O::beam_skip_distance_m, "m", ValueRange::aboveUpTo(0, 100),
                    "a return is explained at a particle when it ends this close to an obstacle of the scan grid")
            .number("beam_skip_threshold", &O::beam_skip_threshold, "", ValueRange::fraction(),
                    "returns explained at fewer than this share of the particles are not weighed (0: off)")
            .number("beam_skip_max_fraction", &O::beam_skip_max_fraction, "", ValueRange::fraction(),
                    "when more than this share of the returns would be skipped, none is")
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
    // Obstacles as MRPT's likelihood field has them: cells below free-probability 0.5 (kUnknownFree).
    m_wall_distance = camera::WallDistance(*m_grid);
    return *m_grid;
}

namespace {

/// Bearing of return i in the sensor frame (MRPT's convention for CObservation2DRangeScan).
double bearingOf(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t i) {
    const std::size_t size = scan.getScanSize();
    const double step = size > 1 ? scan.aperture / static_cast<double>(size - 1) : 0.0;
    const double a = -0.5 * scan.aperture + step * static_cast<double>(i);
    return scan.rightToLeft ? a : -a;
}

}  // namespace

std::vector<char> ScanLikelihood::usableReturns(const mrpt::obs::CObservation2DRangeScan& scan,
                                                const mrpt::math::TPose2D* poses, std::size_t n,
                                                bool skip_unexplained) const {
    std::vector<char> usable(scan.getScanSize());
    for (std::size_t i = 0; i < usable.size(); ++i)
        usable[i] = scan.getScanRangeValidity(i) && scan.getScanRange(i) >= m_opts.min_range_m ? 1 : 0;
    m_last_skipped = 0;
    if (skip_unexplained && m_opts.beam_skip_threshold > 0 && n > 0) skipUnexplained(scan, poses, n, usable);
    return usable;
}

void ScanLikelihood::skipUnexplained(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D* poses,
                                     std::size_t n, std::vector<char>& usable) const {
    gridAt(scan.sensorPose.z());  // the scan plane's grid and its m_wall_distance
    // Return ends in the robot frame (only those weighed: usable and within the model's range).
    std::vector<std::size_t> index;
    std::vector<double> lx, ly;
    const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y(), syaw = scan.sensorPose.yaw();
    for (std::size_t i = 0; i < usable.size(); ++i) {
        const double r = scan.getScanRange(i);
        if (!usable[i] || r > m_opts.max_range_m) continue;
        const double a = syaw + bearingOf(scan, i);
        index.push_back(i);
        lx.push_back(sx + r * std::cos(a));
        ly.push_back(sy + r * std::sin(a));
    }
    if (index.empty()) return;
    // At most ~500 particles decide (evenly strided: the set's order carries no meaning).
    const std::size_t stride = std::max<std::size_t>(1, n / 500);
    std::vector<std::size_t> explained(index.size(), 0);
    std::size_t sampled = 0;
    for (std::size_t p = 0; p < n; p += stride, ++sampled) {
        const double c = std::cos(poses[p].phi), s = std::sin(poses[p].phi);
        for (std::size_t k = 0; k < index.size(); ++k) {
            const double wx = poses[p].x + c * lx[k] - s * ly[k], wy = poses[p].y + s * lx[k] + c * ly[k];
            if (m_wall_distance.at(wx, wy) <= m_opts.beam_skip_distance_m) ++explained[k];
        }
    }
    std::vector<std::size_t> skip;
    const double needed = m_opts.beam_skip_threshold * static_cast<double>(sampled);
    for (std::size_t k = 0; k < index.size(); ++k)
        if (static_cast<double>(explained[k]) < needed) skip.push_back(index[k]);
    if (static_cast<double>(skip.size()) > m_opts.beam_skip_max_fraction * static_cast<double>(index.size())) return;
    for (const auto i : skip) usable[i] = 0;
    m_last_skipped = skip.size();
}

void ScanLikelihood::logLikelihoods(const mrpt::obs::CObservation2DRangeScan& full_scan, const mrpt::math::TPose2D* poses,
                                    std::size_t n, double* out_log, bool skip_unexplained) const {
    const std::vector<char> usable = usableReturns(full_scan, poses, n, skip_unexplained);
    if (std::none_of(usable.begin(), usable.end(), [](char u) { return u != 0; })) {
        std::fill(out_log, out_log + n, 0.0);
        return;
    }
    bool all = true;
    for (std::size_t i = 0; i < usable.size(); ++i) all = all && (usable[i] || !full_scan.getScanRangeValidity(i));
    // A fresh scan with the left-out returns invalid (a copy would share the original's cached points map).
    mrpt::obs::CObservation2DRangeScan reduced;
    if (!all) {
        std::vector<float> ranges(usable.size());
        for (std::size_t i = 0; i < usable.size(); ++i) ranges[i] = full_scan.getScanRange(i);
        reduced.sensorLabel = full_scan.sensorLabel;
        reduced.timestamp = full_scan.timestamp;
        reduced.aperture = full_scan.aperture;
        reduced.rightToLeft = full_scan.rightToLeft;
        reduced.maxRange = full_scan.maxRange;
        reduced.sensorPose = full_scan.sensorPose;
        reduced.stdError = full_scan.stdError;
        reduced.beamAperture = full_scan.beamAperture;
        reduced.deltaPitch = full_scan.deltaPitch;
        reduced.loadFromVectors(usable.size(), ranges.data(), usable.data());
    }
    const auto& scan = all ? full_scan : reduced;
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
