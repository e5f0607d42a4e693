#pragma once
/// \file Visibility.h
/// Which objects a camera sees: field of view and per-class range, truncation at the image
/// borders, occlusion by walls (rays on the floor-plan raster) and by nearer objects (depth
/// test of their projected boxes).

#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/obs/Detection3D.h>
#include <simp/sim/Raster.h>
#include <simp/sim/SensorParams.h>
#include <simp/world/MapObject.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace simp::sim {

/// A pinhole camera placed in the world (optical frame: x right, y down, z forward).
struct CameraView {
    Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
    double fx = 380.07, fy = 379.66, cx = 324.47, cy = 237.79;
    int width_px = 640, height_px = 480;

    /// Pixel of a point in the camera frame (z > 0).
    Eigen::Vector2d project(const Eigen::Vector3d& p_camera) const {
        return {fx * p_camera.x() / p_camera.z() + cx, fy * p_camera.y() / p_camera.z() + cy};
    }
    bool inImage(const Eigen::Vector2d& px) const {
        return px.x() >= 0 && px.y() >= 0 && px.x() <= width_px && px.y() <= height_px;
    }
};

/// The camera at `robot_T_camera` on a robot at `world_T_robot` (planar pose, m / rad).
CameraView makeCameraView(const mrpt::math::TPose2D& world_T_robot, const mrpt::poses::CPose3D& robot_T_camera,
                          const CameraParams& p);
/// Rigid transform of an MRPT pose.
Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& p);

/// One object the camera sees.
struct VisibleObject {
    std::size_t index = 0;         ///< into the object list
    obs::ImageBox2D box_2d;        ///< projected box, clipped to the image (px)
    double depth_m = 0;            ///< box centre depth along the optical axis (m)
    double inside_fraction = 1;    ///< fraction of projected corners inside the image
    double occluded_fraction = 0;  ///< fraction of the 2D box covered by nearer objects
};

/// The projected 2D box of a box in the camera frame, from its corners in front of the camera;
/// `inside_fraction` = fraction of the 8 corners in front and inside the image. False when no
/// corner is in front of the camera.
bool projectBox(const CameraView& view, const geometry::Box3D& box_in_camera, obs::ImageBox2D& box_2d,
                double& inside_fraction);

/// True when at least `min_visible_ray_fraction` of the rays from the camera to points of the
/// object's footprint cross no blocked cell of `walls` (cells within self_margin_m of the
/// object's own footprint are ignored, so a door in a blocked gap stays visible).
bool visibleThroughWalls(const CameraView& view, const world::MapObject& object, const Raster& walls,
                         const VisibilityParams& p, double extra_self_margin_m = 0.0);

/// Objects visible from `view`. `class_names` names the objects' class ids; the per-class
/// ranges of `p` are looked up by name in simp::obs::defaultClassNames() (other names: no limit
/// but default_max_range_m). `door_class` (or -1): doors are seen through gaps and never occlude.
std::vector<VisibleObject> visibleObjects(const CameraView& view, const std::vector<world::MapObject>& objects,
                                          const std::vector<std::string>& class_names, const Raster& walls,
                                          const VisibilityParams& p);

}  // namespace simp::sim
