#include <simp/obs/ObjectClasses.h>
#include <simp/sim/Furniture.h>
#include <simp/sim/Office.h>

#include <cmath>
#include <map>

namespace simp::sim {
namespace {

constexpr double kPixel_m = 0.05;

/// Door object in the middle of a door gap (thinner than the wall, so it touches no wall cell).
world::MapObject doorObject(const Room& r, double wall_thickness_m, int door_class, std::int64_t id) {
    world::MapObject o;
    o.id = id;
    o.class_id = door_class;
    o.room_id = r.id;
    const double cx = 0.5 * (r.door_gap.x0 + r.door_gap.x1), cy = 0.5 * (r.door_gap.y0 + r.door_gap.y1);
    const Eigen::Vector3d size(r.door_gap.width() - 0.06, std::min(0.05, wall_thickness_m - 0.06), 2.0);
    o.box = geometry::makeUprightBox({cx, cy, size.z() / 2}, size, 0.0);
    return o;
}

/// Keep-out zone of the door swing inside a room (and in front of it in the corridor).
geometry::ConvexPolygon doorSwing(const Room& r, double depth_m, bool inside) {
    const double cx = 0.5 * (r.door_gap.x0 + r.door_gap.x1);
    const double w = r.door_gap.width() + 0.3;
    const double dir = inside ? -r.door_side_y : r.door_side_y;
    const double edge = dir > 0 ? r.door_gap.y1 : r.door_gap.y0;
    return geometry::makeRectangle({cx, edge + dir * depth_m / 2}, w, depth_m, 0.0);
}

/// Walls of the room that do not hold the door (0 bottom, 1 top, 2 left, 3 right).
int plainWall(const Room& r, Rng& rng) {
    static const int bottom_door[] = {1, 2, 3}, top_door[] = {0, 2, 3};
    return (r.door_side_y < 0 ? bottom_door : top_door)[rng.index(3)];
}

}  // namespace

std::vector<std::optional<model::NoiseModel>> officeClassNoise(const std::vector<std::string>& class_names) {
    struct Row {
        double mx, my, sx, sy, b;
    };
    // Magnitudes of class_noise.csv of the authors' office (pixels; 1 px = 0.05 m).
    static const std::map<std::string, Row> rows = {
        {"sink", {-1.206, -0.216, 3.560, 4.753, 2}},      {"oven", {-0.272, -0.094, 5.250, 5.927, 4}},
        {"board", {-0.918, 1.036, 2.952, 12.657, 2}},     {"table", {-1.440, -0.977, 7.692, 16.189, 4}},
        {"potted plant", {-3.215, -1.560, 2.946, 3.270, 2}}, {"drawers", {-0.400, -0.530, 5.495, 3.835, 2}},
        {"sofa", {-0.800, 2.304, 7.153, 22.033, 2}},      {"cabinet", {-0.985, 0.781, 4.694, 11.558, 2}},
        {"fire extinguisher", {0.164, -0.378, 1.896, 2.198, 2}}, {"desk", {5.288, 6.393, 5.418, 20.390, 2}},
    };
    std::vector<std::optional<model::NoiseModel>> out(class_names.size());
    for (std::size_t i = 0; i < class_names.size(); ++i) {
        const auto it = rows.find(class_names[i]);
        if (it == rows.end()) continue;
        model::NoiseModel m;
        m.mean_m = Eigen::Vector2d(it->second.mx, it->second.my) * kPixel_m;
        m.cov_m2 = Eigen::Vector2d(std::pow(it->second.sx * kPixel_m, 2), std::pow(it->second.sy * kPixel_m, 2)).asDiagonal();
        m.exponent_b = it->second.b;
        out[i] = m;
    }
    return out;
}

// Furnishing follows the authors' annotated office (simp-office floor.config, global_variance.json:
// 24 tables, 24 cabinets, 16 boards, 9 drawers, 8 sinks, 3 sofas, 2 extinguishers, 1 oven, plant, desk):
// workplaces are "table" (their work tables are desk blocks, ~1.8 x 2.1 m), most offices have a washbasin
// and 1-3 boards, the only "desk" is the reception counter. The per-class noise models come from
// detections of exactly such objects, so the built-in world uses the classes as they did.
void furnishRoom(PlacementContext& ctx, const Room& room, Rng& rng) {
    const Rect& r = ctx.interior;
    const double area = r.area();
    switch (room.type) {
        case RoomType::Office: {
            const int tables = std::min(3, 1 + static_cast<int>(area / 15.0));
            for (int i = 0; i < tables; ++i) {
                const int wall = plainWall(room, rng);
                if (auto t = placeAgainstWall(ctx, "work table", wall, rng)) {
                    placeChairsAt(ctx, *t, false, rng);
                    if (rng.bernoulli(0.4)) placeAgainstWall(ctx, "drawers", wall, rng);
                }
            }
            if (rng.bernoulli(0.75)) placeAgainstWall(ctx, "sink", -1, rng);
            const int boards = 1 + static_cast<int>(rng.index(3));
            for (int i = 0; i < boards; ++i) placeAgainstWall(ctx, "board", plainWall(room, rng), rng);
            const int cabinets = 1 + static_cast<int>(rng.index(2));
            for (int i = 0; i < cabinets; ++i) placeAgainstWall(ctx, "cabinet", -1, rng);
            if (rng.bernoulli(0.1)) placeAgainstWall(ctx, "potted plant", -1, rng);
            if (rng.bernoulli(0.3)) placeAgainstWall(ctx, "box", -1, rng);
            break;
        }
        case RoomType::Meeting: {
            if (auto t = placeInside(ctx, "meeting table", 0.75, rng)) placeChairsAt(ctx, *t, true, rng);
            const int boards = 1 + static_cast<int>(rng.index(2));
            for (int i = 0; i < boards; ++i) placeAgainstWall(ctx, "board", plainWall(room, rng), rng);
            if (rng.bernoulli(0.5)) placeAgainstWall(ctx, "cabinet", -1, rng);
            if (rng.bernoulli(0.2)) placeAgainstWall(ctx, "potted plant", -1, rng);
            break;
        }
        case RoomType::Kitchen: {
            const int wall = plainWall(room, rng);
            if (auto s = placeAgainstWall(ctx, "sink", wall, rng)) {
                // the oven next to the sink on the same counter wall
                const double yaw = geometry::yawOf(s->box);
                const bool horizontal = std::abs(std::sin(yaw)) < 0.5;
                const double a = horizontal ? s->box.center.x() - r.x0 : s->box.center.y() - r.y0;
                const double off = 0.5 * s->box.size.x() + 0.4;
                if (!placeAgainstWall(ctx, "oven", wall, rng, a + off, 1)) placeAgainstWall(ctx, "oven", wall, rng, a - off, 1);
            }
            if (auto t = placeInside(ctx, "kitchen table", 0.8, rng)) placeChairsAt(ctx, *t, true, rng);
            const int sofas = static_cast<int>(rng.index(3));  // the authors' kitchen has a lounge corner
            for (int i = 0; i < sofas; ++i) placeAgainstWall(ctx, "sofa", plainWall(room, rng), rng);
            if (rng.bernoulli(0.5)) placeAgainstWall(ctx, "board", plainWall(room, rng), rng);
            if (rng.bernoulli(0.7)) placeAgainstWall(ctx, "cabinet", -1, rng);
            if (rng.bernoulli(0.3)) placeAgainstWall(ctx, "fire extinguisher", -1, rng);
            if (rng.bernoulli(0.3)) placeAgainstWall(ctx, "box", -1, rng);
            break;
        }
        case RoomType::Reception: {
            if (auto d = placeAgainstWall(ctx, "desk", plainWall(room, rng), rng)) placeChairsAt(ctx, *d, false, rng);
            if (auto s = placeAgainstWall(ctx, "sofa", plainWall(room, rng), rng)) {
                const double yaw = geometry::yawOf(s->box);
                const Eigen::Vector2d p = s->box.center.head<2>() +
                                          Eigen::Vector2d(-std::sin(yaw), std::cos(yaw)) * (0.5 * s->box.size.y() + 0.75);
                tryPlace(ctx, "coffee table", p.x(), p.y(), yaw, rng);
            }
            const int drawers = 1 + static_cast<int>(rng.index(2));
            for (int i = 0; i < drawers; ++i) placeAgainstWall(ctx, "drawers", -1, rng);
            if (rng.bernoulli(0.5)) placeAgainstWall(ctx, "sink", -1, rng);
            if (rng.bernoulli(0.7)) placeAgainstWall(ctx, "cabinet", -1, rng);
            placeAgainstWall(ctx, "potted plant", -1, rng);
            break;
        }
        case RoomType::Corridor: break;
    }
}

GeneratedOffice generateOfficeWithLayout(const OfficeParams& params, std::uint64_t seed) {
    Rng rng(seed);
    GeneratedOffice g;
    g.layout = makeOfficeLayout(params, rng);
    rasterizeLayout(g.layout, params.resolution_m, g.world.floorplan, g.world.rooms);

    auto& data = g.world.objects;
    data.class_names = obs::defaultClassNames();
    data.class_noise = officeClassNoise(data.class_names);
    const int door_class = obs::classIndexOf(data.class_names, "door");
    std::int64_t next_id = 1;

    std::vector<const Room*> rooms, corridors;
    for (const auto& r : g.layout.rooms) (r.type == RoomType::Corridor ? corridors : rooms).push_back(&r);
    for (const Room* r : rooms) data.objects.push_back(doorObject(*r, params.wall_thickness_m, door_class, next_id++));

    for (const Room* r : rooms) {
        PlacementContext ctx;
        ctx.interior = r->interior;
        ctx.room_id = r->id;
        ctx.keepout.push_back(doorSwing(*r, 1.2, true));
        ctx.objects = &data.objects;
        ctx.class_names = &data.class_names;
        ctx.next_id = &next_id;
        furnishRoom(ctx, *r, rng);
    }
    // corridors: fire extinguishers beside doors, boards on the walls (as in the authors' corridor);
    // door fronts stay clear
    for (const Room* c : corridors) {
        PlacementContext ctx;
        ctx.interior = c->interior;
        ctx.room_id = c->id;
        for (const Room* r : rooms) ctx.keepout.push_back(doorSwing(*r, 1.0, false));
        ctx.objects = &data.objects;
        ctx.class_names = &data.class_names;
        ctx.next_id = &next_id;
        for (const Room* r : rooms) {
            if (!rng.bernoulli(0.35)) continue;
            const double cx = 0.5 * (r->door_gap.x0 + r->door_gap.x1);
            if (!c->interior.contains(cx, r->door_side_y > 0 ? r->door_gap.y1 + 0.1 : r->door_gap.y0 - 0.1)) continue;
            const int wall = r->door_side_y > 0 ? 0 : 1;
            const double side = rng.bernoulli(0.5) ? 1.0 : -1.0;
            placeAgainstWall(ctx, "fire extinguisher", wall, rng, cx - c->interior.x0 + side * (0.5 * r->door_gap.width() + 0.4), 1);
        }
        const int wall_items = static_cast<int>(c->interior.area() / 40.0);
        // boards only: a cabinet would narrow the corridor below what the robot needs to pass
        for (int i = 0; i < wall_items; ++i)
            if (rng.bernoulli(0.5)) placeAgainstWall(ctx, "board", static_cast<int>(rng.index(2)), rng);
    }
    return g;
}

world::World generateOffice(const OfficeParams& params, std::uint64_t seed) {
    return generateOfficeWithLayout(params, seed).world;
}

}  // namespace simp::sim
