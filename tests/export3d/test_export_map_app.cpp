// simp-export-map's --gridmap and --octomap, in-process as the program runs them (ExportMapApp with
// the OctoMap writer of libs/export3d), and its command-line errors.
#include <gtest/gtest.h>
#include <octomap/AbstractOcTree.h>
#include <octomap/ColorOcTree.h>
#include <simp/export3d/OctomapExport.h>
#include <simp/world/Gridmap.h>
#include <simp/world/MapConvertApps.h>

#include <memory>
#include <sstream>

#include "SmallWorld.h"

namespace {

std::string runApp(const std::vector<std::string>& args, std::string* printed = nullptr, bool with_writer = true) {
    std::vector<const char*> argv{"simp-export-map"};
    for (const auto& a : args) argv.push_back(a.c_str());
    simp::world::ExportMapApp app;
    if (with_writer) app.octomap_writer = simp::export3d::exportOctomapCommand;
    std::ostringstream out;
    try {
        app.initialize(static_cast<int>(argv.size()), argv.data());
        app.run(out);
    } catch (const std::exception& e) {
        return e.what();
    }
    if (printed) *printed = out.str();
    return "";
}

}  // namespace

TEST(ExportMapApp, GridmapIsTheWorldsFloorPlan) {
    const std::string dir = simp_test::freshDir();
    simp::world::saveWorld(simp_test::smallWorld(), dir + "/W");
    std::string printed;
    ASSERT_EQ(runApp({"--world", dir + "/W", "--gridmap", dir + "/W/floorplan.gridmap"}, &printed), "");
    EXPECT_NE(printed.find("80 x 60 cells at 0.05 m"), std::string::npos) << printed;
    const auto w = simp::world::loadWorld(dir + "/W");
    const auto g = simp::world::loadGridmap(dir + "/W/floorplan.gridmap");
    ASSERT_EQ(g.getSizeX(), 80u);
    ASSERT_EQ(g.getSizeY(), 60u);
    EXPECT_FLOAT_EQ(g.getResolution(), 0.05f);
    EXPECT_NEAR(g.getXMin(), 0.0, 1e-6);
    EXPECT_NEAR(g.getYMax(), 3.0, 1e-6);
    std::size_t walls = 0;
    for (unsigned y = 0; y < 60; ++y)
        for (unsigned x = 0; x < 80; ++x) {
            ASSERT_EQ(g.getCell(x, y), w.floorplan.getCell(x, y));
            walls += g.getCell(x, y) < 0.35f;
        }
    EXPECT_EQ(walls, 160u);
}

TEST(ExportMapApp, OctomapWithResolutionAndConfig) {
    const std::string dir = simp_test::freshDir();
    simp::world::saveWorld(simp_test::smallWorld(), dir + "/W");
    std::ofstream(dir + "/o.ini") << "[octomap]\nceiling_height_m = 2.0\nresolution_m = 0.05\n";
    std::string printed;
    ASSERT_EQ(runApp({"--world", dir + "/W", "--octomap", dir + "/m.ot", "--resolution", "0.1", "--config",
                      dir + "/o.ini"},
                     &printed),
              "");
    EXPECT_NE(printed.find("1 closed doors, 1 open doors left out"), std::string::npos) << printed;
    std::unique_ptr<octomap::AbstractOcTree> tree(octomap::AbstractOcTree::read(dir + "/m.ot"));
    auto* ct = dynamic_cast<octomap::ColorOcTree*>(tree.get());
    ASSERT_NE(ct, nullptr);
    EXPECT_DOUBLE_EQ(ct->getResolution(), 0.1);                // --resolution wins over the .ini
    EXPECT_EQ(ct->search(3.0, 0.05, 2.15), nullptr);           // the .ini's 2.0 m ceiling
    ASSERT_NE(ct->search(3.0, 0.05, 1.95), nullptr);
    EXPECT_TRUE(ct->isNodeOccupied(ct->search(3.0, 0.05, 1.95)));
}

TEST(ExportMapApp, BadCommandLinesSayWhatIsWrong) {
    const std::string dir = simp_test::freshDir();
    simp::world::saveWorld(simp_test::smallWorld(), dir + "/W");
    EXPECT_NE(runApp({"--world", dir + "/W"}).find("nothing to write"), std::string::npos);
    EXPECT_NE(runApp({"--gridmap", "x.gridmap"}).find("missing required option --world W"), std::string::npos);
    EXPECT_NE(runApp({"--world", dir + "/W", "--gridmap", "x.gridmap", "--resolution", "0.1"}).find("--octomap"),
              std::string::npos);
    EXPECT_NE(runApp({"--world", dir + "/W", "--octomap", dir + "/m.bt", "--resolution", "0.1x"}).find("--resolution"),
              std::string::npos);
    EXPECT_NE(runApp({"--world", dir + "/W", "--octomap", dir + "/m.bt", "--resolution", "0.001"}).find("resolution_m"),
              std::string::npos);
    EXPECT_NE(runApp({"--world", dir + "/none", "--gridmap", dir + "/x.gridmap"}).find(dir + "/none"),
              std::string::npos);
    EXPECT_NE(runApp({"--world", dir + "/W", "--octomap", dir + "/m.bt"}, nullptr, false).find("OctoMap"),
              std::string::npos);
}
