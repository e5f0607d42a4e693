#include <simp/lidar/IcpPoseTracker.h>
#include <simp/lidar/IcpPosesApp.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <simp/io/CommandLine.h>
#include <simp/io/StrictIni.h>
#include <simp/io/StrictNumber.h>
#include <simp/localization/RawlogSequence.h>
#include <simp/world/World.h>

#include <filesystem>
#include <stdexcept>

namespace simp::lidar {
namespace {

/// The last 2D scan of a frame (nullptr: none).
const mrpt::obs::CObservation2DRangeScan* lastScan(const mrpt::obs::CSensoryFrame& sf) {
    const mrpt::obs::CObservation2DRangeScan* scan = nullptr;
    for (const auto& o : sf)
        if (const auto* s = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(o.get())) scan = s;
    return scan;
}

}  // namespace

mrpt::math::TPose2D parsePose2D(const std::string& text, const std::string& what) {
    std::vector<double> v;
    std::size_t pos = 0;
    while (true) {
        const auto comma = text.find(',', pos);
        const std::string item = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
        const auto x = io::parseFiniteNumber(item);
        if (!x) throw std::invalid_argument(what + " '" + text + "': '" + item + "' is not a finite number (expected x,y,phi)");
        v.push_back(*x);
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    if (v.size() != 3) throw std::invalid_argument(what + " '" + text + "': expected 3 numbers x,y,phi (m, m, rad)");
    return {v[0], v[1], v[2]};
}

io::CommandLine IcpPosesApp::commandLine() {
    io::CommandLine c("simp-icp-poses",
                      "Scan-matched poses from odometry and 2D LiDAR scans (MRPT's ICP against the floor plan).");
    c.required("world", "W", "world directory: its floor plan is the map the scans are aligned to")
        .required("rawlog", "Q/sequence.rawlog", "rawlog with odometry and CObservation2DRangeScan (simp-sim sequence --lidar)")
        .required("initial-pose", "x,y,phi", "the known start x,y,phi (m, m, rad) in the floor plan's frame")
        .required("out", "P.tum", "the poses of every frame (TUM), e.g. for simp-map --poses P.tum")
        .option("gt", "G.tum", "also print the ATE against this ground truth (as simp-eval traj)")
        .option("config", "INI", "[ICP] knobs (config_ini/icp-poses.ini; doc/lidar.md)");
    return c;
}

std::string IcpPosesApp::usage() { return commandLine().help(); }

bool IcpPosesApp::initialize(const std::vector<std::string>& args, std::ostream& out) {
    io::CommandLine c = commandLine();
    if (!c.parse(args, out)) return false;
    world_dir = c.value("world"), rawlog_path = c.value("rawlog"), out_path = c.value("out");
    gt_path = c.value("gt"), config_path = c.value("config");
    initial_pose = parsePose2D(c.value("initial-pose"), "option --initial-pose");
    if (!gt_path.empty() && !std::filesystem::is_regular_file(gt_path))
        throw std::invalid_argument("option --gt: '" + gt_path + "' does not exist");
    return true;
}

void IcpPosesApp::run(std::ostream& out) {
    const io::StrictIni cfg(config_path);
    IcpPosesOptions opts;
    cfg.loadChecked([&](const io::StrictIni& c) { opts.loadFromConfig(c); });
    if (!std::filesystem::is_directory(world_dir)) throw std::runtime_error("world directory '" + world_dir + "' does not exist");
    const world::World world = world::loadWorld(world_dir);
    const auto seq = localization::loadRawlogSequence(rawlog_path);
    scans = 0;
    for (const auto& f : seq.frames) scans += lastScan(*f.observations) ? 1 : 0;
    if (scans == 0)
        throw std::invalid_argument("rawlog '" + rawlog_path +
                                    "' holds no mrpt::obs::CObservation2DRangeScan (simulate with simp-sim sequence --lidar)");
    const auto& grid = world.floorplan;
    const int cx = grid.x2idx(initial_pose.x), cy = grid.y2idx(initial_pose.y);
    if (cx < 0 || cy < 0 || cx >= static_cast<int>(grid.getSizeX()) || cy >= static_cast<int>(grid.getSizeY()) ||
        !(grid.getCell(cx, cy) > 0.5f))
        throw std::invalid_argument("option --initial-pose: (" + std::to_string(initial_pose.x) + ", " +
                                    std::to_string(initial_pose.y) + ") is not in the free space of '" + world_dir + "'");
    IcpPoseTracker tracker(grid, opts);
    tracker.reset(initial_pose);
    poses.clear();
    for (const auto& f : seq.frames) poses.push_back({f.t_s, tracker.step(f.odometry_increment, lastScan(*f.observations))});
    accepted = tracker.accepted();
    io::writeTum(out_path, poses);
    out << "simp-icp-poses: " << poses.size() << " frames, " << scans << " scans (" << accepted << " aligned, "
        << tracker.rejected() << " left to odometry) against " << tracker.wallPoints() << " wall points; wrote "
        << out_path << "\n";
    if (!gt_path.empty()) {
        metrics = eval::evaluateTrajectoryFiles(gt_path, out_path);
        out << "simp-icp-poses: ATE " << (metrics->ate_trans_m ? std::to_string(*metrics->ate_trans_m) : "n/a")
            << " m, " << (metrics->ate_rot_rad ? std::to_string(*metrics->ate_rot_rad) : "n/a") << " rad against "
            << gt_path << (metrics->success ? "" : " (never within 0.3 m / pi/4: not converged)") << "\n";
    }
}

}  // namespace simp::lidar
