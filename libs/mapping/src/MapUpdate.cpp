/// \file MapUpdate.cpp
/// Change detection of a map update (MapUpdate.h).
#include <simp/camera/Occluders.h>
#include <simp/geometry/Box3DIoU.h>
#include <simp/mapping/MapUpdate.h>
#include <simp/mapping/SessionTurn.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

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

/// The boxes' horizontal circumcircles meet (a cheap test before intersectionVolume).
bool mayIntersect(const geometry::Box3D& a, const geometry::Box3D& b) {
    return planarDistance(a, b) <= 0.5 * (a.size.head<2>().norm() + b.size.head<2>().norm());
}

/// `o` has at least `min_fraction` of its volume inside the box of an object of another class of
/// `m` and does not rise above it (drawers in a cabinet, as annotated): whether a detector sees it
/// through that box is not known. An object whose top stands above the other box (a cabinet half
/// in a table) is in plain view above it. Map boxes are upright.
bool isNested(const world::MapObject& o, const world::ObjectMapData& m, double min_fraction) {
    if (min_fraction <= 0 || !(o.box.size.prod() > 0)) return false;
    const double top = o.box.center.z() + 0.5 * o.box.size.z();
    for (const auto& other : m.objects)
        if (other.id != o.id && other.class_id != o.class_id && top <= other.box.center.z() + 0.5 * other.box.size.z() &&
            mayIntersect(o.box, other.box) && geometry::intersectionVolume(o.box, other.box) >= min_fraction * o.box.size.prod())
            return true;
    return false;
}

/// P(X <= k) for X ~ Binomial(n, p): how likely a present object with match rate p is matched
/// in at most k of the n windows that expected it.
double binomialCdf(int k, int n, double p) {
    double sum = 0;
    for (int i = 0; i <= std::min(k, n); ++i)
        sum += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + i * std::log(p) +
                        (n - i) * std::log1p(-p));
    return std::min(1.0, sum);
}

/// Per class, the rate at which this session matched the earlier map's objects it expected and
/// did see at least once (objects never matched may be gone: left out). Shrunk towards the rate
/// over all classes with kPriorWindows pseudo-windows, so a class with one object is not judged
/// on that object alone. The detector's per-class misses (confidence thresholds, occlusion by
/// unmapped things) show in this rate, which the map's geometry cannot predict.
std::vector<double> classMatchRates(const world::ObjectMapData& m0, const ObjectMapBuilder& builder) {
    constexpr double kPriorWindows = 10.0;
    std::vector<double> matched(m0.class_names.size(), 0), expected(m0.class_names.size(), 0);
    double all_m = 0, all_e = 0;
    for (const auto& o : m0.objects) {
        const SessionEvidence e = builder.evidenceOf(o.id);
        if (e.windows_matched == 0) continue;
        matched[static_cast<std::size_t>(o.class_id)] += e.windows_matched;
        expected[static_cast<std::size_t>(o.class_id)] += e.windows_matched + e.windows_missed;
        all_m += e.windows_matched;
        all_e += e.windows_matched + e.windows_missed;
    }
    const double p_all = (all_m + 1.0) / (all_e + 2.0);
    std::vector<double> rate(m0.class_names.size());
    for (std::size_t c = 0; c < rate.size(); ++c)
        rate[c] = std::clamp((matched[c] + kPriorWindows * p_all) / (expected[c] + kPriorWindows), 0.05, 0.99);
    return rate;
}

/// The object may have left: missed in >= update_min_missed_windows windows and matched in fewer
/// than update_max_seen_fraction of its expected windows, or in fewer than
/// update_reassociate_max_seen_fraction and unlikely for a present object (`p_present`).
bool isGone(const SessionEvidence& e, double p_present, const MappingOptions& opt) {
    const int expected = e.windows_matched + e.windows_missed;
    if (e.windows_missed < opt.update_min_missed_windows) return false;
    return e.windows_matched < opt.update_max_seen_fraction * expected ||
           (e.windows_matched < opt.update_reassociate_max_seen_fraction * expected &&
            p_present < opt.update_removal_alpha);
}

/// Leaves out of `fresh` (and the updated map) the new objects that are twins of an object of m0
/// this session matched: within update_twin_max_distance_m (or that object's length), of its class, matched in fewer than
/// update_twin_max_window_ratio times its windows. A twin is the detector's error from some
/// viewpoints (along a desk, across a cabinet row); a real object next to it would be seen from
/// about as many viewpoints as its neighbour.
/// Also leaves out a new object that shares update_same_overlap_fraction of the smaller box's
/// volume (sides grown by update_same_overlap_margin_m) with an object of m0 of its class that
/// stays (not in `gone`): two objects of a class do not interpenetrate, so it is that object seen
/// again, whatever this session expected of it (a floor plan that draws furniture hides an earlier
/// box that the detector still sees).
void dropTwins(const ObjectMapBuilder& builder, MapUpdateResult& r,
               std::vector<std::size_t>& fresh, std::vector<bool>& drop,
               const std::unordered_map<std::int64_t, std::size_t>& row_of,
               const std::unordered_set<std::int64_t>& gone_ids) {
    const MappingOptions& opt = builder.options();
    std::vector<std::size_t> kept;
    for (const std::size_t k : fresh) {
        const world::MapObject& n = r.map.objects[k];
        const int w_new = builder.evidenceOf(n.id).windows_matched;
        const char* decision = nullptr;
        for (const world::MapObject& o : r.map.objects) {
            if (!builder.isGivenObject(o.id) || o.class_id != n.class_id) continue;  // one class table: r.map's
            const int w_old = builder.evidenceOf(o.id).windows_matched;
            // Along a long object (a desk, a sofa) its twins lie up to its length away.
            const double radius = std::max(opt.update_twin_max_distance_m, std::max(o.box.size.x(), o.box.size.y()));
            if (opt.update_twin_max_window_ratio > 0 && w_old > 0 && planarDistance(o.box, n.box) < radius &&
                w_new < opt.update_twin_max_window_ratio * w_old)
                decision = "twin";
            else if (!decision && opt.update_same_overlap_fraction > 0 && !gone_ids.count(o.id) &&
                     sharedVolumeFraction(o.box, n.box, opt.update_same_overlap_margin_m) >= opt.update_same_overlap_fraction)
                decision = "overlaps-earlier";
        }
        if (!decision) {
            kept.push_back(k);
            continue;
        }
        drop[k] = true;
        r.evidence[row_of.at(n.id)].decision = decision;
    }
    fresh = std::move(kept);
}

}  // namespace

double sharedVolumeFraction(const geometry::Box3D& a, const geometry::Box3D& b, double margin_m) {
    geometry::Box3D ga = a, gb = b;
    for (geometry::Box3D* g : {&ga, &gb}) g->size.x() += 2 * margin_m, g->size.y() += 2 * margin_m;
    const double smaller = std::min(ga.size.prod(), gb.size.prod());
    return smaller > 0 && mayIntersect(ga, gb) ? geometry::intersectionVolume(ga, gb) / smaller : 0.0;
}

MapUpdateResult detectChanges(const world::ObjectMapData& m0, const ObjectMapBuilder& builder) {
    const MappingOptions& opt = builder.options();
    MapUpdateResult r;
    r.map = builder.confirmedMap();
    const auto& names = r.map.class_names;  // m0's classes first (setMap), then any appended

    std::unordered_map<std::int64_t, std::size_t> index_in_map;
    for (std::size_t k = 0; k < r.map.objects.size(); ++k) index_in_map[r.map.objects[k].id] = k;

    // Candidates to leave the map (in m0's order: the report's order). Kinds of evidence:
    //  - Missed: expected in >= update_min_missed_windows windows, matched in < update_max_seen_fraction
    //    of them. Removed only when that is unlikely for a present object of its class (binomial
    //    test on the class's match rate this session); moved when a new object takes its place.
    //  - Weak: matched in < update_reassociate_max_seen_fraction, unlikely for a present object:
    //    moved to a new object of its class nearby (its matches were of that one or a neighbour), else kept.
    struct Gone {
        const world::MapObject* before;
        SessionEvidence evidence;
        bool removable = false;  // the misses alone justify a removal
        bool spared_nested = false;  // removable on its misses, but inside another object's box (isNested)
    };
    std::vector<Gone> gone;
    const std::vector<double> rate = classMatchRates(m0, builder);
    std::unordered_map<std::int64_t, std::size_t> row_of;  // id -> its evidence row
    for (const auto& o : m0.objects) {
        const SessionEvidence e = builder.evidenceOf(o.id);
        const int expected = e.windows_matched + e.windows_missed;
        const double p_present = binomialCdf(e.windows_matched, expected, rate[static_cast<std::size_t>(o.class_id)]);
        UpdateEvidence row;
        row.id = o.id;
        row.origin = "earlier";
        row.class_name = m0.class_names.at(static_cast<std::size_t>(o.class_id));
        row.x_m = o.box.center.x(), row.y_m = o.box.center.y();
        row.windows_matched = e.windows_matched, row.windows_missed = e.windows_missed;
        row.windows_missed_behind_new = e.windows_missed_behind_new;
        row.class_rate = rate[static_cast<std::size_t>(o.class_id)];
        row.p_present = p_present;
        row.decision = !index_in_map.count(o.id) ? "merged" : expected == 0 ? "unseen" : "kept";
        row_of[o.id] = r.evidence.size();
        r.evidence.push_back(row);
        if (!index_in_map.count(o.id)) continue;  // merged into another object of m0: still there
        if (expected == 0) ++r.unseen;
        // Inside another object's box, its misses are no evidence of absence (isNested).
        const bool removable_on_misses = e.windows_missed >= opt.update_min_missed_windows &&
                                         e.windows_matched < opt.update_max_seen_fraction * expected &&
                                         p_present < opt.update_removal_alpha;
        const bool spared_nested = removable_on_misses && isNested(o, m0, opt.update_nested_overlap_fraction);
        const bool removable = removable_on_misses && !spared_nested;
        // The windows that expected it only behind a new object of its class (its possible new
        // place, DisplacedCopies.h) count for a move to such an object, never for a removal.
        SessionEvidence behind = e;
        behind.windows_missed += e.windows_missed_behind_new;
        const int expected_behind = behind.windows_matched + behind.windows_missed;
        const double p_behind = binomialCdf(e.windows_matched, expected_behind, row.class_rate);
        if (isGone(e, p_present, opt))
            gone.push_back({&o, e, removable, spared_nested});
        else if (e.windows_missed_behind_new > 0 && isGone(behind, p_behind, opt))
            gone.push_back({&o, behind, false, spared_nested});
    }

    // New confirmed objects of this session. The earlier map already explains the scene, so a new
    // object needs more viewpoints than confirmation: stray twins of a few windows stay tentative.
    std::vector<std::size_t> fresh;
    std::vector<bool> drop(r.map.objects.size(), false);  // objects left out of the updated map
    for (std::size_t k = 0; k < r.map.objects.size(); ++k) {
        const std::int64_t id = r.map.objects[k].id;
        if (builder.isGivenObject(id)) continue;
        const world::MapObject& n = r.map.objects[k];
        const SessionEvidence e = builder.evidenceOf(id);
        UpdateEvidence row;
        row.id = id;
        row.origin = "new";
        row.class_name = names.at(static_cast<std::size_t>(n.class_id));
        row.x_m = n.box.center.x(), row.y_m = n.box.center.y();
        row.windows_matched = e.windows_matched;
        row.windows_missed = e.windows_missed;
        row.decision = "added";
        row_of[id] = r.evidence.size();
        r.evidence.push_back(row);
        if (e.windows_matched >= opt.update_min_new_windows) {
            fresh.push_back(k);
        } else {
            drop[k] = true;
            r.evidence.back().decision = "too-few-windows";
        }
    }
    std::unordered_set<std::int64_t> gone_ids;
    for (const Gone& g : gone) gone_ids.insert(g.before->id);
    dropTwins(builder, r, fresh, drop, row_of, gone_ids);
    // Nearest object of the other origin and the same class, for the evidence file.
    for (UpdateEvidence& a : r.evidence)
        for (const UpdateEvidence& b : r.evidence) {
            if (a.origin == b.origin || a.class_name != b.class_name) continue;
            if (a.origin == "earlier" && b.decision == "merged") continue;
            const double d = std::hypot(a.x_m - b.x_m, a.y_m - b.y_m);
            if (a.nearest_m < 0 || d < a.nearest_m) a.nearest_id = b.id, a.nearest_m = d, a.nearest_windows = b.windows_matched;
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

    std::vector<world::ChangeRecord> removed, moved, added, doors_closed;
    for (std::size_t g = 0; g < gone.size(); ++g) {
        const world::MapObject& b = *gone[g].before;
        if (partner_of_gone[g] < 0 && !gone[g].removable) {  // no new place, too little evidence: kept
            if (gone[g].spared_nested) r.evidence[row_of.at(b.id)].decision = "nested";
            continue;
        }
        world::ChangeRecord c;
        c.id_before = b.id;
        c.class_name = m0.class_names.at(static_cast<std::size_t>(b.class_id));
        c.before = b.box;
        if (partner_of_gone[g] < 0 && c.class_name == camera::kDoorClass) {
            // A building keeps its doors: one expected and not seen is closed (its leaf in the
            // wall's plane, no door to the detector). It stays in the map for the next session.
            r.evidence[row_of.at(b.id)].decision = "door-closed";
            c.kind = "door_closed";
            c.id_after = b.id;
            c.after = b.box;
            c.confidence = removedConfidence(gone[g].evidence);
            doors_closed.push_back(c);
            continue;
        }
        if (const auto it = index_in_map.find(b.id); it != index_in_map.end()) drop[it->second] = true;
        if (partner_of_gone[g] < 0) {
            r.evidence[row_of.at(b.id)].decision = "removed";
            c.kind = "removed";
            c.confidence = removedConfidence(gone[g].evidence);
            removed.push_back(c);
            continue;
        }
        world::MapObject& n = r.map.objects[fresh[static_cast<std::size_t>(partner_of_gone[g])]];
        const double conf = std::min(removedConfidence(gone[g].evidence), addedConfidence(builder.evidenceOf(n.id)));
        const bool displaced = planarDistance(b.box, n.box) >= opt.update_min_move_m;
        r.evidence[row_of.at(n.id)].decision = "move-target";
        r.evidence[row_of.at(b.id)].decision = displaced ? "moved" : "re-estimated";
        n.id = b.id;  // the object keeps its identity across sessions
        if (!displaced) continue;
        c.kind = "moved";
        c.id_after = n.id;
        c.after = n.box;
        c.confidence = conf;
        moved.push_back(c);
    }
    // Turned: still matched where it was, at another heading (SessionTurn.h).
    for (const auto& o : m0.objects) {
        UpdateEvidence& row = r.evidence[row_of.at(o.id)];
        const TurnEstimate t = estimateTurn(o.box, builder.sessionBoxesOf(o.id));
        row.turn_deg = t.turn_rad * 180.0 / M_PI, row.turn_std_error_deg = t.std_error_rad * 180.0 / M_PI;
        row.turn_concentration = t.concentration;
        const auto it = index_in_map.find(o.id);
        if (row.decision != "kept" || it == index_in_map.end() || drop[it->second] ||
            !isTurned(t, opt.update_turn_min_windows, opt.update_turn_min_deg * M_PI / 180.0, opt.update_turn_sigmas))
            continue;
        const auto after = builder.sessionBoxOf(o.id);
        if (!after) continue;
        world::MapObject& n = r.map.objects[it->second];
        n.box = *after;
        row.decision = "turned";
        world::ChangeRecord c;
        c.kind = "moved";
        c.id_before = c.id_after = o.id;
        c.class_name = m0.class_names.at(static_cast<std::size_t>(o.class_id));
        c.before = o.box;
        c.after = n.box;
        c.confidence = addedConfidence(builder.evidenceOf(o.id));  // w / (w + 1) of its matched windows
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
    r.changes.insert(r.changes.end(), doors_closed.begin(), doors_closed.end());
    return r;
}

}  // namespace simp::mapping
