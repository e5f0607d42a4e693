#include <simp/lidar/IcpPoseTracker.h>
#include <simp/lidar/IcpPosesApp.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
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

std::string IcpPosesApp::usage() {
    return "simp-icp-poses: scan-matched poses from odometry and 2D LiDAR scans (MRPT's ICP against the floor plan)\n"
           "\n"
           "  simp-icp-poses --world W --rawlog Q/sequence.rawlog --initial-pose x,y,phi --out P.tum\n"
           "                 [--gt Q/groundtruth.tum] [--config INI]\n"
           "\n"
           "  --world W          world directory: its floor plan is the map the scans are aligned to\n"
           "  --rawlog R         rawlog with odometry and CObservation2DRangeScan (simp-sim sequence --lidar)\n"
           "  --initial-pose P   the known start x,y,phi (m, m, rad) in the floor plan's frame\n"
           "  --out P.tum        the poses of every frame (TUM), e.g. for simp-map --poses P.tum\n"
           "  --gt G.tum         also print the ATE against this ground truth (as simp-eval traj)\n"
           "  --config INI       [ICP] knobs (config_ini/icp-poses.ini; doc/lidar.md)\n";
}

bool IcpPosesApp::initialize(const std::vector<std::string>& args, std::ostream& out) {
    for (const auto& a : args)
        if (a == "--help" || a == "-h") {
            out << usage();
            return false;
        }
    bool have_pose = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& opt = args[i];
        if (i + 1 >= args.size()) throw std::invalid_argument("option " + opt + " needs a value; see --help");
        const std::string& v = args[++i];
        if (opt == "--world") world_dir = v;
        else if (opt == "--rawlog") rawlog_path = v;
        else if (opt == "--out") out_path = v;
        else if (opt == "--gt") gt_path = v;
        else if (opt == "--config") config_path = v;
        else if (opt == "--initial-pose") {
            initial_pose = parsePose2D(v, "option --initial-pose");
            have_pose = true;
        } else throw std::invalid_argument("unknown option '" + opt + "'; see --help");
    }
    for (const auto& [name, value] : {std::pair<std::string, std::string>{"--world", world_dir}, {"--rawlog", rawlog_path},
                                      {"--out", out_path}})
        if (value.empty()) throw std::invalid_argument("option " + name + " is required; see --help");
    if (!have_pose) throw std::invalid_argument("option --initial-pose is required (the known start x,y,phi)");
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
