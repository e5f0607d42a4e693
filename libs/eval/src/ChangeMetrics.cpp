/// \file ChangeMetrics.cpp
/// scoreChanges (ChangeMetrics.h).
#include <simp/eval/ChangeMetrics.h>
#include <simp/eval/MapMetrics.h>
#include <simp/geometry/Hungarian.h>
#include <simp/io/Tum.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>

namespace simp::eval {
namespace {

using world::ChangeRecord;

double planar(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).head<2>().norm(); }

/// One-to-one pairs (i, j) of a and b with cost(i, j) <= gate, minimum total cost (Hungarian).
template <class Cost>
std::vector<std::pair<std::size_t, std::size_t>> gatedPairs(std::size_t na, std::size_t nb, Cost cost, double gate) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    if (na == 0 || nb == 0) return out;
    const double kOut = 1e3 * (gate + 1);  // inadmissible: never chosen over an admissible pair
    Eigen::MatrixXd c(static_cast<Eigen::Index>(na), static_cast<Eigen::Index>(nb));
    for (std::size_t i = 0; i < na; ++i)
        for (std::size_t j = 0; j < nb; ++j) {
            const double v = cost(i, j);
            c(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = v <= gate ? v : kOut;
        }
    const std::vector<int> a = geometry::solveAssignment(c);
    for (std::size_t i = 0; i < na; ++i)
        if (a[i] >= 0 && c(static_cast<Eigen::Index>(i), a[i]) <= gate) out.emplace_back(i, static_cast<std::size_t>(a[i]));
    return out;
}

/// The kinds of change with their scores, in the order of the command-line contract (removed,
/// moved, added), then door_closed: one list for scoring, JSON and table.
template <class Scores>
auto kindsOf(Scores& s) {
    using Score = decltype(&s.removed);  // const or not, as `s`
    return std::array<std::pair<const char*, Score>, 4>{
        {{"removed", &s.removed}, {"moved", &s.moved}, {"added", &s.added}, {"door_closed", &s.doors_closed}}};
}

void finish(KindScore& k) {
    k.precision = k.n_reported ? static_cast<double>(k.n_correct) / static_cast<double>(k.n_reported) : 1.0;
    k.recall = k.n_true ? static_cast<double>(k.n_correct) / static_cast<double>(k.n_true) : 1.0;
}

struct Placed {
    std::string class_name;
    Eigen::Vector3d center;
};

}  // namespace

std::set<int> visitedRooms(const world::RoomMap& rooms, const std::string& tum_path) {
    std::set<int> out;
    for (const auto& p : io::readTum(tum_path))
        if (const int r = rooms.roomAt(p.pose.x, p.pose.y)) out.insert(r);
    return out;
}

bool sameObjectIds(const world::ObjectMapData& world, const world::ObjectMapData& map) {
    if (world.objects.size() != map.objects.size()) return false;
    std::map<std::int64_t, const world::MapObject*> by_id;
    for (const auto& o : world.objects) by_id[o.id] = &o;
    const auto name = [](const world::ObjectMapData& m, const world::MapObject& o) {
        return o.class_id >= 0 && static_cast<std::size_t>(o.class_id) < m.class_names.size() ? m.class_names[static_cast<std::size_t>(o.class_id)] : std::string();
    };
    for (const auto& o : map.objects) {
        const auto it = by_id.find(o.id);
        if (it == by_id.end() || name(world, *it->second) != name(map, o) ||
            (it->second->box.center - o.box.center).norm() > 1e-3)
            return false;
    }
    return true;
}

ChangeScores scoreChanges(const std::vector<ChangeRecord>& truth_in, const std::vector<ChangeRecord>& report_in,
                          const ChangeMatchParams& p, const BeforeMaps& before) {
    if (!(p.max_center_dist_m > 0)) throw std::invalid_argument("scoreChanges: max_center_dist_m must be > 0");
    const std::set<std::string> classes(p.classes.begin(), p.classes.end());
    const auto visited = [&](const std::optional<geometry::Box3D>& b) {
        return b && p.visited_rooms.count(world::roomOfBox(*p.rooms, *b));
    };
    const auto scored = [&](const ChangeRecord& c) {
        return (c.kind == "removed" || c.kind == "moved" || c.kind == "added" || c.kind == "door_closed") &&
               (classes.empty() || classes.count(c.class_name)) && (!p.rooms || visited(c.before) || visited(c.after));
    };
    std::vector<ChangeRecord> truth, report;
    for (const auto& c : truth_in)
        if (scored(c)) truth.push_back(c);
    for (const auto& c : report_in)
        if (scored(c)) report.push_back(c);

    ChangeScores s;
    std::vector<Placed> missed_by_map;  // W objects still in place that the before map lacks
    if (before.world && before.map) {
        // W's ids -> the map's ids: the map metrics' matching (simp-eval map: footprints must
        // overlap, centres within the gate), so an object of the map that is nowhere near a real
        // one is a ghost here as it is a false object there.
        const auto& W = *before.world;
        const auto& M = *before.map;
        MapMatchParams mp;
        mp.max_center_dist_m = p.max_center_dist_m;
        mp.classes = p.classes;
        std::map<std::int64_t, std::int64_t> w_to_m;
        std::set<std::int64_t> m_with_w;
        if (!W.objects.empty() || !M.objects.empty())
            for (const ObjectMatch& m : evaluateMap(W, M, mp).matches) {
                w_to_m[W.objects.at(m.gt_index).id] = M.objects.at(m.pred_index).id;
                m_with_w.insert(M.objects.at(m.pred_index).id);
            }
        std::set<std::int64_t> changed_w;
        std::vector<ChangeRecord> t2;
        for (auto c : truth) {
            if (c.id_before) changed_w.insert(*c.id_before);
            if (c.kind == "added") {
                t2.push_back(c);
                continue;
            }
            const auto it = w_to_m.find(*c.id_before);
            if (it != w_to_m.end()) {
                c.id_before = it->second;
                t2.push_back(c);
            } else if (c.kind == "moved") {  // new to the map: an addition
                c.kind = "added";
                c.id_before.reset();
                c.before.reset();
                t2.push_back(c);
            } else {
                ++s.truth_not_in_map;
            }
        }
        truth = std::move(t2);
        for (const auto& o : W.objects)
            if (!w_to_m.count(o.id) && !changed_w.count(o.id))
                missed_by_map.push_back({W.class_names.at(static_cast<std::size_t>(o.class_id)), o.box.center});
        std::vector<ChangeRecord> r2;
        for (const auto& c : report) {
            if (c.kind != "added" && c.id_before && !m_with_w.count(*c.id_before)) {
                ++s.ignored_reports;  // a ghost of the before map
                continue;
            }
            r2.push_back(c);
        }
        report = std::move(r2);
    }

    // removed, moved, door_closed: by id_before.
    for (const auto& [kind, score] : kindsOf(s)) {
        if (score == &s.added) continue;  // matched by class and place below
        KindScore& k = *score;
        std::set<std::int64_t> true_ids;
        for (const auto& c : truth)
            if (c.kind == kind) true_ids.insert(*c.id_before);
        k.n_true = true_ids.size();
        std::set<std::int64_t> found;
        for (const auto& c : report)
            if (c.kind == kind) {
                ++k.n_reported;
                if (c.id_before && true_ids.count(*c.id_before) && found.insert(*c.id_before).second) ++k.n_correct;
            }
    }

    // added: per class, Hungarian on the after centres.
    std::vector<const ChangeRecord*> ta, ra;
    for (const auto& c : truth)
        if (c.kind == "added") ta.push_back(&c);
    for (const auto& c : report)
        if (c.kind == "added") ra.push_back(&c);
    std::vector<bool> ra_matched(ra.size(), false);
    const auto cost = [&](const ChangeRecord& t, const ChangeRecord& r) {
        return t.class_name == r.class_name ? planar(t.after->center, r.after->center) : 1e9;
    };
    const auto pairs = gatedPairs(
        ta.size(), ra.size(), [&](std::size_t i, std::size_t j) { return cost(*ta[i], *ra[j]); }, p.max_center_dist_m);
    for (const auto& pr : pairs) ra_matched[pr.second] = true;
    s.added.n_true = ta.size();
    s.added.n_correct = pairs.size();
    s.added.n_reported = ra.size();
    // BeforeMaps: an unmatched addition of an object the before map had missed is no error.
    if (!missed_by_map.empty()) {
        std::vector<std::size_t> open;
        for (std::size_t j = 0; j < ra.size(); ++j)
            if (!ra_matched[j]) open.push_back(j);
        const auto extra = gatedPairs(
            open.size(), missed_by_map.size(),
            [&](std::size_t a, std::size_t b) {
                const ChangeRecord& r = *ra[open[a]];
                return r.class_name == missed_by_map[b].class_name ? planar(r.after->center, missed_by_map[b].center) : 1e9;
            },
            p.max_center_dist_m);
        s.added.n_reported -= extra.size();
        s.ignored_reports += extra.size();
    }
    for (const auto& [kind, score] : kindsOf(s)) finish(*score);
    return s;
}

nlohmann::ordered_json toJson(const ChangeScores& s) {
    // Key order as the command-line contract writes it (removed, moved, added; precision first);
    // door_closed after them.
    const auto k = [](const KindScore& v) {
        return nlohmann::ordered_json{{"precision", v.precision}, {"recall", v.recall}, {"n_true", v.n_true},
                              {"n_reported", v.n_reported}, {"n_correct", v.n_correct}};
    };
    nlohmann::ordered_json j;
    for (const auto& [kind, score] : kindsOf(s)) j[kind] = k(*score);
    return j;
}

std::string changeMarkdownTable(const ChangeScores& s) {
    std::string out = "| kind | true | reported | correct | precision | recall |\n|---|---|---|---|---|---|\n";
    char line[200];
    for (const auto& [name, k] : kindsOf(s)) {
        std::snprintf(line, sizeof line, "| %s | %zu | %zu | %zu | %.3f | %.3f |\n", name, k->n_true, k->n_reported,
                      k->n_correct, k->precision, k->recall);
        out += line;
    }
    return out;
}

}  // namespace simp::eval
