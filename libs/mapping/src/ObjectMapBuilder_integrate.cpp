// ObjectMapBuilder: integration of the local map m^_g into the global map m_g, and the
// visibility (I_active) of the map objects in one camera.
#include <simp/geometry/Box3DIoU.h>
#include <simp/geometry/Hungarian.h>
#include <simp/mapping/AssociationCost.h>
#include <simp/camera/Occluders.h>
#include <simp/mapping/DisplacedCopies.h>
#include <simp/mapping/ObjectMapBuilder.h>

#include <algorithm>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace simp::mapping {
namespace {
constexpr double kNotDuplicate = 3.0;   ///< duplicateCost() of a pair that is not one object
}  // namespace

void ObjectMapBuilder::updateGroups() {
    // Union-find over intersecting boxes (3D IoU > 0). Distinct objects cannot interpenetrate:
    // intersecting map boxes are estimates of one object (duplicates) or nested objects, and a
    // duplicate hidden behind its twin would never become active, never be skipped, never purged.
    const std::size_t n = m_g.objects.size();
    std::vector<int> parent(n);
    for (std::size_t k = 0; k < n; ++k) parent[k] = static_cast<int>(k);
    const auto find = [&](int k) {
        while (parent[static_cast<std::size_t>(k)] != k) k = parent[static_cast<std::size_t>(k)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])];
        return k;
    };
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const auto& a = m_g.objects[i].box;
            const auto& b = m_g.objects[j].box;
            if ((a.center - b.center).norm() > 0.5 * (a.size.norm() + b.size.norm())) continue;
            if (geometry::iou3D(a, b) <= 0) continue;
            parent[static_cast<std::size_t>(find(static_cast<int>(i)))] = find(static_cast<int>(j));
        }
    m_groups.resize(n);
    for (std::size_t k = 0; k < n; ++k) m_groups[k] = find(static_cast<int>(k));
    m_groups_valid = true;
}

void ObjectMapBuilder::visibility(const camera::PinholeCamera& camera, int current_room, std::vector<bool>& active,
                                  std::vector<bool>& candidate, std::vector<bool>* active_behind_new) {
    const std::size_t n = m_g.objects.size();
    active.assign(n, false);
    candidate.assign(n, false);
    if (active_behind_new != nullptr) active_behind_new->assign(n, false);
    if (n == 0) return;
    m_boxes_scratch.resize(n);
    m_occludes_scratch.resize(n);
    const std::vector<char> class_occludes = camera::occludingClasses(m_g.class_names);
    for (std::size_t k = 0; k < n; ++k) {
        m_boxes_scratch[k] = m_g.objects[k].box;
        m_occludes_scratch[k] = camera::occlusionOfClassId(class_occludes, m_g.objects[k].class_id);
    }
    camera::ZBufferParams prm;
    prm.downscale = m_options.zbuffer_downscale;
    prm.near_plane_m = m_options.near_plane_m;
    prm.wall_depth_margin_m = m_options.wall_depth_margin_m;
    prm.max_distance_m = m_options.wall_cast_max_m;
    prm.occludes = &m_occludes_scratch;
    if (!m_options.intersecting_boxes_occlude) {
        if (!m_groups_valid || m_groups.size() != n) updateGroups();
        prm.group = &m_groups;
    }
    if (m_earlier_session && m_options.update_unhide_max_distance_m > 0) {
        // A new object of this session may be an earlier object moved a short way: where it stands
        // between the camera and the old place, it must not hide the old place, or the old object
        // is never expected there, never missed, and the move is reported as an addition.
        if (!m_unhidden_valid || m_unhidden_by.size() != n) {
            m_unhidden_by = displacedCopyCandidates(m_g, m_first_built_id, m_options.update_unhide_max_distance_m);
            m_unhidden_valid = true;
        }
        prm.unhidden_by = &m_unhidden_by;
    }
    m_renderer.render(camera, m_boxes_scratch, &m_walls, prm, m_views_scratch);
    for (std::size_t k = 0; k < n; ++k) {
        const world::MapObject& o = m_g.objects[k];
        // Room policy: only objects of the robot's current room are updated (room 0 = unknown: any).
        if (current_room != 0 && o.room_id != 0 && o.room_id != current_room) continue;
        const camera::BoxView& v = m_views_scratch[k];
        // Candidate: in the frustum and not completely behind walls (other boxes may hide it:
        // nested boxes such as a sink in a counter are still detected).
        if (v.unwalled_px <= 0) continue;
        candidate[k] = true;
        const ClassFilter& f = m_options.filterOf(m_g.class_names[o.class_id]);
        const bool in_range = f.max_range_m > 0 && v.distance_m >= f.min_range_m && v.distance_m <= f.max_range_m;
        active[k] = in_range && v.truncated_fraction <= m_options.truncation_threshold &&
                    v.occludedFraction() <= m_options.max_occluded_fraction;
        if (active[k] && active_behind_new != nullptr && v.occludedFractionByAll() > m_options.max_occluded_fraction)
            (*active_behind_new)[k] = true;
    }
}

double ObjectMapBuilder::duplicateCost(const geometry::Box3D& o1, const model::ObjectDistribution& p_o1, int class_id,
                                       const geometry::Box3D& o2) const {
    const double dist = (o1.center - o2.center).head<2>().norm();
    const double radius = m_options.duplicateCenterRadiusOf(m_g.class_names[class_id]);
    if (m_options.duplicate_min_overlap > 0 && dist < 0.5 * (o1.size.norm() + o2.size.norm())) {
        const double smaller = std::min(o1.size.prod(), o2.size.prod());
        if (smaller > 0 && geometry::intersectionVolume(o1, o2) > m_options.duplicate_min_overlap * smaller)
            return associationCost(o1, p_o1, o2);
    }
    if (dist >= std::max(m_options.duplicate_max_distance_m, radius)) return kNotDuplicate;
    const double c = associationCost(o1, p_o1, o2);
    if (dist < radius) return c;
    return dist < m_options.duplicate_max_distance_m && c < m_options.duplicate_tau_cost ? c : kNotDuplicate;
}

void ObjectMapBuilder::mergeLocalDuplicates() {
    // Greedy: merge the lowest-cost duplicate pair (duplicateCost) until none is left
    // (o1 = the object with more detections, Eq. costfunc).
    for (;;) {
        double best = kNotDuplicate;
        std::size_t bi = 0, bj = 0;
        for (std::size_t i = 0; i < m_local.size(); ++i)
            for (std::size_t j = i + 1; j < m_local.size(); ++j) {
                if (m_local[i].class_id != m_local[j].class_id || detectedApart(sharedFrames(m_local[i].frames, m_local[j].frames))) continue;
                const bool i_ref = m_local[i].n_match >= m_local[j].n_match;
                const LocalObject& a = i_ref ? m_local[i] : m_local[j];
                const LocalObject& b = i_ref ? m_local[j] : m_local[i];
                const double c = duplicateCost(a.box, classDistribution(a.class_id, a.box), a.class_id, b.box);
                if (c < best) best = c, bi = i, bj = j;
            }
        if (best >= kNotDuplicate) return;
        LocalObject& keep = m_local[bi].n_match >= m_local[bj].n_match ? m_local[bi] : m_local[bj];
        const LocalObject& drop = &keep == &m_local[bi] ? m_local[bj] : m_local[bi];
        keep.box = mergeBoxes(keep.box, keep.n_match, drop.box, drop.n_match);
        keep.n_match += drop.n_match;
        keep.may_start = keep.may_start || drop.may_start;
        keep.frames = unionOfFrames(keep.frames, drop.frames);
        m_local.erase(m_local.begin() + static_cast<std::ptrdiff_t>(&drop == &m_local[bi] ? bi : bj));
    }
}

std::size_t ObjectMapBuilder::mergeMapDuplicates(const std::set<std::int64_t>& ids) {
    std::vector<std::size_t> idx;
    for (std::size_t k = 0; k < m_g.objects.size(); ++k)
        if (ids.count(m_g.objects[k].id)) idx.push_back(k);
    std::vector<bool> removed(m_g.objects.size(), false);
    std::size_t n_removed = 0;
    for (;;) {
        double best = kNotDuplicate;
        std::size_t keep = 0, drop = 0;
        for (std::size_t a = 0; a < idx.size(); ++a)
            for (std::size_t b = a + 1; b < idx.size(); ++b) {
                const std::size_t i = idx[a], j = idx[b];
                if (removed[i] || removed[j] || m_g.objects[i].class_id != m_g.objects[j].class_id) continue;
                // A class mapped from two rooms (a door): its copies in different rooms are one
                // object within the class's cross-room radius, whatever the duplicate rules say.
                const world::MapObject &oi = m_g.objects[i], &oj = m_g.objects[j];
                const double cross_radius = m_options.crossRoomMergeRadiusOf(m_g.class_names[oi.class_id]);
                const bool cross_room = cross_radius > 0 && oi.room_id != 0 && oj.room_id != 0 && oi.room_id != oj.room_id;
                std::size_t r = oi.n_match >= oj.n_match ? i : j;
                if (m_earlier_session) {
                    const bool gi = isGivenObject(oi.id), gj = isGivenObject(oj.id);
                    // An earlier object this session has not matched may have been moved: the new
                    // object near it is its candidate new place, not its twin (MapUpdate.h). Not so
                    // for a copy seen from the other room: the earlier object was out of that room.
                    if (!cross_room && gi != gj && evidenceOf(m_g.objects[gi ? i : j].id).windows_matched == 0) continue;
                    if (gi != gj) r = gi ? i : j;  // the earlier object keeps its id
                }
                if (detectedApart(m_codetections.count(oi.id, oj.id))) continue;
                const std::size_t o = r == i ? j : i;
                const world::MapObject& ref = m_g.objects[r];
                const world::MapObject& other = m_g.objects[o];
                double c = 0;
                if (cross_room) {
                    if ((ref.box.center - other.box.center).head<2>().norm() >= cross_radius) continue;
                    c = associationCost(ref.box, objectDistribution(ref, ref.box), other.box);
                } else {
                    c = duplicateCost(ref.box, objectDistribution(ref, ref.box), ref.class_id, other.box);
                }
                if (c < best) best = c, keep = r, drop = o;
            }
        if (best >= kNotDuplicate) break;
        world::MapObject& k = m_g.objects[keep];
        const world::MapObject& d = m_g.objects[drop];
        setEstimate(k, mergeBoxes(estimateOf(k), k.n_match, estimateOf(d), d.n_match));
        m_windows_matched[k.id] += m_windows_matched[d.id];
        if (auto windows = m_session_boxes.extract(d.id)) {
            auto& into = m_session_boxes[k.id];
            into.insert(into.end(), windows.mapped().begin(), windows.mapped().end());
        }
        m_windows_missed[k.id] += m_windows_missed[d.id];
        m_windows_missed_behind_new[k.id] += m_windows_missed_behind_new[d.id];
        m_windows_active[k.id] += m_windows_active[d.id];
        m_codetections.absorb(k.id, d.id);
        forget(d.id);
        k.n_match += d.n_match;
        k.n_skip += d.n_skip;
        k.room_id = roomOf(k.box.center.x(), k.box.center.y());
        removed[drop] = true;
        ++n_removed;
    }
    if (n_removed > 0) {
        std::size_t w = 0;
        for (std::size_t k = 0; k < m_g.objects.size(); ++k)
            if (!removed[k]) m_g.objects[w++] = m_g.objects[k];
        m_g.objects.resize(w);
    }
    return n_removed;
}

bool ObjectMapBuilder::planDrawsOnlyWalls() const {
    return !m_walls.empty() && m_walls.enclosedUnknownArea_m2() <= m_options.wall_align_max_enclosed_unknown_m2;
}

bool ObjectMapBuilder::wallAlignmentActive() const {
    if (m_walls.empty() || m_options.wall_align == WallAlignMode::Off) return false;
    return m_options.wall_align == WallAlignMode::On || planDrawsOnlyWalls();
}

geometry::Box3D ObjectMapBuilder::alignedBox(int class_id, const geometry::Box3D& box) const {
    if (!wallAlignmentActive() || class_id < 0 || static_cast<std::size_t>(class_id) >= m_g.class_names.size())
        return box;
    const auto params = m_options.wallAlignmentOf(m_g.class_names[static_cast<std::size_t>(class_id)]);
    return params ? alignToWalls(box, m_walls, *params) : box;
}

geometry::Box3D ObjectMapBuilder::estimateOf(const world::MapObject& o) const {
    const auto it = m_estimates.find(o.id);
    if (it != m_estimates.end()) return it->second;
    geometry::Box3D b = o.box;
    // An object of a given map (setMap: a loaded or ground-truth map, a deserialized CObjectMap)
    // is where the object is; its detections are expected R_o mu away from it.
    if (m_options.remove_class_bias) b.center.head<2>() += classBiasOf(o.class_id, b);
    return b;
}

void ObjectMapBuilder::setEstimate(world::MapObject& o, const geometry::Box3D& estimate) {
    if (!m_options.remove_class_bias) {
        o.box = estimate;  // aligned by alignToFloorPlan after the integration
        return;
    }
    m_estimates[o.id] = estimate;
    o.box = shownBox(o.class_id, estimate);
}

void ObjectMapBuilder::forget(std::int64_t id) {
    m_estimates.erase(id);
    m_windows_matched.erase(id);
    m_windows_missed.erase(id);
    m_windows_missed_behind_new.erase(id);
    m_windows_active.erase(id);
    m_session_boxes.erase(id);
    m_codetections.forget(id);
}

bool ObjectMapBuilder::detectedApart(int shared_frames) const {
    return m_options.distinct_codetected_frames > 0 && shared_frames >= m_options.distinct_codetected_frames;
}

geometry::Box3D ObjectMapBuilder::shownBox(int class_id, const geometry::Box3D& estimate) const {
    geometry::Box3D b = estimate;
    b.center.head<2>() -= classBiasOf(class_id, b);
    return alignedBox(class_id, b);
}

void ObjectMapBuilder::alignToFloorPlan(world::MapObject& o) const {
    o.box = alignedBox(o.class_id, o.box);
    o.room_id = roomOf(o.box.center.x(), o.box.center.y());
}

void ObjectMapBuilder::flush() {
    m_window_start.reset();
    const double window_steps = static_cast<double>(m_window_steps);
    m_window_steps = 0;
    if (m_local.empty() && m_window_active.empty()) {
        m_window_weak.clear();
        m_window_candidates.clear();
        m_window_active_behind_new.clear();
        return;
    }
    ++m_stats.integrations;
    if (m_options.merge_duplicates) mergeLocalDuplicates();
    // Floor-plan prior on the local map too, so that association compares like with like
    // (aligned with aligned; otherwise means of detections with means of detections).
    if (!m_options.remove_class_bias)
        for (auto& l : m_local) l.box = alignedBox(l.class_id, l.box);

    std::unordered_map<std::int64_t, std::size_t> index_of;
    for (std::size_t k = 0; k < m_g.objects.size(); ++k) index_of[m_g.objects[k].id] = k;

    // Local objects seen often enough, and the association candidates of the map.
    std::vector<const LocalObject*> locals;
    for (const auto& l : m_local)
        if (l.n_match >= m_options.min_local_detections && l.n_match >= m_options.min_local_support * window_steps)
            locals.push_back(&l);
    std::vector<std::size_t> cands;
    for (const std::int64_t id : m_window_candidates)
        if (const auto it = index_of.find(id); it != index_of.end()) cands.push_back(it->second);

    // Hungarian association of local objects to visible map objects (Eq. costfunc, o1 = map object).
    std::vector<int> assignment(locals.size(), -1);
    Eigen::MatrixXd cost(locals.size(), cands.size());
    if (!locals.empty() && !cands.empty()) {
        for (std::size_t r = 0; r < locals.size(); ++r)
            for (std::size_t c = 0; c < cands.size(); ++c) {
                const world::MapObject& o = m_g.objects[cands[c]];
                if (o.class_id != locals[r]->class_id) {
                    cost(r, c) = kForbiddenCost;
                    continue;
                }
                const geometry::Box3D estimate = estimateOf(o);
                cost(r, c) = associationCost(estimate, objectDistribution(o, estimate), locals[r]->box);
            }
        assignment = geometry::solveAssignment(cost);
    }

    std::unordered_set<std::int64_t> matched;
    std::vector<world::MapObject> added;
    std::vector<std::int64_t> id_of_local(locals.size(), -1);  ///< the map object each local object became
    for (std::size_t r = 0; r < locals.size(); ++r) {
        const LocalObject& l = *locals[r];
        const int c = assignment[r];
        if (c >= 0 && cost(r, c) < m_options.tau_cost) {
            // Merge: weighted centre, dimensions and SVD-projected rotation; n_match summed.
            world::MapObject& o = m_g.objects[cands[c]];
            setEstimate(o, mergeBoxes(estimateOf(o), o.n_match, l.box, l.n_match));
            o.n_match += l.n_match;
            o.room_id = roomOf(o.box.center.x(), o.box.center.y());
            matched.insert(o.id);
            id_of_local[r] = o.id;
            ++m_stats.merged;
        } else if (l.may_start) {
            world::MapObject o;
            o.id = m_next_id++;
            o.class_id = l.class_id;
            o.n_match = l.n_match;
            o.n_skip = 0;
            setEstimate(o, l.box);
            o.room_id = roomOf(o.box.center.x(), o.box.center.y());
            id_of_local[r] = o.id;
            added.push_back(o);
            ++m_stats.added;
        }
        // The window's box of the object it matched or made, new objects too: merged into an
        // earlier object later, their windows carry its heading this session (SessionTurn.h).
        if (m_earlier_session && id_of_local[r] >= 0) m_session_boxes[id_of_local[r]].push_back({l.box, double(l.n_match)});
    }
    for (std::size_t r = 0; r < locals.size(); ++r)
        for (std::size_t q = r + 1; q < locals.size(); ++q)
            if (locals[r]->class_id == locals[q]->class_id && id_of_local[r] >= 0 && id_of_local[q] >= 0)
                m_codetections.add(id_of_local[r], id_of_local[q], sharedFrames(locals[r]->frames, locals[q]->frames));
    // n_skip for active map objects that no prediction was associated with, unless a detection of
    // the class that the map's evidence left out (under the class's confidence; a local object seen
    // in too few frames) lies at the object's place, better there than at any other active object
    // of its class (skip_needs_no_detection): a weakly detected object is not absent, while a twin
    // next to a well-seen object still collects its misses.
    std::unordered_set<std::int64_t> detected;
    if (m_options.skip_needs_no_detection) {
        std::vector<const LocalObject*> left_out;
        for (const auto& l : m_local)
            if (std::find(locals.begin(), locals.end(), &l) == locals.end()) left_out.push_back(&l);
        for (const auto& w : m_window_weak) left_out.push_back(&w);
        for (const LocalObject* l : left_out) {
            std::int64_t best = -1;
            double best_cost = m_options.tau_cost;
            for (const std::int64_t id : m_window_active) {
                const auto it = index_of.find(id);
                if (it == index_of.end() || m_g.objects[it->second].class_id != l->class_id) continue;
                const world::MapObject& o = m_g.objects[it->second];
                const geometry::Box3D estimate = estimateOf(o);
                const double c = associationCost(estimate, objectDistribution(o, estimate), l->box);
                if (c < best_cost) best_cost = c, best = id;
            }
            if (best >= 0) detected.insert(best);
        }
    }
    for (const std::int64_t id : m_window_active) {
        ++m_windows_active[id];
        if (!matched.count(id))
            if (const auto it = index_of.find(id); it != index_of.end()) {
                if (!detected.count(id)) ++m_g.objects[it->second].n_skip;
                ++m_windows_missed[id];
            }
    }
    // Expected only behind a possible displaced copy of itself: evidence of a move, not of a
    // removal (MapUpdate.h), and no n_skip (the new object may be a twin in front of it).
    for (const std::int64_t id : m_window_active_behind_new)
        if (!matched.count(id) && !m_window_active.count(id) && index_of.count(id)) ++m_windows_missed_behind_new[id];

    // Purge when n_match / n_skip < tau_purge. When updating an earlier map, its objects stay:
    // the update rule decides at the end on this session's evidence (MapUpdate.h); the purge
    // rule, on their n_skip from earlier sessions, dropped objects that were there (classes
    // detected in a fraction of the windows, e.g. potted plants at confidence 0.95).
    const auto purge = [&](const world::MapObject& o) {
        if (m_earlier_session && isGivenObject(o.id)) return false;
        return o.n_skip > 0 && static_cast<double>(o.n_match) / o.n_skip < m_options.tau_purge;
    };
    const std::size_t before = m_g.objects.size();
    for (const auto& o : m_g.objects)
        if (purge(o)) forget(o.id);
    m_g.objects.erase(std::remove_if(m_g.objects.begin(), m_g.objects.end(), purge), m_g.objects.end());
    m_stats.purged += before - m_g.objects.size();
    m_g.objects.insert(m_g.objects.end(), added.begin(), added.end());
    for (const auto& o : added) matched.insert(o.id);
    for (const std::int64_t id : matched) ++m_windows_matched[id];
    // Floor-plan prior: objects updated in this window stand flush against their wall (with
    // remove_class_bias, setEstimate already gave them their aligned map box).
    if (!m_options.remove_class_bias)
        for (auto& o : m_g.objects)
            if (matched.count(o.id)) alignToFloorPlan(o);
    if (m_options.merge_duplicates) {
        // As the authors' mergeObjects: every object of the robot's room (all objects without a
        // room filter), not only those seen now, so twins left by earlier windows still merge.
        std::set<std::int64_t> seen(m_window_candidates.begin(), m_window_candidates.end());
        for (const auto& o : added) seen.insert(o.id);
        const bool all_rooms = m_options.room_policy == RoomUpdatePolicy::All;
        for (const auto& o : m_g.objects)
            if (all_rooms || (m_window_room != 0 && o.room_id == m_window_room) ||
                m_options.crossRoomMergeRadiusOf(m_g.class_names[o.class_id]) > 0)
                seen.insert(o.id);
        m_stats.duplicates_merged += mergeMapDuplicates(seen);
    }

    m_local.clear();
    m_window_weak.clear();
    m_window_active.clear();
    m_window_active_behind_new.clear();
    m_window_candidates.clear();
    m_groups_valid = false;
    m_unhidden_valid = false;
}

}  // namespace simp::mapping
