/// \file ChangesFile.cpp
/// changes.json read and write (doc/formats.md "changes.json").
#include <simp/world/ChangesFile.h>
#include <simp/world/JsonRead.h>

#include <cmath>
#include <filesystem>

namespace simp::world {
namespace {

constexpr const char* kChangesFormat = "simp-changes";
constexpr int kChangesVersion = 1;

/// Upright boxes need only the yaw (every object of the project's worlds stands upright).
nlohmann::ordered_json poseToJson(const std::optional<geometry::Box3D>& b) {
    if (!b) return nullptr;
    return nlohmann::ordered_json{{"center_m", {b->center.x(), b->center.y(), b->center.z()}},
                                  {"size_m", {b->size.x(), b->size.y(), b->size.z()}},
                                  {"yaw_rad", geometry::yawOf(*b)}};
}

nlohmann::ordered_json idToJson(const std::optional<std::int64_t>& id) {
    if (!id) return nullptr;
    return *id;
}

std::optional<std::int64_t> idFromJson(const nlohmann::json& e, const std::string& key, const std::string& file,
                                       const std::string& where) {
    const nlohmann::json& v = requireKey(e, key, file, where + "." + key);
    if (v.is_null()) return std::nullopt;
    return asInteger(v, file, where + "." + key);
}

std::optional<geometry::Box3D> poseFromJson(const nlohmann::json& e, const std::string& key, const std::string& file,
                                            const std::string& where) {
    const std::string k = where + "." + key;
    const nlohmann::json& v = requireKey(e, key, file, k);
    if (v.is_null()) return std::nullopt;
    if (!v.is_object()) failAt(file, k, "expected a pose object or null");
    const auto c = asNumbers(requireKey(v, "center_m", file, k + ".center_m"), 3, file, k + ".center_m", "3 numbers");
    const auto s = asNumbers(requireKey(v, "size_m", file, k + ".size_m"), 3, file, k + ".size_m", "3 numbers");
    for (double d : s)
        if (!(d > 0)) failAt(file, k + ".size_m", "expected 3 positive numbers");
    const double yaw = asNumber(requireKey(v, "yaw_rad", file, k + ".yaw_rad"), file, k + ".yaw_rad");
    return geometry::makeUprightBox({c[0], c[1], c[2]}, {s[0], s[1], s[2]}, yaw);
}

}  // namespace

void saveChangesFile(const std::vector<ChangeRecord>& changes, const std::string& path,
                     const std::string& before_world) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const ChangeRecord& c : changes) {
        nlohmann::ordered_json e;
        e["kind"] = c.kind;
        e["id_before"] = idToJson(c.id_before);
        e["id_after"] = idToJson(c.id_after);
        e["class"] = c.class_name;
        e["before"] = poseToJson(c.before);
        e["after"] = poseToJson(c.after);
        if (c.confidence) e["confidence"] = *c.confidence;
        list.push_back(e);
    }
    nlohmann::ordered_json j;
    j["format"] = kChangesFormat;
    j["version"] = kChangesVersion;
    if (!before_world.empty()) {
        namespace fs = std::filesystem;
        const fs::path world = fs::absolute(before_world).lexically_normal();
        const fs::path folder = fs::absolute(path).parent_path().lexically_normal();
        const fs::path relative = world.lexically_relative(folder);
        j["before_world"] = (relative.empty() ? world : relative).generic_string();
    }
    j["changes"] = list;
    writeJsonFile(j, path);
}

std::vector<ChangeRecord> loadChangesFile(const std::string& path) { return readChangesFile(path).changes; }

ChangesFileContent readChangesFile(const std::string& path) {
    const nlohmann::json j = readJsonFile(path);
    if (!j.is_object()) failAt(path, "", "expected a JSON object (a simp-changes file)");
    if (asString(requireKey(j, "format", path, "format"), path, "format") != kChangesFormat)
        failAt(path, "format", std::string("expected \"") + kChangesFormat + "\"");
    if (asInteger(requireKey(j, "version", path, "version"), path, "version") != kChangesVersion)
        failAt(path, "version", "unsupported version (this reader knows version 1)");
    ChangesFileContent content;
    if (j.contains("before_world")) {
        const std::string dir = asString(j["before_world"], path, "before_world");
        if (dir.empty()) failAt(path, "before_world", "expected a directory, not an empty string");
        const std::filesystem::path p(dir);
        content.before_world = (p.is_absolute() ? p : std::filesystem::path(path).parent_path() / p).lexically_normal().string();
    }
    const nlohmann::json& list = requireKey(j, "changes", path, "changes");
    if (!list.is_array()) failAt(path, "changes", "expected a list");
    std::vector<ChangeRecord>& out = content.changes;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string where = "changes[" + std::to_string(i) + "]";
        const nlohmann::json& e = list[i];
        if (!e.is_object()) failAt(path, where, "expected an object");
        ChangeRecord c;
        c.kind = asString(requireKey(e, "kind", path, where + ".kind"), path, where + ".kind");
        if (c.kind != "removed" && c.kind != "moved" && c.kind != "added" && c.kind != "door_closed")
            failAt(path, where + ".kind", "'" + c.kind + "': expected removed, moved, added or door_closed");
        c.id_before = idFromJson(e, "id_before", path, where);
        c.id_after = idFromJson(e, "id_after", path, where);
        c.class_name = asString(requireKey(e, "class", path, where + ".class"), path, where + ".class");
        c.before = poseFromJson(e, "before", path, where);
        c.after = poseFromJson(e, "after", path, where);
        // What each kind needs (the schema's nulls): a scorer matches removed/moved by id_before
        // and added by the after pose.
        const bool needs_before = c.kind != "added", needs_after = c.kind != "removed";
        if (needs_before && (!c.id_before || !c.before))
            failAt(path, where, "a '" + c.kind + "' entry needs id_before and before");
        if (needs_after && (!c.id_after || !c.after)) failAt(path, where, "a '" + c.kind + "' entry needs id_after and after");
        if (e.contains("confidence")) {
            const double p = asNumber(e["confidence"], path, where + ".confidence");
            if (p < 0 || p > 1) failAt(path, where + ".confidence", "expected a number in [0, 1]");
            c.confidence = p;
        }
        out.push_back(std::move(c));
    }
    return content;
}

}  // namespace simp::world
