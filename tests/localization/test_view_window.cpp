/// ViewWindow: the views of map objects the camera frames since `lost` should have shown at a pose,
/// and how many a detection showed.

#include "SyntheticScenario.h"
#include "TestUtil.h"

#include <gtest/gtest.h>
#include <simp/localization/ViewWindow.h>

#include <cmath>

using namespace simp::localization;
using namespace simp::localization::test;

namespace {

// The table of room 2 (7.2, 2.0) in the synthetic world (SyntheticScenario.cpp); room 1 lies
// behind the wall x = 5.0 .. 5.1, room 4 holds the other table (12.0, 1.0).
constexpr int kTable = 6;

/// Frames that only teach the table class its range (1.0 .. 3.0 m ahead), then forgotten.
void teachTableRange(ViewWindow& views, const simp::world::World& w, const simp::maps::CObjectMap& map) {
    const mrpt::poses::CPose2D near(6.1, 2.0, 0.0), far(4.1, 2.0, 0.0);  // cameras 0.1 m ahead of the robot
    views.add(map, observe(w, near.asTPose(), {kTable}), near, 0.0);
    views.add(map, observe(w, far.asTPose(), {kTable}), far, 0.0);
    views.clear();
}

}  // namespace

TEST(ViewWindow, CountsTheViewsAPoseShouldShowAndTheOnesShown) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    ViewWindowParams p;
    p.seen_radius_m = 0.3;
    ViewWindow views(p, w.floorplan);
    teachTableRange(views, w, *map);
    // The odometry frame is the world here. Frame A in room 1 (the table 2.5 m ahead, within its
    // range, but behind the wall), frame B in room 2 with the table 1.5 m ahead, detected.
    const mrpt::poses::CPose2D r2(4.6, 2.0, 0.0), r1(5.6, 2.0, 0.0);
    views.add(*map, observe(w, r2.asTPose(), {}), r2, 1.0);
    views.add(*map, observe(w, r1.asTPose(), {kTable}), r1, 1.5);
    // At the true place: B should show the table and does; A shows nothing through the wall.
    const auto right = views.recallAt(*map, r1, r1, 1.5);
    EXPECT_EQ(right.expected, 1u);
    EXPECT_EQ(right.seen, 1u);
    // A frame without any detection at r1: one more view, not shown.
    views.add(*map, observe(w, r1.asTPose(), {}), r1, 2.0);
    const auto with_empty = views.recallAt(*map, r1, r1, 2.0);
    EXPECT_EQ(with_empty.expected, 2u);
    EXPECT_EQ(with_empty.seen, 1u);
    // The same way in room 4: the frames at r1 land at (10, 1), with room 4's table 1.9 m ahead,
    // and B's detection lands 0.4 m short of it; A lands at (9, 1), with that table 2.9 m ahead behind the wall x = 9.5.
    const mrpt::poses::CPose2D elsewhere(10.0, 1.0, 0.0);
    const auto wrong = views.recallAt(*map, elsewhere, r1, 2.0);
    EXPECT_EQ(wrong.expected, 2u);
    EXPECT_EQ(wrong.seen, 0u);
    // Frames older than max_age_s leave; clear() forgets the frames, not the classes' ranges.
    EXPECT_EQ(views.recallAt(*map, r1, r1, 2.0 + p.max_age_s + 1.0).expected, 0u);
    views.clear();
    EXPECT_EQ(views.recallAt(*map, r1, r1, 2.0).expected, 0u);
    views.add(*map, observe(w, r1.asTPose(), {}), r1, 3.0);
    EXPECT_EQ(views.recallAt(*map, r1, r1, 3.0).expected, 1u);
}

TEST(ViewWindow, ExpectsOnlyClassesTheDetectorShowedWithinTheirRange) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    ViewWindow views({}, w.floorplan);
    teachTableRange(views, w, *map);
    // Facing -y towards the table 1.2 m ahead: the chairs in view are of a class the detector never
    // reported, so only the table is expected.
    const mrpt::poses::CPose2D side(7.2, 3.3, -M_PI / 2), back(7.2, 5.3, -M_PI / 2);
    views.add(*map, observe(w, side.asTPose(), {}), side, 1.0);
    EXPECT_EQ(views.recallAt(*map, side, side, 1.0).expected, 1u);
    // 3.2 m away the table is beyond the range its class was detected at.
    EXPECT_EQ(views.recallAt(*map, back, side, 1.0).expected, 0u);
    // max_range_m caps the learnt range.
    ViewWindowParams near;
    near.max_range_m = 1.1;
    ViewWindow capped(near, w.floorplan);
    teachTableRange(capped, w, *map);
    capped.add(*map, observe(w, side.asTPose(), {}), side, 1.0);
    EXPECT_EQ(capped.recallAt(*map, side, side, 1.0).expected, 0u);
}
