#pragma once
/// \file PinholeCamera.h
/// The one pinhole camera of the project: MRPT's intrinsics (mrpt::img::TCamera: fx, fy, cx, cy,
/// optional skew K(0,1), image size ncols x nrows; rectified images, distortion unused) and the
/// pose of its optical frame in the world (x right, y down, z forward; doc/conventions.md).
/// The simulator, the mapper's visibility and the label generator all take this type.

#include <mrpt/img/TCamera.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>
#include <optional>

namespace simp::camera {

/// Intrinsics from values (px), as mrpt::img::TCamera::setIntrinsicParamsFromValues() sets them.
mrpt::img::TCamera makeIntrinsics(int width_px, int height_px, double fx, double fy, double cx, double cy);

/// The default intrinsics everywhere a camera has none: the authors' K for 640 x 480 images
/// (fx 380.07, fy 379.66, cx 324.47, cy 237.79 px).
mrpt::img::TCamera defaultIntrinsics();

/// The intrinsics of an image of width_px x height_px: `given`'s fx, fy, cx, cy when there are any
/// (an observation's own), else `fallback`'s (e.g. a configured default).
mrpt::img::TCamera imageIntrinsics(const std::optional<mrpt::img::TCamera>& given, int width_px, int height_px,
                                   const mrpt::img::TCamera& fallback);

/// Rigid transform of an MRPT pose (rotation matrix and translation copied, no re-orthonormalisation).
Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& pose);

struct PinholeCamera {
    mrpt::img::TCamera intrinsics = defaultIntrinsics();
    Eigen::Isometry3d world_T_camera = Eigen::Isometry3d::Identity();  ///< optical frame in the world

    double fx() const { return intrinsics.fx(); }
    double fy() const { return intrinsics.fy(); }
    double cx() const { return intrinsics.cx(); }
    double cy() const { return intrinsics.cy(); }
    int widthPx() const { return static_cast<int>(intrinsics.ncols); }
    int heightPx() const { return static_cast<int>(intrinsics.nrows); }

    /// K as a matrix (with the skew term, if any), for x = K [R t] X (Eq. reprojection).
    Eigen::Matrix3d K() const { return intrinsics.intrinsicParams.asEigen(); }
    /// Sets K (fx, fy > 0, skew allowed) and the image size.
    void setIntrinsics(const Eigen::Matrix3d& K, int width_px, int height_px);

    /// Pixel of a point in the camera frame (z > 0), without skew: u = fx x / z + cx.
    Eigen::Vector2d project(const Eigen::Vector3d& p_camera) const {
        return {fx() * p_camera.x() / p_camera.z() + cx(), fy() * p_camera.y() / p_camera.z() + cy()};
    }
    /// True for a pixel inside [0, width] x [0, height] (borders included).
    bool inImage(const Eigen::Vector2d& px) const {
        return px.x() >= 0 && px.y() >= 0 && px.x() <= widthPx() && px.y() <= heightPx();
    }

    /// The camera at `robot_T_camera` on a robot at the planar pose `world_T_robot` (m, rad).
    static PinholeCamera onRobot(const mrpt::math::TPose2D& world_T_robot, const mrpt::poses::CPose3D& robot_T_camera,
                                 const mrpt::img::TCamera& intrinsics);
    /// The camera at `robot_T_camera` on a robot at the 3D pose `world_T_robot`.
    static PinholeCamera onRobot(const mrpt::poses::CPose3D& world_T_robot, const mrpt::poses::CPose3D& robot_T_camera,
                                 const mrpt::img::TCamera& intrinsics);
};

}  // namespace simp::camera
