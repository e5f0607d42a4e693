#pragma once
/// \file CameraRig.h
/// A camera rig file: camera name -> pose on the robot and intrinsics (doc/detector-io.md).
/// Two spellings of the same keys:
///  - .ini: section [rig] with `cameras = NAME NAME ...`, then one section [NAME] per camera;
///  - .json: {"cameras": [{"name": NAME, <keys>}, ...]}.
/// Keys per camera: x, y, z (m, robot frame), yaw_rad (0 = forward, pi/2 = left),
/// pitch_down_rad (optional, 0), fx, fy, cx, cy (px), width, height (px).

#include <mrpt/img/TCamera.h>
#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

namespace simp::detector_io {

struct RigCamera {
    std::string name;                    ///< sensor label of its observations
    double x_m = 0, y_m = 0, z_m = 0;    ///< optical centre on the robot (m)
    double yaw_rad = 0, pitch_down_rad = 0;
    mrpt::img::TCamera intrinsics;       ///< fx, fy, cx, cy (px), ncols x nrows

    /// robot_T_camera (camera optical frame, obs::cameraPoseOnRobot()).
    mrpt::poses::CPose3D robotTCamera() const;
};

struct CameraRig {
    std::vector<RigCamera> cameras;
    /// Index of the camera called `name`, or -1.
    int indexOf(const std::string& name) const;
};

/// Reads a rig file (.ini or .json by extension).
/// \throw std::runtime_error naming the file and the key (missing file, missing key,
///        non-number, width/height/focal <= 0, duplicate camera names, no camera).
CameraRig loadCameraRig(const std::string& path);

}  // namespace simp::detector_io
