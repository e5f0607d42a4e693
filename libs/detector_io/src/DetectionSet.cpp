/// \file DetectionSet.cpp
#include <mrpt/poses/CPose2D.h>
#include <simp/detector_io/DetectionSet.h>
#include <simp/obs/ObjectClasses.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace simp::detector_io {

std::vector<obs::RawlogFrame> framesFromDetections(const DetectionSet& set, const std::vector<io::StampedPose2D>& poses,
                                                   const CameraRig& rig, const std::string& source) {
    std::vector<const DetectionImage*> order;
    for (const auto& im : set.images) order.push_back(&im);
    std::stable_sort(order.begin(), order.end(),
                     [](const DetectionImage* a, const DetectionImage* b) { return a->timestamp_s < b->timestamp_s; });
    std::vector<obs::RawlogFrame> frames;
    std::optional<mrpt::poses::CPose2D> previous;
    std::set<std::string> cameras_in_frame;
    for (const DetectionImage* im : order) {
        const std::string where = source + ": image " + std::to_string(im->id) + " (camera '" + im->camera + "', t=" +
                                  std::to_string(im->timestamp_s) + " s)";
        const int cam = rig.indexOf(im->camera);
        if (cam < 0) throw std::runtime_error(where + ": camera not in the rig file");
        const auto stamp = mrpt::Clock::fromDouble(im->timestamp_s);
        if (frames.empty() || frames.back().timestamp != stamp) {
            mrpt::math::TPose2D p;
            if (!io::interpolatePose(poses, im->timestamp_s, p)) {
                std::ostringstream msg;
                msg.precision(17);
                if (poses.empty())  // an empty poses file: no range to name (front() would be UB)
                    msg << where << ": no poses to interpolate (the poses file has no pose)";
                else
                    msg << where << ": time outside the poses' range [" << poses.front().t_s << ", "
                        << poses.back().t_s << "] s";
                throw std::runtime_error(msg.str());
            }
            obs::RawlogFrame f;
            f.timestamp = stamp;
            const mrpt::poses::CPose2D pose(p);
            f.odometry_increment = previous ? (pose - *previous).asTPose() : mrpt::math::TPose2D(0, 0, 0);
            previous = pose;
            frames.push_back(f);
            cameras_in_frame.clear();
        }
        if (!cameras_in_frame.insert(im->camera).second)
            throw std::runtime_error(where + ": two images of this camera at the same time");
        const RigCamera& rc = rig.cameras[static_cast<std::size_t>(cam)];
        auto o = obs::CObservationObjects3D::Create();
        o->sensorLabel = rc.name;
        o->timestamp = stamp;
        o->setCameraPose(rc.robotTCamera());
        o->setIntrinsics(rc.intrinsics);
        o->setImageSize(rc.intrinsics.ncols, rc.intrinsics.nrows);
        o->setClassNames(set.class_names);
        try {
            o->setDetections(im->detections);
        } catch (const std::exception& e) {
            throw std::runtime_error(where + ": " + e.what());
        }
        frames.back().observations.push_back(o);
    }
    return frames;
}

DetectionSet detectionsFromFrames(const std::vector<obs::RawlogFrame>& frames) {
    DetectionSet set;
    std::int64_t next_id = 0;
    for (const auto& f : frames)
        for (const auto& o : f.observations) {
            DetectionImage im;
            im.id = next_id++;
            im.timestamp_s = mrpt::Clock::toDouble(o->timestamp);
            im.camera = o->sensorLabel;
            for (const std::string& name : o->classNames())
                if (obs::classIndexOf(set.class_names, name) < 0) set.class_names.push_back(name);
            for (const obs::Detection3D& d : o->detections()) {
                const std::string& name = o->classNameOf(d);
                const int c = obs::classIndexOf(set.class_names, name);
                obs::Detection3D e = d;
                e.class_id = static_cast<std::uint16_t>(c);
                im.detections.push_back(e);
            }
            set.images.push_back(im);
        }
    return set;
}

}  // namespace simp::detector_io
