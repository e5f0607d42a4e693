/// \file OffsetSamples.cpp
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/stats/GroundTruthMatch.h>
#include <simp/stats/OffsetSamples.h>
#include <simp/model/NoiseFrame.h>

#include <cmath>

namespace simp::stats {

Eigen::Vector2d offsetInObjectFrame(const geometry::Box3D& prediction_in_world, const geometry::Box3D& object) {
    // The class noise frame (y along the longer side), in which the simulator, the sensor model
    // and the mapper read a class model: independent of which of the box's equivalent frames it has.
    const double yaw = model::classNoiseFrameYaw(object);
    const Eigen::Vector2d d = (prediction_in_world.center - object.center).head<2>();
    const double c = std::cos(yaw), s = std::sin(yaw);
    return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

OffsetSamples collectOffsetSamples(const std::vector<obs::RawlogFrame>& frames,
                                   const std::vector<io::StampedPose2D>& poses,
                                   const world::ObjectMapData& gt, const SampleOptions& options) {
    OffsetSamples out;
    out.per_class.resize(gt.class_names.size());
    for (const obs::RawlogFrame& frame : frames) {
        for (const auto& ob : frame.observations) {
            const std::size_t n = ob->size();
            out.counts.detections += n;
            mrpt::math::TPose2D pose2d;
            if (!io::interpolatePose(poses, mrpt::Clock::toDouble(ob->timestamp), pose2d)) {
                out.counts.no_pose += n;
                continue;
            }
            const mrpt::poses::CPose3D world_T_robot{mrpt::poses::CPose2D(pose2d)};
            for (std::size_t i = 0; i < n; ++i) {
                const obs::Detection3D& d = ob->detections()[i];
                if (d.confidence < options.min_confidence) {
                    ++out.counts.low_confidence;
                    continue;
                }
                const int cls = gt.classId(ob->classNameOf(d));
                if (cls < 0) {
                    ++out.counts.unknown_class;
                    continue;
                }
                const geometry::Box3D box = ob->boxInWorld(i, world_T_robot);
                const auto m = matchToGroundTruth(box, cls, gt, options.delta_m);
                if (!m) {
                    ++out.counts.discarded;
                    continue;
                }
                out.per_class[static_cast<std::size_t>(cls)].push_back(
                    offsetInObjectFrame(box, gt.objects[m->object_index].box));
                ++out.counts.matched;
            }
        }
    }
    return out;
}

}  // namespace simp::stats
