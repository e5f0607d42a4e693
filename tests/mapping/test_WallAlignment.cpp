#include <gtest/gtest.h>
#include <simp/mapping/ObjectMapBuilder.h>
#include <simp/mapping/WallAlignment.h>

#include "MappingTestScene.h"

using namespace simp::mapping;
using simp::geometry::Box3D;
using simp::geometry::makeUprightBox;
using simp::geometry::yawOf;

namespace {

// Floor [0, 10] x [0, 6]; inner wall at x = 5 with a door for y in (2.6, 3.4). The grid stores
// its geometry in float: positions agree to 1e-6 m.
const auto kGrid = test::makeFloorPlan(10, 6, 5.0, 2.6, 3.4);
const simp::camera::FloorPlanGrid kWalls(kGrid);
// Wall faces that bound the left room, from the grid's own cells (makeFloorPlan: two cells per wall).
const double kRes = kGrid.getResolution();
const double kFaceY0 = kGrid.idx2y(kGrid.y2idx(0.0)) + 0.5 * kRes;    // the floor's lower wall
const double kFaceX0 = kGrid.idx2x(kGrid.x2idx(0.0)) + 0.5 * kRes;    // the floor's left wall
const double kFaceInner = kGrid.idx2x(kGrid.x2idx(5.0) - 1) - 0.5 * kRes;  // the inner wall, left room side

// A cabinet 1.0 m wide (along x), 0.45 m deep, whose back side (-y) is `gap` in front of the lower wall.
Box3D cabinetAtGap(double gap, double x = 2.0, double yaw = 0.0) {
    return makeUprightBox({x, kFaceY0 + gap + 0.225, 0.8}, {1.0, 0.45, 1.6}, yaw);
}

/// A builder on the test floor plan with an empty map of one class.
ObjectMapBuilder builderOnTestFloor(const MappingOptions& opts, const std::string& class_name) {
    ObjectMapBuilder b(opts);
    b.setFloorPlan(kGrid, {});
    simp::world::ObjectMapData m;
    m.class_names = {class_name};
    m.class_noise.resize(1);
    b.setMap(m);
    return b;
}

}  // namespace

TEST(WallAlignment, WallFacesOfTheTestGrid) {
    // The expected faces are where a ray from the room meets the first wall cell.
    EXPECT_NEAR(2.0 - kWalls.castRay({2.0, 2.0}, {0, -1}, 5.0), kFaceY0, 1e-6);
    EXPECT_NEAR(2.0 - kWalls.castRay({2.0, 2.0}, {-1, 0}, 5.0), kFaceX0, 1e-6);
    EXPECT_NEAR(2.0 + kWalls.castRay({2.0, 1.0}, {1, 0}, 5.0), kFaceInner, 1e-6);
}

TEST(WallAlignment, SideInFrontOfAWallIsMovedFlush) {
    const WallAlignmentParams p;  // max gap 0.3 m
    for (const double gap : {0.12, 0.29, -0.1, -0.28}) {  // in front of the face, and inside the wall
        const auto c = wallContact(cabinetAtGap(gap), 1, -1, kWalls, p);
        ASSERT_TRUE(c.has_value()) << gap;
        EXPECT_NEAR(c->gap_m, gap, 1e-6);
        EXPECT_NEAR(c->slope, 0.0, 1e-9);
        EXPECT_EQ(c->hits, p.rays_per_side);
        const Box3D a = alignToWalls(cabinetAtGap(gap), kWalls, p);
        EXPECT_NEAR(a.center.y() - 0.225, kFaceY0, 1e-6) << gap;  // back side on the wall face
        EXPECT_NEAR(a.center.x(), 2.0, 1e-6);
        EXPECT_NEAR(a.center.z(), 0.8, 1e-9);
        EXPECT_TRUE(a.size.isApprox(Eigen::Vector3d(1.0, 0.45, 1.6)));
        EXPECT_NEAR(yawOf(a), 0.0, 1e-6);
    }
}

TEST(WallAlignment, FarFromEveryWallIsUnchanged) {
    const WallAlignmentParams p;
    for (const double gap : {0.31, 0.6, -0.35}) {
        EXPECT_FALSE(wallContact(cabinetAtGap(gap), 1, -1, kWalls, p).has_value()) << gap;
        const Box3D a = alignToWalls(cabinetAtGap(gap), kWalls, p);
        EXPECT_TRUE(a.center.isApprox(cabinetAtGap(gap).center)) << gap;
        EXPECT_TRUE(a.R.isApprox(cabinetAtGap(gap).R)) << gap;
    }
    // A bigger per-class gap reaches it.
    WallAlignmentParams wide;
    wide.max_gap_m = 0.7;
    EXPECT_NEAR(alignToWalls(cabinetAtGap(0.6), kWalls, wide).center.y() - 0.225, kFaceY0, 1e-6);
}

TEST(WallAlignment, SlightlyTurnedBoxIsTurnedParallel) {
    const WallAlignmentParams p;  // up to 0.2 rad
    for (const double yaw : {0.08, -0.15}) {
        const Box3D a = alignToWalls(cabinetAtGap(0.1, 2.0, yaw), kWalls, p);
        EXPECT_NEAR(yawOf(a), 0.0, 1e-6) << yaw;
        EXPECT_NEAR(a.center.y() - 0.225, kFaceY0, 1e-6) << yaw;
    }
    // Standing at an angle to the wall (0.35 rad): not against it, left alone.
    const Box3D oblique = cabinetAtGap(0.1, 2.0, 0.35);
    const Box3D a = alignToWalls(oblique, kWalls, p);
    EXPECT_TRUE(a.center.isApprox(oblique.center));
    EXPECT_NEAR(yawOf(a), 0.35, 1e-6);
}

TEST(WallAlignment, BoxInACornerTouchesBothWalls) {
    const WallAlignmentParams p;
    // 0.15 m from the lower wall and 0.1 m into the left wall.
    const Box3D corner = cabinetAtGap(0.15, kFaceX0 - 0.1 + 0.5);
    const Box3D a = alignToWalls(corner, kWalls, p);
    EXPECT_NEAR(a.center.y() - 0.225, kFaceY0, 1e-6);
    EXPECT_NEAR(a.center.x() - 0.5, kFaceX0, 1e-6);
}

TEST(WallAlignment, SideFacingADoorGapIsNotAligned) {
    const WallAlignmentParams p;
    // A 0.6 m long sideboard along the inner wall (long side along y), 0.1 m from it, centred
    // on the door: every ray passes through the opening.
    const Box3D in_door = makeUprightBox({kFaceInner - 0.1 - 0.2, 3.0, 0.5}, {0.4, 0.6, 1.0}, 0.0);
    EXPECT_FALSE(wallContact(in_door, 0, 1, kWalls, p).has_value());
    EXPECT_TRUE(alignToWalls(in_door, kWalls, p).center.isApprox(in_door.center));
    // The same beside the door: aligned.
    const Box3D beside = makeUprightBox({kFaceInner - 0.1 - 0.2, 1.5, 0.5}, {0.4, 0.6, 1.0}, 0.0);
    EXPECT_NEAR(alignToWalls(beside, kWalls, p).center.x() + 0.2, kFaceInner, 1e-6);
}

TEST(WallAlignment, NoFloorPlanOrBadParametersChangeNothing) {
    const Box3D b = cabinetAtGap(0.1);
    EXPECT_TRUE(alignToWalls(b, simp::camera::FloorPlanGrid(), WallAlignmentParams()).center.isApprox(b.center));
    WallAlignmentParams one_ray;
    one_ray.rays_per_side = 1;
    EXPECT_TRUE(alignToWalls(b, kWalls, one_ray).center.isApprox(b.center));
}

TEST(WallAlignment, BuilderPutsACabinetSeenOffTheWallAgainstIt) {
    // Every detection of the cabinet sits 0.12 m in front of the wall (a persistent detector error,
    // which averaging cannot remove); the floor-plan prior puts the map box on the wall.
    const std::vector<std::string> classes = {"cabinet"};
    const std::vector<test::TrueObject> seen = {{0, cabinetAtGap(0.12)}};
    const auto run = [&](bool wall_align) {
        auto opts = test::testOptions();
        opts.wall_align = wall_align ? WallAlignMode::Auto : WallAlignMode::Off;
        ObjectMapBuilder b = builderOnTestFloor(opts, classes[0]);
        std::mt19937 rng(3);
        for (int s = 0; s < 20; ++s) {
            const mrpt::poses::CPose3D pose(1.0 + 0.1 * s, 3.0, 0, -M_PI / 2, 0, 0);  // facing the wall
            for (const auto& o : test::observe(seen, classes, pose, rng, test::DetectionNoise{0.01, 0.01, 0.01}))
                b.insert(o, pose);
        }
        b.flush();
        return b.confirmedMap();
    };
    const auto aligned = run(true);
    ASSERT_EQ(aligned.objects.size(), 1u);
    EXPECT_NEAR(aligned.objects[0].box.center.y() - 0.225, kFaceY0, 0.01);
    // parallel to the wall (the builder's canonical frame may turn the box by 90 deg)
    EXPECT_NEAR(std::sin(2.0 * yawOf(aligned.objects[0].box)), 0.0, 0.02);
    const auto raw = run(false);
    ASSERT_EQ(raw.objects.size(), 1u);
    EXPECT_NEAR(raw.objects[0].box.center.y() - 0.225, kFaceY0 + 0.12, 0.01);
}

TEST(ObjectMapBuilder, TentativeObjectsStayOutOfTheConfirmedMap) {
    const std::vector<std::string> classes = {"table"};
    const std::vector<test::TrueObject> truth = {{0, makeUprightBox({2.5, 3.0, 0.375}, {1.2, 0.8, 0.75}, 0.0)}};
    auto opts = test::testOptions();
    ASSERT_EQ(opts.min_confirmed_matches, 3);
    ObjectMapBuilder b = builderOnTestFloor(opts, classes[0]);
    std::mt19937 rng(4);
    const mrpt::poses::CPose3D pose(1.0, 3.0, 0, 0, 0, 0);  // front camera sees the table
    int detections = 0;
    for (int k = 1; k <= 3; ++k) {
        for (const auto& o : test::observe(truth, classes, pose, rng, test::DetectionNoise{0, 0, 0})) {
            detections += static_cast<int>(o.size());
            b.insert(o, pose);
        }
        b.flush();
        ASSERT_EQ(detections, k);  // one camera sees it
        ASSERT_EQ(b.map().objects.size(), 1u);
        EXPECT_EQ(b.map().objects[0].n_match, k);
        EXPECT_EQ(b.confirmedMap().objects.size(), k >= 3 ? 1u : 0u) << k << " detections";
    }
    opts.min_confirmed_matches = 1;
    b.options() = opts;
    EXPECT_EQ(b.confirmedMap().objects.size(), 1u);

    // A burst from one viewpoint is no confirmation: 6 detections in one window stay tentative
    // until the object is matched in min_confirmed_windows = 2 windows.
    ObjectMapBuilder burst = builderOnTestFloor(test::testOptions(), classes[0]);
    ASSERT_EQ(burst.options().min_confirmed_windows, 2);
    for (int window = 1; window <= 3; ++window) {
        for (int k = 0; k < (window == 1 ? 6 : 1); ++k)
            for (const auto& o : test::observe(truth, classes, pose, rng, test::DetectionNoise{0, 0, 0})) burst.insert(o, pose);
        burst.flush();
        ASSERT_EQ(burst.map().objects.size(), 1u);
        EXPECT_EQ(burst.confirmedMap().objects.size(), window >= 2 ? 1u : 0u) << window << " windows";
    }
    EXPECT_EQ(burst.map().objects[0].n_match, 8);
    burst.options().min_confirmed_windows = 4;
    EXPECT_EQ(burst.confirmedMap().objects.size(), 0u);
    burst.options().min_confirmed_windows = 1;
    EXPECT_EQ(burst.confirmedMap().objects.size(), 1u);

    // Objects of the map the builder is given (a ground-truth map: one "detection" each) are
    // established content, not tentative ones.
    simp::world::ObjectMapData given;
    given.class_names = classes;
    given.class_noise.resize(1);
    simp::world::MapObject table;
    table.id = 7;
    table.class_id = 0;
    table.box = truth[0].box;
    table.n_match = 1;
    given.objects.push_back(table);
    ObjectMapBuilder updating(test::testOptions());
    updating.setFloorPlan(kGrid, {});
    updating.setMap(given);
    ASSERT_EQ(updating.confirmedMap().objects.size(), 1u);
    EXPECT_EQ(updating.confirmedMap().objects[0].id, 7);
}

TEST(ObjectMapBuilder, DetectionOutsideTheBuildingIsRejected) {
    // A depth error puts the cabinet 0.3 m behind the outer wall (unknown cells of the floor
    // plan); the room lookup's search radius would give it the room in front of the wall.
    const std::vector<std::string> classes = {"cabinet"};
    const auto run = [&](double y) {
        ObjectMapBuilder b = builderOnTestFloor(test::testOptions(), classes[0]);
        std::mt19937 rng(9);
        const std::vector<test::TrueObject> seen = {{0, makeUprightBox({2.0, y, 0.8}, {1.0, 0.45, 1.6}, 0.0)}};
        const mrpt::poses::CPose3D pose(2.0, 2.0, 0, -M_PI / 2, 0, 0);  // front camera faces the wall
        for (const auto& o : test::observe(seen, classes, pose, rng, test::DetectionNoise{0, 0, 0})) b.insert(o, pose);
        b.flush();
        return b;
    };
    const ObjectMapBuilder outside = run(kFaceY0 - 0.3);
    EXPECT_EQ(outside.stats().detections, 1u);
    EXPECT_EQ(outside.stats().rejected_outside, 1u);
    EXPECT_TRUE(outside.map().objects.empty());
    const ObjectMapBuilder inside = run(kFaceY0 + 0.3);  // the same in front of the wall
    EXPECT_EQ(inside.stats().rejected_outside, 0u);
    EXPECT_EQ(inside.map().objects.size(), 1u);
}

TEST(WallAlignment, AutoIsOffOnAFloorPlanThatDrawsFurniture) {
    // The authors' GT rendering draws furniture into the floor plan: walls around unknown cells.
    // There a drawn board's front face passes for the wall, so auto leaves the boxes alone.
    auto grid = test::makeFloorPlan(10, 6, 5.0, 2.6, 3.4);
    const auto drawBlock = [&](double x0, double y0, double x1, double y1) {  // outline + unknown interior
        for (int cy = grid.y2idx(y0); cy <= grid.y2idx(y1); ++cy)
            for (int cx = grid.x2idx(x0); cx <= grid.x2idx(x1); ++cx) {
                const bool edge = cx == grid.x2idx(x0) || cx == grid.x2idx(x1) || cy == grid.y2idx(y0) || cy == grid.y2idx(y1);
                grid.setCell(cx, cy, edge ? 0.0f : 0.5f);
            }
    };
    drawBlock(6.0, 1.0, 7.6, 2.0);  // a drawn table of 1.6 m x 1.0 m
    // interior: (1.6 - one cell) x (1.0 - one cell) inside the one-cell outline
    EXPECT_NEAR(simp::camera::FloorPlanGrid(grid).enclosedUnknownArea_m2(), 1.55 * 0.95, 1e-6);
    EXPECT_NEAR(kWalls.enclosedUnknownArea_m2(), 0.0, 1e-12);
    auto opts = test::testOptions();
    ObjectMapBuilder plain(opts);
    plain.setFloorPlan(kGrid, {});
    EXPECT_TRUE(plain.wallAlignmentActive());
    ObjectMapBuilder drawn(opts);
    drawn.setFloorPlan(grid, {});
    EXPECT_FALSE(drawn.wallAlignmentActive());
    opts.wall_align = WallAlignMode::On;
    ObjectMapBuilder forced(opts);
    forced.setFloorPlan(grid, {});
    EXPECT_TRUE(forced.wallAlignmentActive());
    opts.wall_align = WallAlignMode::Off;
    ObjectMapBuilder off(opts);
    off.setFloorPlan(kGrid, {});
    EXPECT_FALSE(off.wallAlignmentActive());
    // A detection centred in the drawn table (unknown, but enclosed) is inside the building.
    EXPECT_FALSE(simp::camera::FloorPlanGrid(grid).isOutside(6.6, 1.5));
    EXPECT_TRUE(simp::camera::FloorPlanGrid(grid).isOutside(-0.3, 3.0));
}
