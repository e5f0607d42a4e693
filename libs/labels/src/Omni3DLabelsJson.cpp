/// \file Omni3DLabelsJson.cpp
/// writeOmni3DLabels(): the Omni3D dataset JSON (github.com/facebookresearch/omni3d, DATA.md).
#include <simp/world/JsonRead.h>

#include <simp/labels/LabelGenerator.h>
#include <simp/detector_io/Omni3DBox.h>

namespace simp::labels {

namespace {

nlohmann::ordered_json boxJson(const camera::ImageBox& b) { return {b(0), b(1), b(2), b(3)}; }

}  // namespace

void writeOmni3DLabels(const std::string& path, const LabelSet& labels, const std::string& dataset_name) {
    using oj = nlohmann::ordered_json;
    oj j;
    j["info"] = {{"id", 0}, {"source", "simp-labels"}, {"name", dataset_name}, {"split", ""}, {"version", "1"},
                 {"url", ""}};
    oj ims = oj::array();
    for (const PosedImage& im : labels.images)
        ims.push_back({{"id", im.id}, {"dataset_id", 0}, {"file_path", im.file_path}, {"width", im.camera.widthPx()},
                       {"height", im.camera.heightPx()}, {"K", world::toJson(im.camera.K())}, {"src_90_rotate", 0}, {"src_flagged", false},
                       {"timestamp", im.timestamp_s}});
    j["images"] = ims;
    oj cats = oj::array();
    for (std::size_t c = 0; c < labels.categories.size(); ++c) cats.push_back({{"id", c}, {"name", labels.categories[c]}});
    j["categories"] = cats;
    oj anns = oj::array();
    for (const LabelAnnotation& a : labels.annotations) {
        oj o;
        o["id"] = a.id;
        o["image_id"] = a.image_id;
        o["dataset_id"] = 0;
        o["category_id"] = a.category_id;
        o["category_name"] = labels.categories.at(static_cast<std::size_t>(a.category_id));
        o["object_id"] = a.object_id;
        o["valid3D"] = a.box_cam.center.z() > 0;
        o["bbox2D_tight"] = a.detection ? oj{a.detection->x_min, a.detection->y_min, a.detection->x_max, a.detection->y_max}
                                        : oj{-1, -1, -1, -1};
        o["bbox2D_proj"] = boxJson(a.projection.bbox_proj);
        o["bbox2D_trunc"] = boxJson(a.projection.bbox_trunc);
        oj corners = oj::array();
        for (const Eigen::Vector3d& c : detector_io::omni3DCorners(a.box_cam)) corners.push_back(world::toJson(c));
        o["bbox3D_cam"] = corners;
        o["center_cam"] = world::toJson(a.box_cam.center);
        o["dimensions"] = world::toJson(detector_io::omni3DDimensions(a.box_cam));
        o["R_cam"] = world::toJson(a.box_cam.R);
        o["behind_camera"] = a.box_cam.center.z() <= 0;
        o["truncation"] = a.projection.truncation;
        o["visibility"] = a.visibility;
        o["segmentation_pts"] = -1;
        o["lidar_pts"] = -1;
        o["depth_error"] = -1;
        if (a.detection) o["score2D"] = a.detection->score;
        anns.push_back(o);
    }
    j["annotations"] = anns;
    world::writeJsonFile(j, path, world::JsonLayout::Indent1);
}

}  // namespace simp::labels
