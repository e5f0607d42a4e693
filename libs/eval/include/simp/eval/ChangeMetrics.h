#pragma once
/// \file ChangeMetrics.h
/// Precision and recall of a change report (simp-map --update's M/changes.json) against the true
/// changes (the simulator's Q/changes.json), per kind of change (simp-eval changes,
/// doc/evaluation.md "Change detection").
///
/// Definitions:
///  - kinds scored: removed, moved, added (door_closed entries are ignored);
///  - removed, moved: a reported entry is correct when a true entry of the same kind has its
///    id_before (ids of the "before" map);
///  - added: reported and true entries of one class are matched one-to-one (Hungarian method on
///    the planar distance of the "after" centres), a pair counts when the distance is <=
///    max_center_dist_m (default 1.0 m, the map metrics' gate: an added box is as good as a mapped one);
///  - precision = correct / reported (1 when nothing is reported), recall = correct / true
///    (1 when nothing changed).
/// With a built "before" map (ids of its own, not the world's), BeforeMaps translates the truth
/// (ChangeMetrics.cpp, doc/evaluation.md): W's objects are matched to the map's per class
/// (the map metrics' matching, MapMetrics.h); a true removal of an object the map never had is
/// dropped, a true move of one becomes an addition; reports about map objects without a W
/// counterpart (ghosts) and additions of W objects the map had missed (still in place) are neither
/// right nor wrong (counted in ignored_reports).

#include <simp/world/ChangesFile.h>
#include <simp/world/ObjectMapData.h>
#include <simp/world/World.h>

#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

namespace simp::eval {

struct ChangeMatchParams {
    double max_center_dist_m = 1.0;    ///< gate of added entries and of W <-> before-map matching (m)
    std::vector<std::string> classes;  ///< when not empty, only changes of these classes are scored
    /// When set: only changes in the rooms `visited_rooms` (room of the before or after box in
    /// `rooms`) are scored: a session that never entered a room cannot see what changed there.
    const world::RoomMap* rooms = nullptr;
    std::set<int> visited_rooms;
};

/// Room ids of `rooms` that the trajectory `tum_path` passes through (room 0 left out).
std::set<int> visitedRooms(const world::RoomMap& rooms, const std::string& tum_path);

struct KindScore {
    std::size_t n_true = 0, n_reported = 0, n_correct = 0;
    double precision = 1, recall = 1;
};

struct ChangeScores {
    KindScore removed, moved, added;
    KindScore doors_closed;  ///< door_closed entries, matched by id_before as removals are
    std::size_t ignored_reports = 0;   ///< BeforeMaps: reports about ghosts / objects the map had missed
    std::size_t truth_not_in_map = 0;  ///< BeforeMaps: true removals of objects the map never had
};

/// The "before" world of the truth and the "before" map of the report, when their ids differ.
struct BeforeMaps {
    const world::ObjectMapData* world = nullptr;  ///< W: the truth's ids
    const world::ObjectMapData* map = nullptr;    ///< M0: the report's ids
};

/// True when `map` holds `world`'s objects under the same ids (as many, and per id the same class
/// name and a centre within 1 mm): a report on `map` then speaks in the truth's ids (e.g. M0 = W).
bool sameObjectIds(const world::ObjectMapData& world, const world::ObjectMapData& map);

/// Scores `report` against `truth`. \throw std::invalid_argument when params are out of range.
ChangeScores scoreChanges(const std::vector<world::ChangeRecord>& truth, const std::vector<world::ChangeRecord>& report,
                          const ChangeMatchParams& params = {}, const BeforeMaps& before = {});

/// `{"removed": {"precision": p, "recall": r, "n_true": .., "n_reported": .., "n_correct": ..}, "moved": ..., "added": ...,
/// "door_closed": ...}`
nlohmann::ordered_json toJson(const ChangeScores& s);
/// A Markdown table, one row per kind.
std::string changeMarkdownTable(const ChangeScores& s);

}  // namespace simp::eval
