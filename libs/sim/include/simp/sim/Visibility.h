#pragma once
/// \file Visibility.h
/// What the simulated cameras see: the one occlusion renderer of simp::camera (ZBufferVisibility.h)
/// at the simulator's own resolution and thresholds, plus the simulated detector's limits (per-class
/// range, truncation). Rendering is physics; the thresholds are the simulated detector's, not the
/// mapper's or the localizer's model of it (doc/simulator.md "Cameras").

#include <simp/camera/FloorPlanGrid.h>
#include <simp/camera/PinholeCamera.h>
#include <simp/camera/ZBufferVisibility.h>

#include <simp/obs/Detection3D.h>
#include <simp/sim/SensorParams.h>
#include <simp/world/MapObject.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>
#include <vector>

namespace simp::sim {

/// One object the camera sees.
struct VisibleObject {
    std::size_t index = 0;         ///< into the object list
    double inside_fraction = 1;    ///< fraction of the 8 projected corners in front and inside the image
    double occluded_fraction = 0;  ///< of its rendered pixels in front of the walls, the fraction nearer boxes hide
};

/// The 2D box of a detection: the near-clipped projection of a box given in the camera frame,
/// clipped to the image (camera::projectBox). Empty boxes: false.
bool imageBoxOf(const camera::PinholeCamera& view, const geometry::Box3D& box_in_camera, obs::ImageBox2D& box_2d);

/// Fraction of the 8 corners of `box_world` in front of the camera and inside the image.
double insideCornerFraction(const camera::PinholeCamera& view, const geometry::Box3D& box_world);

/// The walls the simulated cameras see: the floor plan's wall cells (camera::FloorPlanGrid, the
/// grid of the mapper and the labels) less those within `self_margin_m` of the footprint of an
/// object that occludes (not a door): a floor plan that draws furniture outlines draws the
/// furniture, which is rendered as its box, not a wall in front of it. Pass every object that
/// stands in the world, or stood when the plan was drawn.
camera::FloorPlanGrid cameraWalls(const mrpt::maps::COccupancyGridMap2D& floorplan, const std::vector<world::MapObject>& objects,
                                  const std::vector<std::string>& class_names, double self_margin_m);

/// The objects a camera sees in one world. Keeps the renderer's buffers across frames.
class SceneVisibility {
   public:
    SceneVisibility(const camera::FloorPlanGrid& walls, const VisibilityParams& params) : m_walls(walls), m_params(params) {}

    /// Objects visible from `view`, in object order. `class_names` names the objects' class ids;
    /// the per-class ranges are looked up by name in simp::obs::defaultClassNames() (other names:
    /// no limit but default_max_range_m). Doors (camera::occludes() false) are seen but hide nothing.
    std::vector<VisibleObject> visible(const camera::PinholeCamera& view, const std::vector<world::MapObject>& objects,
                                       const std::vector<std::string>& class_names);

   private:
    const camera::FloorPlanGrid& m_walls;
    VisibilityParams m_params;
    camera::ZBufferRenderer m_renderer;
    std::vector<geometry::Box3D> m_boxes;
    std::vector<char> m_occludes;
    std::vector<std::size_t> m_index;
    std::vector<camera::BoxView> m_views;
};

}  // namespace simp::sim
