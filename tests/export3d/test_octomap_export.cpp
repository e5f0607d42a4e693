// The OctoMap export (libs/export3d): read back with OctoMap and with MRPT's COctoMap, occupancy at a
// wall, in a box, in free space and in unknown space; class colours; resolution and size limits.
#include "common/ErrorOf.h"

#include <gtest/gtest.h>
#include <mrpt/maps/COctoMap.h>
#include <octomap/AbstractOcTree.h>
#include <octomap/ColorOcTree.h>
#include <octomap/OcTree.h>
#include <simp/export3d/OctomapExport.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/Palette.h>

#include <memory>

#include "SmallWorld.h"

namespace {

using simp::export3d::OctomapExportOptions;
using simp::export3d::writeWorldOctomap;

/// +1 occupied, 0 free, -1 unknown.
int stateAt(const octomap::OcTree& t, double x, double y, double z) {
    const auto* n = t.search(x, y, z);
    if (!n) return -1;
    return t.isNodeOccupied(n) ? 1 : 0;
}

using simp_test::errorOf;

}  // namespace

TEST(OctomapExport, BinaryTreeHoldsWallsBoxesClosedDoorsAndFreeSpace) {
    const auto w = simp_test::smallWorld();
    const std::string path = simp_test::freshDir() + "/world.bt";
    OctomapExportOptions opt;  // 0.05 m, ceiling 2.5 m
    const auto s = writeWorldOctomap(w, opt, path);
    EXPECT_EQ(s.wall_cells, 160u);                    // 80 x 2 cells
    EXPECT_EQ(s.free_cells, 80u * 60u - 160u - 400u);  // minus the wall and the unknown corner
    EXPECT_EQ(s.objects, 2u);                          // table + closed door
    EXPECT_EQ(s.closed_doors, 1u);
    EXPECT_EQ(s.open_doors_skipped, 1u);
    EXPECT_GT(s.bytes, 0u);

    octomap::OcTree t(path);  // the binary reader
    EXPECT_DOUBLE_EQ(t.getResolution(), 0.05);
    EXPECT_EQ(stateAt(t, 3.0, 0.05, 0.1), 1);   // wall at the floor
    EXPECT_EQ(stateAt(t, 3.0, 0.05, 2.45), 1);  // wall just under the ceiling
    EXPECT_EQ(stateAt(t, 3.0, 0.05, 2.6), -1);  // above the ceiling: nothing known
    EXPECT_EQ(stateAt(t, 2.0, 1.5, 0.4), 1);    // table centre
    EXPECT_EQ(stateAt(t, 2.0, 1.5, 0.78), 1);   // just under its top (0.8 m)
    EXPECT_EQ(stateAt(t, 2.0, 1.5, 0.9), 0);    // above the table: free
    // The table is yawed 0.3 rad: its long axis end at centre + 0.45 (cos 0.3, sin 0.3) is inside,
    // the same distance across the short axis is outside (0.3 m half-width + half a voxel < 0.45 m).
    EXPECT_EQ(stateAt(t, 2.0 + 0.45 * std::cos(0.3), 1.5 + 0.45 * std::sin(0.3), 0.4), 1);
    EXPECT_EQ(stateAt(t, 2.0 - 0.45 * std::sin(0.3), 1.5 + 0.45 * std::cos(0.3), 0.4), 0);
    EXPECT_EQ(stateAt(t, 1.0, 2.0, 1.0), 0);    // free room space
    EXPECT_EQ(stateAt(t, 0.5, 2.5, 1.0), 0);    // the open door's gap stays free
    EXPECT_EQ(stateAt(t, 3.5, 2.5, 1.0), -1);   // unknown floor-plan corner stays unknown
    EXPECT_EQ(stateAt(t, 1.0, 0.05, 1.9), 1);   // closed door (in the wall)
}

TEST(OctomapExport, MrptCOctoMapOfTheExportedFiles) {
    const auto w = simp_test::smallWorld();
    const std::string dir = simp_test::freshDir();
    OctomapExportOptions opt;
    opt.resolution_m = 0.1;
    writeWorldOctomap(w, opt, dir + "/world.bt");
    writeWorldOctomap(w, opt, dir + "/world.ot");
    for (const char* name : {"/world.bt", "/world.ot"}) {
        const auto map = simp::export3d::toMrptOctoMap(dir + name);
        double p = 0;
        ASSERT_TRUE(map.getPointOccupancy(3.0f, 0.05f, 1.0f, p)) << name;  // wall
        EXPECT_GT(p, 0.5);
        ASSERT_TRUE(map.getPointOccupancy(2.0f, 1.5f, 0.4f, p)) << name;  // table
        EXPECT_GT(p, 0.5);
        ASSERT_TRUE(map.getPointOccupancy(1.0f, 2.0f, 1.0f, p)) << name;  // free
        EXPECT_LT(p, 0.5);
        EXPECT_FALSE(map.getPointOccupancy(3.5f, 2.5f, 1.0f, p)) << name;  // unknown
    }
    EXPECT_NE(errorOf([&] { simp::export3d::toMrptOctoMap(dir + "/world.bt", 100); }).find("voxels"),
              std::string::npos);
}

TEST(OctomapExport, ColourTreeCarriesClassColours) {
    const auto w = simp_test::smallWorld();
    const std::string path = simp_test::freshDir() + "/world.ot";
    OctomapExportOptions opt;
    opt.resolution_m = 0.1;
    opt.ceiling_height_m = 2.0;
    writeWorldOctomap(w, opt, path);
    std::unique_ptr<octomap::AbstractOcTree> tree(octomap::AbstractOcTree::read(path));
    ASSERT_TRUE(tree);
    auto* ct = dynamic_cast<octomap::ColorOcTree*>(tree.get());
    ASSERT_NE(ct, nullptr) << tree->getTreeType();
    EXPECT_DOUBLE_EQ(ct->getResolution(), 0.1);
    const auto* table = ct->search(2.0, 1.5, 0.4);
    ASSERT_NE(table, nullptr);
    EXPECT_TRUE(ct->isNodeOccupied(table));
    const auto rgb = simp::obs::classColorRgb("table");  // the palette's table, whatever its id
    EXPECT_EQ(table->getColor(), octomap::ColorOcTreeNode::Color(rgb[0], rgb[1], rgb[2]));
    const auto* wall = ct->search(3.0, 0.05, 1.0);
    ASSERT_NE(wall, nullptr);
    EXPECT_TRUE(ct->isNodeOccupied(wall));
    EXPECT_EQ(wall->getColor(), octomap::ColorOcTreeNode::Color(160, 160, 160));
    EXPECT_EQ(ct->search(3.0, 0.05, 2.15), nullptr);  // above the 2.0 m ceiling
}

TEST(OctomapExport, OpenDoorsOnRequestAndNoFreeSpace) {
    const auto w = simp_test::smallWorld();
    const std::string path = simp_test::freshDir() + "/world.bt";
    OctomapExportOptions opt;
    opt.export_open_doors = true;
    opt.mark_free_space = false;
    const auto s = writeWorldOctomap(w, opt, path);
    EXPECT_EQ(s.closed_doors, 2u);
    EXPECT_EQ(s.free_leaves, 0u);
    octomap::OcTree t(path);
    EXPECT_EQ(stateAt(t, 0.5, 2.5, 1.0), 1);   // the open door is now a box
    EXPECT_EQ(stateAt(t, 1.0, 2.0, 1.0), -1);  // free space not marked: unknown
}

TEST(OctomapExport, RefusesBadResolutionSizeAndExtension) {
    const auto w = simp_test::smallWorld();
    const std::string dir = simp_test::freshDir();
    OctomapExportOptions opt;
    opt.resolution_m = 0.001;
    EXPECT_NE(errorOf([&] { writeWorldOctomap(w, opt, dir + "/a.bt"); }).find("resolution_m"), std::string::npos);
    opt.resolution_m = 0.05;
    // 4 x 3 m of known cells, 50 layers of 0.05 m: 4400 cells x 50 = 220000 voxels + the boxes.
    const double estimate = simp::export3d::estimateVoxels(w, opt);
    EXPECT_NEAR(estimate, 4400.0 * 50.0, 0.05 * 4400.0 * 50.0);
    opt.max_voxels = 1000;
    const std::string msg = errorOf([&] { writeWorldOctomap(w, opt, dir + "/b.bt"); });
    EXPECT_NE(msg.find("max_voxels"), std::string::npos) << msg;
    EXPECT_FALSE(std::filesystem::exists(dir + "/b.bt"));
    opt.max_voxels = 2e7;
    EXPECT_NE(errorOf([&] { writeWorldOctomap(w, opt, dir + "/c.ply"); }).find(".bt"), std::string::npos);
    opt.ceiling_height_m = -1;
    EXPECT_NE(errorOf([&] { writeWorldOctomap(w, opt, dir + "/d.bt"); }).find("ceiling_height_m"), std::string::npos);
}

TEST(OctomapExport, IniKeysAreReadAndCheckedByName) {
    const std::string dir = simp_test::freshDir();
    const auto shipped = simp::export3d::loadOctomapExportOptions(std::string(SIMP_SOURCE_DIR) + "/config_ini/octomap.ini");
    EXPECT_DOUBLE_EQ(shipped.resolution_m, OctomapExportOptions{}.resolution_m);  // the file states the defaults
    EXPECT_DOUBLE_EQ(shipped.ceiling_height_m, OctomapExportOptions{}.ceiling_height_m);
    EXPECT_DOUBLE_EQ(shipped.max_voxels, OctomapExportOptions{}.max_voxels);
    std::ofstream(dir + "/ok.ini") << "[octomap]\nresolution_m = 0.1\nceiling_height_m = 3.0\nmark_free_space = false\n";
    const auto opt = simp::export3d::loadOctomapExportOptions(dir + "/ok.ini");
    EXPECT_DOUBLE_EQ(opt.resolution_m, 0.1);
    EXPECT_DOUBLE_EQ(opt.ceiling_height_m, 3.0);
    EXPECT_FALSE(opt.mark_free_space);
    std::ofstream(dir + "/typo.ini") << "[octomap]\nresolution = 0.1\n";
    const std::string typo = errorOf([&] { simp::export3d::loadOctomapExportOptions(dir + "/typo.ini"); });
    EXPECT_NE(typo.find("typo.ini"), std::string::npos) << typo;
    EXPECT_NE(typo.find("'resolution'"), std::string::npos) << typo;
    std::ofstream(dir + "/bad.ini") << "[octomap]\nresolution_m = 5\n";
    const std::string bad = errorOf([&] { simp::export3d::loadOctomapExportOptions(dir + "/bad.ini"); });
    EXPECT_NE(bad.find("bad.ini"), std::string::npos) << bad;
    EXPECT_NE(bad.find("resolution_m"), std::string::npos) << bad;
    EXPECT_NE(errorOf([&] { simp::export3d::loadOctomapExportOptions(dir + "/none.ini"); }).find("none.ini"),
              std::string::npos);
}
