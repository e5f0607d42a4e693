#pragma once
/// \file ViewWindow.h
/// The camera frames since `lost` (every frame, also those without a detection), each with the
/// odometry pose it was taken at, and for a candidate pose now: how many views of map objects the
/// frames should have shown and how many of them a detection did show. Negative evidence, not in
/// the paper: a look-alike place can explain the few objects a robot sees, but it also holds objects
/// in view that the robot never saw. The challenger's take-over elsewhere asks it
/// (doc/localization.md "Challenger").
///
/// A map object is expected in a frame when the mapper's visibility says it is active there
/// (camera::ZBufferRenderer with the floor plan's walls and the other objects as occluders, doors
/// hiding nothing; at most max_truncated_fraction of its projected box outside the image and
/// max_occluded_fraction of it hidden) and its distance lies within the class's range: what the
/// detector has shown so far in this run, from the nearest to the farthest usable detection of the
/// class (capped at max_range_m); a class never detected is expected nowhere (a detector that does
/// not report a class says nothing of it). It is shown when a usable detection of its class in that
/// frame lies within seen_radius_m of it.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose2D.h>
#include <simp/camera/FloorPlanGrid.h>
#include <simp/camera/ZBufferVisibility.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/CObservationObjects3D.h>

#include <cstddef>
#include <deque>
#include <vector>

namespace simp::localization {

struct ViewWindowParams {
    double max_range_m = 4.0;      ///< no object farther from the camera than this is expected (m)
    double seen_radius_m = 1.0;    ///< a detection of the class this close to the object shows it (m)
    double max_truncated_fraction = 0.5;  ///< as the mapper's truncation_threshold
    double max_occluded_fraction = 0.5;   ///< as the mapper's max_occluded_fraction
    double max_age_s = 30.0;       ///< frames older than this leave the window (s)
    std::size_t max_frames = 600;  ///< ... and the oldest beyond this many
};

class ViewWindow {
   public:
    ViewWindow(const ViewWindowParams& params, const mrpt::maps::COccupancyGridMap2D& floorplan);

    /// A camera frame taken at t_s with the robot at `odometry_pose` (odometry frame). Its usable
    /// detections also widen their class's range.
    void add(const maps::CObjectMap& map, const simp::obs::CObservationObjects3D::Ptr& obs,
             const mrpt::poses::CPose2D& odometry_pose, double t_s);
    /// Forgets the frames (not the classes' ranges: they are the detector's).
    void clear() { m_frames.clear(); }

    struct Recall {
        std::size_t expected = 0;  ///< views of map objects the frames should have shown
        std::size_t seen = 0;      ///< ... of which a detection showed
    };
    /// With the robot at `estimate` (world) now, at odometry pose `odometry_now`: each frame at
    /// estimate (+) (odometry_now^-1 (+) its odometry pose). Frames older than max_age_s before
    /// t_now_s are left out.
    Recall recallAt(const maps::CObjectMap& map, const mrpt::poses::CPose2D& estimate,
                    const mrpt::poses::CPose2D& odometry_now, double t_now_s) const;

   private:
    /// A usable detection of a frame: its map class and box centre in the robot frame (m).
    struct Shown {
        int map_class = -1;
        double x = 0, y = 0;
    };
    struct Frame {
        simp::obs::CObservationObjects3D::Ptr obs;
        mrpt::poses::CPose2D odometry_pose;
        double t_s = 0;
        std::vector<Shown> shown;  ///< its usable detections, classed once when it was added
    };
    ViewWindowParams m_params;
    camera::FloorPlanGrid m_walls;
    mutable camera::ZBufferRenderer m_renderer;  ///< its buffers, reused by every recallAt()
    mutable std::vector<geometry::Box3D> m_boxes;   ///< the map objects near a frame's camera
    mutable std::vector<std::size_t> m_box_object;  ///< ... their indices in the map
    mutable std::vector<char> m_box_occludes;
    mutable std::vector<camera::BoxView> m_views;
    std::deque<Frame> m_frames;
    std::vector<double> m_min_range_m, m_max_range_m;  ///< per map class; min > max: never detected
};

}  // namespace simp::localization
