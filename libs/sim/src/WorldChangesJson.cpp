/// \file WorldChangesJson.cpp
/// `Q/changes.json`: the true changes of a simulated sequence's world against the map
/// (doc/formats.md "changes.json"). simp-map --update writes the same schema for the changes it
/// detects, so that simp-eval changes can score one against the other.

#include <simp/geometry/Box3D.h>
#include <simp/sim/WorldChanges.h>
#include <simp/world/JsonRead.h>

#include <stdexcept>

namespace simp::sim {
namespace {

constexpr const char* kFormat = "simp-changes";
constexpr int kVersion = 1;

/// An object's box as the change file states it: upright boxes need only the yaw (the
/// simulator's and the authors' objects all stand upright).
nlohmann::ordered_json poseToJson(const std::optional<world::MapObject>& o) {
    if (!o) return nullptr;
    const auto& b = o->box;
    return nlohmann::ordered_json{{"center_m", {b.center.x(), b.center.y(), b.center.z()}},
                                  {"size_m", {b.size.x(), b.size.y(), b.size.z()}},
                                  {"yaw_rad", geometry::yawOf(b)}};
}

nlohmann::ordered_json idToJson(const std::optional<world::MapObject>& o) {
    if (!o) return nullptr;
    return o->id;
}

}  // namespace

const char* kindName(ObjectChange::Kind kind) {
    switch (kind) {
        case ObjectChange::Kind::Removed: return "removed";
        case ObjectChange::Kind::Moved: return "moved";
        case ObjectChange::Kind::Added: return "added";
        case ObjectChange::Kind::DoorClosed: return "door_closed";
    }
    throw std::invalid_argument("kindName: unknown kind");
}

void saveChangesJson(const ChangeSummary& summary, const std::vector<std::string>& class_names, const std::string& path) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const ObjectChange& c : summary.changes) {
        const auto& any = c.before ? c.before : c.after;
        if (!any) throw std::invalid_argument("saveChangesJson: a change without an object before or after");
        const auto cls = static_cast<std::size_t>(any->class_id);
        if (cls >= class_names.size()) throw std::invalid_argument("saveChangesJson: class id out of range");
        nlohmann::ordered_json e;
        e["kind"] = kindName(c.kind);
        e["id_before"] = idToJson(c.before);
        e["id_after"] = idToJson(c.after);
        e["class"] = class_names[cls];
        e["before"] = poseToJson(c.before);
        e["after"] = poseToJson(c.after);
        list.push_back(e);
    }
    nlohmann::ordered_json j;
    j["format"] = kFormat;
    j["version"] = kVersion;
    j["changes"] = list;
    world::writeJsonFile(j, path);
}

}  // namespace simp::sim
