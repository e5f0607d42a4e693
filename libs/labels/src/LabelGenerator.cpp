/// \file LabelGenerator.cpp
#include <simp/geometry/Hungarian.h>
#include <simp/camera/Occluders.h>
#include <simp/camera/ZBufferVisibility.h>
#include <simp/labels/LabelGenerator.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace simp::labels {

const io::OptionTable<LabelOptions>& LabelOptions::table() {
    using O = LabelOptions;
    using io::ValueRange;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("simp-labels")
            .number("iou_threshold", &O::iou_threshold, "", ValueRange::aboveUpTo(0, 1), "minimum 2D IoU between a detection and the clipped projected box (`bbox2D_trunc`); `--iou` overrides")
            .flag("keep_unmatched", &O::keep_unmatched, "also annotate objects in view that no detection matched (`bbox2D_tight` = [-1,-1,-1,-1])")
            .number("max_truncation", &O::max_truncation, "", ValueRange::between(0, 1), "objects more truncated are not candidates")
            .number("near_m", &O::near_m, "m", ValueRange::positive(), "near clipping plane (camera z)")
            .integer("visibility_pixel_step", [](auto& o) -> auto& { return o.visibility.pixel_step; }, "px", ValueRange::atLeast(1),
                     "visibility rendered at one pixel per N x N image pixels")
            .number("visibility_occupied_threshold", [](auto& o) -> auto& { return o.visibility.occupied_threshold; }, "",
                    ValueRange::aboveUpTo(0, 1), "floor-plan cells with occupancy >= this are walls")
            .flag("visibility_ignore_object_cells", [](auto& o) -> auto& { return o.visibility.ignore_object_cells; },
                  "cells under an object's footprint (grown by the margin) are not walls: the authors' GT floor plan draws "
                  "furniture outlines, which would hide every object behind its own footprint")
            .number("visibility_object_cell_margin_m", [](auto& o) -> auto& { return o.visibility.object_cell_margin_m; }, "m",
                    ValueRange::atLeast(0), "margin around the footprints for the previous key; the authors' outlines lie up to 2 cells outside the boxes")
            .number("visibility_max_range_m", [](auto& o) -> auto& { return o.visibility.max_range_m; }, "m", ValueRange::positive(),
                    "boxes and walls farther than this are not rendered");
    return t;
}

void LabelOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void LabelOptions::validate() const { table().validate(*this); }
void LabelOptions::dumpToTextStream(std::ostream& out) const { table().dump(*this, out); }

geometry::Box3D boxInCameraOmni3D(const PosedImage& image, const geometry::Box3D& box_world) {
    const geometry::Box3D up = geometry::canonicalizeUpright(box_world);
    Eigen::Matrix3d R_world_local;  // columns: local x = object x, local y = down, local z = object y
    R_world_local << up.R.col(0), -up.R.col(2), up.R.col(1);
    const Eigen::Isometry3d camera_T_world = image.camera.world_T_camera.inverse();
    geometry::Box3D b;
    b.center = camera_T_world * up.center;
    b.R = camera_T_world.linear() * R_world_local;
    b.size = Eigen::Vector3d(up.size.x(), up.size.z(), up.size.y());
    return b;
}

LabelSet generateLabels(const world::ObjectMapData& gt, const mrpt::maps::COccupancyGridMap2D* floorplan,
                        const std::vector<PosedImage>& images, const std::vector<Detection2D>& detections,
                        const LabelOptions& options) {
    options.validate();
    LabelSet out;
    out.categories = gt.class_names;
    out.images = images;
    std::map<std::int64_t, std::vector<const Detection2D*>> by_image;
    for (const Detection2D& d : detections) by_image[d.image_id].push_back(&d);
    std::map<std::int64_t, bool> known;
    for (const PosedImage& im : images) known[im.id] = true;
    for (const auto& [id, dets] : by_image)
        if (!known.count(id)) out.detections_unknown_image += dets.size();

    std::vector<geometry::Box3D> boxes;
    for (const auto& o : gt.objects) boxes.push_back(o.box);
    // Walls: the floor plan's, minus the cells under the objects (furniture outlines of a GT plan).
    camera::FloorPlanGrid walls;
    if (floorplan != nullptr) {
        walls = camera::FloorPlanGrid(*floorplan, 1.0 - options.visibility.occupied_threshold);
        if (options.visibility.ignore_object_cells) walls.clearWallsUnder(boxes, options.visibility.object_cell_margin_m);
    }
    // How each box hides (camera/Occluders.h, as in the simulator and the mapper): doors hide nothing, tables with their top.
    const std::vector<char> class_occludes = camera::occludingClasses(gt.class_names);
    std::vector<char> occludes(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) occludes[i] = camera::occlusionOfClassId(class_occludes, gt.objects[i].class_id);
    // The one occlusion renderer, at the pixel step, walls along every pixel's own ray (the
    // authors' cameras are tilted) and no depth margin behind them.
    camera::ZBufferParams render;
    render.downscale = options.visibility.pixel_step;
    render.near_plane_m = options.near_m;
    render.wall_depth_margin_m = 0.0;
    render.max_distance_m = options.visibility.max_range_m;
    render.walls_per_pixel = true;
    render.occludes = &occludes;
    camera::ZBufferRenderer renderer;
    std::vector<camera::BoxView> views;
    for (const PosedImage& im : images) {
        std::vector<camera::ProjectedBox> proj(boxes.size());
        for (std::size_t i = 0; i < boxes.size(); ++i) proj[i] = camera::projectBox(im.camera, boxes[i], options.near_m);
        renderer.render(im.camera, boxes, floorplan != nullptr ? &walls : nullptr, render, views);
        const auto& dets = by_image[im.id];
        std::vector<int> match_of_object(boxes.size(), -1);
        // Per class: Hungarian assignment on 1 - IoU(bbox2D_trunc, detection), accepted above the threshold.
        for (std::size_t c = 0; c < gt.class_names.size(); ++c) {
            std::vector<std::size_t> objs, ds;
            for (std::size_t i = 0; i < boxes.size(); ++i)
                if (gt.objects[i].class_id == static_cast<int>(c) && proj[i].visible_in_front &&
                    proj[i].truncation <= options.max_truncation && camera::area(proj[i].bbox_trunc) > 0)
                    objs.push_back(i);
            for (std::size_t k = 0; k < dets.size(); ++k)
                if (dets[k]->class_name == gt.class_names[c]) ds.push_back(k);
            if (objs.empty() || ds.empty()) continue;
            Eigen::MatrixXd cost(static_cast<Eigen::Index>(objs.size()), static_cast<Eigen::Index>(ds.size()));
            for (std::size_t a = 0; a < objs.size(); ++a)
                for (std::size_t b = 0; b < ds.size(); ++b) {
                    const Detection2D& d = *dets[ds[b]];
                    cost(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) =
                        1.0 - camera::iou2D(proj[objs[a]].bbox_trunc, camera::ImageBox(d.x_min, d.y_min, d.x_max, d.y_max));
                }
            const std::vector<int> assignment = geometry::solveAssignment(cost);
            for (std::size_t a = 0; a < objs.size(); ++a)
                if (assignment[a] >= 0 &&
                    1.0 - cost(static_cast<Eigen::Index>(a), assignment[a]) >= options.iou_threshold)
                    match_of_object[objs[a]] = static_cast<int>(ds[static_cast<std::size_t>(assignment[a])]);
        }
        std::vector<char> used(dets.size(), 0);
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            const bool matched = match_of_object[i] >= 0;
            if (matched) used[static_cast<std::size_t>(match_of_object[i])] = 1;
            if (!matched && !(options.keep_unmatched && proj[i].visible_in_front && proj[i].truncation <= options.max_truncation &&
                              camera::area(proj[i].bbox_trunc) > 0))
                continue;
            LabelAnnotation a;
            a.id = static_cast<std::int64_t>(out.annotations.size());
            a.image_id = im.id;
            a.category_id = gt.objects[i].class_id;
            a.object_id = gt.objects[i].id;
            a.box_cam = boxInCameraOmni3D(im, boxes[i]);
            a.projection = proj[i];
            if (matched) a.detection = *dets[static_cast<std::size_t>(match_of_object[i])];
            a.visibility = views[i].visibleFraction();
            out.annotations.push_back(a);
        }
        for (char u : used) out.detections_unmatched += u ? 0 : 1;
    }
    return out;
}

}  // namespace simp::labels
