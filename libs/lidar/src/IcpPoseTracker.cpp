#include <simp/lidar/IcpPoseTracker.h>
#include <simp/lidar/ScanPoints.h>

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace simp::lidar {

IcpPoseTracker::IcpPoseTracker(const mrpt::maps::COccupancyGridMap2D& floorplan, const IcpPosesOptions& options)
    : m_opts(options), m_walls(wallSurfacePoints(floorplan)), m_wall_distance(floorplan) {  // the same walls (< kUnknownFree)
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
    const bool gated = m_opts.alignment_sigma_m > 0;
    if (gated) {
        const double t = odometry_increment.norm(), r = std::abs(odometry_increment.phi());
        const double s_xy = std::max(m_opts.process_min_m, m_opts.process_m_per_m * t + m_opts.process_m_per_rad * r);
        const double s_phi = std::max(m_opts.process_min_rad, m_opts.process_rad_per_m * t + m_opts.process_rad_per_rad * r);
        m_var_xy += s_xy * s_xy;
        m_var_phi += s_phi * s_phi;
    }
    if (scan == nullptr) return m_pose.asTPose();
    const auto pts = scanToPoints(*scan, static_cast<std::size_t>(m_opts.scan_decimation), m_opts.min_range_m, m_opts.max_range_m);
    if (pts.size() < static_cast<std::size_t>(m_opts.min_points)) {
        ++m_rejected;
        return m_pose.asTPose();
    }
    mrpt::slam::CICP::TReturnInfo info;
    const auto pdf = m_icp.Align(&m_walls, &pts, predicted, info);
    const mrpt::poses::CPose2D aligned = pdf->getMeanVal();
    const mrpt::poses::CPose2D correction = aligned - predicted;
    if (gated) {
        const double r_xy = m_opts.alignment_sigma_m * m_opts.alignment_sigma_m;
        const double r_phi = std::pow(m_opts.alignment_sigma_deg * M_PI / 180.0, 2);
        const double d_xy = std::hypot(aligned.x() - predicted.x(), aligned.y() - predicted.y());
        const double d_phi = mrpt::math::wrapToPi(aligned.phi() - predicted.phi());
        const double g2 = m_opts.gate_sigmas * m_opts.gate_sigmas;
        const bool ok = info.goodness >= m_opts.min_goodness && d_xy * d_xy <= g2 * (m_var_xy + r_xy) &&
                        d_phi * d_phi <= g2 * (m_var_phi + r_phi);
        if (!ok) {
            ++m_rejected;
            return m_pose.asTPose();
        }
        const double k_xy = m_var_xy / (m_var_xy + r_xy), k_phi = m_var_phi / (m_var_phi + r_phi);
        const mrpt::poses::CPose2D target = constrained(predicted, aligned, pts);
        m_pose = mrpt::poses::CPose2D(predicted.x() + k_xy * (target.x() - predicted.x()),
                                      predicted.y() + k_xy * (target.y() - predicted.y()),
                                      predicted.phi() + k_phi * d_phi);
        m_var_xy *= 1.0 - k_xy;
        m_var_phi *= 1.0 - k_phi;
        ++m_accepted;
        return m_pose.asTPose();
    }
    const bool ok = info.goodness >= m_opts.min_goodness && correction.norm() <= m_opts.max_correction_m &&
                    std::abs(mrpt::math::wrapToPi(correction.phi())) <= m_opts.max_correction_deg * M_PI / 180.0;
    if (ok) {
        m_pose = constrained(predicted, aligned, pts);
        ++m_accepted;
    } else {
        ++m_rejected;
    }
    return m_pose.asTPose();
}

mrpt::poses::CPose2D IcpPoseTracker::constrained(const mrpt::poses::CPose2D& predicted, const mrpt::poses::CPose2D& aligned,
                                                 const mrpt::maps::CSimplePointsMap& scan_points) const {
    if (m_opts.min_constraint_points <= 0) return aligned;
    Eigen::Matrix2d info = Eigen::Matrix2d::Zero();
    for (std::size_t i = 0; i < scan_points.size(); ++i) {
        float lx = 0, ly = 0;
        scan_points.getPoint(i, lx, ly);
        double wx = 0, wy = 0;
        aligned.composePoint(lx, ly, wx, wy);
        if (m_wall_distance.at(wx, wy) > m_opts.threshold_dist_m) continue;
        Eigen::Vector2d n = m_wall_distance.gradient(wx, wy);
        if (n.norm() < 1e-9) continue;  // inside a wall, between two, or on the grid's border: no direction
        n.normalize();
        info += n * n.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(info);
    const Eigen::Vector2d correction(aligned.x() - predicted.x(), aligned.y() - predicted.y());
    Eigen::Vector2d kept = Eigen::Vector2d::Zero();
    for (int k = 0; k < 2; ++k)
        if (eig.eigenvalues()(k) >= m_opts.min_constraint_points)
            kept += eig.eigenvectors().col(k) * eig.eigenvectors().col(k).dot(correction);
    return {predicted.x() + kept.x(), predicted.y() + kept.y(), aligned.phi()};
}

}  // namespace simp::lidar
