#pragma once
/// \file LabelGenerator.h
/// 3D label generation (paper Sec. "Label Generation for 3D Object Detection"): the ground-truth
/// boxes are projected into every posed image (Eq. reprojection), truncation and visibility are
/// computed, and each 2D detection is matched to a projected box of its class by 2D IoU; the
/// matched objects become Omni3D annotations (doc/labels.md).

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/camera/BoxProjection.h>
#include <simp/camera/FloorPlanThresholds.h>
#include <simp/io/OptionTable.h>
#include <simp/labels/CameraFrames.h>
#include <simp/labels/Detections2D.h>
#include <simp/world/ObjectMapData.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace simp::labels {

/// Visibility settings (camera::ZBufferRenderer on the floor plan's walls, per pixel; doors hide
/// nothing, camera/Occluders.h).
struct VisibilityOptions {
    int pixel_step = 4;                  ///< visibility rendered at one pixel per pixel_step x pixel_step image pixels
    double occupied_threshold = 1.0 - camera::floorplan::kWallMaxFree;  ///< cells with occupancy (1 - P(free)) >= this are walls
    bool ignore_object_cells = true;     ///< cells under an object's footprint (+ margin) are not walls
    double object_cell_margin_m = 0.10;  ///< margin around the footprint for ignore_object_cells (m)
    double max_range_m = 30.0;           ///< boxes and walls farther than this are not rendered (m)
};

/// Settings, section [simp-labels] of an .ini (key = field name; visibility keys prefixed "visibility_").
struct LabelOptions {
    double iou_threshold = 0.5;     ///< min 2D IoU between a detection and the clipped projected box
    bool keep_unmatched = false;    ///< also annotate projected objects no detection matched (bbox2D_tight = -1s)
    double max_truncation = 0.99;   ///< objects more truncated than this are not candidates
    double near_m = 0.05;           ///< near clipping plane (m)
    VisibilityOptions visibility;   ///< visibility_pixel_step, visibility_occupied_threshold, ...

    /// The keys, declared once: loading, checks, dump and doc/labels.md's key table derive from it.
    static const io::OptionTable<LabelOptions>& table();
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
    /// \throw std::invalid_argument naming the key.
    void validate() const;
    void dumpToTextStream(std::ostream& out) const;
};

/// The ground-truth box of a world object in a camera, in Omni3D's axis convention: local x = the
/// object's x (yaw direction), local y = down (gravity), local z = the object's y; so
/// dimensions [W, H, L] = [extent along the object's y, height, extent along its x].
geometry::Box3D boxInCameraOmni3D(const PosedImage& image, const geometry::Box3D& box_world);

struct LabelAnnotation {
    std::int64_t id = 0;
    std::int64_t image_id = 0;
    int category_id = 0;                   ///< index into the world's classes
    std::int64_t object_id = 0;            ///< world object id
    geometry::Box3D box_cam;               ///< boxInCameraOmni3D()
    camera::ProjectedBox projection;       ///< bbox2D_proj, bbox2D_trunc, truncation
    std::optional<Detection2D> detection;  ///< the matched 2D detection (bbox2D_tight)
    double visibility = 0;
};

struct LabelSet {
    std::vector<std::string> categories;
    std::vector<PosedImage> images;
    std::vector<LabelAnnotation> annotations;
    std::size_t detections_unmatched = 0;      ///< 2D detections without a 3D box (dynamic objects, ...)
    std::size_t detections_unknown_image = 0;  ///< 2D detections whose image id is not in the frames
};

/// Runs the generation. `floorplan` may be null (no wall occlusion).
LabelSet generateLabels(const world::ObjectMapData& gt, const mrpt::maps::COccupancyGridMap2D* floorplan,
                        const std::vector<PosedImage>& images, const std::vector<Detection2D>& detections,
                        const LabelOptions& options);

/// Writes the Omni3D JSON (info, images, categories, annotations) read by Cube R-CNN's data loader.
void writeOmni3DLabels(const std::string& path, const LabelSet& labels, const std::string& dataset_name = "simp");

}  // namespace simp::labels
