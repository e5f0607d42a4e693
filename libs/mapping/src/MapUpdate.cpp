/// \file MapUpdate.cpp
/// Change detection of a map update (MapUpdate.h).
#include <simp/mapping/MapUpdate.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace simp::mapping {
namespace {

double removedConfidence(const SessionEvidence& e) {
    return 1.0 - (e.windows_matched + 1.0) / (e.windows_missed + 2.0);
}

double addedConfidence(const SessionEvidence& e) {
    const double w = std::max(1, e.windows_matched);
    return w / (w + 1.0);
}

double planarDistance(const geometry::Box3D& a, const geometry::Box3D& b) {
    return (a.center - b.center).head<2>().norm();
}

}  // namespace

MapUpdateResult detectChanges(const world::ObjectMapData& m0, const ObjectMapBuilder& builder) {
    const MappingOptions& opt = builder.options();
    MapUpdateResult r;
    r.map = builder.confirmedMap();
    const auto& names = r.map.class_names;  // m0's classes first (setMap), then any appended

    std::unordered_map<std::int64_t, std::size_t> index_in_map;
    for (std::size_t k = 0; k < r.map.objects.size(); ++k) index_in_map[r.map.objects[k].id] = k;

    // Objects of m0 gone on this session's evidence (in m0's order: the report's order).
    struct Gone {
        const world::MapObject* before;
        SessionEvidence evidence;
    };
    std::vector<Gone> gone;
    for (const auto& o : m0.objects) {
        const auto purged = builder.purgedGivenObjects().find(o.id);
        if (purged != builder.purgedGivenObjects().end()) {
            gone.push_back({&o, purged->second});
            continue;
        }
        if (!index_in_map.count(o.id)) continue;  // merged into another object of m0: still there
        const SessionEvidence e = builder.evidenceOf(o.id);
        const int expected = e.windows_matched + e.windows_missed;
        if (expected == 0) ++r.unseen;
        if (e.windows_missed >= opt.update_min_missed_windows &&
            e.windows_matched < opt.update_max_seen_fraction * expected)
            gone.push_back({&o, e});
    }

    // New confirmed objects of this session. The earlier map already explains the scene, so a new
    // object needs more viewpoints than confirmation: stray twins of a few windows stay tentative.
    std::vector<std::size_t> fresh;
    std::vector<bool> drop(r.map.objects.size(), false);  // objects left out of the updated map
    for (std::size_t k = 0; k < r.map.objects.size(); ++k) {
        const std::int64_t id = r.map.objects[k].id;
        if (builder.isGivenObject(id)) continue;
        if (builder.evidenceOf(id).windows_matched >= opt.update_min_new_windows)
            fresh.push_back(k);
        else
            drop[k] = true;
    }

    // Pair gone and new objects of one class, closest first (deterministic: ties by order).
    struct Pair {
        double dist;
        std::size_t g, f;
    };
    std::vector<Pair> pairs;
    for (std::size_t g = 0; g < gone.size(); ++g)
        for (std::size_t f = 0; f < fresh.size(); ++f) {
            const auto& n = r.map.objects[fresh[f]];
            if (names.at(static_cast<std::size_t>(n.class_id)) !=
                m0.class_names.at(static_cast<std::size_t>(gone[g].before->class_id)))
                continue;
            const double d = planarDistance(gone[g].before->box, n.box);
            if (d <= opt.update_move_max_distance_m) pairs.push_back({d, g, f});
        }
    std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.dist < b.dist; });
    std::vector<int> partner_of_gone(gone.size(), -1), partner_of_fresh(fresh.size(), -1);
    for (const Pair& p : pairs)
        if (partner_of_gone[p.g] < 0 && partner_of_fresh[p.f] < 0)
            partner_of_gone[p.g] = static_cast<int>(p.f), partner_of_fresh[p.f] = static_cast<int>(p.g);

    std::vector<world::ChangeRecord> removed, moved, added;
    for (std::size_t g = 0; g < gone.size(); ++g) {
        const world::MapObject& b = *gone[g].before;
        if (const auto it = index_in_map.find(b.id); it != index_in_map.end()) drop[it->second] = true;
        world::ChangeRecord c;
        c.id_before = b.id;
        c.class_name = m0.class_names.at(static_cast<std::size_t>(b.class_id));
        c.before = b.box;
        if (partner_of_gone[g] < 0) {
            c.kind = "removed";
            c.confidence = removedConfidence(gone[g].evidence);
            removed.push_back(c);
            continue;
        }
        world::MapObject& n = r.map.objects[fresh[static_cast<std::size_t>(partner_of_gone[g])]];
        const double conf = std::min(removedConfidence(gone[g].evidence), addedConfidence(builder.evidenceOf(n.id)));
        const bool displaced = planarDistance(b.box, n.box) >= opt.update_min_move_m;
        n.id = b.id;  // the object keeps its identity across sessions
        if (!displaced) continue;
        c.kind = "moved";
        c.id_after = n.id;
        c.after = n.box;
        c.confidence = conf;
        moved.push_back(c);
    }
    for (std::size_t f = 0; f < fresh.size(); ++f) {
        if (partner_of_fresh[f] >= 0) continue;
        const world::MapObject& n = r.map.objects[fresh[f]];
        world::ChangeRecord c;
        c.kind = "added";
        c.id_after = n.id;
        c.class_name = names.at(static_cast<std::size_t>(n.class_id));
        c.after = n.box;
        c.confidence = addedConfidence(builder.evidenceOf(n.id));
        added.push_back(c);
    }
    // Removed objects leave; a moved or re-estimated one lives on in its new box, under its old id.
    std::vector<world::MapObject> kept;
    for (std::size_t k = 0; k < r.map.objects.size(); ++k)
        if (!drop[k]) kept.push_back(r.map.objects[k]);
    r.map.objects = std::move(kept);
    r.changes = std::move(removed);
    r.changes.insert(r.changes.end(), moved.begin(), moved.end());
    r.changes.insert(r.changes.end(), added.begin(), added.end());
    return r;
}

}  // namespace simp::mapping
