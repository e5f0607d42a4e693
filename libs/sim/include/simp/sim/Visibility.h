#pragma once
/// \file Visibility.h
/// Visibility strategy of the simulator: which objects a camera sees. Field of view and per-class
/// range, truncation at the image borders, occlusion by walls (rays on the floor-plan raster) and
/// by nearer objects (depth test of their projected 2D boxes). The sequences are generated with
/// it, so it stays as it is; the camera, the door rule and the thresholds are simp::camera's
/// (doc/architecture.md "Camera and visibility").

#include <simp/camera/PinholeCamera.h>

#include <simp/obs/Detection3D.h>
#include <simp/sim/Raster.h>
#include <simp/sim/SensorParams.h>
#include <simp/world/MapObject.h>

#include <string>
#include <vector>

namespace simp::sim {

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
bool projectBox(const camera::PinholeCamera& view, const geometry::Box3D& box_in_camera, obs::ImageBox2D& box_2d,
                double& inside_fraction);

/// True when at least `min_visible_ray_fraction` of the rays from the camera to points of the
/// object's footprint cross no blocked cell of `walls` (cells within self_margin_m of the
/// object's own footprint are ignored, so a door in a blocked gap stays visible).
bool visibleThroughWalls(const camera::PinholeCamera& view, const world::MapObject& object, const Raster& walls,
                         const VisibilityParams& p, double extra_self_margin_m = 0.0);

/// Objects visible from `view`. `class_names` names the objects' class ids; the per-class
/// ranges of `p` are looked up by name in simp::obs::defaultClassNames() (other names: no limit
/// but default_max_range_m). Objects that do not occlude (doors, camera::occludes()) are seen
/// through their gap (a wider self margin) and hide nothing.
std::vector<VisibleObject> visibleObjects(const camera::PinholeCamera& view, const std::vector<world::MapObject>& objects,
                                          const std::vector<std::string>& class_names, const Raster& walls,
                                          const VisibilityParams& p);

}  // namespace simp::sim
