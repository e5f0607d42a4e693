// ROS map_server floor plans: thresholds, negate, origin (exact, not rounded by MRPT), row
// order, scale mode, save/load round trip and every bad-input message.
#include "TestUtil.h"

#include <gmock/gmock.h>
#include <opencv2/imgcodecs.hpp>
#include <simp/world/World.h>

using namespace simp::world;
using simp_test::freshDir;
using simp_test::errorOf;
using simp_test::writeFile;
using ::testing::HasSubstr;

namespace {

/// 4 x 3 image, row 0 = top. Values chosen around the thresholds 0.65 / 0.196:
///   v = 0   -> p = 1.0       v = 89  -> p = 0.651 (occupied)   v = 90 -> p = 0.647 (unknown)
///   v = 205 -> p = 0.19608 (unknown: not < 0.196)  v = 206 -> p = 0.192 (free)  v = 255 -> p = 0
cv::Mat1b testImage() {
    cv::Mat1b img(3, 4);
    img << 0, 89, 90, 205,  //
        206, 255, 255, 255,  //
        255, 255, 255, 0;
    return img;
}

std::string writeMap(const std::string& dir, const std::string& yaml_extra, bool negate_image = false) {
    cv::Mat1b img = testImage();
    if (negate_image) img = 255 - img;
    cv::imwrite(dir + "/map.png", img);
    writeFile(dir + "/map.yaml", "image: map.png\nresolution: 0.05\norigin: [-13.9155, -11.04537, 0.0]\n" + yaml_extra);
    return dir + "/map.yaml";
}

const char* kThresholds = "occupied_thresh: 0.65\nfree_thresh: 0.196\n";

}  // namespace

TEST(RosMap, TrinaryThresholdsRowOrderAndExactOrigin) {
    const std::string dir = freshDir();
    mrpt::maps::COccupancyGridMap2D g;
    loadRosMap(writeMap(dir, std::string("negate: 0\n") + kThresholds), g);
    ASSERT_EQ(g.getSizeX(), 4u);
    ASSERT_EQ(g.getSizeY(), 3u);
    EXPECT_FLOAT_EQ(g.getResolution(), 0.05f);
    // MRPT's setSize alone would round these to -13.90 / -11.05.
    EXPECT_FLOAT_EQ(g.getXMin(), -13.9155f);
    EXPECT_FLOAT_EQ(g.getYMin(), -11.04537f);
    EXPECT_FLOAT_EQ(g.getXMax(), static_cast<float>(-13.9155 + 4 * 0.05));
    // Image row 0 (top) is grid row cy = 2.
    EXPECT_LT(g.getCell(0, 2), 0.01f);           // v = 0
    EXPECT_LT(g.getCell(1, 2), 0.01f);           // v = 89, p = 0.651 > 0.65
    EXPECT_FLOAT_EQ(g.getCell(2, 2), 0.5f);      // v = 90, p = 0.647
    EXPECT_FLOAT_EQ(g.getCell(3, 2), 0.5f);      // v = 205, p = 0.19608
    EXPECT_GT(g.getCell(0, 1), 0.99f);           // v = 206, p = 0.192 < 0.196
    EXPECT_GT(g.getCell(0, 0), 0.99f);           // bottom-left, v = 255
    EXPECT_LT(g.getCell(3, 0), 0.01f);           // bottom-right, v = 0
    // World lookup honours the origin: the bottom-right cell's centre.
    EXPECT_LT(g.getPos(-13.9155f + 3.5f * 0.05f, -11.04537f + 0.5f * 0.05f), 0.01f);
}

TEST(RosMap, NegateInvertsTheImage) {
    const std::string dir = freshDir();
    mrpt::maps::COccupancyGridMap2D g;
    // With negate = 1, p = v / 255: the inverted image gives the same grid.
    loadRosMap(writeMap(dir, std::string("negate: 1\n") + kThresholds, true), g);
    EXPECT_LT(g.getCell(0, 2), 0.01f);
    EXPECT_LT(g.getCell(1, 2), 0.01f);
    EXPECT_FLOAT_EQ(g.getCell(2, 2), 0.5f);
    EXPECT_FLOAT_EQ(g.getCell(3, 2), 0.5f);
    EXPECT_GT(g.getCell(0, 1), 0.99f);
    EXPECT_GT(g.getCell(0, 0), 0.99f);
}

TEST(RosMap, OtherThresholdsMoveTheClasses) {
    const std::string dir = freshDir();
    mrpt::maps::COccupancyGridMap2D g;
    loadRosMap(writeMap(dir, "negate: 0\noccupied_thresh: 0.9\nfree_thresh: 0.1\n"), g);
    EXPECT_FLOAT_EQ(g.getCell(1, 2), 0.5f);  // p = 0.651: no longer occupied
    EXPECT_FLOAT_EQ(g.getCell(0, 1), 0.5f);  // p = 0.192: no longer free
    EXPECT_LT(g.getCell(0, 2), 0.01f);
}

TEST(RosMap, ScaleModeKeepsIntermediateValues) {
    const std::string dir = freshDir();
    mrpt::maps::COccupancyGridMap2D g;
    loadRosMap(writeMap(dir, std::string("mode: scale\n") + kThresholds), g);
    // v = 90: p = 165/255; occupancy = (p - 0.196) / (0.65 - 0.196).
    EXPECT_NEAR(1.0 - g.getCell(2, 2), (165.0 / 255.0 - 0.196) / (0.65 - 0.196), 0.01);  // MRPT stores P(free)
}

TEST(RosMap, SaveLoadRoundTrip) {
    const std::string dir = freshDir();
    mrpt::maps::COccupancyGridMap2D g, r;
    loadRosMap(writeMap(dir, kThresholds), g);
    saveRosMap(g, dir + "/out/floorplan.yaml");
    ASSERT_TRUE(std::filesystem::exists(dir + "/out/floorplan.png"));
    const cv::Mat1b img = cv::imread(dir + "/out/floorplan.png", cv::IMREAD_UNCHANGED);
    EXPECT_EQ(img(0, 0), 0);    // occupied
    EXPECT_EQ(img(0, 2), 205);  // unknown
    EXPECT_EQ(img(2, 0), 254);  // free
    loadRosMap(dir + "/out/floorplan.yaml", r);
    ASSERT_EQ(r.getSizeX(), g.getSizeX());
    ASSERT_EQ(r.getSizeY(), g.getSizeY());
    EXPECT_EQ(r.getXMin(), g.getXMin());
    EXPECT_EQ(r.getYMin(), g.getYMin());
    for (unsigned y = 0; y < g.getSizeY(); ++y)
        for (unsigned x = 0; x < g.getSizeX(); ++x) EXPECT_EQ(r.getCell(x, y), g.getCell(x, y)) << x << "," << y;
    const RosMapYaml meta = readRosMapYaml(dir + "/out/floorplan.yaml");
    EXPECT_EQ(meta.origin_x_m, -13.9155);  // written as the shortest text of the float
    EXPECT_EQ(meta.origin_y_m, -11.04537);
}

TEST(RosMap, BlockStyleOriginAndAbsoluteImagePath) {
    const std::string dir = freshDir();
    cv::imwrite(dir + "/map.png", testImage());
    writeFile(dir + "/map.yaml", "image: " + dir + "/map.png\nresolution: 0.1\norigin:\n- 1.5\n- -2.25\n- 0.0\n" +
                                     kThresholds);
    mrpt::maps::COccupancyGridMap2D g;
    loadRosMap(dir + "/map.yaml", g);
    EXPECT_FLOAT_EQ(g.getXMin(), 1.5f);
    EXPECT_FLOAT_EQ(g.getYMin(), -2.25f);
    EXPECT_FLOAT_EQ(g.getYMax(), -1.95f);
}

TEST(RosMap, MissingYaml) {
    mrpt::maps::COccupancyGridMap2D g;
    EXPECT_THAT(errorOf([&] { loadRosMap("/nonexistent/map.yaml", g); }),
                HasSubstr("/nonexistent/map.yaml: file not found"));
}

TEST(RosMap, MissingImageKey) {
    const std::string dir = freshDir();
    writeFile(dir + "/map.yaml", std::string("resolution: 0.05\norigin: [0, 0, 0]\n") + kThresholds);
    mrpt::maps::COccupancyGridMap2D g;
    EXPECT_THAT(errorOf([&] { loadRosMap(dir + "/map.yaml", g); }), HasSubstr("map.yaml: image: missing"));
}

TEST(RosMap, MissingResolution) {
    const std::string dir = freshDir();
    writeFile(dir + "/map.yaml", std::string("image: map.png\norigin: [0, 0, 0]\n") + kThresholds);
    mrpt::maps::COccupancyGridMap2D g;
    EXPECT_THAT(errorOf([&] { loadRosMap(dir + "/map.yaml", g); }), HasSubstr("map.yaml: resolution: missing"));
}

TEST(RosMap, MissingThreshold) {
    const std::string dir = freshDir();
    writeFile(dir + "/map.yaml", "image: map.png\nresolution: 0.05\norigin: [0, 0, 0]\nfree_thresh: 0.196\n");
    mrpt::maps::COccupancyGridMap2D g;
    EXPECT_THAT(errorOf([&] { loadRosMap(dir + "/map.yaml", g); }),
                HasSubstr("map.yaml: occupied_thresh: missing"));
}

TEST(RosMap, BadOrigin) {
    const std::string dir = freshDir();
    writeFile(dir + "/map.yaml", std::string("image: map.png\nresolution: 0.05\norigin: [0, 0]\n") + kThresholds);
    mrpt::maps::COccupancyGridMap2D g;
    EXPECT_THAT(errorOf([&] { loadRosMap(dir + "/map.yaml", g); }), HasSubstr("map.yaml: origin: expected"));
}

TEST(RosMap, RotatedOriginRejected) {
    const std::string dir = freshDir();
    writeFile(dir + "/map.yaml", std::string("image: map.png\nresolution: 0.05\norigin: [0, 0, 0.3]\n") + kThresholds);
    mrpt::maps::COccupancyGridMap2D g;
    EXPECT_THAT(errorOf([&] { loadRosMap(dir + "/map.yaml", g); }),
                HasSubstr("map.yaml: origin: a non-zero yaw is not supported"));
}

TEST(RosMap, NonPositiveResolution) {
    const std::string dir = freshDir();
    writeFile(dir + "/map.yaml", std::string("image: map.png\nresolution: 0\norigin: [0, 0, 0]\n") + kThresholds);
    mrpt::maps::COccupancyGridMap2D g;
    EXPECT_THAT(errorOf([&] { loadRosMap(dir + "/map.yaml", g); }),
                HasSubstr("map.yaml: resolution: expected a positive number"));
}

TEST(RosMap, MissingImageFile) {
    const std::string dir = freshDir();
    writeFile(dir + "/map.yaml", std::string("image: nothere.png\nresolution: 0.05\norigin: [0, 0, 0]\n") + kThresholds);
    mrpt::maps::COccupancyGridMap2D g;
    EXPECT_THAT(errorOf([&] { loadRosMap(dir + "/map.yaml", g); }),
                HasSubstr("map.yaml: image: file '" + dir + "/nothere.png' not found"));
}

TEST(RosMap, UnreadableImage) {
    const std::string dir = freshDir();
    writeFile(dir + "/map.png", "not a png");
    writeFile(dir + "/map.yaml", std::string("image: map.png\nresolution: 0.05\norigin: [0, 0, 0]\n") + kThresholds);
    mrpt::maps::COccupancyGridMap2D g;
    EXPECT_THAT(errorOf([&] { loadRosMap(dir + "/map.yaml", g); }), HasSubstr("map.png: cannot read the image"));
}
