#include <simp/lidar/IcpPoseTracker.h>
#include <simp/lidar/ScanPoints.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <stdexcept>

namespace simp::lidar {

IcpPoseTracker::IcpPoseTracker(const mrpt::maps::COccupancyGridMap2D& floorplan, const IcpPosesOptions& options)
    : m_opts(options), m_walls(wallSurfacePoints(floorplan)) {
    if (m_walls.empty()) throw std::invalid_argument("IcpPoseTracker: the floor plan has no wall");
    auto& o = m_icp.options;
    o.ICP_algorithm = mrpt::slam::icpClassic;
    o.maxIterations = static_cast<unsigned>(m_opts.max_iterations);
    o.thresholdDist = m_opts.threshold_dist_m;
    o.thresholdAng = m_opts.threshold_ang_deg * M_PI / 180.0;
    o.ALFA = m_opts.alfa;
    o.smallestThresholdDist = m_opts.smallest_threshold_dist_m;
    o.onlyUniqueRobust = false;
    o.doRANSAC = false;
    o.corresponding_points_decimation = 1;
}

mrpt::math::TPose2D IcpPoseTracker::step(const mrpt::poses::CPose2D& odometry_increment,
                                         const mrpt::obs::CObservation2DRangeScan* scan) {
    const mrpt::poses::CPose2D predicted = m_pose + odometry_increment;
    m_pose = predicted;
    if (scan == nullptr) return m_pose.asTPose();
    const auto pts = scanToPoints(*scan, static_cast<std::size_t>(m_opts.scan_decimation), m_opts.max_range_m);
    if (pts.size() < static_cast<std::size_t>(m_opts.min_points)) {
        ++m_rejected;
        return m_pose.asTPose();
    }
    mrpt::slam::CICP::TReturnInfo info;
    const auto pdf = m_icp.Align(&m_walls, &pts, predicted, info);
    const mrpt::poses::CPose2D aligned = pdf->getMeanVal();
    const mrpt::poses::CPose2D correction = aligned - predicted;
    const bool ok = info.goodness >= m_opts.min_goodness && correction.norm() <= m_opts.max_correction_m &&
                    std::abs(mrpt::math::wrapToPi(correction.phi())) <= m_opts.max_correction_deg * M_PI / 180.0;
    if (ok) {
        m_pose = aligned;
        ++m_accepted;
    } else {
        ++m_rejected;
    }
    return m_pose.asTPose();
}

}  // namespace simp::lidar
