#include <gtest/gtest.h>
#include <simp/mapping/RoomSegmentation.h>

#include <simp/world/World.h>

#include <filesystem>
#include <map>

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

TEST(RoomSegmentation, AuthorsOfficeAgainstItsRoomRaster) {
    const std::string dir = std::string(SIMP_SHARED_DATA_DIR) + "/simp-office";
    if (!std::filesystem::exists(dir + "/Map.yaml") || !std::filesystem::exists(dir + "/roomseg.png"))
        GTEST_SKIP() << "the authors' data " << dir << " is absent (Map.yaml, roomseg.png)";
    mrpt::maps::COccupancyGridMap2D grid;
    simp::world::loadRosMap(dir + "/Map.yaml", grid);
    const auto meta = simp::world::readRosMapYaml(dir + "/Map.yaml");
    const auto truth = simp::world::loadRoomMap(dir + "/roomseg.png", meta.resolution_m, meta.origin_x_m, meta.origin_y_m);
    MappingOptions defaults;
    const auto rooms = segmentRooms(grid, RoomSegmentationParams{defaults.room_door_width_m, defaults.room_min_area_m2, 0.65});
    // Purity: fraction of segmented pixels that fall in the majority true room of their segment.
    std::map<int, std::map<int, int>> counts;
    for (int r = 0; r < rooms.ids.rows; ++r)
        for (int c = 0; c < rooms.ids.cols; ++c)
            if (rooms.ids(r, c) && truth.ids(r, c)) ++counts[rooms.ids(r, c)][truth.ids(r, c)];
    long total = 0, majority = 0;
    for (const auto& [id, m] : counts) {
        int best = 0;
        for (const auto& [t, n] : m) total += n, best = std::max(best, n);
        majority += best;
    }
    ASSERT_GT(total, 0);
    // Measured 9 rooms of 12 and purity 0.78 (doc/mapping.md); a 1 m erosion gives 4 rooms, 0.45.
    EXPECT_GE(countRooms(rooms), 7);
    EXPECT_GT(static_cast<double>(majority) / total, 0.7);
}
