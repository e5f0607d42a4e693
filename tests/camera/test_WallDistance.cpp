// WallDistance: the distance of each grid cell to its nearest obstacle cell, and its gradient.
#include <gtest/gtest.h>
#include <simp/camera/WallDistance.h>

#include <cmath>

namespace {

/// 10 m x 4 m of free floor (0.05 m cells) with one wall: the cells of x in [5.0, 5.2).
mrpt::maps::COccupancyGridMap2D gridWithAWall() {
    mrpt::maps::COccupancyGridMap2D g(0.0f, 10.0f, 0.0f, 4.0f, 0.05f);
    for (unsigned cy = 0; cy < g.getSizeY(); ++cy)
        for (unsigned cx = 0; cx < g.getSizeX(); ++cx) g.setCell(static_cast<int>(cx), static_cast<int>(cy), 1.0f);
    for (unsigned cy = 0; cy < g.getSizeY(); ++cy)
        for (int cx = 100; cx < 104; ++cx) g.setCell(cx, static_cast<int>(cy), 0.0f);
    return g;
}

}  // namespace

TEST(WallDistance, DistanceToTheNearestWallCellAndItsNormal) {
    const simp::camera::WallDistance d(gridWithAWall());
    EXPECT_DOUBLE_EQ(d.at(5.1, 2.0), 0.0);              // in the wall
    EXPECT_NEAR(d.at(4.0 + 0.025, 2.0), 1.00, 1e-3);    // cell 80: 20 cells (centre to centre) from cell 100
    EXPECT_NEAR(d.at(6.0 + 0.025, 2.0), 0.85, 1e-3);    // cell 120: 17 cells right of cell 103
    EXPECT_TRUE(std::isinf(d.at(-1.0, 2.0)));          // outside the grid
    EXPECT_TRUE(std::isinf(d.at(3.0, 4.5)));
    // the gradient points away from the wall, along x only
    const Eigen::Vector2d left = d.gradient(4.0, 2.0), right = d.gradient(6.0, 2.0);
    EXPECT_LT(left.x(), 0.0);
    EXPECT_GT(right.x(), 0.0);
    EXPECT_NEAR(left.y(), 0.0, 1e-6);
    EXPECT_NEAR(right.y(), 0.0, 1e-6);
    EXPECT_NEAR(right.x(), 0.1, 1e-3);  // two cells of 0.05 m apart
    // zero on the border cells and outside
    EXPECT_EQ(d.gradient(0.01, 2.0), Eigen::Vector2d::Zero());
    EXPECT_EQ(d.gradient(-3.0, 2.0), Eigen::Vector2d::Zero());
}

TEST(WallDistance, TheObstacleThresholdIsAParameter) {
    auto g = gridWithAWall();
    g.setCell(20, 40, 0.4f);  // below 0.5 (the default): an obstacle; not below 0.35
    const simp::camera::WallDistance default_rule(g), wall_rule(g, 0.35f);
    const double x = 20 * 0.05 + 0.025, y = 40 * 0.05 + 0.025;
    EXPECT_DOUBLE_EQ(default_rule.at(x, y), 0.0);
    EXPECT_GT(wall_rule.at(x, y), 1.0);
}
