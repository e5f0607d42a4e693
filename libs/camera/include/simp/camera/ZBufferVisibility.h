#pragma once
/// \file ZBufferVisibility.h
/// The project's one occlusion renderer; the mapper's I_active of Eq. objdef, fast enough for every
/// frame: the boxes are rendered into a reduced-resolution z-buffer of the camera (depth test),
/// walls of the floor plan are ray cast once per z-buffer column (or per pixel) and block what lies
/// behind them, and the projected box's fraction outside the image measures truncation.
/// The simulator renders its cameras with it too, at its own resolution and thresholds
/// (sim/Visibility.h), and the label generator at its pixel step with walls per pixel.
/// doc/architecture.md "Camera and visibility".

#include <simp/camera/FloorPlanGrid.h>
#include <simp/camera/Occluders.h>
#include <simp/camera/PinholeCamera.h>
#include <simp/geometry/Box3D.h>

#include <vector>

namespace simp::camera {

/// What the camera sees of one box.
struct BoxView {
    int covered_px = 0;             ///< z-buffer pixels the box covers inside the image (any depth)
    int visible_px = 0;             ///< of those, pixels where it is the front-most surface and not behind a wall
    int unwalled_px = 0;            ///< covered pixels not behind a wall (other boxes ignored)
    int unhidden_px = 0;            ///< of visible_px, pixels counted only because the front-most box does not hide it (ZBufferParams::unhidden_by)
    double truncated_fraction = 1;  ///< fraction of its projected 2D bounding box outside the image, [0, 1]
    double distance_m = 0;          ///< camera centre -> box centre (m)

    /// Fraction of the covered pixels where the box is seen, [0, 1] (0 when not covered): the labels' visibility.
    double visibleFraction() const { return covered_px > 0 ? double(visible_px) / covered_px : 0.0; }
    /// Fraction of the covered pixels hidden by other boxes or walls, [0, 1] (1 when not covered).
    double occludedFraction() const { return covered_px > 0 ? 1.0 - double(visible_px) / covered_px : 1.0; }
    /// The same when the boxes of ZBufferParams::unhidden_by hid it too.
    double occludedFractionByAll() const {
        return covered_px > 0 ? 1.0 - double(visible_px - unhidden_px) / covered_px : 1.0;
    }
};

/// Most pixels a z-buffer holds (2048 x 2048; about 100 MB of buffers). A camera whose image at
/// `downscale` would need more is rendered at the smallest coarser downscale that fits, so that an
/// image size read from a file (up to obs::limits::kMaxImageSide_px per side) cannot exhaust memory.
inline constexpr long kMaxRenderedPixels = 2048L * 2048L;

struct ZBufferParams {
    int downscale = 8;                ///< image pixels per z-buffer pixel (per side); coarser when needed (kMaxRenderedPixels)
    double near_plane_m = 0.05;       ///< m
    double wall_depth_margin_m = 0.3; ///< m; box surfaces up to this far behind a wall still count visible
    double max_distance_m = 12.0;     ///< boxes and walls farther than this are ignored (m)
    /// Walls along every pixel's own ray (exact for tilted and rolled cameras, one ray cast per
    /// pixel) instead of once per column along the column's ray at the principal row (exact for
    /// level cameras; the mapper's and the simulator's).
    bool walls_per_pixel = false;
    /// Optional, one entry per box: boxes with the same group id >= 0 do not occlude each other
    /// (BoxView::visible_px counts a pixel where a box of its own group is front-most). Used for
    /// boxes that intersect: distinct objects cannot interpenetrate, so they are estimates of one
    /// object (or nested objects) and must not hide each other. Costs a second rasterization.
    const std::vector<int>* group = nullptr;
    /// Optional, one entry per box, an OcclusionKind (Occluders.h): kSolid (1) hides with the whole
    /// box; kSeeThrough (0, a door) is seen but hides nothing; kOpenBelow (2, a table) hides only
    /// with its top. Boxes not solid are rendered a second time against the final z-buffer.
    const std::vector<char>* occludes = nullptr;
    /// Optional, one entry per box: the boxes (indices, sorted) that do not hide it, where it is
    /// not behind a wall (BoxView::visible_px counts a pixel where one of them is front-most). A
    /// one-way relation, unlike `group`: used by a map update for the new objects that may be an
    /// earlier object's displaced copy (simp::mapping::displacedCopyCandidates).
    const std::vector<std::vector<int>>* unhidden_by = nullptr;
};

/// Renders boxes into a reduced-resolution z-buffer. Reuses its buffers across calls
/// (one instance per thread); no heap allocation once warmed up.
class ZBufferRenderer {
   public:
    /// Views of all `boxes_in_world` for `camera`; walls may be null or empty (no wall occlusion).
    /// out[k] describes boxes_in_world[k].
    void render(const PinholeCamera& camera, const std::vector<geometry::Box3D>& boxes_in_world,
                const FloorPlanGrid* walls, const ZBufferParams& params, std::vector<BoxView>& out);

   private:
    void rasterizePolygon(const Eigen::Vector3d* pts_px_invz, int n, int object);
    /// Not a solid box: seen where nothing hides it (or its own top is front-most), hides at most with its top.
    bool seeThrough(int object) const { return m_occludes != nullptr && (*m_occludes)[static_cast<std::size_t>(object)] != kSolid; }
    bool m_depth_only = false;          ///< pass 0, rasterizing the hiding top of an open-below box
    int m_pass = 0;                     ///< 0: depth and coverage; 1: visibility against the final z-buffer
    const std::vector<int>* m_group = nullptr;
    const std::vector<char>* m_occludes = nullptr;
    const std::vector<std::vector<int>>* m_unhidden_by = nullptr;
    std::vector<int> m_stamp_visible;   ///< last box counted visible at a pixel (pass 1)

    int m_w = 0, m_h = 0;
    std::vector<float> m_depth;   ///< nearest depth per pixel (camera z, m)
    std::vector<int> m_id;        ///< front-most box per pixel, -1 = wall / nothing
    std::vector<int> m_stamp;     ///< last box that covered a pixel (dedupes its faces)
    std::vector<int> m_stamp_unwalled;  ///< last box that covered a pixel in front of the wall
    std::vector<float> m_wall_depth;    ///< wall depth + margin per pixel (camera z, m)
    std::vector<BoxView>* m_out = nullptr;
};

}  // namespace simp::camera
