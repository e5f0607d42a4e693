#pragma once
/// \file DetectionSet.h
/// Detector output independent of its file format: images (timestamp, camera) with their 3D
/// detections, and the conversion to / from rawlog frames (doc/detector-io.md).

#include <simp/io/Tum.h>
#include <simp/detector_io/CameraRig.h>
#include <simp/obs/RawlogReader.h>

#include <cstdint>
#include <string>
#include <vector>

namespace simp::detector_io {

/// One camera image and the detector's output on it (boxes in the camera optical frame).
struct DetectionImage {
    std::int64_t id = 0;                       ///< image id of the source file
    double timestamp_s = 0;                    ///< time of the image (s, same clock as the poses)
    std::string camera;                        ///< camera name (rig entry, observation sensor label)
    std::vector<obs::Detection3D> detections;  ///< class_id indexes DetectionSet::class_names
};

struct DetectionSet {
    std::vector<std::string> class_names;
    std::vector<DetectionImage> images;
};

/// Builds rawlog frames: images with the same timestamp form one frame (one observation per
/// camera, sensor label = camera name, camera pose and intrinsics from the rig); the frames are
/// sorted by time; each frame's odometry increment is pose(t_k) (-) pose(t_{k-1}) from `poses`
/// interpolated linearly (zero for the first frame).
/// `source` names the detections file in messages.
/// \throw std::runtime_error naming source, image id and camera for a camera missing from the rig,
///        a time outside the poses' range, or two images of one camera at the same time.
std::vector<obs::RawlogFrame> framesFromDetections(const DetectionSet& set, const std::vector<io::StampedPose2D>& poses,
                                                   const CameraRig& rig, const std::string& source);

/// The inverse for export: one image per observation (ids 0, 1, ... in file order), classes by
/// name (union of the observations' class lists, in order of first appearance).
DetectionSet detectionsFromFrames(const std::vector<obs::RawlogFrame>& frames);

}  // namespace simp::detector_io
