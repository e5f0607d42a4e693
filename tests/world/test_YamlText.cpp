// Floor-plan YAML text checked before libfyaml reads it (libs/world YamlText.h): the fuzzed file that
// hung libfyaml, bytes that are not UTF-8, control characters, oversize files; real files still read.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/world/World.h>
#include <simp/world/YamlText.h>

#include <fstream>
#include <iterator>

#include "TestUtil.h"

using ::testing::HasSubstr;
using simp_test::errorOf;
using simp_test::freshDir;
using simp_test::writeFile;

namespace {

std::string yamlError(const std::string& path) {
    return errorOf([&] { simp::world::readRosMapYaml(path); });
}

}  // namespace

TEST(YamlText, TheFuzzedDirectiveThatHungLibfyamlIsRejected) {
    // fuzz_floorplan's input: byte 0 picks the YAML branch, the rest is map.yaml. Before the check,
    // libfyaml 0.7.12 looped forever in fy_scan_directive (a '%' line with a byte that is not UTF-8);
    // a hang would now end in the test's timeout.
    std::ifstream in(std::string(SIMP_SOURCE_DIR) + "/tests/data/fuzz_regressions/floorplan/timeout-directive-not-utf8.bin",
                     std::ios::binary);
    const std::string fuzzed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_EQ(fuzzed.size(), 31u);
    const std::string dir = freshDir();
    writeFile(dir + "/map.yaml", fuzzed.substr(1));
    mrpt::maps::COccupancyGridMap2D grid;
    const auto msg = errorOf([&] { simp::world::loadRosMap(dir + "/map.yaml", grid); });
    EXPECT_THAT(msg, HasSubstr("map.yaml: line 1: YAML directives ('%...') are not accepted"));
    // The trigger alone, and a directive that is valid YAML: neither belongs in a map_server file.
    for (const std::string text : {"%a\xf6", "%YAML 1.2\n---\nimage: map.png\n"}) {
        writeFile(dir + "/map.yaml", text);
        EXPECT_THAT(yamlError(dir + "/map.yaml"), HasSubstr("line 1: YAML directives")) << text;
    }
}

TEST(YamlText, BytesThatAreNotUtf8OrNotPrintableNameTheLine) {
    const std::string dir = freshDir();
    const std::string path = dir + "/map.yaml";
    const std::string head = "image: map.png\n";
    const struct {
        std::string text, expected;
    } cases[] = {
        {head + "resolution: \xf6\n", "line 2: byte 0xF6 is not UTF-8"},
        {head + "resolution: \xc0\xaf\n", "line 2: byte 0xC0 is not UTF-8"},      // overlong '/'
        {head + "resolution: \xed\xa0\x80\n", "line 2: byte 0xED is not UTF-8"},  // a surrogate
        {head + "a: \xe2\x82\n", "line 2: byte 0xE2 is not UTF-8"},               // cut short
        {head + head + "a: 1\x0c\n", "line 3: control character 0x0C"},
        {"a: 1\x7f\n", "line 1: control character 0x7F"},
        {std::string("a: \0 1\n", 7), "line 1: control character 0x00"},
    };
    for (const auto& c : cases) {
        writeFile(path, c.text);
        const auto msg = yamlError(path);
        EXPECT_THAT(msg, HasSubstr("map.yaml: " + c.expected)) << c.text;
    }
    writeFile(path, std::string(simp::world::kMaxYamlBytes + 1, '#'));
    EXPECT_THAT(yamlError(path), HasSubstr("1048577 bytes, more than the 1048576 a floor-plan YAML file may have"));
}

TEST(YamlText, RealFloorPlansStillRead) {
    // UTF-8 text, CRLF line ends, a comment, a '%' inside a value: all fine.
    const std::string dir = freshDir();
    writeFile(dir + "/map.yaml",
              "# B\xc3\xbcro 3.OG\r\nimage: map.png\r\nresolution: 0.05\r\norigin: [-1.5, 2, 0]\r\n"
              "occupied_thresh: 0.65\r\nfree_thresh: 0.196 # 19.6%\r\nnegate: 0\r\n");
    const auto m = simp::world::readRosMapYaml(dir + "/map.yaml");
    EXPECT_DOUBLE_EQ(m.resolution_m, 0.05);
    EXPECT_DOUBLE_EQ(m.origin_x_m, -1.5);
    EXPECT_DOUBLE_EQ(m.free_thresh, 0.196);
    EXPECT_EQ(simp::world::readYamlText(dir + "/map.yaml").size(), 132u);
}
