/// \file Omni3DPredictions.cpp
#include <simp/world/JsonRead.h>

#include <simp/detector_io/Omni3DBox.h>
#include <simp/detector_io/Omni3DPredictions.h>
#include <simp/obs/ObjectClasses.h>

#include <map>

namespace simp::detector_io {

namespace {

using nlohmann::json;

std::uint16_t classOf(const json& p, const std::vector<std::string>& names, const std::string& file,
                      const std::string& key) {
    const bool has_cat = p.contains("category");
    const json& v = has_cat ? p["category"] : world::requireKey(p, "category_id", file, key + ".category");
    const std::string k = key + (has_cat ? ".category" : ".category_id");
    if (v.is_string()) {
        const int c = obs::classIndexOf(names, v.get<std::string>());
        if (c < 0) world::failAt(file, k, "unknown class '" + v.get<std::string>() + "' (not in the categories)");
        return static_cast<std::uint16_t>(c);
    }
    const long long c = world::asInteger(v, file, k);
    if (c < 0 || c >= static_cast<long long>(names.size()))
        world::failAt(file, k, "unknown class id " + std::to_string(c) + " (" + std::to_string(names.size()) + " categories)");
    return static_cast<std::uint16_t>(c);
}

obs::Detection3D detectionOf(const json& p, const std::vector<std::string>& names, const std::string& file,
                             const std::string& key) {
    obs::Detection3D d;
    d.class_id = classOf(p, names, file, key);
    d.confidence = static_cast<float>(world::asNumber(world::requireKey(p, "score", file, key + ".score"), file, key + ".score"));
    const auto c = world::asNumberArray(world::requireKey(p, "center_cam", file, key + ".center_cam"), 3, file, key + ".center_cam");
    const auto s = world::asNumberArray(world::requireKey(p, "dimensions", file, key + ".dimensions"), 3, file, key + ".dimensions");
    const std::string rkey = p.contains("R_cam") ? "R_cam" : "pose";
    const Eigen::Matrix3d R = world::asMatrix3(world::requireKey(p, rkey, file, key + ".R_cam"), file, key + "." + rkey);
    d.box_in_camera = boxFromOmni3D({c[0], c[1], c[2]}, {s[0], s[1], s[2]}, R);
    if (p.contains("bbox2D")) {
        const auto b = world::asNumberArray(p["bbox2D"], 4, file, key + ".bbox2D");
        d.box_2d = obs::ImageBox2D{static_cast<float>(b[0]), static_cast<float>(b[1]), static_cast<float>(b[2]),
                                   static_cast<float>(b[3])};
    } else if (p.contains("bbox")) {  // Omni3D results: x, y, w, h
        const auto b = world::asNumberArray(p["bbox"], 4, file, key + ".bbox");
        d.box_2d = obs::ImageBox2D{static_cast<float>(b[0]), static_cast<float>(b[1]), static_cast<float>(b[0] + b[2]),
                                   static_cast<float>(b[1] + b[3])};
    }
    if (p.contains("detector_id")) d.detector_id = world::asInteger(p["detector_id"], file, key + ".detector_id");
    try {
        obs::validateDetection(d, names.size(), key);
    } catch (const std::exception& e) {
        world::failAt(file, key, e.what());
    }
    return d;
}

}  // namespace

DetectionSet readOmni3DPredictions(const std::string& path) {
    const json j = world::readJsonFile(path);
    DetectionSet set;
    set.class_names = obs::defaultClassNames();
    const json* preds = &j;
    std::map<std::int64_t, std::size_t> image_index;
    std::map<std::pair<double, std::string>, std::size_t> by_time;
    if (j.is_object()) {
        if (j.contains("categories")) {
            const json& cats = j["categories"];
            if (!cats.is_array() || cats.empty()) world::failAt(path, "categories", "expected a non-empty list of names");
            set.class_names.clear();
            for (std::size_t i = 0; i < cats.size(); ++i) {
                const std::string k = "categories[" + std::to_string(i) + "]";
                // Omni3D style {"id", "name"} or a plain name.
                set.class_names.push_back(cats[i].is_object() ? world::asString(world::requireKey(cats[i], "name", path, k + ".name"), path, k + ".name")
                                                              : world::asString(cats[i], path, k));
            }
        }
        if (j.contains("images")) {
            const json& ims = j["images"];
            if (!ims.is_array()) world::failAt(path, "images", "expected a list");
            for (std::size_t i = 0; i < ims.size(); ++i) {
                const std::string k = "images[" + std::to_string(i) + "]";
                DetectionImage im;
                im.id = world::asInteger(world::requireKey(ims[i], "id", path, k + ".id"), path, k + ".id");
                im.timestamp_s = world::asNumber(world::requireKey(ims[i], "timestamp", path, k + ".timestamp"), path, k + ".timestamp");
                im.camera = world::asString(world::requireKey(ims[i], "camera", path, k + ".camera"), path, k + ".camera");
                if (!image_index.emplace(im.id, set.images.size()).second)
                    world::failAt(path, k + ".id", "duplicate image id " + std::to_string(im.id));
                by_time.emplace(std::make_pair(im.timestamp_s, im.camera), set.images.size());
                set.images.push_back(im);
            }
        }
        preds = &world::requireKey(j, "predictions", path, "predictions");
    }
    if (!preds->is_array()) world::failAt(path, "predictions", "expected a list of predictions");
    for (std::size_t i = 0; i < preds->size(); ++i) {
        const json& p = (*preds)[i];
        const std::string key = "predictions[" + std::to_string(i) + "]";
        if (!p.is_object()) world::failAt(path, key, "expected an object");
        std::size_t target = 0;
        if (p.contains("timestamp") || !p.contains("image_id")) {
            const double t = world::asNumber(world::requireKey(p, "timestamp", path, key + ".timestamp"), path, key + ".timestamp");
            const std::string cam = world::asString(world::requireKey(p, "camera", path, key + ".camera"), path, key + ".camera");
            auto it = by_time.find({t, cam});
            if (it == by_time.end()) {
                DetectionImage im;
                im.id = p.contains("image_id") ? world::asInteger(p["image_id"], path, key + ".image_id")
                                               : static_cast<std::int64_t>(set.images.size());
                im.timestamp_s = t;
                im.camera = cam;
                it = by_time.emplace(std::make_pair(t, cam), set.images.size()).first;
                set.images.push_back(im);
            }
            target = it->second;
        } else {
            const std::int64_t id = world::asInteger(p["image_id"], path, key + ".image_id");
            const auto it = image_index.find(id);
            if (it == image_index.end())
                world::failAt(path, key + ".image_id", "unknown image id " + std::to_string(id) +
                                                          " (not in \"images\"; or give \"timestamp\" and \"camera\")");
            target = it->second;
        }
        set.images[target].detections.push_back(detectionOf(p, set.class_names, path, key));
    }
    return set;
}

void writeOmni3DPredictions(const std::string& path, const DetectionSet& set) {
    nlohmann::ordered_json j;
    j["categories"] = set.class_names;
    nlohmann::ordered_json ims = nlohmann::ordered_json::array(), preds = nlohmann::ordered_json::array();
    for (const DetectionImage& im : set.images) {
        ims.push_back({{"id", im.id}, {"timestamp", im.timestamp_s}, {"camera", im.camera}});
        for (const obs::Detection3D& d : im.detections) {
            nlohmann::ordered_json p;
            p["image_id"] = im.id;
            p["category"] = set.class_names.at(d.class_id);
            p["category_id"] = d.class_id;
            p["score"] = d.confidence;
            p["center_cam"] = world::toJson(d.box_in_camera.center);
            p["dimensions"] = world::toJson(omni3DDimensions(d.box_in_camera));
            p["R_cam"] = world::toJson(d.box_in_camera.R);
            if (d.box_2d) p["bbox2D"] = {d.box_2d->x_min, d.box_2d->y_min, d.box_2d->x_max, d.box_2d->y_max};
            if (d.detector_id) p["detector_id"] = *d.detector_id;
            preds.push_back(p);
        }
    }
    j["images"] = ims;
    j["predictions"] = preds;
    world::writeJsonFile(j, path, world::JsonLayout::Indent1);
}

}  // namespace simp::detector_io
