/// \file SimpExport.cpp
/// A world -> the authors' map format, the inverse of SimpImport.cpp (doc/import-export.md).

#include <opencv2/imgcodecs.hpp>
#include <simp/geometry/Box3D.h>
#include <simp/world/JsonRead.h>
#include <simp/world/SimpFormat.h>
#include <simp/world/SimpPixels.h>
#include <simp/world/World.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

namespace simp::world {

namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

/// The value as written to a yaml by saveRosMap (shortest float text), read back as double.
double asWrittenToYaml(float v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    return std::stod(std::string(buf, r.ptr));
}

std::string num(double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    return std::string(buf, r.ptr);
}

struct ObjectPx {
    int category = 0;
    long long uid = 0;
    double mx = 0, my = 0, sx = 0, sy = 0, b = 2;
    std::array<Eigen::Vector2i, 4> corners;
};

/// Box -> the authors' numbers. Footprint corners counter-clockwise in the world (as their
/// ConvexHull), starting at the box's (-x, -y) corner; noise mean as an absolute pixel,
/// scales = sqrt of the diagonal of Sigma in pixel axes (off-diagonal terms are not
/// representable in their format and are dropped).
ObjectPx toPixels(const ObjectMapData& d, const MapObject& o, const SimpPixelFrame& px) {
    const geometry::Box3D box = geometry::canonicalizeUpright(o.box);
    const double yaw = geometry::yawOf(box);
    Eigen::Matrix2d R;
    R << std::cos(yaw), -std::sin(yaw), std::sin(yaw), std::cos(yaw);
    const Eigen::Vector2d c = box.center.head<2>();
    const Eigen::Vector2d half = 0.5 * box.size.head<2>();
    ObjectPx out;
    out.category = o.class_id;
    out.uid = o.id;
    const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (std::size_t k = 0; k < 4; ++k)
        out.corners[k] = px.toPixelRounded(c + R * Eigen::Vector2d(signs[k][0] * half.x(), signs[k][1] * half.y()));
    const model::NoiseModel n = d.noiseOf(o).value_or(model::NoiseModel{});
    const Eigen::Vector2d mean_px = px.toPixel(c + R * n.mean_m);
    const Eigen::Matrix2d cov_world = R * n.cov_m2 * R.transpose();
    out.mx = mean_px.x();
    out.my = mean_px.y();
    out.sx = std::sqrt(cov_world(0, 0)) / px.resolution_m;
    out.sy = std::sqrt(cov_world(1, 1)) / px.resolution_m;
    out.b = n.exponent_b;
    return out;
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path);
    if (!out) failAt(path, "", "cannot open for writing");
    out << text;
    if (!out) failAt(path, "", "write failed");
}

}  // namespace

void exportSimpMap(const World& world, const std::string& dir) {
    validateObjectMap(world.objects, "object map to export");
    fs::create_directories(dir);
    const auto out = [&](const std::string& name) { return (fs::path(dir) / name).string(); };
    const ObjectMapData& d = world.objects;
    const auto& grid = world.floorplan;
    const SimpPixelFrame px{asWrittenToYaml(grid.getResolution()), asWrittenToYaml(grid.getXMin()),
                            asWrittenToYaml(grid.getYMin()), static_cast<int>(grid.getSizeY())};

    saveRosMap(grid, out("Map.yaml"));  // writes Map.png

    // roomseg.png: 8-bit (the authors read it with cv::imread, which would scale 16-bit).
    cv::Mat1b roomseg = cv::Mat1b::zeros(static_cast<int>(grid.getSizeY()), static_cast<int>(grid.getSizeX()));
    if (!world.rooms.empty()) {
        double max_id = 0;
        cv::minMaxLoc(world.rooms.ids, nullptr, &max_id);
        if (max_id > 255) failAt(out("roomseg.png"), "", "room id " + num(max_id) + " does not fit 8 bits");
        if (world.rooms.ids.size() != roomseg.size()) failAt(out("roomseg.png"), "", "room raster size differs from the floor plan");
        world.rooms.ids.convertTo(roomseg, CV_8U);
    }
    if (!cv::imwrite(out("roomseg.png"), roomseg)) failAt(out("roomseg.png"), "", "cannot write the image");

    std::vector<ObjectPx> objs;
    for (const MapObject& o : d.objects) objs.push_back(toPixels(d, o, px));

    // global_variance.json (+ .csv with the same content).
    ojson gv;
    for (const char* key : {"category", "uid", "mx", "my", "sx", "sy", "b", "corners"}) gv[key] = ojson::array();
    std::string csv = "category,uid,mx,my,sx,sy,b,corners\n";
    for (const ObjectPx& o : objs) {
        std::vector<int> flat;
        for (const auto& c : o.corners) {
            flat.push_back(c.x());
            flat.push_back(c.y());
        }
        gv["category"].push_back(o.category);
        gv["uid"].push_back(o.uid);
        gv["mx"].push_back(o.mx);
        gv["my"].push_back(o.my);
        gv["sx"].push_back(o.sx);
        gv["sy"].push_back(o.sy);
        gv["b"].push_back(o.b);
        gv["corners"].push_back(flat);
        std::string cs;
        for (std::size_t k = 0; k < flat.size(); ++k) cs += (k ? ", " : "") + std::to_string(flat[k]);
        csv += std::to_string(o.category) + "," + std::to_string(o.uid) + "," + num(o.mx) + "," + num(o.my) + "," +
               num(o.sx) + "," + num(o.sy) + "," + num(o.b) + ",\"[" + cs + "]\"\n";
    }
    writeJsonFile(gv, out("global_variance.json"));
    writeText(out("global_variance.csv"), csv);

    // class_noise.csv: class frame, in pixels of the floor plan's resolution.
    std::string cn = "category,mx,my,sx,sy,b\n";
    for (std::size_t c = 0; c < d.class_names.size(); ++c) {
        const auto& n = c < d.class_noise.size() ? d.class_noise[c] : std::nullopt;
        cn += std::to_string(c);
        if (n)
            cn += "," + num(n->mean_m.x() / px.resolution_m) + "," + num(n->mean_m.y() / px.resolution_m) + "," +
                  num(std::sqrt(n->cov_m2(0, 0)) / px.resolution_m) + "," +
                  num(std::sqrt(n->cov_m2(1, 1)) / px.resolution_m) + "," + num(n->exponent_b);
        else
            cn += ",,,,,";
        cn += "\n";
    }
    writeText(out("class_noise.csv"), cn);

    // floor.config: classes, room categories, rooms with the bounding rectangles of their objects.
    std::vector<std::string> categories = d.room_categories;
    for (const RoomInfo& r : d.rooms)
        if (!r.category.empty() && std::find(categories.begin(), categories.end(), r.category) == categories.end())
            categories.push_back(r.category);
    if (categories.empty()) categories.push_back("room");
    std::map<int, RoomInfo> rooms;  // by id (>= 1)
    for (const RoomInfo& r : d.rooms) rooms[r.id] = r;
    if (!world.rooms.empty()) {
        double max_id = 0;
        cv::minMaxLoc(world.rooms.ids, nullptr, &max_id);
        for (int id = 1; id <= static_cast<int>(max_id); ++id)
            if (!rooms.count(id)) rooms[id] = RoomInfo{id, std::to_string(id - 1), ""};
    }
    for (const MapObject& o : d.objects)
        if (o.room_id > 0 && !rooms.count(o.room_id)) rooms[o.room_id] = RoomInfo{o.room_id, std::to_string(o.room_id - 1), ""};
    ojson fc;
    fc["name"] = "0";
    fc["roomSeg"] = "roomseg.png";
    fc["map"] = ojson::array({ojson{{"type", "GMap"}, {"image", "Map.png"}, {"resolution", px.resolution_m},
                                    {"origin", {px.origin_x_m, px.origin_y_m, 0.0}}, {"negate", 0},
                                    {"occupied_thresh", kWrittenOccupiedThresh}, {"free_thresh", kWrittenFreeThresh}, {"augment", 0}}});
    fc["semantic"] = ojson{{"classes", d.class_names}, {"categories", categories}};
    ojson jrooms = ojson::array();
    for (const auto& [id, r] : rooms) {
        const auto cat = std::find(categories.begin(), categories.end(), r.category);
        ojson jr{{"name", r.name}, {"purpose", cat == categories.end() ? 0 : cat - categories.begin()}, {"id", id - 1}};
        ojson members = ojson::array();
        for (std::size_t i = 0; i < d.objects.size(); ++i) {
            if (d.objects[i].room_id != id) continue;
            int u0 = 1 << 30, v0 = 1 << 30, u1 = -(1 << 30), v1 = -(1 << 30);
            for (const auto& c : objs[i].corners) {
                u0 = std::min(u0, c.x());
                v0 = std::min(v0, c.y());
                u1 = std::max(u1, c.x());
                v1 = std::max(v1, c.y());
            }
            // [u_min, v_min, u_max + 1, v_max + 1], as in the authors' floor.config.
            members.push_back(ojson{{"semLabel", objs[i].category}, {"position", {u0, v0, u1 + 1, v1 + 1}}, {"id", objs[i].uid}});
        }
        jr["objects"] = members;
        jrooms.push_back(jr);
    }
    fc["rooms"] = jrooms;
    writeJsonFile(fc, out("floor.config"));

    ojson meta;
    meta["thing_classes"] = d.class_names;
    ojson ids = ojson::object();
    for (std::size_t c = 0; c < d.class_names.size(); ++c) ids[std::to_string(c)] = c;
    meta["thing_dataset_id_to_contiguous_id"] = ids;
    writeJsonFile(meta, out("category_meta.json"));
}

}  // namespace simp::world
