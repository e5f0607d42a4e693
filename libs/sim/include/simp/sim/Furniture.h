#pragma once
/// \file Furniture.h
/// Object templates (realistic size ranges of the paper's classes) and placement primitives
/// that put upright boxes into a room without overlapping walls, doors or each other.

#include <simp/geometry/ConvexPolygon.h>
#include <simp/sim/OfficeLayout.h>
#include <simp/sim/Random.h>
#include <simp/world/MapObject.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::sim {

/// Size ranges of one kind of object: width along its local x, depth along local y, height (m);
/// `z_bottom_m` is the height of its lowest point (wall-mounted boards are above the floor).
struct ObjectTemplate {
    std::string class_name;
    double w_min, w_max, d_min, d_max, h_min, h_max;
    double z_bottom_m = 0;
};

/// The template named `kind`: a class name of simp::obs::defaultClassNames(), or one of the
/// variants "meeting table", "kitchen table", "coffee table".
/// \throw std::invalid_argument naming the unknown kind.
const ObjectTemplate& objectTemplate(const std::string& kind);

/// A room being furnished: its free rectangle, forbidden zones (door swings) and the
/// footprints of everything placed so far in the whole world.
struct PlacementContext {
    Rect interior;                                   ///< free space of the room (m)
    int room_id = 0;
    std::vector<geometry::ConvexPolygon> keepout;    ///< zones no object may touch
    std::vector<world::MapObject>* objects = nullptr;  ///< all placed objects (appended to)
    const std::vector<std::string>* class_names = nullptr;
    double gap_m = 0.05;                             ///< minimum free gap between objects (m)
    std::int64_t* next_id = nullptr;                 ///< id of the next object (incremented)
};

/// Footprint of a map object on the floor (world frame).
geometry::ConvexPolygon objectFootprint(const world::MapObject& o);

/// Places an object of `kind` with yaw `yaw_rad` and centre (x, y) if it fits (inside the
/// interior, clear of keep-out zones and other objects by gap_m). Returns the placed object.
std::optional<world::MapObject> tryPlace(PlacementContext& ctx, const std::string& kind, double x, double y,
                                         double yaw_rad, Rng& rng);

/// Walls of a room: 0 = bottom (y0), 1 = top (y1), 2 = left (x0), 3 = right (x1).
/// Puts the object's back against wall `wall` (random wall when < 0) at a random position along
/// it (or at `along_m` from the wall's start), facing into the room. Up to `tries` attempts.
std::optional<world::MapObject> placeAgainstWall(PlacementContext& ctx, const std::string& kind, int wall, Rng& rng,
                                                 std::optional<double> along_m = std::nullopt, int tries = 30);

/// Places an object anywhere at least `wall_margin_m` from the walls, yaw a multiple of 90 deg.
std::optional<world::MapObject> placeInside(PlacementContext& ctx, const std::string& kind, double wall_margin_m,
                                            Rng& rng, int tries = 30);

/// Chairs at a desk (one, in front) or around a table (along both long sides).
void placeChairsAt(PlacementContext& ctx, const world::MapObject& table, bool around, Rng& rng);

}  // namespace simp::sim
