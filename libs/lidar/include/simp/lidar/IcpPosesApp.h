#pragma once
/// \file IcpPosesApp.h
/// `simp-icp-poses --world W --rawlog Q/sequence.rawlog --initial-pose x,y,phi --out P.tum
///  [--gt Q/groundtruth.tum] [--config INI]`: scan-matched poses (IcpPoseTracker) of every frame of a
/// rawlog with CObservation2DRangeScan observations, written as TUM; with --gt, their ATE
/// (simp::eval::evaluateTrajectory, as `simp-eval traj`). The app's main() is initialize() + run().

#include <mrpt/math/TPose2D.h>
#include <simp/eval/TrajectoryMetrics.h>
#include <simp/io/CommandLine.h>
#include <simp/io/Tum.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace simp::lidar {

class IcpPosesApp {
   public:
    static std::string usage();
    static io::CommandLine commandLine();  ///< the declared options
    /// Parses the arguments (without the program name). \return false after --help (printed to `out`).
    /// \throw std::invalid_argument naming the option on bad input.
    bool initialize(const std::vector<std::string>& args, std::ostream& out);
    /// \throw std::invalid_argument / std::runtime_error naming the file (world, rawlog without scans, .ini).
    void run(std::ostream& out);

    std::string world_dir, rawlog_path, out_path, gt_path, config_path;
    mrpt::math::TPose2D initial_pose;

    /// Results of run().
    std::vector<io::StampedPose2D> poses;
    std::size_t scans = 0, accepted = 0;
    std::optional<eval::TrajMetrics> metrics;  ///< with --gt
};

/// "x,y,phi" (m, m, rad) of --initial-pose. \throw std::invalid_argument naming the text.
mrpt::math::TPose2D parsePose2D(const std::string& text, const std::string& what);

}  // namespace simp::lidar
