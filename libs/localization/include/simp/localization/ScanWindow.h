#pragma once
/// \file ScanWindow.h
/// The last few scans weighed, each with the odometry pose of its update: the LiDAR's evidence on
/// where the robot has been, scored for a handful of candidate poses now (the challenger's take-over,
/// doc/lidar.md "The scan in the challenger's take-over"). One scan does not tell a look-alike place
/// from the right one; a window of scans along the way mostly does.

#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <deque>
#include <vector>

namespace simp::localization {

class ScanLikelihood;

class ScanWindow {
   public:
    explicit ScanWindow(std::size_t capacity) : m_capacity(capacity) {}

    /// Adds a scan taken with the robot at `odometry_pose` (odometry frame); the oldest goes beyond capacity.
    void add(mrpt::obs::CObservation2DRangeScan::Ptr scan, const mrpt::poses::CPose2D& odometry_pose);
    void clear() { m_scans.clear(); }
    std::size_t size() const { return m_scans.size(); }

    /// out[i] = sum over the window of model's log-likelihood (weight applied, every usable return:
    /// no beam skipping, which would judge the candidates by each other) with the robot at poses[i]
    /// now (world) and at odometry_now: each scan at poses[i] (+) (odometry_now^-1 (+) its odometry pose).
    void score(const ScanLikelihood& model, const std::vector<mrpt::math::TPose2D>& poses,
               const mrpt::poses::CPose2D& odometry_now, std::vector<double>& out) const;

   private:
    struct Entry {
        mrpt::obs::CObservation2DRangeScan::Ptr scan;
        mrpt::poses::CPose2D odometry;
    };
    std::size_t m_capacity;
    std::deque<Entry> m_scans;
};

}  // namespace simp::localization
