/// The floor-plan grid: thresholds on P(free), wall ray casting, clearing walls under objects.
#include <gtest/gtest.h>
#include <simp/camera/FloorPlanGrid.h>

#include <cmath>

using namespace simp::camera;

namespace {

/// 4 m x 2 m at 0.1 m, free, with a wall column at x in [2.0, 2.1) and one cell of each value.
mrpt::maps::COccupancyGridMap2D testGrid() {
    mrpt::maps::COccupancyGridMap2D g(0, 4, 0, 2, 0.1f);
    g.fill(1.0f);
    for (int cy = 0; cy < static_cast<int>(g.getSizeY()); ++cy) g.setCell(20, cy, 0.0f);
    g.setCell(5, 5, 0.5f);  // unknown: neither wall nor free
    g.setCell(6, 5, 0.3f);  // below kWallMaxFree: wall
    g.setCell(7, 5, 0.6f);  // between the thresholds: neither
    return g;
}

}  // namespace

TEST(FloorPlanGrid, ThresholdsClassifyCells) {
    const FloorPlanGrid w(testGrid());
    EXPECT_TRUE(w.isWall(2.05, 1.0));
    EXPECT_FALSE(w.isWall(0.55, 0.55));   // unknown does not occlude
    EXPECT_FALSE(w.isFree(0.55, 0.55));
    EXPECT_TRUE(w.isWall(0.65, 0.55));
    EXPECT_FALSE(w.isWall(0.75, 0.55));
    EXPECT_FALSE(w.isFree(0.75, 0.55));
    EXPECT_TRUE(w.isFree(1.05, 1.05));
    EXPECT_LT(floorplan::kWallMaxFree, floorplan::kUnknownFree);
    EXPECT_DOUBLE_EQ(floorplan::kFreeMinFree, 1.0 - floorplan::kWallMaxFree);
}

TEST(FloorPlanGrid, CastRayStopsAtTheFirstWallCell) {
    const FloorPlanGrid w(testGrid());
    EXPECT_NEAR(w.castRay({1.0, 1.0}, {1.0, 0.0}, 10.0), 1.0, 1e-6);  // float resolution
    EXPECT_NEAR(w.castRay({1.0, 1.0}, {2.0, 0.0}, 10.0), 1.0, 1e-6);  // direction need not be unit
    EXPECT_TRUE(std::isinf(w.castRay({1.0, 1.0}, {1.0, 0.0}, 0.9)));  // beyond max distance
    EXPECT_TRUE(std::isinf(w.castRay({1.0, 1.5}, {-1.0, 0.0}, 10.0)));
    EXPECT_NEAR(w.castRay({1.0, 0.5}, {1.0, 1.0}, 10.0), std::sqrt(2.0), 1e-6);  // 45 deg: 1 m in x
}

TEST(FloorPlanGrid, ClearWallsUnderABoxOpensItsFootprint) {
    FloorPlanGrid w(testGrid());
    // A 0.4 m box centred on the wall column at y = 1: its footprint + 0.1 m margin is no wall.
    const auto box = simp::geometry::makeUprightBox({2.05, 1.0, 0.5}, {0.4, 0.4, 1.0}, 0.0);
    w.clearWallsUnder({box}, 0.1);
    EXPECT_FALSE(w.isWall(2.05, 1.0));
    EXPECT_FALSE(w.isWall(2.05, 1.25));  // inside the margin
    EXPECT_TRUE(w.isWall(2.05, 1.45));   // beyond it
    EXPECT_TRUE(std::isinf(w.castRay({1.0, 1.0}, {1.0, 0.0}, 10.0)));
    EXPECT_NEAR(w.castRay({1.0, 0.3}, {1.0, 0.0}, 10.0), 1.0, 1e-6);  // float resolution
}
