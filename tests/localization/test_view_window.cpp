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

// Map objects of the synthetic world (SyntheticScenario.cpp): room 2 holds the table (7.2, 2.0)
// and the chair (8.0, 2.6); the wall x = 5.0 .. 5.1 separates it from room 1 at y = 2.
constexpr int kTable = 6, kChair = 8;

}  // namespace

TEST(ViewWindow, CountsTheViewsAPoseShouldShowAndTheOnesShown) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    ViewWindow views({}, w.floorplan);
    // The odometry frame is the world here. Frame 1 in room 2 sees the table 0.6 m and the chair
    // 1.5 m ahead; frame 2, 2.5 m behind it in room 1, "detects" both through the wall, which only
    // teaches their classes' ranges (table 0.6 .. 3.1 m, chair 1.5 .. 3.95 m).
    const mrpt::poses::CPose2D r1(6.5, 2.0, 0.0), r2(4.0, 2.0, 0.0);
    views.add(*map, observe(w, r1.asTPose(), {kTable, kChair}), r1, 0.0);
    views.add(*map, observe(w, r2.asTPose(), {kTable, kChair}), r2, 0.5);
    // At the true place: frame 1 should show both and does; frame 2 shows nothing through the wall.
    const auto right = views.recallAt(*map, r2, r2, 0.5);
    EXPECT_EQ(right.expected, 2u);
    EXPECT_EQ(right.seen, 2u);
    // A frame without any detection at the place of frame 1: two more views, none shown.
    views.add(*map, observe(w, r1.asTPose(), {}), r1, 1.0);
    const auto with_empty = views.recallAt(*map, r1, r1, 1.0);
    EXPECT_EQ(with_empty.expected, 4u);
    EXPECT_EQ(with_empty.seen, 2u);
    // The same way in room 4, facing -y: frame 1 lands at (11, 2.5), where the table (12, 1) is in
    // view 1.7 m away and no detection lands near it; the others face walls or nothing.
    const mrpt::poses::CPose2D elsewhere(11.0, 2.5, -M_PI / 2);
    const auto wrong = views.recallAt(*map, elsewhere, r1, 1.0);
    EXPECT_GE(wrong.expected, 2u);  // the table from frames 1 and 3
    EXPECT_EQ(wrong.seen, 0u);
    // Frames older than max_age_s leave; clear() forgets the frames, not the classes' ranges.
    EXPECT_EQ(views.recallAt(*map, r1, r1, 1.0 + ViewWindowParams{}.max_age_s + 1.0).expected, 0u);
    views.clear();
    EXPECT_EQ(views.recallAt(*map, r1, r1, 1.0).expected, 0u);
    views.add(*map, observe(w, r1.asTPose(), {}), r1, 2.0);
    EXPECT_EQ(views.recallAt(*map, r1, r1, 2.0).expected, 2u);
}

TEST(ViewWindow, ExpectsOnlyClassesTheDetectorShowedWithinTheirRange) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    ViewWindow views({}, w.floorplan);
    const mrpt::poses::CPose2D r1(6.5, 2.0, 0.0);
    // Only the table was ever detected, at 0.6 m: the chair in view is no class the detector
    // reports, and a table farther than 0.6 m would be out of its range.
    views.add(*map, observe(w, r1.asTPose(), {kTable}), r1, 0.0);
    auto r = views.recallAt(*map, r1, r1, 0.0);
    EXPECT_EQ(r.expected, 1u);
    EXPECT_EQ(r.seen, 1u);
    const mrpt::poses::CPose2D back(6.0, 2.0, 0.0);  // the table 1.1 m away: beyond its range so far
    EXPECT_EQ(views.recallAt(*map, back, r1, 0.0).expected, 0u);
    // max_range_m caps the learnt range.
    ViewWindowParams near;
    near.max_range_m = 0.5;
    ViewWindow capped(near, w.floorplan);
    capped.add(*map, observe(w, r1.asTPose(), {kTable}), r1, 0.0);
    EXPECT_EQ(capped.recallAt(*map, r1, r1, 0.0).expected, 0u);
}
