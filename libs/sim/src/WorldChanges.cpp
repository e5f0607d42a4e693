#include <simp/geometry/Footprint.h>
#include <simp/sim/Furniture.h>
#include <simp/sim/Raster.h>
#include <simp/sim/WorldChanges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace simp::sim {
namespace {

/// True when `o` stands on free floor (every footprint cell free in `walls`), inside a room
/// when there is a room map, and keeps a 5 cm gap to every object of `others` except `skip`.
bool fits(const world::MapObject& o, const Raster& walls, const world::World& w, std::size_t skip) {
    const auto fp = geometry::footprint(o.box);
    Eigen::Vector2d lo, hi;
    fp.bounds(lo, hi);
    for (int cy = walls.cellY(lo.y()) - 1; cy <= walls.cellY(hi.y()) + 1; ++cy)
        for (int cx = walls.cellX(lo.x()) - 1; cx <= walls.cellX(hi.x()) + 1; ++cx) {
            if (!walls.inside(cx, cy)) return false;
            const Eigen::Vector2d c(walls.centreX(cx), walls.centreY(cy));
            const auto cell = geometry::makeRectangle(c, walls.resolution_m, walls.resolution_m, 0.0);
            if (walls.isBlocked(cx, cy) && geometry::intersectionArea(cell, fp) > 0) return false;
        }
    if (!w.rooms.empty() && w.rooms.roomAt(o.box.center.x(), o.box.center.y()) <= 0) return false;
    const double yaw = geometry::yawOf(o.box);
    const auto grown = geometry::makeRectangle(o.box.center.head<2>(), o.box.size.x() + 0.1, o.box.size.y() + 0.1, yaw);
    const double reach = 0.5 * o.box.size.head<2>().norm() + 0.05;
    for (std::size_t i = 0; i < w.objects.objects.size(); ++i) {
        const auto& b = w.objects.objects[i].box;
        if (i == skip || (b.center - o.box.center).head<2>().norm() > reach + 0.5 * b.size.head<2>().norm()) continue;
        if (geometry::intersectionArea(grown, geometry::footprint(b)) > 0) return false;
    }
    return true;
}

/// True when a moved object stays in the room it stood in (when there is a room map and it stood
/// in a room). Without it a cabinet against a wall could reappear 0.9 m away on the wall's far
/// side, in the corridor or the next room (11 % of the moves of the batteries before 2026-12-07).
/// Rooms, not a wall-free straight way: a floor plan may draw the furniture itself as occupied.
bool staysInItsRoom(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const world::World& w) {
    if (w.rooms.empty()) return true;
    const int room = w.rooms.roomAt(from.x(), from.y());
    return room <= 0 || w.rooms.roomAt(to.x(), to.y()) == room;
}

/// The cells of the largest area a disc of radius `r` can drive in (Trajectory's goal area).
std::vector<std::uint8_t> drivableArea(const world::World& w, double r) {
    const Raster cspace = inflate(drivingObstacles(w), r);
    return largestFreeArea(cspace, clearance(cspace));
}

/// Keeps the passages: `candidate` (the world with one object placed or moved) leaves the robot the
/// area `before` (drivableArea of the world without it) but for the object's footprint grown by `r`
/// and a pocket (kPocketM2), and a way into every room it could drive into. An added table across a
/// corridor cuts off the rooms beyond it.
class PassageKeeper {
   public:
    /// Floor it may cut off beyond its own: a pocket behind furniture, not a room (m^2).
    static constexpr double kPocketM2 = 2.0;
    explicit PassageKeeper(double r) : m_r(r) {}
    bool keeps(const world::World& before, const world::World& candidate, const world::MapObject& placed) {
        if (m_r <= 0) return true;
        if (m_area.empty()) m_area = drivableArea(before, m_r), m_rooms = roomsIn(before, m_area);
        const auto after = drivableArea(candidate, m_r);
        std::size_t lost = 0;
        for (std::size_t i = 0; i < after.size() && i < m_area.size(); ++i) lost += m_area[i] && !after[i];
        const double res = candidate.floorplan.getResolution(), cell = res * res;
        const Eigen::Vector3d& s = placed.box.size;
        const double grown = (s.x() + 2 * m_r) * (s.y() + 2 * m_r) - (4 - M_PI) * m_r * m_r;
        return static_cast<double>(lost) * cell <= grown + kPocketM2 && roomsIn(candidate, after) == m_rooms;
    }
    /// The world changed: the next check recomputes the area.
    void changed() { m_area.clear(); }

   private:
    /// The rooms (ids > 0 of the room map; none without one) with a cell of `area`.
    static std::vector<int> roomsIn(const world::World& w, const std::vector<std::uint8_t>& area) {
        std::vector<int> ids;
        if (w.rooms.empty()) return ids;
        // `area` is laid out as the floor plan's cells (wallRaster).
        const auto& g = w.floorplan;
        const int nx = static_cast<int>(g.getSizeX()), ny = static_cast<int>(g.getSizeY());
        for (int cy = 0; cy < ny; ++cy)
            for (int cx = 0; cx < nx; ++cx)
                if (area[static_cast<std::size_t>(cy) * nx + cx]) {
                    const int id = w.rooms.roomAt(g.idx2x(cx), g.idx2y(cy));
                    if (id > 0 && std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
                }
        std::sort(ids.begin(), ids.end());
        return ids;
    }
    double m_r;
    std::vector<std::uint8_t> m_area;
    std::vector<int> m_rooms;
};

}  // namespace

void closeDoor(world::World& world, const world::MapObject& door) {
    auto& grid = world.floorplan;
    const Raster walls = wallRaster(grid);
    const double yaw = geometry::yawOf(door.box);
    const Eigen::Vector2d ax(std::cos(yaw), std::sin(yaw)), ay(-std::sin(yaw), std::cos(yaw));
    const Eigen::Vector2d c = door.box.center.head<2>();
    const double half_w = 0.5 * door.box.size.x() + 0.1, half_d = 0.3;
    const double res = walls.resolution_m;
    for (double v = -half_d; v <= half_d; v += 0.5 * res)
        for (double u = -half_w; u <= half_w; u += 0.5 * res) {
            const Eigen::Vector2d q = c + ax * u + ay * v;
            if (walls.isBlockedAt(q.x(), q.y())) continue;
            // a gap cell has wall on both sides along the door's width at the same depth
            const Eigen::Vector2d left = c - ax * (half_w + res) + ay * v, right = c + ax * (half_w + res) + ay * v;
            if (walls.isBlockedAt(left.x(), left.y()) && walls.isBlockedAt(right.x(), right.y()))
                grid.setCell(grid.x2idx(q.x()), grid.y2idx(q.y()), 0.0f);
        }
}

world::World applyChanges(const world::World& map, const ChangeParams& p, Rng& rng, ChangeSummary* summary) {
    if (!(p.fraction >= 0 && p.fraction <= 1)) throw std::invalid_argument("applyChanges: fraction must be in [0, 1]");
    world::World w = map;
    ChangeSummary s;
    const int door_class = w.objects.classId("door");
    std::vector<std::size_t> doors, others;
    for (std::size_t i = 0; i < w.objects.objects.size(); ++i)
        (w.objects.objects[i].class_id == door_class ? doors : others).push_back(i);

    // doors first: closed doors change where objects may stand
    const double door_fraction = p.door_close_fraction < 0 ? p.fraction : p.door_close_fraction;
    const auto n_doors = static_cast<std::size_t>(std::lround(door_fraction * static_cast<double>(doors.size())));
    for (std::size_t i = doors.size(); i > 1; --i) std::swap(doors[i - 1], doors[rng.index(i)]);
    std::vector<std::size_t> closed;
    for (std::size_t k = 0; k < n_doors; ++k) {
        closeDoor(w, w.objects.objects[doors[k]]);
        closed.push_back(doors[k]);
        ++s.doors_closed;
    }

    const auto n_change = static_cast<std::size_t>(std::lround(p.fraction * static_cast<double>(others.size())));
    const std::size_t n_remove = n_change / 3, n_move = n_change / 3, n_add = n_change - n_remove - n_move;
    for (std::size_t i = others.size(); i > 1; --i) std::swap(others[i - 1], others[rng.index(i)]);
    const Raster walls = wallRaster(w.floorplan);
    PassageKeeper passages(p.passage_radius_m);

    std::vector<bool> drop(w.objects.objects.size(), false);
    for (std::size_t k = 0; k < n_remove && k < others.size(); ++k) drop[others[k]] = true;
    for (std::size_t k = n_remove; k < n_remove + n_move && k < others.size(); ++k) {
        const std::size_t i = others[k];
        const world::MapObject orig = w.objects.objects[i];
        bool moved = false;
        for (int attempt = 0; attempt < 30 && !moved; ++attempt) {
            world::MapObject o = orig;
            const double dist = rng.uniform(p.shift_min_m, p.shift_max_m), dir = rng.uniform(-M_PI, M_PI);
            const double yaw = geometry::yawOf(orig.box) + rng.normal(0.0, p.rotation_std_deg * M_PI / 180.0);
            const Eigen::Vector3d c = orig.box.center + Eigen::Vector3d(dist * std::cos(dir), dist * std::sin(dir), 0);
            o.box = geometry::makeUprightBox(c, orig.box.size, yaw);
            if (staysInItsRoom(orig.box.center.head<2>(), c.head<2>(), w) && fits(o, walls, w, i)) {
                world::World candidate = w;
                candidate.objects.objects[i] = o;
                if (!passages.keeps(w, candidate, o)) continue;
                if (!w.rooms.empty()) o.room_id = w.rooms.roomAt(c.x(), c.y());
                w.objects.objects[i] = o;
                passages.changed();
                moved = true;
            }
        }
        if (moved) ++s.moved;
        else drop[i] = true;  // nowhere to go: it left the building
    }
    s.removed = static_cast<int>(std::count(drop.begin(), drop.end(), true));

    std::int64_t next_id = 1;
    for (const auto& o : w.objects.objects) next_id = std::max(next_id, o.id + 1);
    for (std::size_t k = 0; k < n_add && !others.empty(); ++k) {
        const auto& like = map.objects.objects[others[rng.index(others.size())]];
        const std::string& name = w.objects.class_names.at(static_cast<std::size_t>(like.class_id));
        for (int attempt = 0; attempt < 200; ++attempt) {
            const int cx = static_cast<int>(rng.index(static_cast<std::size_t>(walls.nx)));
            const int cy = static_cast<int>(rng.index(static_cast<std::size_t>(walls.ny)));
            if (walls.isBlocked(cx, cy)) continue;
            world::MapObject o = like;
            o.id = next_id;
            o.noise.reset();
            Eigen::Vector3d size = like.box.size;
            double z0 = like.box.center.z() - 0.5 * size.z();
            try {
                const auto& t = objectTemplate(name);
                size = {rng.uniform(t.w_min, t.w_max), rng.uniform(t.d_min, t.d_max), rng.uniform(t.h_min, t.h_max)};
                z0 = t.z_bottom_m;
            } catch (const std::invalid_argument&) {
                // imported class without a template: copy the size of the object it imitates
            }
            const double yaw = 0.5 * M_PI * static_cast<double>(rng.index(4));
            o.box = geometry::makeUprightBox({walls.centreX(cx), walls.centreY(cy), z0 + 0.5 * size.z()}, size, yaw);
            if (!fits(o, walls, w, w.objects.objects.size())) continue;
            world::World candidate = w;
            candidate.objects.objects.push_back(o);
            if (!passages.keeps(w, candidate, o)) continue;
            passages.changed();
            if (!w.rooms.empty()) o.room_id = w.rooms.roomAt(walls.centreX(cx), walls.centreY(cy));
            w.objects.objects.push_back(o);
            drop.push_back(false);
            ++next_id;
            ++s.added;
            break;
        }
    }
    // the record of Q/changes.json; drawing nothing, it leaves every random number as it was
    using Kind = ObjectChange::Kind;
    const std::size_t n_map = map.objects.objects.size();
    std::vector<bool> was_moved(n_map, false);
    for (std::size_t k = n_remove; k < n_remove + n_move && k < others.size(); ++k) was_moved[others[k]] = !drop[others[k]];
    for (std::size_t i = 0; i < n_map; ++i)
        if (drop[i]) s.changes.push_back({Kind::Removed, map.objects.objects[i], std::nullopt});
    for (std::size_t i = 0; i < n_map; ++i)
        if (was_moved[i]) s.changes.push_back({Kind::Moved, map.objects.objects[i], w.objects.objects[i]});
    for (std::size_t i = n_map; i < w.objects.objects.size(); ++i)
        s.changes.push_back({Kind::Added, std::nullopt, w.objects.objects[i]});
    std::sort(closed.begin(), closed.end());
    for (const std::size_t i : closed) s.changes.push_back({Kind::DoorClosed, map.objects.objects[i], w.objects.objects[i]});

    std::vector<world::MapObject> kept;
    for (std::size_t i = 0; i < w.objects.objects.size(); ++i)
        if (!drop[i]) kept.push_back(w.objects.objects[i]);
    w.objects.objects = std::move(kept);
    if (summary) *summary = s;
    return w;
}

}  // namespace simp::sim
