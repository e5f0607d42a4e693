// MRPT's .gridmap (libs/world Gridmap.h): written gzip-compressed and read back exactly as MRPT's
// pf-localization reads `map_file = F.gridmap` (CFileGZInputStream into the [MetricMap]'s grid).
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/world/Gridmap.h>
#include <simp/world/World.h>

#include <cmath>
#include <fstream>

#include "TestUtil.h"

namespace {

mrpt::maps::COccupancyGridMap2D testGrid(double x_min_m = -13.9, double y_min_m = 2.35) {
    mrpt::maps::COccupancyGridMap2D g;
    simp::world::setGridExactly(g, x_min_m, y_min_m, 37, 21, 0.05, 0.5f);
    for (unsigned y = 0; y < 21; ++y)
        for (unsigned x = 0; x < 37; ++x) g.setCell(x, y, (x + 2 * y) % 3 == 0 ? 0.0f : ((x + y) % 5 == 0 ? 0.5f : 1.0f));
    return g;
}

void expectSameGrid(const mrpt::maps::COccupancyGridMap2D& a, const mrpt::maps::COccupancyGridMap2D& b) {
    ASSERT_EQ(a.getSizeX(), b.getSizeX());
    ASSERT_EQ(a.getSizeY(), b.getSizeY());
    EXPECT_FLOAT_EQ(a.getResolution(), b.getResolution());
    EXPECT_FLOAT_EQ(a.getXMin(), b.getXMin());
    EXPECT_FLOAT_EQ(a.getYMin(), b.getYMin());
    for (unsigned y = 0; y < a.getSizeY(); ++y)
        for (unsigned x = 0; x < a.getSizeX(); ++x) ASSERT_EQ(a.getCell(x, y), b.getCell(x, y)) << x << "," << y;
}

}  // namespace

TEST(Gridmap, RoundTripKeepsSizeResolutionOriginAndCells) {
    const auto g = testGrid();
    const std::string path = simp_test::freshDir() + "/floor.gridmap";
    simp::world::saveGridmap(g, path);
    std::ifstream f(path, std::ios::binary);
    unsigned char magic[2] = {0, 0};
    f.read(reinterpret_cast<char*>(magic), 2);
    EXPECT_EQ(magic[0], 0x1f);  // gzip, as MRPT writes its own .gridmap files
    EXPECT_EQ(magic[1], 0x8b);
    expectSameGrid(g, simp::world::loadGridmap(path));
}

TEST(Gridmap, LoadsAsPfLocalizationLoadsIt) {
    const auto g = testGrid();
    const std::string path = simp_test::freshDir() + "/floor.gridmap";
    simp::world::saveGridmap(g, path);
    // pf-localization: a CMultiMetricMap from [MetricMap], then the file into its occupancy grid.
    mrpt::config::CConfigFileMemory ini("[MetricMap]\noccupancyGrid_count=1\n");
    mrpt::maps::TSetOfMetricMapInitializers defs;
    defs.loadFromConfigFile(ini, "MetricMap");
    mrpt::maps::CMultiMetricMap maps;
    maps.setListOfMaps(defs);
    auto grid = maps.mapByClass<mrpt::maps::COccupancyGridMap2D>();
    ASSERT_TRUE(grid);
    mrpt::io::CFileGZInputStream in(path);
    mrpt::serialization::archiveFrom(in) >> *grid;
    expectSameGrid(g, *grid);
}

TEST(Gridmap, MrptReadsAnOriginOffTheCellLatticeRounded) {
    // MRPT's COccupancyGridMap2D deserialization calls setSize(), which rounds the origin to a multiple
    // of the resolution: a map_server origin such as -13.9155 m comes back shifted by < half a cell.
    const auto g = testGrid(-13.9155, 2.3629);
    const std::string path = simp_test::freshDir() + "/floor.gridmap";
    simp::world::saveGridmap(g, path);
    const auto back = simp::world::loadGridmap(path);
    ASSERT_EQ(back.getSizeX(), g.getSizeX());
    ASSERT_EQ(back.getSizeY(), g.getSizeY());
    EXPECT_LE(std::abs(back.getXMin() - g.getXMin()), 0.5 * 0.05 + 1e-6);
    EXPECT_LE(std::abs(back.getYMin() - g.getYMin()), 0.5 * 0.05 + 1e-6);
    EXPECT_GT(std::abs(back.getXMin() - g.getXMin()), 1e-3);  // really moved: the documented limitation
    EXPECT_NEAR(simp::world::gridmapOriginShift(g), std::hypot(back.getXMin() - g.getXMin(), back.getYMin() - g.getYMin()), 1e-5);
    for (unsigned y = 0; y < g.getSizeY(); ++y)
        for (unsigned x = 0; x < g.getSizeX(); ++x) ASSERT_EQ(back.getCell(x, y), g.getCell(x, y));
    EXPECT_LT(simp::world::gridmapOriginShift(testGrid()), 1e-5);  // float storage only
}

TEST(Gridmap, ErrorsNameTheFile) {
    const std::string dir = simp_test::freshDir();
    EXPECT_NE(simp_test::errorOf([&] { simp::world::loadGridmap(dir + "/none.gridmap"); }).find("none.gridmap"),
              std::string::npos);
    simp_test::writeFile(dir + "/text.gridmap", "not a grid map");
    const std::string msg = simp_test::errorOf([&] { simp::world::loadGridmap(dir + "/text.gridmap"); });
    EXPECT_NE(msg.find("text.gridmap"), std::string::npos) << msg;
}
