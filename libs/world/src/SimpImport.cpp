/// \file SimpImport.cpp
/// The authors' map format -> a world (doc/import-export.md, "How the numbers are read").

#include <simp/io/StrictIni.h>
#include <simp/io/StrictNumber.h>
#include <simp/geometry/Box3D.h>
#include <simp/world/JsonRead.h>
#include <simp/model/NoiseFrame.h>
#include <simp/world/SimpFormat.h>
#include <simp/world/SimpPixels.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace simp::world {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
constexpr double kPi = 3.14159265358979323846;

/// One row of class_noise.csv, in the authors' units (0.05 m cells, class frame).
struct ClassNoisePx {
    double mx = 0, my = 0, sx = 0, sy = 0, b = 2;
};

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> out;
    std::string cell;
    std::stringstream ss(line);
    while (std::getline(ss, cell, ',')) out.push_back(cell);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    for (auto& c : out) {
        while (!c.empty() && (c.back() == '\r' || c.back() == ' ')) c.pop_back();
        while (!c.empty() && c.front() == ' ') c.erase(c.begin());
    }
    return out;
}

double parseCsvNumber(const std::string& s, const std::string& file, const std::string& key) {
    const auto v = io::parseFiniteNumber(s);
    if (!v) failAt(file, key, "expected a finite number, got '" + s + "'");
    return *v;
}

/// class_noise.csv: header category,mx,my,sx,sy,b; a row with only the category = not modelled.
std::vector<std::optional<ClassNoisePx>> readClassNoiseCsv(const std::string& path, std::size_t num_classes) {
    std::vector<std::optional<ClassNoisePx>> out(num_classes);
    std::ifstream in(path);
    if (!in) failAt(path, "", "cannot open for reading");
    std::string line;
    if (!std::getline(in, line)) failAt(path, "header", "empty file");
    const std::vector<std::string> expected = {"category", "mx", "my", "sx", "sy", "b"};
    if (splitCsv(line) != expected) failAt(path, "header", "expected 'category,mx,my,sx,sy,b'");
    int line_no = 1;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty() || line == "\r") continue;
        const std::string row = "line " + std::to_string(line_no);
        const auto f = splitCsv(line);
        if (f.size() != 6) failAt(path, row, "expected 6 comma-separated fields");
        const double cat = parseCsvNumber(f[0], path, row + ".category");
        if (cat != std::floor(cat) || cat < 0 || cat >= static_cast<double>(num_classes))
            failAt(path, row + ".category", "expected a class index in [0, " + std::to_string(num_classes) + ")");
        bool all_empty = true, any_empty = false;
        for (std::size_t k = 1; k < 6; ++k) {
            if (f[k].empty()) any_empty = true;
            else all_empty = false;
        }
        if (all_empty) continue;  // class not modelled
        if (any_empty) failAt(path, row, "either all of mx,my,sx,sy,b or none must be given");
        ClassNoisePx n;
        n.mx = parseCsvNumber(f[1], path, row + ".mx");
        n.my = parseCsvNumber(f[2], path, row + ".my");
        n.sx = parseCsvNumber(f[3], path, row + ".sx");
        n.sy = parseCsvNumber(f[4], path, row + ".sy");
        n.b = parseCsvNumber(f[5], path, row + ".b");
        if (n.sx <= 0 || n.sy <= 0) failAt(path, row + ".sx/sy", "expected positive scales");
        if (n.b <= 0) failAt(path, row + ".b", "expected a positive exponent");
        out[static_cast<std::size_t>(cat)] = n;
    }
    return out;
}

std::vector<double> numberArray(const json& gv, const std::string& key, std::size_t n, const std::string& file) {
    return asNumbers(requireKey(gv, key, file, key), n, file, key,
                             std::to_string(n) + " numbers (one per object, as many as \"uid\")");
}

double classHeight(const std::string& name, const SimpImportOptions& opt) {
    std::string underscored = name;
    for (auto& ch : underscored)
        if (ch == ' ') ch = '_';
    for (const std::string& k : {name, underscored}) {
        const auto it = opt.class_height_m.find(k);
        if (it != opt.class_height_m.end()) return it->second;
    }
    return defaultClassHeight(name);
}

Eigen::Matrix2d rot2(double yaw) {
    Eigen::Matrix2d R;
    R << std::cos(yaw), -std::sin(yaw), std::sin(yaw), std::cos(yaw);
    return R;
}

/// The authors rotate the class scale matrix diag(sx, sy) by the object's yaw and keep its
/// diagonal (ComputeStatsOnPred.py, estimateGlobalVariance4center). Of the two box axes
/// choices (yaw, yaw + 90 deg) pick the one that reproduces the object's (sx, sy) best;
/// without a usable class model, x is the longer side.
double chooseYaw(const RectangleFit& fit, const std::optional<ClassNoisePx>& cls, double sx, double sy) {
    const double candidates[2] = {fit.yaw_rad, fit.yaw_rad + kPi / 2};
    int best = fit.length_y_m > fit.length_x_m ? 1 : 0;
    if (cls && std::abs(cls->sx - cls->sy) > 1e-9) {
        double best_err = 1e300;
        for (int k = 0; k < 2; ++k) {
            const double c2 = std::pow(std::cos(candidates[k]), 2), s2 = std::pow(std::sin(candidates[k]), 2);
            const double err = std::abs(cls->sx * c2 + cls->sy * s2 - sx) + std::abs(cls->sx * s2 + cls->sy * c2 - sy);
            if (err < best_err - 1e-12) {
                best_err = err;
                best = k;
            }
        }
    }
    double yaw = candidates[best];
    if (yaw > kPi / 2) yaw -= kPi;  // keep (-pi/2, pi/2]
    return yaw;
}


// The authors derive each object's model in global_variance.json from its class model, but the
// class means of class_noise.csv are not in the frame those objects use (the y axis is flipped
// for most classes, the desk's mean is turned by 90 deg), and the objects' models are what the
// detections follow. The class mean becomes the mean of the objects' offsets in the class noise
// frame (simp::model::classNoiseFrameYaw), as simp-stats learns it, so that a mapper that removes
// the class bias (doc/mapping.md "Detector bias") removes the one its detections have.
void classMeansFromObjects(ObjectMapData& map) {
    std::vector<Eigen::Vector2d> sum(map.class_names.size(), Eigen::Vector2d::Zero());
    std::vector<int> count(map.class_names.size(), 0);
    for (const MapObject& o : map.objects) {
        if (!o.noise) continue;
        const Eigen::Vector2d world = Eigen::Rotation2Dd(geometry::yawOf(o.box)) * o.noise->mean_m;
        sum[static_cast<std::size_t>(o.class_id)] += Eigen::Rotation2Dd(-model::classNoiseFrameYaw(o.box)) * world;
        ++count[static_cast<std::size_t>(o.class_id)];
    }
    for (std::size_t c = 0; c < map.class_names.size(); ++c)
        if (c < map.class_noise.size() && map.class_noise[c] && count[c] > 0)
            map.class_noise[c]->mean_m = sum[c] / count[c];
}

}  // namespace

SimpImportOptions loadSimpImportOptions(const std::string& ini_path) {
    const io::StrictIni ini(ini_path);  // exists, is a file, is an .ini
    SimpImportOptions opt;
    std::vector<std::string> keys;
    ini.getAllKeys("class_heights", keys);
    // Any class name is a key of [class_heights]; a height is in (0, 100] m (the box side limit).
    for (const auto& k : keys) opt.class_height_m[k] = ini.readNumber("class_heights", k, 0, 1e-6, 100);
    ini.checkUnknown();
    return opt;
}

World importSimpMap(const std::string& dir, const SimpImportOptions& options) {
    if (!fs::is_directory(dir)) throw std::runtime_error("authors' map directory '" + dir + "' does not exist");
    const auto in = [&](const std::string& name) { return (fs::path(dir) / name).string(); };
    World w;

    // floor.config: class names, room names and categories, room raster name.
    const std::string fc_path = in("floor.config");
    const json fc = readJsonFile(fc_path);
    const json& semantic = requireKey(fc, "semantic", fc_path, "semantic");
    const json& classes = requireKey(semantic, "classes", fc_path, "semantic.classes");
    if (!classes.is_array() || classes.empty()) failAt(fc_path, "semantic.classes", "expected a non-empty list of names");
    for (std::size_t i = 0; i < classes.size(); ++i)
        w.objects.class_names.push_back(asString(classes[i], fc_path, "semantic.classes[" + std::to_string(i) + "]"));
    const std::size_t num_classes = w.objects.class_names.size();
    if (semantic.contains("categories")) {
        const json& cats = semantic["categories"];
        if (!cats.is_array()) failAt(fc_path, "semantic.categories", "expected a list of names");
        for (std::size_t i = 0; i < cats.size(); ++i)
            w.objects.room_categories.push_back(asString(cats[i], fc_path, "semantic.categories[" + std::to_string(i) + "]"));
    }
    if (fc.contains("rooms")) {
        const json& rooms = fc["rooms"];
        if (!rooms.is_array()) failAt(fc_path, "rooms", "expected a list");
        for (std::size_t i = 0; i < rooms.size(); ++i) {
            const std::string key = "rooms[" + std::to_string(i) + "]";
            RoomInfo r;
            const long long raw_id = asInteger(requireKey(rooms[i], "id", fc_path, key + ".id"), fc_path, key + ".id");
            if (raw_id < 0 || raw_id >= 65535)  // room ids are stored in a 16-bit raster, + 1
                failAt(fc_path, key + ".id", "expected an integer in [0, 65534], got " + std::to_string(raw_id));
            r.id = static_cast<int>(raw_id) + 1;
            if (rooms[i].contains("name")) r.name = asString(rooms[i]["name"], fc_path, key + ".name");
            if (rooms[i].contains("purpose")) {
                const long long p = asInteger(rooms[i]["purpose"], fc_path, key + ".purpose");
                if (p < 0 || static_cast<std::size_t>(p) >= w.objects.room_categories.size())
                    failAt(fc_path, key + ".purpose", "index outside semantic.categories");
                r.category = w.objects.room_categories[static_cast<std::size_t>(p)];
            }
            w.objects.rooms.push_back(r);
        }
    }

    // Map.yaml + image, roomseg.
    const std::string yaml_path = in("Map.yaml");
    if (!fs::exists(yaml_path)) throw std::runtime_error(yaml_path + ": missing (the floor plan of the authors' map)");
    const RosMapYaml meta = readRosMapYaml(yaml_path);
    loadRosMap(yaml_path, w.floorplan);
    const SimpPixelFrame px{meta.resolution_m, meta.origin_x_m, meta.origin_y_m, static_cast<int>(w.floorplan.getSizeY())};
    std::string roomseg = in("roomseg.png");
    const bool roomseg_named = fc.contains("roomSeg");
    if (roomseg_named) roomseg = in(asString(fc["roomSeg"], fc_path, "roomSeg"));
    if (fs::exists(roomseg)) {
        w.rooms = loadRoomMap(roomseg, meta.resolution_m, meta.origin_x_m, meta.origin_y_m);
        if (static_cast<unsigned>(w.rooms.ids.cols) != w.floorplan.getSizeX() ||
            static_cast<unsigned>(w.rooms.ids.rows) != w.floorplan.getSizeY())
            throw std::runtime_error(roomseg + ": size differs from the floor plan " + meta.image_path);
    } else if (roomseg_named) {
        failAt(fc_path, "roomSeg", "file '" + roomseg + "' not found");
    }

    // class_noise.csv (optional): class frame, 0.05 m cells -> metres.
    std::vector<std::optional<ClassNoisePx>> class_px(num_classes);
    if (fs::exists(in("class_noise.csv"))) class_px = readClassNoiseCsv(in("class_noise.csv"), num_classes);
    const double res = meta.resolution_m;
    w.objects.class_noise.assign(num_classes, std::nullopt);
    for (std::size_t c = 0; c < num_classes; ++c)
        if (class_px[c]) {
            model::NoiseModel n;
            n.mean_m = res * Eigen::Vector2d(class_px[c]->mx, class_px[c]->my);
            n.cov_m2 = res * res * Eigen::Vector2d(class_px[c]->sx * class_px[c]->sx, class_px[c]->sy * class_px[c]->sy).asDiagonal();
            n.exponent_b = class_px[c]->b;
            w.objects.class_noise[c] = n;
        }

    // global_variance.json: the objects.
    const std::string gv_path = in("global_variance.json");
    const json gv = readJsonFile(gv_path);
    const json& uid = requireKey(gv, "uid", gv_path, "uid");
    if (!uid.is_array()) failAt(gv_path, "uid", "expected a list of integers");
    const std::size_t n = uid.size();
    const auto category = numberArray(gv, "category", n, gv_path);
    const auto mx = numberArray(gv, "mx", n, gv_path), my = numberArray(gv, "my", n, gv_path);
    const auto sx = numberArray(gv, "sx", n, gv_path), sy = numberArray(gv, "sy", n, gv_path);
    const auto b = numberArray(gv, "b", n, gv_path);
    const json& corners = requireKey(gv, "corners", gv_path, "corners");
    if (!corners.is_array() || corners.size() != n)
        failAt(gv_path, "corners", std::to_string(n) + " corner lists expected (one per object, as many as \"uid\")");
    std::set<long long> seen;
    for (std::size_t i = 0; i < n; ++i) {
        const std::string idx = "[" + std::to_string(i) + "]";
        MapObject o;
        // The authors write uids as JSON integers; a float (-5.0, 3.5) or a negative uid is a broken file.
        if (!uid[i].is_number_integer() || asInteger(uid[i], gv_path, "uid" + idx) < 0)
            failAt(gv_path, "uid" + idx, "expected an integer >= 0, got " + uid[i].dump());
        o.id = asInteger(uid[i], gv_path, "uid" + idx);
        if (!seen.insert(o.id).second) failAt(gv_path, "uid" + idx, "duplicate uid " + std::to_string(o.id));
        if (category[i] != std::floor(category[i]) || category[i] < 0 || category[i] >= static_cast<double>(num_classes))
            failAt(gv_path, "category" + idx, "expected a class index in [0, " + std::to_string(num_classes) + ")");
        o.class_id = static_cast<int>(category[i]);
        if (sx[i] <= 0 || sy[i] <= 0) failAt(gv_path, "sx/sy" + idx, "expected positive scales (px)");
        if (b[i] <= 0) failAt(gv_path, "b" + idx, "expected a positive exponent");
        const auto c = asNumbers(corners[i], 8, gv_path, "corners" + idx, "8 numbers (4 pixel corners u0,v0,...,u3,v3)");
        std::array<Eigen::Vector2d, 4> pts;
        for (std::size_t k = 0; k < 4; ++k) pts[k] = px.toWorld(Eigen::Vector2d(c[2 * k], c[2 * k + 1]));
        RectangleFit fit;
        try {
            fit = fitRectangle(pts);
        } catch (const std::invalid_argument& e) {
            failAt(gv_path, "corners" + idx, e.what());
        }
        const double yaw = chooseYaw(fit, class_px[static_cast<std::size_t>(o.class_id)], sx[i], sy[i]);
        const bool swapped = std::abs(std::remainder(yaw - fit.yaw_rad, kPi)) > kPi / 4;
        const std::string& cname = w.objects.class_names[static_cast<std::size_t>(o.class_id)];
        double h = 0;
        try {
            h = classHeight(cname, options);
        } catch (const std::invalid_argument&) {
            failAt(fc_path, "semantic.classes[" + std::to_string(o.class_id) + "]",
                         "no height for class '" + cname + "' (give one with --heights INI, section [class_heights])");
        }
        o.box = geometry::makeUprightBox(
            Eigen::Vector3d(fit.center_m.x(), fit.center_m.y(), h / 2),
            Eigen::Vector3d(swapped ? fit.length_y_m : fit.length_x_m, swapped ? fit.length_x_m : fit.length_y_m, h), yaw);
        // Per-object noise: absolute mean pixel -> offset from the box centre in the object
        // frame; pixel-axis scales -> Sigma_world = res^2 diag(sx^2, sy^2) -> R^T Sigma R.
        const Eigen::Matrix2d R = rot2(yaw);
        model::NoiseModel noise;
        noise.mean_m = R.transpose() * (px.toWorld(Eigen::Vector2d(mx[i], my[i])) - fit.center_m);
        const Eigen::Matrix2d cov_world = res * res * Eigen::Vector2d(sx[i] * sx[i], sy[i] * sy[i]).asDiagonal();
        noise.cov_m2 = R.transpose() * cov_world * R;
        // Exactly symmetric; drop rounding residue of cos(90 deg) for axis-aligned objects.
        if (std::abs(noise.cov_m2(0, 1)) < 1e-12 * noise.cov_m2.trace()) noise.cov_m2(0, 1) = 0;
        noise.cov_m2(1, 0) = noise.cov_m2(0, 1);
        noise.exponent_b = b[i];
        o.noise = noise;
        o.room_id = roomOfBox(w.rooms, o.box);
        w.objects.objects.push_back(o);
    }
    classMeansFromObjects(w.objects);
    validateObjectMap(w.objects, gv_path);
    return w;
}

}  // namespace simp::world
