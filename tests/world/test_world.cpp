// Room raster lookup and IO, and the world directory (load/save, missing parts).
#include "TestUtil.h"

#include <gmock/gmock.h>
#include <opencv2/imgcodecs.hpp>
#include <simp/obs/ObjectClasses.h>
#include <simp/world/World.h>

using namespace simp::world;
using simp_test::freshDir;
using simp_test::errorOf;
using ::testing::HasSubstr;

namespace {

/// 3 x 2 rooms raster at 0.5 m, origin (10, -4): top row 1 1 2, bottom row 0 3 3.
RoomMap smallRooms() {
    RoomMap r;
    r.ids = cv::Mat1w(2, 3);
    r.ids << 1, 1, 2, 0, 3, 3;
    r.resolution_m = 0.5;
    r.origin_x_m = 10.0;
    r.origin_y_m = -4.0;
    return r;
}

World smallWorld() {
    World w;
    setGridExactly(w.floorplan, 10.0, -4.0, 3, 2, 0.5, 0.0f);
    w.floorplan.setCell(0, 0, 1.0f);
    w.rooms = smallRooms();
    w.objects.class_names = simp::obs::defaultClassNames();
    w.objects.class_noise.assign(w.objects.class_names.size(), std::nullopt);
    MapObject o;
    o.id = 5;
    o.class_id = 13;
    o.box = simp::geometry::makeUprightBox({10.7, -3.2, 0.375}, {1.6, 0.8, 0.75}, 0.25);
    o.room_id = 1;
    w.objects.objects.push_back(o);
    return w;
}

}  // namespace

TEST(RoomMap, LookupUsesTheFloorPlanGeometry) {
    const RoomMap r = smallRooms();
    // Bottom row (image row 1) covers y in [-4, -3.5); top row y in [-3.5, -3).
    EXPECT_EQ(r.roomAt(10.25, -3.75), 0);
    EXPECT_EQ(r.roomAt(10.75, -3.75), 3);
    EXPECT_EQ(r.roomAt(11.25, -3.75), 3);
    EXPECT_EQ(r.roomAt(10.25, -3.25), 1);
    EXPECT_EQ(r.roomAt(11.49, -3.01), 2);
    // Cell edges: x = 11.0 starts column 2.
    EXPECT_EQ(r.roomAt(11.0, -3.25), 2);
    EXPECT_EQ(r.roomAt(10.999, -3.25), 1);
    // Outside, NaN, empty map.
    EXPECT_EQ(r.roomAt(9.99, -3.25), 0);
    EXPECT_EQ(r.roomAt(11.5, -3.25), 0);
    EXPECT_EQ(r.roomAt(10.5, -3.0), 0);
    EXPECT_EQ(r.roomAt(std::nan(""), -3.25), 0);
    EXPECT_EQ(RoomMap{}.roomAt(10.25, -3.25), 0);
}

TEST(RoomMap, PixelOfAPointAlsoOutsideTheRaster) {
    const RoomMap r = smallRooms();
    int row = -9, col = -9;
    ASSERT_TRUE(r.pixelOf(11.25, -3.75, row, col));  // bottom row, third column
    EXPECT_EQ(row, 1);
    EXPECT_EQ(col, 2);
    EXPECT_EQ(r.roomAtPixel(row, col), r.roomAt(11.25, -3.75));
    // Just left of the raster: column -1, which a search around the point steps from into column 0.
    ASSERT_TRUE(r.pixelOf(9.9, -3.25, row, col));
    EXPECT_EQ(row, 0);
    EXPECT_EQ(col, -1);
    EXPECT_EQ(r.roomAtPixel(row, col), 0);
    EXPECT_EQ(r.roomAtPixel(row, col + 1), 1);
    // Far away stays outside (no integer overflow); not finite: no pixel.
    ASSERT_TRUE(r.pixelOf(1e300, -1e300, row, col));
    EXPECT_EQ(r.roomAtPixel(row, col), 0);
    EXPECT_FALSE(r.pixelOf(std::nan(""), -3.25, row, col));
}

TEST(RoomMap, SixteenBitRoundTripAndEightBitInput) {
    const std::string dir = freshDir();
    RoomMap r = smallRooms();
    r.ids(0, 0) = 1000;  // needs 16 bits
    saveRoomMap(r, dir + "/rooms.png");
    const RoomMap back = loadRoomMap(dir + "/rooms.png", 0.5, 10.0, -4.0);
    EXPECT_EQ(cv::countNonZero(back.ids != r.ids), 0);
    EXPECT_EQ(back.roomAt(10.25, -3.25), 1000);
    cv::Mat1b eight(2, 3);
    eight << 1, 1, 2, 0, 3, 3;
    cv::imwrite(dir + "/rooms8.png", eight);
    EXPECT_EQ(loadRoomMap(dir + "/rooms8.png", 0.5, 10.0, -4.0).roomAt(10.75, -3.75), 3);
}

TEST(RoomMap, BadFiles) {
    const std::string dir = freshDir();
    EXPECT_THAT(errorOf([&] { loadRoomMap(dir + "/none.png", 0.5, 0, 0); }), HasSubstr("none.png: file not found"));
    cv::imwrite(dir + "/colour.png", cv::Mat3b(2, 2, cv::Vec3b(1, 2, 3)));
    EXPECT_THAT(errorOf([&] { loadRoomMap(dir + "/colour.png", 0.5, 0, 0); }),
                HasSubstr("colour.png: expected a single-channel"));
}

TEST(World, SaveLoadRoundTrip) {
    const std::string dir = freshDir() + "/w";
    const World w = smallWorld();
    saveWorld(w, dir);
    for (const char* f : {"floorplan.yaml", "floorplan.png", "rooms.png", "objects.json"})
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
    const World r = loadWorld(dir);
    EXPECT_EQ(r.floorplan.getSizeX(), 3u);
    EXPECT_EQ(r.floorplan.getSizeY(), 2u);
    EXPECT_FLOAT_EQ(r.floorplan.getXMin(), 10.0f);
    EXPECT_FLOAT_EQ(r.floorplan.getYMin(), -4.0f);
    EXPECT_GT(r.floorplan.getCell(0, 0), 0.99f);
    EXPECT_LT(r.floorplan.getCell(1, 0), 0.01f);
    EXPECT_EQ(r.rooms.roomAt(10.75, -3.75), 3);
    EXPECT_DOUBLE_EQ(r.rooms.resolution_m, 0.5);
    ASSERT_EQ(r.objects.objects.size(), 1u);
    EXPECT_EQ(r.objects.objects[0].box.center, w.objects.objects[0].box.center);
}

TEST(World, RoomsAreOptional) {
    const std::string dir = freshDir() + "/w";
    World w = smallWorld();
    w.rooms = RoomMap{};
    saveWorld(w, dir);
    EXPECT_FALSE(std::filesystem::exists(dir + "/rooms.png"));
    EXPECT_TRUE(loadWorld(dir).rooms.empty());
}

TEST(World, MissingDirectory) {
    EXPECT_THAT(errorOf([] { loadWorld("/nonexistent/world"); }),
                HasSubstr("world directory '/nonexistent/world' does not exist"));
}

TEST(World, MissingFloorPlan) {
    const std::string dir = freshDir() + "/w";
    saveWorld(smallWorld(), dir);
    std::filesystem::remove(dir + "/floorplan.yaml");
    EXPECT_THAT(errorOf([&] { loadWorld(dir); }), HasSubstr("w/floorplan.yaml: missing"));
}

TEST(World, MissingObjectMap) {
    const std::string dir = freshDir() + "/w";
    saveWorld(smallWorld(), dir);
    std::filesystem::remove(dir + "/objects.json");
    EXPECT_THAT(errorOf([&] { loadWorld(dir); }), HasSubstr("w/objects.json: missing"));
}

TEST(World, RoomRasterOfAnotherSize) {
    const std::string dir = freshDir() + "/w";
    saveWorld(smallWorld(), dir);
    cv::imwrite(dir + "/rooms.png", cv::Mat1w(5, 5, static_cast<unsigned short>(1)));
    EXPECT_THAT(errorOf([&] { loadWorld(dir); }), HasSubstr("rooms.png: size 5x5 differs from the floor plan's 3x2"));
}

TEST(RoomMap, RoomOfBoxOnAWall) {
    // 5 x 1 raster at 1 m: rooms 1 1 0 2 2 (a wall in column 2).
    RoomMap r;
    r.ids = cv::Mat1w(1, 5);
    r.ids << 1, 1, 0, 2, 2;
    r.resolution_m = 1.0;
    // Centre inside room 2.
    EXPECT_EQ(roomOfBox(r, simp::geometry::makeUprightBox({3.5, 0.5, 1}, {0.5, 0.5, 1}, 0)), 2);
    // Centre on the wall; the footprint grown by one cell spans 1.9 m of room 1, 1.3 m of room 2.
    EXPECT_EQ(roomOfBox(r, simp::geometry::makeUprightBox({2.2, 0.5, 1}, {2.2, 0.2, 1}, 0)), 1);
    // Nothing around: 0.
    RoomMap none = r;
    none.ids.setTo(0);
    EXPECT_EQ(roomOfBox(none, simp::geometry::makeUprightBox({2.5, 0.5, 1}, {0.5, 0.5, 1}, 0)), 0);
}
