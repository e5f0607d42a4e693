#pragma once
/// \file CameraFrames.h
/// Posed camera images, the FRAMES.json input of simp-labels (doc/labels.md):
///   {"images": [{"id": 0, "file_path": "rgb/000000.png", "timestamp": 12.5 (optional),
///                "width": 640, "height": 480, "K": [[fx, 0, cx], [0, fy, cy], [0, 0, 1]],
///                "position_m": [x, y, z],
///                "rotation": [[..], [..], [..]]  or  "quaternion_wxyz": [w, x, y, z]}]}
/// position_m / rotation = pose of the camera optical frame (x right, y down, z forward) in the
/// world: p_world = R p_camera + position (the columns of R are the camera axes in the world).
///
/// Alternatively an image gives `"camera": NAME` and `"timestamp"` instead of K / width / height /
/// position_m / rotation: the pose is then world_T_robot(timestamp) (+) robot_T_camera and K the
/// camera's, from robot poses (TUM, interpolated) and a camera rig file (CameraRig.h).

#include <simp/camera/PinholeCamera.h>
#include <simp/io/Tum.h>
#include <simp/detector_io/CameraRig.h>

#include <cstdint>
#include <string>
#include <vector>

namespace simp::labels {

struct PosedImage {
    std::int64_t id = 0;            ///< image id (unique)
    std::string file_path;          ///< as given; written to the Omni3D "file_path"
    double timestamp_s = 0;         ///< optional time (s)
    camera::PinholeCamera camera;   ///< K (skew allowed), image size and the optical frame in the world
};

/// \throw std::runtime_error naming the file and key (missing file/key, non-number, bad K,
///        width/height <= 0, rotation not orthonormal, duplicate id).
///        An image with "camera" needs `rig` and `poses` (else: error naming the key), a camera of the
///        rig and a timestamp inside the poses' range.
std::vector<PosedImage> readCameraFrames(const std::string& path, const detector_io::CameraRig* rig = nullptr,
                                         const std::vector<io::StampedPose2D>* poses = nullptr);
/// Writes the same format (rotation as a 3x3 matrix, full precision).
void writeCameraFrames(const std::string& path, const std::vector<PosedImage>& images);

}  // namespace simp::labels
