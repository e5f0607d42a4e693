/// \file WorldChangesJson.cpp
/// `Q/changes.json`: the true changes of a simulated sequence's world against the map
/// (doc/formats.md "changes.json"), written through the one change-file writer
/// (world::saveChangesFile) that simp-map --update uses too.

#include <simp/sim/WorldChanges.h>
#include <simp/world/ChangesFile.h>

#include <stdexcept>

namespace simp::sim {

const char* kindName(ObjectChange::Kind kind) {
    switch (kind) {
        case ObjectChange::Kind::Removed: return "removed";
        case ObjectChange::Kind::Moved: return "moved";
        case ObjectChange::Kind::Added: return "added";
        case ObjectChange::Kind::DoorClosed: return "door_closed";
    }
    throw std::invalid_argument("kindName: unknown kind");
}

void saveChangesJson(const ChangeSummary& summary, const std::vector<std::string>& class_names, const std::string& path,
                     const std::string& before_world) {
    std::vector<world::ChangeRecord> records;
    for (const ObjectChange& c : summary.changes) {
        const auto& any = c.before ? c.before : c.after;
        if (!any) throw std::invalid_argument("saveChangesJson: a change without an object before or after");
        const auto cls = static_cast<std::size_t>(any->class_id);
        if (cls >= class_names.size()) throw std::invalid_argument("saveChangesJson: class id out of range");
        world::ChangeRecord r;
        r.kind = kindName(c.kind);
        if (c.before) r.id_before = c.before->id, r.before = c.before->box;
        if (c.after) r.id_after = c.after->id, r.after = c.after->box;
        r.class_name = class_names[cls];
        records.push_back(std::move(r));
    }
    world::saveChangesFile(records, path, before_world);
}

}  // namespace simp::sim
