#include <simp/lidar/IcpPoseTracker.h>
#include <simp/lidar/ScanPoints.h>

#include <mrpt/math/wrap2pi.h>
#include <simp/camera/FloorPlanThresholds.h>
#include <opencv2/imgproc.hpp>

#include <Eigen/Eigenvalues>
#include <algorithm>

#include <cmath>
#include <stdexcept>

namespace simp::lidar {

IcpPoseTracker::IcpPoseTracker(const mrpt::maps::COccupancyGridMap2D& floorplan, const IcpPosesOptions& options)
    : m_opts(options), m_walls(wallSurfacePoints(floorplan)) {
    if (m_walls.empty()) throw std::invalid_argument("IcpPoseTracker: the floor plan has no wall");
    // The walls of wallSurfacePoints (cells below kUnknownFree), as a distance map: its gradient is the
    // wall normal at a scan point.
    cv::Mat1b free_cells(static_cast<int>(floorplan.getSizeY()), static_cast<int>(floorplan.getSizeX()));
    for (int cy = 0; cy < free_cells.rows; ++cy)
        for (int cx = 0; cx < free_cells.cols; ++cx)
            free_cells(cy, cx) = floorplan.getCell(cx, cy) < camera::floorplan::kUnknownFree ? 0 : 255;
    cv::distanceTransform(free_cells, m_wall_distance_m, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    m_res = floorplan.getResolution();
    m_wall_distance_m *= m_res;
    m_x_min = floorplan.getXMin();
    m_y_min = floorplan.getYMin();
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
    const int cols = m_wall_distance_m.cols, rows = m_wall_distance_m.rows;
    const auto d = [&](int cx, int cy) { return m_wall_distance_m(std::clamp(cy, 0, rows - 1), std::clamp(cx, 0, cols - 1)); };
    for (std::size_t i = 0; i < scan_points.size(); ++i) {
        float lx = 0, ly = 0;
        scan_points.getPoint(i, lx, ly);
        double wx = 0, wy = 0;
        aligned.composePoint(lx, ly, wx, wy);
        const mrpt::math::TPoint2D w(wx, wy);
        const int cx = static_cast<int>(std::floor((w.x - m_x_min) / m_res)), cy = static_cast<int>(std::floor((w.y - m_y_min) / m_res));
        if (cx < 1 || cy < 1 || cx >= cols - 1 || cy >= rows - 1 || d(cx, cy) > m_opts.threshold_dist_m) continue;
        Eigen::Vector2d n(d(cx + 1, cy) - d(cx - 1, cy), d(cx, cy + 1) - d(cx, cy - 1));
        if (n.norm() < 1e-9) continue;  // inside a wall, or between two: no direction
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
