#pragma once
/// \file MapUpdate.h
/// Map update across sessions (simp-map --update, doc/mapping.md "Map update across sessions"):
/// after an ObjectMapBuilder was given the map of an earlier session (setMap(m0, true)) and this
/// session's detections, decides what changed and writes the updated map.
///
/// Rule (MappingOptions update_*). Only this session's evidence counts (ObjectMapBuilder keeps
/// m0's objects through the session instead of purging them on their n_skip), so an object with a
/// long history goes as readily as a new one:
///  - removed: an object of m0 that this session expected to see (I_active: in view, in range,
///    not occluded, the builder's own visibility) in >= update_min_missed_windows integration
///    windows without a match, matched in < update_max_seen_fraction of them, and for which so
///    few matches are unlikely if it were there: P(<= matched | expected windows, p) <
///    update_removal_alpha, p the class's match rate this session (classes detected in a fraction of
///    the windows, e.g. potted plants at confidence 0.95, need more misses);
///  - moved: a new (confirmed) object of the same class within update_move_max_distance_m (closest
///    pairs first) takes the place of an m0 object that was missed as above (the binomial test not
///    needed: the new object is the second half of the evidence), or matched in fewer than
///    update_reassociate_max_seen_fraction of its windows and unlikely for a present object
///    (detections of its new place or of a neighbour, along a wall, still reach it). It keeps its
///    m0 id. A pair closer
///    than update_min_move_m is the object re-estimated: no change, the new box replaces it;
///    The windows in which the object was expected only because a new object of its class within
///    update_unhide_max_distance_m (its possible new place) did not hide it (DisplacedCopies.h,
///    SessionEvidence::windows_missed_behind_new) count as misses for a move, never for a removal;
///  - twins: a new object within update_twin_max_distance_m (or the m0 object's length) of an m0
///    object of its class that this session matched, matched in fewer than
///    update_twin_max_window_ratio times its windows, is its twin: neither added nor a new place;
///  - the same object seen again: a new object sharing update_same_overlap_fraction of the smaller
///    box's volume (sharedVolumeFraction, update_same_overlap_margin_m) with an m0 object of its
///    class that is not gone (two objects of a class do not
///    interpenetrate), whatever the session expected of that object: neither added nor a new place;
///  - nested: an m0 object with update_nested_overlap_fraction of its volume inside the box of an
///    m0 object of another class, its top not above it, is never removed on misses alone (a new
///    place still moves it);
///  - door closed: a door of m0 with the removal evidence and no new place is reported
///    `door_closed` and stays in the map (a building keeps its doors; a closed one is not seen);
///  - added: the other new confirmed objects (new ids, above every id of m0).
///  New objects count (and enter the updated map) only once matched in update_min_new_windows
///  integration windows: the earlier map already explains the scene, so a twin made of a few
///  windows' errors must not become a change.
///  Objects missed without a partner and without the removal evidence stay.
/// Objects of m0 the session never expected to see stay as they were.

#include <simp/mapping/ObjectMapBuilder.h>
#include <simp/mapping/UpdateEvidence.h>
#include <simp/world/ChangesFile.h>
#include <simp/world/ObjectMapData.h>

#include <vector>

namespace simp::mapping {

/// Fraction of the smaller box's volume that boxes a and b share once both have their horizontal
/// sides grown by margin_m on each side, in [0, 1]: two estimates of one thin object (a board)
/// would otherwise have to agree across its thickness to centimetres.
double sharedVolumeFraction(const geometry::Box3D& a, const geometry::Box3D& b, double margin_m);

struct MapUpdateResult {
    world::ObjectMapData map;                 ///< the updated map (builder's confirmed map minus removed objects)
    std::vector<world::ChangeRecord> changes; ///< removed, moved, added, door_closed, each with a confidence
    std::size_t unseen = 0;                   ///< objects of m0 this session never expected to see (kept)
    /// Per object of m0 (its order), then per new object of the builder's confirmed map: the
    /// evidence and the decision (M/update_evidence.tsv).
    std::vector<UpdateEvidence> evidence;
};

/// The changes between `m0` (the map given to the builder's setMap) and what the builder made of it.
/// Confidence: removed = 1 - (matched + 1) / (missed + 2) (Laplace estimate of "not there" from
/// the session's windows); added = w / (w + 1) with w its matched windows; moved = the smaller of both.
MapUpdateResult detectChanges(const world::ObjectMapData& m0, const ObjectMapBuilder& builder);

}  // namespace simp::mapping
