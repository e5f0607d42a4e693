#pragma once
/// \file IcpPoseTracker.h
/// Scan-matched poses (the paper's "ICP" map poses): from a known start, each step predicts the pose
/// with the odometry increment and aligns the step's scan to the floor plan's wall surfaces with
/// MRPT's ICP (mrpt::slam::CICP, scan-to-map), the prediction as the initial guess. An alignment
/// with few paired points or a large jump from the prediction is rejected (odometry only).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/slam/CICP.h>
#include <simp/lidar/IcpOptions.h>
#include <simp/camera/WallDistance.h>

#include <cstddef>

namespace simp::lidar {

class IcpPoseTracker {
   public:
    IcpPoseTracker(const mrpt::maps::COccupancyGridMap2D& floorplan, const IcpPosesOptions& options);

    /// Starts at `pose` (m, rad; world frame of the floor plan).
    /// The start is known: the uncertainty gate's variances start at 0.
    void reset(const mrpt::math::TPose2D& pose) {
        m_pose = mrpt::poses::CPose2D(pose);
        m_var_xy = m_var_phi = 0.0;
    }

    /// One step: `odometry_increment` (robot frame of the previous step), then `scan` (nullptr: none).
    /// \return the pose after the step.
    mrpt::math::TPose2D step(const mrpt::poses::CPose2D& odometry_increment,
                             const mrpt::obs::CObservation2DRangeScan* scan);

    mrpt::math::TPose2D pose() const { return m_pose.asTPose(); }
    std::size_t accepted() const { return m_accepted; }  ///< scans whose alignment was used
    std::size_t rejected() const { return m_rejected; }  ///< scans left to odometry
    std::size_t wallPoints() const { return m_walls.size(); }

    /// The correction from `predicted` to `aligned` kept along the directions that `scan_points` (robot
    /// frame) at `aligned` constrain (IcpPosesOptions::min_constraint_points): the pose to use.
    mrpt::poses::CPose2D constrained(const mrpt::poses::CPose2D& predicted, const mrpt::poses::CPose2D& aligned,
                                     const mrpt::maps::CSimplePointsMap& scan_points) const;

   private:
    IcpPosesOptions m_opts;
    mrpt::maps::CSimplePointsMap m_walls;
    camera::WallDistance m_wall_distance;  ///< its gradient: the wall normal at a scan point
    mrpt::slam::CICP m_icp;
    mrpt::poses::CPose2D m_pose;
    std::size_t m_accepted = 0, m_rejected = 0;
    double m_var_xy = 0.0, m_var_phi = 0.0;  ///< the pose's variance (m^2, rad^2; uncertainty gate)
};

}  // namespace simp::lidar
