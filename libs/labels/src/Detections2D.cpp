/// \file Detections2D.cpp
#include <simp/world/JsonRead.h>

#include <simp/io/NameValueList.h>
#include <simp/io/StrictNumber.h>
#include <simp/labels/Detections2D.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace simp::labels {

namespace {

void check(const Detection2D& d, const std::vector<std::string>& names, const std::string& file, const std::string& where) {
    if (std::find(names.begin(), names.end(), d.class_name) == names.end())
        world::failAt(file, where, "unknown class '" + d.class_name + "' (not a class of the world)");
    if (!(d.x_max > d.x_min) || !(d.y_max > d.y_min)) world::failAt(file, where, "expected x_min < x_max and y_min < y_max");
    if (!(d.score >= 0 && d.score <= 1)) world::failAt(file, where, "score " + std::to_string(d.score) + " must be in [0, 1]");
}

std::vector<Detection2D> readCsv(const std::string& path, const std::vector<std::string>& names) {
    std::ifstream in(path);
    if (!in) world::failAt(path, "", "cannot open for reading");
    std::vector<Detection2D> out;
    std::string line;
    std::size_t n = 0;
    while (std::getline(in, line)) {
        ++n;
        const std::string t = io::trimIniValue(line);
        if (t.empty() || t[0] == '#' || (n == 1 && t.rfind("image_id", 0) == 0)) continue;
        std::vector<std::string> f;
        std::stringstream ss(t);
        for (std::string c; std::getline(ss, c, ',');) f.push_back(io::trimIniValue(c));
        const std::string where = "line " + std::to_string(n);
        if (f.size() != 7)
            world::failAt(path, where, "wrong column count " + std::to_string(f.size()) +
                                          " (expected 7: image_id,class,x_min,y_min,x_max,y_max,score)");
        double v[7] = {};
        for (std::size_t c : {2u, 3u, 4u, 5u, 6u}) {
            const auto x = io::parseFiniteNumber(f[c]);
            if (!x) world::failAt(path, where, "column " + std::to_string(c + 1) + ": expected a finite number, got '" + f[c] + "'");
            v[c] = *x;
        }
        const auto image_id = io::parseWholeInteger(f[0]);
        if (!image_id) world::failAt(path, where, "column 1: image_id must be an integer, got '" + f[0] + "'");
        Detection2D d{*image_id, f[1], v[2], v[3], v[4], v[5], v[6]};
        check(d, names, path, where);
        out.push_back(d);
    }
    return out;
}

std::vector<Detection2D> readJson(const std::string& path, const std::vector<std::string>& names) {
    const nlohmann::json j = world::readJsonFile(path);
    const nlohmann::json& dets = world::requireKey(j, "detections", path, "detections");
    if (!dets.is_array()) world::failAt(path, "detections", "expected a list");
    std::vector<Detection2D> out;
    for (std::size_t i = 0; i < dets.size(); ++i) {
        const std::string k = "detections[" + std::to_string(i) + "]";
        Detection2D d;
        d.image_id = world::asInteger(world::requireKey(dets[i], "image_id", path, k + ".image_id"), path, k + ".image_id");
        d.class_name = world::asString(world::requireKey(dets[i], "class", path, k + ".class"), path, k + ".class");
        const auto b = world::asNumberArray(world::requireKey(dets[i], "bbox", path, k + ".bbox"), 4, path, k + ".bbox");
        d.x_min = b[0], d.y_min = b[1], d.x_max = b[2], d.y_max = b[3];
        if (dets[i].contains("score")) d.score = world::asNumber(dets[i]["score"], path, k + ".score");
        check(d, names, path, k);
        out.push_back(d);
    }
    return out;
}

}  // namespace

std::vector<Detection2D> readDetections2D(const std::string& path, const std::vector<std::string>& class_names) {
    if (!std::filesystem::exists(path)) world::failAt(path, "", "file not found");
    return std::filesystem::path(path).extension() == ".json" ? readJson(path, class_names) : readCsv(path, class_names);
}

}  // namespace simp::labels
