#include <gtest/gtest.h>
#include <simp/mapping/RoomSegmentation.h>

#include "MappingTestScene.h"

using namespace simp::mapping;

namespace {
int idAt(const simp::world::RoomMap& r, double x, double y) {
    const int col = static_cast<int>(std::floor((x - r.origin_x_m) / r.resolution_m));
    const int row = r.ids.rows - 1 - static_cast<int>(std::floor((y - r.origin_y_m) / r.resolution_m));
    return r.ids(row, col);
}
}  // namespace

TEST(RoomSegmentation, TwoRoomsJoinedByADoorGiveTwoRooms) {
    // 10 m x 6 m, wall at x = 5 with a 0.8 m door; erosion closes openings up to 1 m.
    const auto grid = test::makeFloorPlan(10, 6, 5.0, 2.6, 3.4);
    const simp::world::RoomMap rooms = segmentRooms(grid, RoomSegmentationParams{1.0, 1.0, 0.65});
    EXPECT_EQ(countRooms(rooms), 2);
    const int left = idAt(rooms, 2.5, 3.0), right = idAt(rooms, 7.5, 3.0);
    EXPECT_NE(left, 0);
    EXPECT_NE(right, 0);
    EXPECT_NE(left, right);
    // Labels grow back over all the free space: corners and the door itself are labelled.
    EXPECT_EQ(idAt(rooms, 0.2, 0.2), left);
    EXPECT_EQ(idAt(rooms, 9.8, 5.8), right);
    EXPECT_NE(idAt(rooms, 5.0, 3.0), 0);
    // Walls stay 0; the raster is aligned with the grid.
    EXPECT_EQ(idAt(rooms, 5.0, 1.0), 0);
    EXPECT_EQ(rooms.ids.cols, static_cast<int>(grid.getSizeX()));
    EXPECT_EQ(rooms.ids.rows, static_cast<int>(grid.getSizeY()));
}

TEST(RoomSegmentation, AnOpeningWiderThanADoorJoinsTheRooms) {
    const auto grid = test::makeFloorPlan(10, 6, 5.0, 1.0, 4.0);  // 3 m opening
    EXPECT_EQ(countRooms(segmentRooms(grid, RoomSegmentationParams{1.0, 1.0, 0.65})), 1);
}

TEST(RoomSegmentation, SmallComponentsAreNotRooms) {
    const auto grid = test::makeFloorPlan(10, 6, 5.0, 2.6, 3.4);
    // Both rooms are 5 m x 6 m (~ 30 m^2 before erosion): a 40 m^2 minimum drops them.
    EXPECT_EQ(countRooms(segmentRooms(grid, RoomSegmentationParams{1.0, 40.0, 0.65})), 0);
}

TEST(RoomSegmentation, NoFreeSpaceGivesNoRoom) {
    mrpt::maps::COccupancyGridMap2D unknown(0.0f, 4.0f, 0.0f, 4.0f, 0.05f);  // all cells 0.5 = unknown
    EXPECT_EQ(countRooms(segmentRooms(unknown)), 0);
}

TEST(RoomSegmentation, BadParametersThrow) {
    const auto grid = test::makeFloorPlan(4, 4);
    EXPECT_THROW(segmentRooms(grid, RoomSegmentationParams{std::nan(""), 1.0, 0.65}), std::invalid_argument);
    EXPECT_THROW(segmentRooms(grid, RoomSegmentationParams{1.0, -1.0, 0.65}), std::invalid_argument);
}
