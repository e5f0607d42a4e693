/// \file ObjectMapJson.cpp
/// The object map file `objects.json` (doc/formats.md): reading with named errors, writing
/// with full double precision (nlohmann::json prints the shortest text that reads back to the
/// same double), and the content checks shared by both.

#include <simp/world/ObjectMapData.h>
#include <simp/world/JsonRead.h>

#include <limits>
#include <set>
#include <simp/obs/InputLimits.h>
#include <sstream>
#include <stdexcept>

namespace simp::world {

namespace {

using nlohmann::json;

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

/// An int-typed counter of the file: an integer in [lo, hi] (a wider value would wrap).
int asInt(const json& v, const std::string& file, const std::string& key, long long lo, long long hi) {
    const long long x = asInteger(v, file, key);
    if (x < lo || x > hi)
        failAt(file, key, "expected an integer >= " + std::to_string(lo) + " and <= " + std::to_string(hi) +
                              ", got " + std::to_string(x));
    return static_cast<int>(x);
}

constexpr const char* kObjectMapFormat = "simp-object-map";
constexpr int kObjectMapVersion = 1;

nlohmann::ordered_json noiseToJson(const model::NoiseModel& n) {
    return nlohmann::ordered_json{{"mean_m", {n.mean_m.x(), n.mean_m.y()}},
                {"cov_m2", {{n.cov_m2(0, 0), n.cov_m2(0, 1)}, {n.cov_m2(1, 0), n.cov_m2(1, 1)}}},
                {"b", n.exponent_b}};
}

model::NoiseModel noiseFromJson(const json& j, const std::string& file, const std::string& key) {
    if (!j.is_object()) failAt(file, key, "expected an object with mean_m, cov_m2, b");
    model::NoiseModel n;
    const auto mean = asNumbers(requireKey(j, "mean_m", file, key + ".mean_m"), 2, file,
                                        key + ".mean_m", "2 numbers [x, y] (m)");
    n.mean_m = Eigen::Vector2d(mean[0], mean[1]);
    const json& cov = requireKey(j, "cov_m2", file, key + ".cov_m2");
    const std::string cov_expect = "a 2x2 matrix [[a, b], [c, d]] (m^2)";
    if (!cov.is_array() || cov.size() != 2) failAt(file, key + ".cov_m2", "expected " + cov_expect);
    for (int r = 0; r < 2; ++r) {
        const auto row = asNumbers(cov[static_cast<std::size_t>(r)], 2, file, key + ".cov_m2", cov_expect);
        n.cov_m2(r, 0) = row[0];
        n.cov_m2(r, 1) = row[1];
    }
    n.exponent_b = asNumber(requireKey(j, "b", file, key + ".b"), file, key + ".b");
    if (!n.isValid())
        failAt(file, key, "invalid noise model (cov_m2 must be symmetric positive definite, b > 0)");
    return n;
}

Eigen::Matrix3d rotationFromJson(const json& o, const std::string& file, const std::string& key) {
    const bool has_R = o.contains("rotation");
    const bool has_yaw = o.contains("yaw_rad");
    if (has_R == has_yaw)
        failAt(file, key + ".rotation", "expected exactly one of \"rotation\" (3x3) or \"yaw_rad\"");
    if (has_yaw) {
        const double yaw = asNumber(o["yaw_rad"], file, key + ".yaw_rad");
        return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    }
    const json& R = o["rotation"];
    const std::string expect = "a 3x3 rotation matrix, row-major [[r00, r01, r02], [..], [..]]";
    if (!R.is_array() || R.size() != 3) failAt(file, key + ".rotation", "expected " + expect);
    Eigen::Matrix3d M;
    for (int r = 0; r < 3; ++r) {
        const auto row = asNumbers(R[static_cast<std::size_t>(r)], 3, file, key + ".rotation", expect);
        for (int c = 0; c < 3; ++c) M(r, c) = row[static_cast<std::size_t>(c)];
    }
    return M;
}

}  // namespace

void validateObjectMap(const ObjectMapData& d, const std::string& where) {
    if (d.class_names.empty()) failAt(where, "classes", "expected a non-empty list of class names");
    if (d.class_names.size() > obs::limits::kMaxClasses)
        failAt(where, "classes", std::to_string(d.class_names.size()) + " classes exceed the maximum " +
                                     std::to_string(obs::limits::kMaxClasses));
    if (d.objects.size() > obs::limits::kMaxMapObjects)
        failAt(where, "objects", std::to_string(d.objects.size()) + " objects exceed the maximum " +
                                     std::to_string(obs::limits::kMaxMapObjects));
    std::set<std::string> names;
    for (std::size_t i = 0; i < d.class_names.size(); ++i) {
        const std::string key = "classes[" + std::to_string(i) + "]";
        if (d.class_names[i].empty()) failAt(where, key, "empty class name");
        if (d.class_names[i].size() > obs::limits::kMaxNameLength) failAt(where, key, "class name too long");
        if (!names.insert(d.class_names[i]).second)
            failAt(where, key, "duplicate class name '" + d.class_names[i] + "'");
    }
    if (d.class_noise.size() > d.class_names.size())
        failAt(where, "class_noise", "more noise models than classes");
    for (std::size_t c = 0; c < d.class_noise.size(); ++c)
        if (d.class_noise[c] && !d.class_noise[c]->isValid())
            failAt(where, "class_noise." + d.class_names[c],
                         "invalid noise model (cov_m2 must be symmetric positive definite, b > 0)");
    std::set<std::int64_t> ids;
    for (std::size_t i = 0; i < d.objects.size(); ++i) {
        const MapObject& o = d.objects[i];
        const std::string key = "objects[" + std::to_string(i) + "]";
        if (!ids.insert(o.id).second) failAt(where, key + ".id", "duplicate id " + std::to_string(o.id));
        if (o.class_id < 0 || static_cast<std::size_t>(o.class_id) >= d.class_names.size())
            failAt(where, key + ".class", "class id " + std::to_string(o.class_id) + " out of range");
        if (!o.box.center.allFinite()) failAt(where, key + ".center_m", "expected 3 finite numbers");
        if (o.box.center.cwiseAbs().maxCoeff() > obs::limits::kMaxCoordinate_m)
            failAt(where, key + ".center_m", "coordinate beyond the maximum " + number(obs::limits::kMaxCoordinate_m) +
                                                 " m (got " + number(o.box.center.cwiseAbs().maxCoeff()) + ")");
        if (!o.box.size.allFinite() || (o.box.size.array() <= 0.0).any())
            failAt(where, key + ".size_m", "expected 3 positive numbers");
        if (o.box.size.maxCoeff() > obs::limits::kMaxBoxSide_m)
            failAt(where, key + ".size_m", "side " + number(o.box.size.maxCoeff()) + " m exceeds the maximum " +
                                               number(obs::limits::kMaxBoxSide_m) + " m");
        if (!o.box.isValid(1e-6))
            failAt(where, key + ".rotation", "not a rotation matrix (R^T R = I, det R = +1, tol 1e-6)");
        if (o.n_match < 0) failAt(where, key + ".n_match", "expected an integer >= 0");
        if (o.n_skip < 0) failAt(where, key + ".n_skip", "expected an integer >= 0");
        if (o.room_id < 0) failAt(where, key + ".room", "expected an integer >= 0 (0 = no room)");
        if (o.noise && !o.noise->isValid())
            failAt(where, key + ".noise", "invalid noise model (cov_m2 must be symmetric positive definite, b > 0)");
    }
    std::set<int> room_ids;
    for (std::size_t i = 0; i < d.rooms.size(); ++i)
        if (d.rooms[i].id < 1 || !room_ids.insert(d.rooms[i].id).second)
            failAt(where, "rooms[" + std::to_string(i) + "].id", "expected a unique integer >= 1");
}

ObjectMapData loadObjectMap(const std::string& path) {
    const json j = readJsonFile(path);
    if (!j.is_object()) failAt(path, "", "expected a JSON object at the top level");
    const std::string format = asString(requireKey(j, "format", path, "format"), path, "format");
    if (format != kObjectMapFormat) failAt(path, "format", "expected \"" + std::string(kObjectMapFormat) + "\", got \"" + format + "\"");
    const long long version = asInteger(requireKey(j, "version", path, "version"), path, "version");
    if (version != kObjectMapVersion)
        failAt(path, "version", "unsupported version " + std::to_string(version) + " (this build reads version " +
                                          std::to_string(kObjectMapVersion) + ")");

    ObjectMapData d;
    const json& classes = requireKey(j, "classes", path, "classes");
    if (!classes.is_array() || classes.empty()) failAt(path, "classes", "expected a non-empty list of class names");
    for (std::size_t i = 0; i < classes.size(); ++i)
        d.class_names.push_back(asString(classes[i], path, "classes[" + std::to_string(i) + "]"));
    d.class_noise.assign(d.class_names.size(), std::nullopt);

    if (j.contains("class_noise")) {
        const json& cn = j["class_noise"];
        if (!cn.is_object()) failAt(path, "class_noise", "expected an object {class name: noise model}");
        for (const auto& [name, model] : cn.items()) {
            const int c = d.classId(name);
            if (c < 0) failAt(path, "class_noise." + name, "unknown class '" + name + "' (not in \"classes\")");
            d.class_noise[static_cast<std::size_t>(c)] = noiseFromJson(model, path, "class_noise." + name);
        }
    }

    const json& objects = requireKey(j, "objects", path, "objects");
    if (!objects.is_array()) failAt(path, "objects", "expected a list of objects");
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const json& o = objects[i];
        const std::string key = "objects[" + std::to_string(i) + "]";
        if (!o.is_object()) failAt(path, key, "expected an object");
        MapObject m;
        m.id = asInteger(requireKey(o, "id", path, key + ".id"), path, key + ".id");
        const std::string cls = asString(requireKey(o, "class", path, key + ".class"), path, key + ".class");
        m.class_id = d.classId(cls);
        if (m.class_id < 0) failAt(path, key + ".class", "unknown class '" + cls + "' (not in \"classes\")");
        const auto c = asNumbers(requireKey(o, "center_m", path, key + ".center_m"), 3, path,
                                         key + ".center_m", "3 finite numbers [x, y, z] (m)");
        const auto s = asNumbers(requireKey(o, "size_m", path, key + ".size_m"), 3, path,
                                         key + ".size_m", "3 positive numbers");
        if (s[0] <= 0 || s[1] <= 0 || s[2] <= 0) failAt(path, key + ".size_m", "expected 3 positive numbers");
        m.box.center = Eigen::Vector3d(c[0], c[1], c[2]);
        m.box.size = Eigen::Vector3d(s[0], s[1], s[2]);
        m.box.R = rotationFromJson(o, path, key);
        constexpr long long kMaxCounter = std::numeric_limits<int>::max();
        if (o.contains("n_match")) m.n_match = asInt(o["n_match"], path, key + ".n_match", 0, kMaxCounter);
        if (o.contains("n_skip")) m.n_skip = asInt(o["n_skip"], path, key + ".n_skip", 0, kMaxCounter);
        if (o.contains("room")) m.room_id = asInt(o["room"], path, key + ".room", 0, kMaxCounter);
        if (o.contains("noise") && !o["noise"].is_null()) m.noise = noiseFromJson(o["noise"], path, key + ".noise");
        d.objects.push_back(m);
    }

    if (j.contains("room_categories")) {
        const json& rc = j["room_categories"];
        if (!rc.is_array()) failAt(path, "room_categories", "expected a list of names");
        for (std::size_t i = 0; i < rc.size(); ++i)
            d.room_categories.push_back(asString(rc[i], path, "room_categories[" + std::to_string(i) + "]"));
    }
    if (j.contains("rooms")) {
        const json& rooms = j["rooms"];
        if (!rooms.is_array()) failAt(path, "rooms", "expected a list of {id, name, category}");
        for (std::size_t i = 0; i < rooms.size(); ++i) {
            const std::string key = "rooms[" + std::to_string(i) + "]";
            RoomInfo r;
            r.id = asInt(requireKey(rooms[i], "id", path, key + ".id"), path, key + ".id", 1,
                         std::numeric_limits<int>::max());
            if (rooms[i].contains("name")) r.name = asString(rooms[i]["name"], path, key + ".name");
            if (rooms[i].contains("category")) r.category = asString(rooms[i]["category"], path, key + ".category");
            d.rooms.push_back(r);
        }
    }
    validateObjectMap(d, path);
    return d;
}

void saveObjectMap(const ObjectMapData& d, const std::string& path) {
    validateObjectMap(d, path);
    nlohmann::ordered_json j;
    j["format"] = kObjectMapFormat;
    j["version"] = kObjectMapVersion;
    j["classes"] = d.class_names;
    nlohmann::ordered_json cn = nlohmann::ordered_json::object();
    for (std::size_t c = 0; c < d.class_noise.size(); ++c)
        if (d.class_noise[c]) cn[d.class_names[c]] = noiseToJson(*d.class_noise[c]);
    j["class_noise"] = cn;
    nlohmann::ordered_json objects = nlohmann::ordered_json::array();
    for (const MapObject& m : d.objects) {
        nlohmann::ordered_json o;
        o["id"] = m.id;
        o["class"] = d.class_names[static_cast<std::size_t>(m.class_id)];
        o["center_m"] = {m.box.center.x(), m.box.center.y(), m.box.center.z()};
        o["size_m"] = {m.box.size.x(), m.box.size.y(), m.box.size.z()};
        nlohmann::ordered_json R = nlohmann::ordered_json::array();
        for (int r = 0; r < 3; ++r) R.push_back({m.box.R(r, 0), m.box.R(r, 1), m.box.R(r, 2)});
        o["rotation"] = R;
        o["n_match"] = m.n_match;
        o["n_skip"] = m.n_skip;
        o["room"] = m.room_id;
        if (m.noise) o["noise"] = noiseToJson(*m.noise);
        objects.push_back(o);
    }
    j["objects"] = objects;
    if (!d.room_categories.empty()) j["room_categories"] = d.room_categories;
    if (!d.rooms.empty()) {
        nlohmann::ordered_json rooms = nlohmann::ordered_json::array();
        for (const RoomInfo& r : d.rooms) rooms.push_back({{"id", r.id}, {"name", r.name}, {"category", r.category}});
        j["rooms"] = rooms;
    }
    writeJsonFile(j, path);
}

}  // namespace simp::world
