/// \file DetectionRawlog.cpp
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/detector_io/DetectionRawlog.h>

#include <filesystem>
#include <stdexcept>

namespace simp::detector_io {

void writeDetectionRawlog(const std::string& path, const std::vector<obs::RawlogFrame>& frames) {
    const std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    mrpt::io::CFileOutputStream file;
    if (!file.open(path)) throw std::runtime_error("rawlog '" + path + "': cannot open for writing");
    auto archive = mrpt::serialization::archiveFrom(file);
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motion;  // Gaussian model, MRPT defaults
    for (const obs::RawlogFrame& f : frames) {
        mrpt::obs::CActionCollection acts;
        mrpt::obs::CActionRobotMovement2D move;
        move.timestamp = f.timestamp;
        move.computeFromOdometry(mrpt::poses::CPose2D(f.odometry_increment.value_or(mrpt::math::TPose2D(0, 0, 0))),
                                 motion);
        acts.insert(move);
        mrpt::obs::CSensoryFrame sf;
        for (const auto& o : f.observations) sf.insert(o);
        archive << acts << sf;
    }
}

std::vector<io::StampedPose2D> integrateOdometry(const std::vector<obs::RawlogFrame>& frames) {
    std::vector<io::StampedPose2D> out;
    mrpt::poses::CPose2D pose;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        if (k > 0 && frames[k].odometry_increment) pose = pose + mrpt::poses::CPose2D(*frames[k].odometry_increment);
        const double t = mrpt::Clock::toDouble(frames[k].timestamp);
        if (!out.empty() && t <= out.back().t_s) continue;  // TUM needs increasing times
        out.push_back({t, pose.asTPose()});
    }
    return out;
}

}  // namespace simp::detector_io
