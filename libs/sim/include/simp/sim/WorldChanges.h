#pragma once
/// \file WorldChanges.h
/// Long-term change between the map and the world a sequence is recorded in: objects removed,
/// moved (shifted and rotated) and added; doors closed (door object kept, gap blocked).

#include <mrpt/config/CConfigFileBase.h>
#include <simp/io/OptionTable.h>
#include <simp/sim/Random.h>
#include <simp/world/World.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::sim {

/// [changes] section of sim.ini (`--changes F` sets `fraction`).
struct ChangeParams {
    double fraction = 0;             ///< fraction of the (non-door) objects that change, in [0, 1]
    double shift_min_m = 0.3;        ///< a moved object is shifted by a distance in [min, max] (m)
    double shift_max_m = 1.0;
    double rotation_std_deg = 30;    ///< and rotated by N(0, std) (deg)
    double door_close_fraction = -1; ///< fraction of doors closed; < 0: the same as `fraction`
    /// A moved or added object may not cut off floor the robot could drive to: the largest area a
    /// disc of this radius (m) can reach must keep a cell in every room it had one in and lose no
    /// more than the object's own footprint grown by the radius (plus 2 m^2 of pocket).
    /// < 0: the trajectory's robot_radius_m + clearance_m (simulateSequence); 0 = off (before
    /// 2026-12-07: an added table could close a corridor).
    double passage_radius_m = -1;

    /// [changes] keys, declared once (SimParams.cpp).
    static const io::OptionTable<ChangeParams>& table();
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/// One change applied to the world, as `Q/changes.json` lists it (doc/formats.md).
struct ObjectChange {
    enum class Kind { Removed, Moved, Added, DoorClosed };
    Kind kind = Kind::Removed;
    std::optional<world::MapObject> before;  ///< the object in the map (its id is the map's); none when added
    std::optional<world::MapObject> after;   ///< the object in the changed world; none when removed
};

/// The name of a kind in changes.json: "removed", "moved", "added", "door_closed".
const char* kindName(ObjectChange::Kind kind);

/// What applyChanges() did.
struct ChangeSummary {
    int removed = 0, moved = 0, added = 0, doors_closed = 0;
    /// every change, grouped by kind in the order removed, moved, added, door_closed; within a
    /// kind in the order of the objects in the map (added: in the changed world)
    std::vector<ObjectChange> changes;
};

/// The world changed: of the n non-door objects, round(fraction * n) change, split evenly into
/// removals, moves within the object's room (one that cannot be moved so without overlap is removed) and additions
/// (new objects of classes drawn from the map's objects, placed on free floor inside rooms).
/// Objects never overlap each other or walls. Door closing blocks the door's wall gap in the
/// floor plan. fraction = 0 and door_close_fraction <= 0 returns an identical copy.
world::World applyChanges(const world::World& map, const ChangeParams& p, Rng& rng, ChangeSummary* summary = nullptr);

/// Writes `summary.changes` as the change file `path` (doc/formats.md "changes.json"; an
/// empty list when nothing changed). `class_names` names the objects' class ids.
/// \throw std::runtime_error naming the file when it cannot be written.
void saveChangesJson(const ChangeSummary& summary, const std::vector<std::string>& class_names, const std::string& path,
                     const std::string& before_world = {});

/// Blocks the wall gap a door object stands in (free cells between wall cells on both sides of
/// the door along its width).
void closeDoor(world::World& world, const world::MapObject& door);

}  // namespace simp::sim
