// Hostile world directories (issue #14): absurd numbers, JSON number overflow, floor plans of
// absurd resolution or declared size. Every error names the file and the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/world/ImageLimits.h>
#include <simp/world/ObjectMapData.h>
#include <simp/world/World.h>

#include <fstream>

#include "TestUtil.h"

using ::testing::HasSubstr;
using simp_test::freshDir;
using simp_test::errorOf;
using simp_test::writeFile;

namespace {

std::string objectsJson(const std::string& object) {
    return R"({"format": "simp-object-map", "version": 1, "classes": ["table"], "objects": [)" + object + "]}";
}

std::string loadError(const std::string& text) {
    const std::string path = freshDir() + "/objects.json";
    writeFile(path, text);
    return errorOf([&] { simp::world::loadObjectMap(path); });
}

const std::string kTable = R"("id": 1, "class": "table", "yaw_rad": 0)";

}  // namespace

TEST(HostileWorld, JsonNumberOverflowNamesTheFile) {
    const auto msg = loadError(objectsJson("{" + kTable + R"(, "center_m": [1e400, 0, 0], "size_m": [1, 1, 1]})"));
    EXPECT_THAT(msg, HasSubstr("objects.json: invalid JSON"));
    EXPECT_THAT(msg, HasSubstr("number overflow"));
}

TEST(HostileWorld, AbsurdCentreAndSizeAreRejected) {
    EXPECT_THAT(loadError(objectsJson("{" + kTable + R"(, "center_m": [1e300, 0, 0], "size_m": [1, 1, 1]})")),
                HasSubstr("objects.json: objects[0].center_m: coordinate beyond the maximum"));
    EXPECT_THAT(loadError(objectsJson("{" + kTable + R"(, "center_m": [0, 0, 0], "size_m": [1e6, 1, 1]})")),
                HasSubstr("objects.json: objects[0].size_m: side 1e+06 m exceeds the maximum"));
}

TEST(HostileWorld, CountersOutsideIntAreRejected) {
    EXPECT_THAT(loadError(objectsJson("{" + kTable + R"(, "center_m": [0, 0, 0], "size_m": [1, 1, 1], "n_match": 1e12})")),
                HasSubstr("objects[0].n_match: expected an integer >= 0"));
    EXPECT_THAT(loadError(objectsJson("{" + kTable +
                                      R"(, "center_m": [0, 0, 0], "size_m": [1, 1, 1], "room": 18446744073709551615})")),
                HasSubstr("objects[0].room"));
}

TEST(HostileWorld, FloorPlanResolutionOutOfRange) {
    const std::string dir = freshDir();
    for (const std::string res : {"1e-9", "1e9"}) {
        writeFile(dir + "/map.yaml", "image: map.png\nresolution: " + res +
                                         "\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
        const auto msg = errorOf([&] { simp::world::readRosMapYaml(dir + "/map.yaml"); });
        EXPECT_THAT(msg, HasSubstr("map.yaml: resolution"));
        EXPECT_THAT(msg, HasSubstr("outside"));
    }
}

TEST(HostileWorld, HugeDeclaredImageFailsBeforeDecoding) {
    const std::string dir = freshDir();
    // A PNG signature and an IHDR declaring 2e9 x 2e9 px: rejected from the header alone.
    std::ofstream png(dir + "/map.png", std::ios::binary);
    const unsigned char header[24] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                      0x77, 0x35, 0x94, 0x00, 0x77, 0x35, 0x94, 0x00};
    png.write(reinterpret_cast<const char*>(header), sizeof header);
    png.close();
    writeFile(dir + "/map.yaml",
              "image: map.png\nresolution: 0.05\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    mrpt::maps::COccupancyGridMap2D grid;
    const auto msg = errorOf([&] { simp::world::loadRosMap(dir + "/map.yaml", grid); });
    EXPECT_THAT(msg, HasSubstr("map.png: image of 2000000000 x 2000000000 px exceeds the maximum"));
    // A PGM header declares its size in text.
    writeFile(dir + "/big.pgm", "P5\n# comment\n100000 100000\n255\n");
    const auto s = simp::world::declaredImageSize(dir + "/big.pgm");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->width, 100000u);
    EXPECT_THROW(simp::world::checkRasterSize("big.pgm", *s), std::runtime_error);
}
