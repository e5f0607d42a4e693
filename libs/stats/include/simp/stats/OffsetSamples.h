#pragma once
/// \file OffsetSamples.h
/// Collection of matched prediction centres in the object-centric ground frame: the samples
/// of the per-class noise distribution p(c | l) (Eq. perclassdist).

#include <simp/geometry/Box3D.h>
#include <simp/io/Tum.h>
#include <simp/obs/RawlogReader.h>
#include <simp/world/ObjectMapData.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace simp::stats {

/// Centre of `prediction_in_world` relative to the object, on the ground, in the object frame:
/// origin = object centre, x = the object's local x axis projected on the floor (its yaw),
/// y = 90 deg to the left of it (m). d = Rz(-yaw) (c_pred,xy - c_obj,xy).
Eigen::Vector2d offsetInObjectFrame(const geometry::Box3D& prediction_in_world, const geometry::Box3D& object);

/// Options of collectOffsetSamples().
struct SampleOptions {
    double delta_m = 1.0;          ///< matching gate: centre distance (m)
    double min_confidence = 0.0;   ///< predictions below this score are skipped
};

/// Counters of collectOffsetSamples().
struct SampleCounts {
    std::size_t detections = 0;        ///< detections read
    std::size_t low_confidence = 0;    ///< skipped: score < min_confidence
    std::size_t no_pose = 0;           ///< skipped: timestamp outside the trajectory
    std::size_t unknown_class = 0;     ///< skipped: class name not in the world's classes
    std::size_t discarded = 0;         ///< no ground-truth object within delta
    std::size_t matched = 0;           ///< became a sample
};

/// Samples per class id of `gt` (outer index = class id).
struct OffsetSamples {
    std::vector<std::vector<Eigen::Vector2d>> per_class;  ///< object-frame offsets (m)
    SampleCounts counts;
};

/// For every detection of every frame: robot pose interpolated at the observation's timestamp
/// from `poses` (world_T_robot), box to the world (world_T_robot + robot_T_camera + box in camera),
/// matched with matchToGroundTruth(), offset stored with offsetInObjectFrame().
/// Class names of the observations are looked up by name in `gt.class_names`.
OffsetSamples collectOffsetSamples(const std::vector<obs::RawlogFrame>& frames,
                                   const std::vector<io::StampedPose2D>& poses,
                                   const world::ObjectMapData& gt, const SampleOptions& options);

}  // namespace simp::stats
