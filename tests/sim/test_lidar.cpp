// The simulated 2D LiDAR: MRPT's laserScanSimulator on a hand-made world (a wall at a known range,
// furniture by its height, people), determinism, and the sequence's scans read back by MRPT's rawlog-edit.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/LidarSimulator.h>
#include <simp/sim/Office.h>
#include <simp/sim/OfficeLayout.h>
#include <simp/sim/Sequence.h>

#include "SimTestUtil.h"
#include "common/MrptTool.h"

#include <cstdio>
#include <string>

namespace {

using simp::sim::LidarParams;
using simp::sim::LidarSimulator;

/// A 10 m x 6 m free room with a 0.15 m wall across it at x = 6 m and one along y = 5.85 m.
simp::world::World wallWorld() {
    simp::world::World w;
    w.floorplan.setSize(0, 10, 0, 6, 0.05, 1.0f);
    simp::sim::fillRect(w.floorplan, {6.0, 0.0, 6.15, 6.0}, true);
    simp::sim::fillRect(w.floorplan, {0.0, 5.85, 10.0, 6.0}, true);
    w.objects.class_names = simp::obs::defaultClassNames();
    return w;
}

simp::world::MapObject box(const std::string& cls, double x, double y, double z_centre, double height_m) {
    simp::world::MapObject o;
    o.id = 1;
    o.class_id = simp::obs::classIndexOf(simp::obs::defaultClassNames(), cls);
    o.box = simp::geometry::makeUprightBox({x, y, z_centre}, {0.5, 0.5, height_m}, 0.0);
    return o;
}

LidarParams noiseless() {
    LidarParams p;
    p.range_std_m = 0.0;
    return p;
}

/// The range of the beam looking straight ahead (beam 540 of 1081 over 270 deg).
float ahead(const mrpt::obs::CObservation2DRangeScan& s) { return s.getScanRange(s.getScanSize() / 2); }

}  // namespace

TEST(SimLidar, WallAtKnownRange) {
    const auto w = wallWorld();
    LidarSimulator lidar(w, noiseless());
    simp::sim::Rng rng(1);
    const auto s = lidar.scan({2.0, 3.0, 0.0}, {}, 0.0, rng);
    ASSERT_EQ(s.getScanSize(), 1081u);
    EXPECT_NEAR(s.aperture, 270.0 * M_PI / 180.0, 1e-6);
    ASSERT_TRUE(s.getScanRangeValidity(540));
    EXPECT_NEAR(ahead(s), 4.0, 0.06);  // wall face at x = 6 m, 4 m ahead (one cell of 0.05 m)
    // beam at +90 deg (left): the wall at y = 5.85 m is 2.85 m away
    EXPECT_NEAR(s.getScanRange(540 + 360), 2.85, 0.06);
    // beam at -90 deg (right): the map ends at y = 0 with no wall: no hit, not valid
    EXPECT_FALSE(s.getScanRangeValidity(540 - 360));
    // facing the wall from 1 m
    const auto s2 = lidar.scan({5.0, 3.0, 0.0}, {}, 0.0, rng);
    EXPECT_NEAR(ahead(s2), 1.0, 0.06);
}

TEST(SimLidar, FurnitureByHeightAndPeopleAreSeen) {
    auto w = wallWorld();
    w.objects.objects.push_back(box("cabinet", 4.0, 3.0, 0.9, 1.8));  // spans the 0.3 m scan plane
    w.objects.objects.push_back(box("board", 3.0, 3.0, 1.2, 0.8));    // hangs at 0.8 .. 1.6 m: above it
    LidarSimulator lidar(w, noiseless());
    simp::sim::Rng rng(1);
    EXPECT_NEAR(ahead(lidar.scan({2.0, 3.0, 0.0}, {}, 0.0, rng)), 1.75, 0.06);  // cabinet face at x = 3.75 m
    auto only_board = wallWorld();
    only_board.objects.objects.push_back(box("board", 3.0, 3.0, 1.2, 0.8));
    LidarSimulator lidar_board(only_board, noiseless());
    EXPECT_NEAR(ahead(lidar_board.scan({2.0, 3.0, 0.0}, {}, 0.0, rng)), 4.0, 0.06);
    // a person 1 m ahead, then gone: the grid is restored after the scan
    const std::vector<simp::world::MapObject> person{box("person", 3.25, 3.0, 0.9, 1.8)};
    EXPECT_NEAR(ahead(lidar_board.scan({2.0, 3.0, 0.0}, person, 0.0, rng)), 1.0, 0.06);
    EXPECT_NEAR(ahead(lidar_board.scan({2.0, 3.0, 0.0}, {}, 0.0, rng)), 4.0, 0.06);
}

TEST(SimLidar, NoiseHasTheConfiguredSpreadAndIsDeterministic) {
    const auto w = wallWorld();
    LidarParams p;
    p.range_std_m = 0.02;
    LidarSimulator a(w, p), b(w, p);
    simp::sim::Rng ra(7), rb(7);
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int k = 0; k < 200; ++k) {
        const auto sa = a.scan({2.0, 3.0, 0.0}, {}, 0.0, ra), sb = b.scan({2.0, 3.0, 0.0}, {}, 0.0, rb);
        ASSERT_EQ(ahead(sa), ahead(sb));
        const double e = ahead(sa) - 4.0;
        sum += e;
        sum2 += e * e;
        ++n;
    }
    const double mean = sum / n, std = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(std, 0.02, 0.004);
    // MRPT's ray casting stops inside the first occupied cell: a bias below one cell (0.05 m)
    EXPECT_GE(mean, -0.01);
    EXPECT_LT(mean, 0.05);
}

TEST(SimLidar, SequenceWritesOneScanPerStepAndRawlogEditCountsThem) {
    simp::sim::OfficeParams op;
    op.rooms = 3;
    const auto world = simp::sim::generateOffice(op, 3);
    simp::sim::SimParams p;
    p.duration_s = 5;
    p.progress = false;
    p.lidar.enabled = true;
    const std::string dir = simp::sim::test::clearedDir("lidar_seq");
    const auto s = simp::sim::simulateSequence(world, p, 4, dir);
    EXPECT_EQ(s.scans, s.steps);
    // same seed: the same bytes; without --lidar: no scan at all
    const std::string dir2 = simp::sim::test::clearedDir("lidar_seq2");
    simp::sim::simulateSequence(world, p, 4, dir2);
    EXPECT_EQ(simp::sim::test::slurp(dir + "/sequence.rawlog"), simp::sim::test::slurp(dir2 + "/sequence.rawlog"));
    p.lidar.enabled = false;
    const std::string dir3 = simp::sim::test::clearedDir("lidar_seq3");
    EXPECT_EQ(simp::sim::simulateSequence(world, p, 4, dir3).scans, 0u);

    if (std::system("command -v rawlog-edit > /dev/null") != 0) GTEST_SKIP() << "rawlog-edit (mrpt-apps) not installed";
    const std::string cmd = simp_test::mrptToolEnv() + "rawlog-edit --plugins " + std::string(SIMP_BINARY_DIR) +
                            "/lib/libsimp_obs.so --info -i " + dir + "/sequence.rawlog 2>&1";
    FILE* pipe = popen(cmd.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string out;
    char buf[4096];
    while (std::fgets(buf, sizeof buf, pipe)) out += buf;
    ASSERT_EQ(pclose(pipe), 0) << out;
    // "LIDAR /     50 /10.000 /..." : one scan per 10 Hz step
    EXPECT_NE(out.find("LIDAR /     " + std::to_string(s.scans) + " /"), std::string::npos) << out;
}
