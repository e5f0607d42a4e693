#include <gtest/gtest.h>
#include <simp/geometry/Box3DIoU.h>
#include <simp/mapping/ObjectMapBuilder.h>

#include "MappingTestScene.h"

#include <map>

using namespace simp::mapping;
using simp::geometry::makeUprightBox;

namespace {

const std::vector<std::string> kClasses = {"table", "cabinet", "chair"};

simp::world::ObjectMapData emptyMap() { return test::emptyMapOf(kClasses); }

void insertAll(ObjectMapBuilder& b, const std::vector<simp::obs::CObservationObjects3D>& obs,
               const mrpt::poses::CPose3D& pose) {
    for (const auto& o : obs) b.insert(o, pose);
}

/// The map object of class `cls` closest to `c`, or nullptr.
const simp::world::MapObject* closest(const simp::world::ObjectMapData& m, int cls, const Eigen::Vector3d& c) {
    const simp::world::MapObject* best = nullptr;
    for (const auto& o : m.objects)
        if (o.class_id == cls && (!best || (o.box.center - c).norm() < (best->box.center - c).norm())) best = &o;
    return best;
}

/// An empty map whose cabinets (class 1) have a class model with mean `mu` and 0.1 m sigma.
simp::world::ObjectMapData mapWithCabinetBias(const Eigen::Vector2d& mu) {
    auto m = emptyMap();
    simp::model::NoiseModel biased;
    biased.mean_m = mu;
    biased.cov_m2 = Eigen::Matrix2d::Identity() * 0.01;
    m.class_noise[1] = biased;
    return m;
}

/// Exact (noise-free) detections of `truth` from each robot pose, inserted into `b`.
void insertExact(ObjectMapBuilder& b, const std::vector<test::TrueObject>& truth,
                 const std::vector<mrpt::poses::CPose3D>& poses, unsigned seed) {
    std::mt19937 rng(seed);
    for (const auto& pose : poses) insertAll(b, test::observe(truth, kClasses, pose, rng, test::DetectionNoise{0, 0, 0}), pose);
}

}  // namespace

TEST(ObjectMapBuilder, StaticSceneConvergesToTheTrueBoxes) {
    const std::vector<test::TrueObject> truth = {
        {0, makeUprightBox({1.4, 3.0, 0.375}, {1.2, 0.8, 0.75}, 0.3)},
        {1, makeUprightBox({6.6, 1.0, 0.9}, {0.5, 1.0, 1.8}, 0.0)},
        {2, makeUprightBox({4.0, 5.2, 0.45}, {0.5, 0.5, 0.9}, 0.7)}};
    ObjectMapBuilder b(test::testOptions());
    b.setFloorPlan(test::makeFloorPlan(8, 6), {});
    b.setMap(emptyMap());
    std::mt19937 rng(7);
    const test::DetectionNoise noise;  // 5 cm centre sigma per axis
    constexpr int kSteps = 120;
    for (int s = 0; s < kSteps; ++s) {  // a circle of radius 1.2 m around the room centre
        const double a = 2.0 * M_PI * s / kSteps;
        const mrpt::poses::CPose3D pose(4.0 + 1.2 * std::cos(a), 3.0 + 1.2 * std::sin(a), 0, a + M_PI / 2, 0, 0);
        insertAll(b, test::observe(truth, kClasses, pose, rng, noise), pose);
    }
    b.flush();
    const auto& m = b.map();
    // Each true object collects ~100 detections; duplicates made by early noisy detections are
    // merged or purged, or stay transient with few detections.
    int confirmed = 0;
    for (const auto& o : m.objects) confirmed += o.n_match >= 20;
    EXPECT_EQ(confirmed, static_cast<int>(truth.size()));
    for (const auto& t : truth) {
        const auto* o = closest(m, t.class_id, t.box.center);
        ASSERT_NE(o, nullptr);
        ASSERT_GE(o->n_match, 20);
        // The centre is the mean of n_match detections: 3 sigma bound of its horizontal error.
        const double tol = 3.0 * noise.center_sigma_m * std::sqrt(2.0 / o->n_match);
        EXPECT_LT((o->box.center - t.box.center).head<2>().norm(), tol) << m.class_names[t.class_id];
        EXPECT_GT(simp::geometry::iou3D(o->box, t.box), 0.8) << m.class_names[t.class_id];
        EXPECT_EQ(o->room_id, 1);
    }
}

TEST(ObjectMapBuilder, RemovedObjectIsPurged) {
    auto m0 = emptyMap();
    simp::world::MapObject ghost;  // in the map, no longer in the world
    ghost.id = 10;
    ghost.class_id = 1;
    ghost.box = makeUprightBox({6.0, 3.0, 0.9}, {0.5, 1.0, 1.8}, 0.0);
    ghost.n_match = 4;
    m0.objects.push_back(ghost);
    const std::vector<test::TrueObject> truth = {{0, makeUprightBox({6.0, 4.6, 0.375}, {1.2, 0.8, 0.75}, 0.0)}};
    auto opts = test::testOptions();
    ObjectMapBuilder b(opts);
    b.setFloorPlan(test::makeFloorPlan(8, 6), {});
    b.setMap(m0);
    std::mt19937 rng(3);
    int skips_seen = 0;
    for (int s = 0; s < 60; ++s) {  // back and forth in front of it, facing +x
        const double x = 2.5 + 0.05 * (s % 20 < 10 ? s % 10 : 10 - s % 10);
        const mrpt::poses::CPose3D pose(x, 3.0 + 0.01 * s, 0, 0, 0, 0);
        insertAll(b, test::observe(truth, kClasses, pose, rng), pose);
        for (const auto& o : b.map().objects)
            if (o.id == 10) skips_seen = o.n_skip;
    }
    b.flush();
    // Purged once n_match / n_skip < tau_purge, i.e. after more than 4 / 0.5 = 8 active windows.
    EXPECT_GE(skips_seen, 8);
    for (const auto& o : b.map().objects) EXPECT_NE(o.id, 10);
    EXPECT_EQ(b.stats().purged, 1u);
    // The object that is there stays.
    const auto* table = closest(b.map(), 0, truth[0].box.center);
    ASSERT_NE(table, nullptr);
    EXPECT_LT((table->box.center - truth[0].box.center).norm(), 0.1);
}

namespace {

/// Drives 40 poses along y = 3 m from x = x0 (facing +x, small turns) past `truth` (objects of one
/// class) and expects each true object mapped once: as many well-seen (>= 10 detections)
/// confirmed map objects of the class as true objects, the nearest one within 0.1 m of each.
void expectEachMappedOnce(const std::vector<test::TrueObject>& truth, const MappingOptions& opts, unsigned seed,
                          double x0) {
    const int cls = truth.front().class_id;
    ObjectMapBuilder b(opts);
    b.setFloorPlan(test::makeFloorPlan(8, 6), {});
    b.setMap(emptyMap());
    std::mt19937 rng(seed);
    for (int s = 0; s < 40; ++s) {
        const mrpt::poses::CPose3D pose(x0 + 0.03 * s, 3.0, 0, 0.01 * (s % 7), 0, 0);
        insertAll(b, test::observe(truth, kClasses, pose, rng), pose);
    }
    b.flush();
    int well_seen = 0;
    for (const auto& o : b.confirmedMap().objects) well_seen += o.class_id == cls && o.n_match >= 10;
    EXPECT_EQ(well_seen, static_cast<int>(truth.size()));
    for (const auto& t : truth) {
        const auto* o = closest(b.map(), cls, t.box.center);
        ASSERT_NE(o, nullptr);
        EXPECT_LT((o->box.center - t.box.center).head<2>().norm(), 0.1);
    }
}

}  // namespace

TEST(ObjectMapBuilder, TwoCloseObjectsOfOneClassStayTwo) {
    const std::vector<test::TrueObject> chairs = {{2, makeUprightBox({5.0, 2.6, 0.45}, {0.5, 0.5, 0.9}, 0.0)},
                                                  {2, makeUprightBox({5.0, 3.4, 0.45}, {0.5, 0.5, 0.9}, 0.0)}};
    expectEachMappedOnce(chairs, test::testOptions(), 11, 2.0);
}

TEST(ObjectMapBuilder, TablesBackToBackStayTwoWithTheDefaultRules) {
    // Two work tables pushed together (2 cm apart), as in the authors' office: the duplicate
    // rules of the defaults (centre radius 0.5 m, cost < 0.7 within 1 m, overlap > 20 %) must not
    // make them one (their centres are 0.82 m apart, their boxes do not interpenetrate).
    const std::vector<test::TrueObject> tables = {{0, makeUprightBox({5.0, 2.59, 0.375}, {1.6, 0.8, 0.75}, 0.0)},
                                                  {0, makeUprightBox({5.0, 3.41, 0.375}, {1.6, 0.8, 0.75}, 0.0)}};
    const auto opts = test::testOptions();
    ASSERT_DOUBLE_EQ(opts.duplicate_min_overlap, 0.2);
    expectEachMappedOnce(tables, opts, 12, 1.8);
}

namespace {

simp::world::MapObject mapObject(std::int64_t id, int cls, const simp::geometry::Box3D& box, int n_match) {
    simp::world::MapObject o;
    o.id = id;
    o.class_id = cls;
    o.box = box;
    o.n_match = n_match;
    return o;
}

/// Builder over an 8 m x 6 m room holding `objects`, after one window in which the robot at
/// (2, 3) looking along +x saw them all (and detected nothing).
ObjectMapBuilder afterOneEmptyWindow(const MappingOptions& opts, const std::vector<simp::world::MapObject>& objects) {
    ObjectMapBuilder b(opts);
    b.setFloorPlan(test::makeFloorPlan(8, 6), {});
    auto map = emptyMap();
    map.objects = objects;
    b.setMap(map);
    std::mt19937 rng(3);
    const mrpt::poses::CPose3D pose(2.0, 3.0, 0, 0, 0, 0);
    insertAll(b, test::observe({}, kClasses, pose, rng), pose);
    b.flush();
    return b;
}

}  // namespace

TEST(ObjectMapBuilder, DuplicatesWithinTheCentreRadiusMerge) {
    // Two cabinets 0.4 m apart (< duplicate_center_radius_m = 0.5, the authors' centerMerge) are one
    // object; a third 1.3 m away (disjoint box, cost ~1 > duplicate_tau_cost) stays.
    const auto opts = test::testOptions();
    ASSERT_DOUBLE_EQ(opts.duplicateCenterRadiusOf("cabinet"), 0.5);
    const ObjectMapBuilder b = afterOneEmptyWindow(
        opts, {mapObject(1, 1, makeUprightBox({5.0, 2.0, 0.45}, {0.5, 0.5, 0.9}, 0.0), 30),
               mapObject(2, 1, makeUprightBox({5.0, 2.4, 0.45}, {0.5, 0.5, 0.9}, 0.0), 10),
               mapObject(3, 1, makeUprightBox({5.0, 3.7, 0.45}, {0.5, 0.5, 0.9}, 0.0), 20)});
    ASSERT_EQ(b.map().objects.size(), 2u);
    const auto* merged = closest(b.map(), 1, {5.0, 2.1, 0.45});
    ASSERT_NE(merged, nullptr);
    EXPECT_EQ(merged->n_match, 40);
    EXPECT_NEAR(merged->box.center.y(), (30 * 2.0 + 10 * 2.4) / 40, 1e-9);  // n_match-weighted
    EXPECT_EQ(b.stats().duplicates_merged, 1u);
}

TEST(ObjectMapBuilder, OverlapRuleMergesInterpenetratingBoxesOnlyWhenEnabled) {
    // Two tables 1.6 m long, 0.6 m apart along their length: 62 % of either box is shared. Their
    // Eq. costfunc cost is ~0.77 (IoU 0.45, centres 3 sigma apart), above duplicate_tau_cost = 0.7,
    // and 0.6 m > the 0.5 m centre radius: only the overlap rule makes them one object.
    const std::vector<simp::world::MapObject> tables = {
        mapObject(1, 0, makeUprightBox({5.0, 2.7, 0.375}, {0.8, 1.6, 0.75}, 0.0), 20),
        mapObject(2, 0, makeUprightBox({5.0, 3.3, 0.375}, {0.8, 1.6, 0.75}, 0.0), 20)};
    auto opts = test::testOptions();
    opts.duplicate_min_overlap = 0;  // off
    EXPECT_EQ(afterOneEmptyWindow(opts, tables).map().objects.size(), 2u);
    opts.duplicate_min_overlap = 0.5;
    const ObjectMapBuilder b = afterOneEmptyWindow(opts, tables);
    ASSERT_EQ(b.map().objects.size(), 1u);
    EXPECT_NEAR(b.map().objects[0].box.center.y(), 3.0, 1e-9);
    opts.duplicate_min_overlap = 0.7;  // 62 % < 70 %
    EXPECT_EQ(afterOneEmptyWindow(opts, tables).map().objects.size(), 2u);
}

TEST(ObjectMapBuilder, DetectionInAnotherRoomDoesNotTouchThatRoom) {
    // Rooms: x < 5 and x > 5 (door at y in [2.6, 3.4]). Object A in the left room.
    const auto grid = test::makeFloorPlan(10, 6, 5.0, 2.6, 3.4);
    auto m0 = emptyMap();
    simp::world::MapObject a;
    a.id = 1;
    a.class_id = 0;
    a.box = makeUprightBox({3.0, 1.5, 0.375}, {1.2, 0.8, 0.75}, 0.0);
    a.n_match = 5;
    m0.objects.push_back(a);
    // The robot in the right room; a detection (seen through the wall by a faulty detector)
    // lands on A.
    const std::vector<test::TrueObject> truth = {{0, makeUprightBox({3.05, 1.5, 0.375}, {1.2, 0.8, 0.75}, 0.0)}};
    const mrpt::poses::CPose3D pose(6.5, 2.0, 0, 0, 0, 0);  // rear camera faces A
    auto run = [&](RoomUpdatePolicy policy) {
        auto opts = test::testOptions();
        opts.room_policy = policy;
        ObjectMapBuilder b(opts);
        b.setFloorPlan(grid, {});
        b.setMap(m0);
        std::mt19937 rng(5);
        insertAll(b, test::observe(truth, kClasses, pose, rng, test::DetectionNoise{0, 0, 0}), pose);
        b.flush();
        return b;
    };
    const ObjectMapBuilder b = run(RoomUpdatePolicy::CurrentRoom);
    EXPECT_NE(b.roomOf(3.0, 1.5), b.roomOf(6.5, 2.0));
    ASSERT_EQ(b.map().objects.size(), 1u);
    const auto& o = b.map().objects[0];
    EXPECT_EQ(o.n_match, 5);
    EXPECT_EQ(o.n_skip, 0);
    EXPECT_TRUE(o.box.center.isApprox(a.box.center));
    EXPECT_EQ(b.stats().rejected_room, 1u);
    // Without the room policy the detection does enter the map (A is behind the wall, so a new
    // object is made, and the duplicate rule then merges it into A 5 cm away): the room filter
    // is what kept it out.
    const ObjectMapBuilder all = run(RoomUpdatePolicy::All);
    EXPECT_EQ(all.stats().rejected_room, 0u);
    EXPECT_EQ(all.stats().added, 1u);
    int detections_in_map = 0;
    for (const auto& obj : all.map().objects) detections_in_map += obj.n_match;
    EXPECT_EQ(detections_in_map, 6);
}

TEST(ObjectMapBuilder, AClassListedForCrossRoomMergeIsOneObjectFromBothSidesOfItsDoorway) {
    // Rooms: x < 5 and x > 5, doorway at y in [2.6, 3.4]. A thin "cabinet" (standing for a door)
    // stands in the doorway and was mapped twice, once from each room, its two faces 0.2 m apart;
    // the robot is in the left room. Two other cabinets hang back to back on the wall 0.3 m apart.
    const auto grid = test::makeFloorPlan(10, 6, 5.0, 2.6, 3.4);
    auto m0 = emptyMap();
    m0.objects = {mapObject(1, 1, makeUprightBox({4.9, 3.0, 1.0}, {0.05, 0.8, 2.0}, 0.0), 30),
                  mapObject(2, 1, makeUprightBox({5.1, 3.0, 1.0}, {0.05, 0.8, 2.0}, 0.0), 10),
                  mapObject(3, 1, makeUprightBox({4.85, 1.0, 1.0}, {0.05, 0.8, 0.6}, 0.0), 20),
                  mapObject(4, 1, makeUprightBox({5.15, 1.0, 1.0}, {0.05, 0.8, 0.6}, 0.0), 20)};
    const mrpt::poses::CPose3D pose(2.0, 3.0, 0, 0, 0, 0);
    auto run = [&](std::map<std::string, double> radius) {
        auto opts = test::testOptions();
        opts.class_cross_room_merge_radius_m = std::move(radius);
        ObjectMapBuilder b(opts);
        b.setFloorPlan(grid, {});
        b.setMap(m0);
        std::mt19937 rng(3);
        insertAll(b, test::observe({}, kClasses, pose, rng), pose);
        b.flush();
        return b;
    };
    const ObjectMapBuilder authors = run({});
    ASSERT_NE(authors.roomOf(4.9, 3.0), authors.roomOf(5.1, 3.0));
    EXPECT_EQ(authors.map().objects.size(), 4u);  // the room rule keeps each room's copy
    // Listed with 0.5 m: the doorway's copies merge (weighted by their matches: 30 : 10); the
    // back-to-back pair 0.3 m apart merges too (the rule is by class: list only classes that stand
    // between rooms); a radius under their distance keeps both pairs.
    const ObjectMapBuilder merged = run({{"cabinet", 0.5}});
    ASSERT_EQ(merged.map().objects.size(), 2u);
    const auto* door = closest(merged.map(), 1, {5.0, 3.0, 1.0});
    ASSERT_NE(door, nullptr);
    EXPECT_EQ(door->n_match, 40);
    EXPECT_NEAR(door->box.center.x(), 4.95, 1e-6);
    EXPECT_EQ(run({{"cabinet", 0.19}}).map().objects.size(), 4u);
    EXPECT_EQ(run({{"table", 0.5}}).map().objects.size(), 4u);  // another class listed
}

TEST(ObjectMapBuilder, FiltersDetectionsByClassConfidenceAndRange) {
    auto opts = test::testOptions();
    opts.per_class["chair"] = ClassFilter{0.5, 0.0, 0.0};  // disabled
    opts.per_class["cabinet"] = ClassFilter{0.95, 0.0, 6.0};
    opts.per_class["table"] = ClassFilter{0.5, 0.0, 2.0};
    ObjectMapBuilder b(opts);
    b.setMap(emptyMap());
    const std::vector<test::TrueObject> truth = {{2, makeUprightBox({2.0, 0.0, 0.45}, {0.5, 0.5, 0.9}, 0.0)},
                                                 {1, makeUprightBox({3.0, 0.5, 0.9}, {0.5, 1.0, 1.8}, 0.0)},
                                                 {0, makeUprightBox({3.0, -0.5, 0.375}, {1.2, 0.8, 0.75}, 0.0)}};
    std::mt19937 rng(1);
    const mrpt::poses::CPose3D pose(0, 0, 0, 0, 0, 0);
    insertAll(b, test::observe(truth, kClasses, pose, rng), pose);  // confidence 0.9
    b.flush();
    EXPECT_EQ(b.stats().rejected_class, 1u);
    EXPECT_EQ(b.stats().rejected_confidence, 1u);
    EXPECT_EQ(b.stats().rejected_range, 1u);
    EXPECT_TRUE(b.map().objects.empty());
}

TEST(ObjectMapBuilder, UnknownClassesAreAppendedByName) {
    ObjectMapBuilder b(test::testOptions());
    simp::world::ObjectMapData m;
    m.class_names = {"sofa"};
    m.class_noise.resize(1);
    b.setMap(m);
    const std::vector<test::TrueObject> truth = {{1, makeUprightBox({2.0, 0.0, 0.45}, {0.5, 0.5, 0.9}, 0.0)}};
    std::mt19937 rng(1);
    const mrpt::poses::CPose3D pose(0, 0, 0, 0, 0, 0);
    insertAll(b, test::observe(truth, kClasses, pose, rng), pose);
    b.flush();
    ASSERT_EQ(b.map().objects.size(), 1u);
    EXPECT_EQ(b.map().class_names[b.map().objects[0].class_id], "cabinet");
    EXPECT_EQ(b.map().class_names.size(), b.map().class_noise.size());
}

TEST(ObjectMapBuilder, InvalidMapIsRejected) {
    ObjectMapBuilder b(test::testOptions());
    auto m = emptyMap();
    simp::world::MapObject o;
    o.class_id = 7;
    m.objects.push_back(o);
    EXPECT_THROW(b.setMap(m), std::invalid_argument);
    m.objects[0].class_id = 0;
    m.objects[0].box.center.x() = std::nan("");
    EXPECT_THROW(b.setMap(m), std::invalid_argument);
}

TEST(ObjectMapBuilder, TheDetectorBiasCancelsBetweenPredictions) {
    // A class model with a 0.5 m bias and 0.1 m sigma: with mu in C_cen two identical detections
    // would cost 0.5 * (1 - exp(-0.5 * 25)) ~ 0.5 > tau_cost and never merge.
    const auto m0 = mapWithCabinetBias({0.5, 0.0});
    const std::vector<test::TrueObject> truth = {{1, makeUprightBox({3.0, 0.0, 0.9}, {0.5, 1.0, 1.8}, 0.0)}};
    auto run = [&](bool use_mean) {
        auto opts = test::testOptions();
        opts.cost_uses_noise_mean = use_mean;
        opts.merge_duplicates = false;
        ObjectMapBuilder b(opts);
        b.setMap(m0);
        insertExact(b, truth, {mrpt::poses::CPose3D(0.0, 0, 0, 0, 0, 0), mrpt::poses::CPose3D(0.3, 0, 0, 0, 0, 0)}, 1);  // two windows
        b.flush();
        return b.map().objects.size();
    };
    EXPECT_EQ(run(false), 1u);
    EXPECT_EQ(run(true), 2u);
}

TEST(ObjectMapBuilder, TheClassBiasIsRemovedFromTheMapObjects) {
    // Detections of a cabinet biased by the class model's mean: mu = (0.3, 0.1) m in the class
    // noise frame (the box's own here: its y side is the longer one, yaw 0).
    const Eigen::Vector2d mu(0.3, 0.1);
    const auto m0 = mapWithCabinetBias(mu);
    const auto true_box = makeUprightBox({3.0, 2.0, 0.9}, {0.5, 1.0, 1.8}, 0.0);
    auto seen_box = true_box;
    seen_box.center.head<2>() += mu;
    std::vector<mrpt::poses::CPose3D> poses;  // 8 windows
    for (int s = 0; s < 8; ++s) poses.emplace_back(0.5 + 0.25 * s, 0.2, 0, 0, 0, 0);
    auto run = [&](bool remove) {
        auto opts = test::testOptions();
        opts.remove_class_bias = remove;
        ObjectMapBuilder b(opts);
        b.setMap(m0);
        insertExact(b, {{1, seen_box}}, poses, 3);
        b.flush();
        EXPECT_EQ(b.map().objects.size(), 1u);
        return b.map().objects.empty() ? Eigen::Vector3d(1e9, 1e9, 1e9) : b.map().objects[0].box.center;
    };
    EXPECT_NEAR((run(true) - true_box.center).norm(), 0.0, 1e-9);
    EXPECT_NEAR((run(false) - seen_box.center).norm(), 0.0, 1e-9);

    // A given map (a ground-truth or reloaded map) holds the object where it is: the same biased
    // detections confirm it in place instead of pulling it by mu again.
    auto given = m0;
    given.objects.push_back(mapObject(7, 1, true_box, 50));
    ObjectMapBuilder b(test::testOptions());
    b.setMap(given);
    insertExact(b, {{1, seen_box}}, poses, 3);
    b.flush();
    ASSERT_EQ(b.map().objects.size(), 1u);
    EXPECT_GT(b.map().objects[0].n_match, 50);
    EXPECT_NEAR((b.map().objects[0].box.center - true_box.center).norm(), 0.0, 1e-9);
}

TEST(ObjectMapBuilder, ObjectsInsideAWallAreLeftOutOfTheOutputMap) {
    // A chair detected on the line of the room's west wall (x = 0), which no furniture can stand in.
    const std::vector<test::TrueObject> truth = {{2, makeUprightBox({0.0, 3.0, 0.45}, {0.5, 0.5, 0.9}, 0.0)},
                                                 {2, makeUprightBox({2.0, 3.0, 0.45}, {0.5, 0.5, 0.9}, 0.0)}};
    auto run = [&](bool hide) {
        auto opts = test::testOptions();
        opts.hide_objects_in_walls = hide;
        ObjectMapBuilder b(opts);
        b.setFloorPlan(test::makeFloorPlan(8, 6), {});
        b.setMap(emptyMap());
        std::vector<mrpt::poses::CPose3D> poses;
        for (int s = 0; s < 8; ++s) poses.emplace_back(3.0 + 0.25 * s, 3.2, 0, M_PI, 0, 0);
        insertExact(b, truth, poses, 5);
        b.flush();
        EXPECT_EQ(b.map().objects.size(), 2u);  // the builder keeps both
        return b.confirmedMap().objects.size();
    };
    EXPECT_EQ(run(true), 1u);
    EXPECT_EQ(run(false), 2u);
}

TEST(ObjectMapBuilder, OneOffDetectionOfAWindowDoesNotReachTheMap) {
    // A table seen in every step of a window, a cabinet (a false or stray detection) in one of 10.
    const std::vector<test::TrueObject> steady = {{0, makeUprightBox({5.0, 3.0, 0.375}, {1.2, 0.8, 0.75}, 0.0)}};
    std::vector<test::TrueObject> with_stray = steady;
    with_stray.push_back({1, makeUprightBox({5.0, 4.5, 0.9}, {0.5, 1.0, 1.8}, 0.0)});
    const auto run = [&](double min_support) {
        auto opts = test::testOptions();
        opts.min_local_support = min_support;
        ObjectMapBuilder b(opts);
        b.setFloorPlan(test::makeFloorPlan(8, 6), {});
        b.setMap(emptyMap());
        std::mt19937 rng(5);
        for (int s = 0; s < 10; ++s) {  // 10 steps 1 cm apart: one window (trigger 0.2 m)
            const mrpt::poses::CPose3D pose(2.5 + 0.01 * s, 3.0, 0, 0, 0, 0);
            insertAll(b, test::observe(s == 4 ? with_stray : steady, kClasses, pose, rng), pose);
        }
        b.flush();
        std::map<int, int> per_class;
        for (const auto& o : b.map().objects) ++per_class[o.class_id];
        return per_class;
    };
    // The authors' rule: 1 detection < 0.3 x 10 steps -> dropped; the table (10 of 10) stays.
    auto kept = run(0.3);
    EXPECT_EQ(kept[0], 1);
    EXPECT_EQ(kept[1], 0);
    // Without the rule the stray detection becomes a map object.
    kept = run(0.0);
    EXPECT_EQ(kept[0], 1);
    EXPECT_EQ(kept[1], 1);
}

TEST(ObjectMapBuilder, AnImportedObjectsOwnNoiseIsReadInItsBoxFrame) {
    // A cabinet of a given map, 1.6 m long along its x axis (the class noise frame is turned by
    // 90 deg), with its own noise model as imported maps carry it, in its box frame: sigma 0.5 m
    // along the box x, 0.05 m across. Detections 0.15 m along its x are 0.3 sigma away in that
    // frame (C = 0.11 < tau_cost): they confirm it. Read in the class frame they would be 3 sigma
    // away (C = 0.58) and start a second cabinet. Duplicate merging is off to see the association.
    auto given = emptyMap();
    const auto true_box = makeUprightBox({4.5, 2.0, 0.9}, {1.6, 0.5, 1.8}, 0.0);
    auto cabinet = mapObject(7, 1, true_box, 50);
    simp::model::NoiseModel own;
    own.cov_m2 << 0.25, 0.0, 0.0, 0.0025;
    cabinet.noise = own;
    given.objects.push_back(cabinet);
    auto seen_box = true_box;
    seen_box.center.x() += 0.15;
    std::vector<mrpt::poses::CPose3D> poses;  // 8 windows
    for (int s = 0; s < 8; ++s) poses.emplace_back(0.5 + 0.25 * s, 0.2, 0, 0, 0, 0);
    auto opts = test::testOptions();
    opts.duplicate_center_radius_m = 0.0;
    opts.class_duplicate_center_radius_m.clear();
    opts.duplicate_tau_cost = 0.0;
    opts.duplicate_min_overlap = 0.0;
    ObjectMapBuilder b(opts);
    b.setMap(given);
    insertExact(b, {{1, seen_box}}, poses, 3);
    b.flush();
    ASSERT_EQ(b.map().objects.size(), 1u);
    EXPECT_EQ(b.map().objects[0].id, 7);
    EXPECT_GT(b.map().objects[0].n_match, 50);
}
