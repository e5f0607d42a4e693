// Q/changes.json (doc/formats.md): every change simulateSequence applied to the world, checked
// against the summary's counts and against an independent comparison of W with Q/world.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <simp/sim/Office.h>
#include <simp/sim/Sequence.h>
#include <simp/world/World.h>
#include <simp/world/ChangesFile.h>

#include "SimTestUtil.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace {

using nlohmann::json;

simp::world::World smallOffice() {
    simp::sim::OfficeParams p;
    p.rooms = 4;
    return simp::sim::generateOffice(p, 21);
}

json readJson(const std::string& path) {
    std::ifstream f(path);
    return json::parse(f);
}

std::map<std::int64_t, const simp::world::MapObject*> byId(const simp::world::World& w) {
    std::map<std::int64_t, const simp::world::MapObject*> m;
    for (const auto& o : w.objects.objects) m[o.id] = &o;
    return m;
}

/// The change file's pose equals the object's box (same doubles: the file keeps full precision).
void expectPoseOf(const json& pose, const simp::world::MapObject& o, const std::string& what) {
    ASSERT_TRUE(pose.is_object()) << what;
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(pose.at("center_m")[static_cast<std::size_t>(i)].get<double>(), o.box.center[i]) << what;
        EXPECT_EQ(pose.at("size_m")[static_cast<std::size_t>(i)].get<double>(), o.box.size[i]) << what;
    }
    EXPECT_NEAR(pose.at("yaw_rad").get<double>(), std::atan2(o.box.R(1, 0), o.box.R(0, 0)), 1e-12) << what;
}

TEST(SimChangesJson, ListsExactlyTheChangesApplied) {
    const auto W = smallOffice();
    simp::sim::SimParams p;
    p.duration_s = 2;
    p.progress = false;
    p.changes.fraction = 0.4;
    const std::string dir = simp::sim::test::clearedDir("changes_json");
    const std::string world_dir = simp::sim::test::clearedDir("changes_json_world");
    simp::world::saveWorld(W, world_dir);
    const auto s = simp::sim::simulateSequence(W, p, 11, dir, world_dir);
    ASSERT_GT(s.changes.removed, 0);
    ASSERT_GT(s.changes.moved, 0);
    ASSERT_GT(s.changes.added, 0);
    ASSERT_GT(s.changes.doors_closed, 0);
    const auto Q = simp::world::loadWorld(dir + "/world");
    const auto in_w = byId(W), in_q = byId(Q);

    const json j = readJson(dir + "/changes.json");
    EXPECT_EQ(j.at("format"), "simp-changes");
    EXPECT_EQ(j.at("version"), 1);
    // The world whose ids `before` speaks of, relative to the file (simp-eval changes reads it).
    EXPECT_TRUE(std::filesystem::equivalent(simp::world::readChangesFile(dir + "/changes.json").before_world, world_dir));
    std::map<std::string, int> count;
    std::set<std::int64_t> removed, moved, added, doors;
    for (const json& c : j.at("changes")) {
        const std::string kind = c.at("kind");
        ++count[kind];
        const std::string cls = c.at("class");
        const json &id_before = c.at("id_before"), &id_after = c.at("id_after");
        if (kind == "added") {
            EXPECT_TRUE(id_before.is_null() && c.at("before").is_null());
        } else {
            ASSERT_TRUE(in_w.count(id_before.get<std::int64_t>())) << kind << " id " << id_before << " is not in W";
            const auto& o = *in_w.at(id_before.get<std::int64_t>());
            EXPECT_EQ(W.objects.class_names[static_cast<std::size_t>(o.class_id)], cls);
            expectPoseOf(c.at("before"), o, kind + " before");
        }
        if (kind == "removed") {
            EXPECT_TRUE(id_after.is_null() && c.at("after").is_null());
            EXPECT_FALSE(in_q.count(id_before.get<std::int64_t>())) << "removed id " << id_before << " is in Q/world";
            removed.insert(id_before.get<std::int64_t>());
            continue;
        }
        ASSERT_TRUE(in_q.count(id_after.get<std::int64_t>())) << kind << " id " << id_after << " is not in Q/world";
        const auto& q = *in_q.at(id_after.get<std::int64_t>());
        EXPECT_EQ(Q.objects.class_names[static_cast<std::size_t>(q.class_id)], cls);
        expectPoseOf(c.at("after"), q, kind + " after");
        if (kind == "moved") {
            EXPECT_EQ(id_before, id_after);
            const double shift_m = (in_w.at(id_before.get<std::int64_t>())->box.center - q.box.center).head<2>().norm();
            EXPECT_GE(shift_m, p.changes.shift_min_m - 1e-9);
            EXPECT_LE(shift_m, p.changes.shift_max_m + 1e-9);
            moved.insert(id_after.get<std::int64_t>());
        } else if (kind == "added") {
            EXPECT_FALSE(in_w.count(id_after.get<std::int64_t>())) << "added id " << id_after << " was in W";
            added.insert(id_after.get<std::int64_t>());
        } else {
            ASSERT_EQ(kind, "door_closed");
            EXPECT_EQ(cls, "door");
            EXPECT_EQ(id_before, id_after);
            doors.insert(id_after.get<std::int64_t>());
        }
        EXPECT_FALSE(c.contains("confidence"));  // the simulator writes the truth
    }
    EXPECT_EQ(count["removed"], s.changes.removed);
    EXPECT_EQ(count["moved"], s.changes.moved);
    EXPECT_EQ(count["added"], s.changes.added);
    EXPECT_EQ(count["door_closed"], s.changes.doors_closed);
    EXPECT_EQ(j.at("changes").size(), static_cast<std::size_t>(s.changes.removed + s.changes.moved + s.changes.added +
                                                                s.changes.doors_closed));

    // Independently: what differs between W and Q/world is exactly what the file lists.
    std::set<std::int64_t> gone, changed, appeared;
    for (const auto& [id, o] : in_w) {
        if (!in_q.count(id)) gone.insert(id);
        else if (in_q.at(id)->box.center != o->box.center || in_q.at(id)->box.R != o->box.R) changed.insert(id);
    }
    for (const auto& [id, o] : in_q)
        if (!in_w.count(id)) appeared.insert(id);
    EXPECT_EQ(gone, removed);
    EXPECT_EQ(changed, moved);
    EXPECT_EQ(appeared, added);
    // every closed door blocked floor cells around it, and no cell changed elsewhere
    const auto& gw = W.floorplan;
    const auto& gq = Q.floorplan;
    std::map<std::int64_t, int> blocked_near;
    for (unsigned cy = 0; cy < gw.getSizeY(); ++cy)
        for (unsigned cx = 0; cx < gw.getSizeX(); ++cx) {
            if (gw.getCell(cx, cy) == gq.getCell(cx, cy)) continue;
            const Eigen::Vector2d c(gw.idx2x(cx), gw.idx2y(cy));
            bool near_door = false;
            for (const auto id : doors)
                if ((in_w.at(id)->box.center.head<2>() - c).norm() < 0.8) ++blocked_near[id], near_door = true;
            EXPECT_TRUE(near_door) << "floor cell (" << c.x() << ", " << c.y() << ") changed away from the closed doors";
        }
    for (const auto id : doors) EXPECT_GT(blocked_near[id], 5) << "door " << id << " listed as closed, its gap is open";
}

TEST(SimChangesJson, EmptyListWithoutChange) {
    simp::sim::SimParams p;
    p.duration_s = 1;
    p.progress = false;
    const std::string dir = simp::sim::test::clearedDir("changes_json_none");
    simp::sim::simulateSequence(smallOffice(), p, 2, dir);
    const json j = readJson(dir + "/changes.json");
    ASSERT_TRUE(j.at("changes").is_array());
    EXPECT_TRUE(j.at("changes").empty());
}

TEST(SimChanges, SummaryRecordsEveryChange) {
    const auto map = smallOffice();
    simp::sim::ChangeParams p;
    p.fraction = 0.3;
    simp::sim::Rng rng(8);
    simp::sim::ChangeSummary s;
    simp::sim::applyChanges(map, p, rng, &s);
    std::map<simp::sim::ObjectChange::Kind, int> n;
    for (const auto& c : s.changes) {
        ++n[c.kind];
        EXPECT_EQ(c.before.has_value(), c.kind != simp::sim::ObjectChange::Kind::Added);
        EXPECT_EQ(c.after.has_value(), c.kind != simp::sim::ObjectChange::Kind::Removed);
    }
    EXPECT_EQ(n[simp::sim::ObjectChange::Kind::Removed], s.removed);
    EXPECT_EQ(n[simp::sim::ObjectChange::Kind::Moved], s.moved);
    EXPECT_EQ(n[simp::sim::ObjectChange::Kind::Added], s.added);
    EXPECT_EQ(n[simp::sim::ObjectChange::Kind::DoorClosed], s.doors_closed);
}

}  // namespace
