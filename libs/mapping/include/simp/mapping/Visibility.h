#pragma once
/// \file Visibility.h
/// Which map objects a camera sees (the I_active state of Eq. objdef): the map's boxes are
/// rendered into a small z-buffer of the camera (depth test), walls of the floor plan are
/// ray cast per image column and block what lies behind them, and the projected box's
/// fraction outside the image measures truncation.

#include <simp/geometry/Box3D.h>
#include <simp/mapping/WallGrid.h>

#include <Eigen/Geometry>
#include <vector>

namespace simp::mapping {

/// A pinhole camera in the world. Optical frame: x right, y down, z forward.
struct PinholeCamera {
    Eigen::Isometry3d world_T_camera{Eigen::Isometry3d::Identity()};
    double fx_px = 380.0, fy_px = 380.0, cx_px = 320.0, cy_px = 240.0;
    int width_px = 640, height_px = 480;
};

/// What the camera sees of one box.
struct BoxView {
    int covered_px = 0;             ///< z-buffer pixels the box covers inside the image (any depth)
    int visible_px = 0;             ///< of those, pixels where it is the front-most surface and not behind a wall
    int unwalled_px = 0;            ///< covered pixels not behind a wall (other boxes ignored)
    double truncated_fraction = 1;  ///< fraction of its projected 2D bounding box outside the image, [0, 1]
    double distance_m = 0;          ///< camera centre -> box centre (m)

    /// Fraction of the covered pixels hidden by other boxes or walls, [0, 1] (1 when not covered).
    double occludedFraction() const { return covered_px > 0 ? 1.0 - double(visible_px) / covered_px : 1.0; }
};

struct RenderParams {
    int downscale = 8;                ///< image pixels per z-buffer pixel (per side)
    double near_plane_m = 0.05;       ///< m
    double wall_depth_margin_m = 0.3; ///< m; box surfaces up to this far behind a wall still count visible
    double max_distance_m = 12.0;     ///< boxes and walls farther than this are ignored (m)
    /// Optional, one entry per box: boxes with the same group id >= 0 do not occlude each other
    /// (BoxView::visible_px counts a pixel where a box of its own group is front-most). Used for
    /// boxes that intersect: distinct objects cannot interpenetrate, so they are estimates of one
    /// object (or nested objects) and must not hide each other. Costs a second rasterization.
    const std::vector<int>* group = nullptr;
};

/// Renders boxes into a reduced-resolution z-buffer. Reuses its buffers across calls
/// (one instance per thread); no heap allocation once warmed up.
class VisibilityRenderer {
   public:
    /// Views of all `boxes_in_world` for `camera`; walls may be null or empty (no wall occlusion).
    /// out[k] describes boxes_in_world[k].
    void render(const PinholeCamera& camera, const std::vector<geometry::Box3D>& boxes_in_world, const WallGrid* walls,
                const RenderParams& params, std::vector<BoxView>& out);

   private:
    void rasterizePolygon(const Eigen::Vector3d* pts_px_invz, int n, int object);
    int m_pass = 0;                     ///< 0: depth and coverage; 1: visibility with groups
    const std::vector<int>* m_group = nullptr;
    std::vector<int> m_stamp_visible;   ///< last box counted visible at a pixel (pass 1)

    int m_w = 0, m_h = 0;
    std::vector<float> m_depth;   ///< nearest depth per pixel (camera z, m)
    std::vector<int> m_id;        ///< front-most box per pixel, -1 = wall / nothing
    std::vector<int> m_stamp;     ///< last box that covered a pixel (dedupes its faces)
    std::vector<int> m_stamp_unwalled;  ///< last box that covered a pixel in front of the wall
    std::vector<float> m_wall_depth;    ///< wall depth + margin per pixel (camera z, m)
    std::vector<BoxView>* m_out = nullptr;
};

}  // namespace simp::mapping
