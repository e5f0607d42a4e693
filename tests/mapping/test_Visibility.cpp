#include <gtest/gtest.h>
#include <simp/mapping/ObjectMapBuilder.h>
#include <simp/camera/ZBufferVisibility.h>

#include "MappingTestScene.h"

using namespace simp::mapping;
using simp::camera::BoxView;
using simp::camera::PinholeCamera;
using simp::camera::ZBufferParams;
using simp::camera::ZBufferRenderer;
using simp::geometry::makeUprightBox;

namespace {

/// A camera at (x, y, 0.63) looking horizontally along yaw (world).
PinholeCamera cameraAt(double x, double y, double yaw) {
    return PinholeCamera::onRobot(mrpt::math::TPose2D(x, y, yaw), simp::obs::cameraPoseOnRobot(0, 0, 0.63, 0),
                                  simp::camera::defaultIntrinsics());
}

simp::world::ObjectMapData mapOf(const std::vector<simp::geometry::Box3D>& boxes) {
    simp::world::ObjectMapData m;
    m.class_names = {"cabinet"};
    m.class_noise.resize(1);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        simp::world::MapObject o;
        o.id = static_cast<std::int64_t>(i + 1);
        o.box = boxes[i];
        m.objects.push_back(o);
    }
    return m;
}

}  // namespace

TEST(Visibility, RenderedAreaMatchesTheProjection) {
    // A 1 m x 1 m face 3 m ahead, centred on the optical axis: 1/3 * f px per side.
    const PinholeCamera cam = cameraAt(0, 0, 0);
    const auto box = makeUprightBox({3.5, 0, 0.63}, {1.0, 1.0, 1.0}, 0.0);  // front face at x = 3
    ZBufferRenderer r;
    std::vector<BoxView> views;
    ZBufferParams p;
    r.render(cam, {box}, nullptr, p, views);
    const double side_px = 380.0 / 3.0 / p.downscale;  // z-buffer pixels per side
    EXPECT_NEAR(views[0].covered_px, side_px * side_px, 0.25 * side_px * side_px);
    EXPECT_EQ(views[0].visible_px, views[0].covered_px);
    EXPECT_NEAR(views[0].truncated_fraction, 0.0, 1e-12);
    EXPECT_NEAR(views[0].distance_m, 3.5, 1e-9);
}

TEST(Visibility, ObjectBehindAWallIsNotActive) {
    // Wall at x = 5 (door far away at y in [5, 5.8]); robot in the right room looking at -x.
    const auto grid = test::makeFloorPlan(10, 6, 5.0, 5.0, 5.8);
    auto opts = test::testOptions();
    opts.room_policy = RoomUpdatePolicy::All;  // isolate the wall test from the room policy
    ObjectMapBuilder b(opts);
    b.setFloorPlan(grid, {});
    const auto behind = makeUprightBox({3.0, 1.5, 0.5}, {0.6, 0.6, 1.0}, 0.0);
    const auto in_front = makeUprightBox({6.0, 2.6, 0.5}, {0.6, 0.6, 1.0}, 0.0);
    b.setMap(mapOf({behind, in_front}));
    std::vector<bool> active, candidate;
    b.visibility(cameraAt(7.2, 2.0, M_PI), 0, active, candidate);
    EXPECT_FALSE(active[0]);
    EXPECT_FALSE(candidate[0]);
    EXPECT_TRUE(active[1]);
    // Without the floor plan the same object is visible: the wall made the difference.
    ObjectMapBuilder no_walls(opts);
    no_walls.setMap(mapOf({behind, in_front}));
    no_walls.visibility(cameraAt(7.2, 2.0, M_PI), 0, active, candidate);
    EXPECT_TRUE(active[0]);
}

TEST(Visibility, OccludedAndTruncatedObjectsAreNotActive) {
    auto opts = test::testOptions();
    ObjectMapBuilder b(opts);
    const auto big = makeUprightBox({3.0, 0.0, 1.0}, {1.0, 2.0, 2.0}, 0.0);
    const auto hidden = makeUprightBox({5.0, 0.0, 0.5}, {0.5, 0.5, 1.0}, 0.0);
    // 45 deg to the left at 2 m: the horizontal half field of view is atan(324 / 380) = 40 deg.
    const auto edge = makeUprightBox({1.41, 1.41, 0.6}, {0.5, 0.5, 1.2}, 0.0);
    b.setMap(mapOf({big, hidden, edge}));
    std::vector<bool> active, candidate;
    b.visibility(cameraAt(0, 0, 0), 0, active, candidate);
    EXPECT_TRUE(active[0]);
    EXPECT_FALSE(active[1]);
    EXPECT_TRUE(candidate[1]);   // hidden by a box, not by a wall: a detection may still match it
    EXPECT_FALSE(active[2]);     // more than half of its projection is outside the image
    EXPECT_TRUE(candidate[2]);   // ... but partly visible: it may still be associated

    ZBufferRenderer r;
    std::vector<BoxView> views;
    r.render(cameraAt(0, 0, 0), {big, hidden, edge}, nullptr, ZBufferParams{}, views);
    EXPECT_GT(views[2].truncated_fraction, opts.truncation_threshold);
    EXPECT_NEAR(views[1].occludedFraction(), 1.0, 1e-12);
}

TEST(Visibility, ObjectsBehindTheCameraOrOutOfRangeAreNotActive) {
    auto opts = test::testOptions();
    opts.default_filter.max_range_m = 4.0;
    ObjectMapBuilder b(opts);
    b.setMap(mapOf({makeUprightBox({-3.0, 0.0, 0.5}, {0.5, 0.5, 1.0}, 0.0),
                    makeUprightBox({4.5, 0.0, 0.5}, {0.5, 0.5, 1.0}, 0.0)}));
    std::vector<bool> active, candidate;
    b.visibility(cameraAt(0, 0, 0), 0, active, candidate);
    EXPECT_FALSE(candidate[0]);
    EXPECT_FALSE(active[1]);   // 4.5 m > 4 m range
    EXPECT_TRUE(candidate[1]);
}

TEST(Visibility, IntersectingBoxesDoNotHideEachOtherWhenGrouped) {
    // A duplicate 0.3 m behind its twin: hidden while intersecting boxes occlude (the default);
    // with intersecting_boxes_occlude = false both are active, a separate box behind still is not.
    const auto twin = makeUprightBox({3.0, 0.0, 0.5}, {1.0, 1.0, 1.0}, 0.0);
    const auto dup = makeUprightBox({3.3, 0.0, 0.5}, {1.0, 1.0, 1.0}, 0.0);
    const auto behind = makeUprightBox({5.0, 0.0, 0.4}, {0.5, 0.5, 0.8}, 0.0);
    const auto activeWith = [&](const MappingOptions& opts) {
        ObjectMapBuilder b(opts);
        b.setMap(mapOf({twin, dup, behind}));
        std::vector<bool> active, candidate;
        b.visibility(cameraAt(0, 0, 0), 0, active, candidate);
        return active;
    };
    auto opts = test::testOptions();
    EXPECT_EQ(activeWith(opts), (std::vector<bool>{true, false, false}));
    opts.intersecting_boxes_occlude = false;
    EXPECT_EQ(activeWith(opts), (std::vector<bool>{true, true, false}));
    // the renderer with groups: visible pixels of the grouped pair are all their covered pixels
    ZBufferRenderer r;
    std::vector<BoxView> views;
    ZBufferParams p;
    const std::vector<int> group{0, 0, 2};
    p.group = &group;
    r.render(cameraAt(0, 0, 0), {twin, dup, behind}, nullptr, p, views);
    EXPECT_EQ(views[1].visible_px, views[1].covered_px);
    EXPECT_NEAR(views[2].occludedFraction(), 1.0, 1e-12);
}
