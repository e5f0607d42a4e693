// ScanWindow: the scans since `lost`, each at its odometry pose, scored for candidate poses now (the
// challenger's take-over with a LiDAR, doc/lidar.md).
#include <gtest/gtest.h>
#include <simp/localization/ScanLikelihood.h>
#include <simp/localization/ScanWindow.h>
#include <simp/sim/LidarSimulator.h>
#include <simp/sim/OfficeLayout.h>

#include <memory>

namespace {

using simp::localization::LidarModelOptions;
using simp::localization::ScanLikelihood;
using simp::localization::ScanWindow;

/// An L-shaped pair of rooms: a 6 m x 4 m room and a 2 m wide corridor off its top-right corner.
simp::world::World lRooms() {
    simp::world::World w;
    auto& g = w.floorplan;
    g.setSize(-0.5, 10.5, -0.5, 8.5, 0.05, 0.5f);
    simp::sim::fillRect(g, {-0.15, -0.15, 6.15, 4.15}, true);
    simp::sim::fillRect(g, {0.0, 0.0, 6.0, 4.0}, false);
    simp::sim::fillRect(g, {3.85, 3.85, 10.15, 8.15}, true);
    simp::sim::fillRect(g, {4.0, 4.0, 10.0, 8.0}, false);
    simp::sim::fillRect(g, {4.0, 3.9, 6.0, 4.1}, false);  // the opening
    return w;
}

mrpt::obs::CObservation2DRangeScan::Ptr scanAt(const simp::world::World& w, const mrpt::math::TPose2D& pose, int seed) {
    simp::sim::LidarParams p;
    p.range_std_m = 0.01;
    simp::sim::LidarSimulator lidar(w, p);
    simp::sim::Rng rng(seed);
    return std::make_shared<mrpt::obs::CObservation2DRangeScan>(lidar.scan(pose, {}, 0.0, rng));
}

}  // namespace

TEST(ScanWindow, ScoresEachScanAtItsOwnPoseAlongTheWay) {
    const auto w = lRooms();
    LidarModelOptions o;
    o.weight = 1.0;
    ScanLikelihood model(w.floorplan, o);
    // The robot drives 2 m along +x; odometry is exact, in an odometry frame turned and shifted from the world.
    const mrpt::poses::CPose2D world_T_odo(-3.0, 1.0, 0.7);
    ScanWindow window(10);
    mrpt::math::TPose2D now;
    mrpt::poses::CPose2D odo_now;
    for (int k = 0; k <= 4; ++k) {
        now = {2.0 + 0.5 * k, 2.0, 0.0};
        odo_now = mrpt::poses::CPose2D() - world_T_odo + mrpt::poses::CPose2D(now);  // odometry frame
        window.add(scanAt(w, now, k), odo_now);
    }
    EXPECT_EQ(window.size(), 5u);
    // the true pose now, the same pose 0.3 m off, and turned 0.1 rad
    const std::vector<mrpt::math::TPose2D> poses{now, {now.x, now.y + 0.3, now.phi}, {now.x, now.y, now.phi + 0.1}};
    std::vector<double> score;
    window.score(model, poses, odo_now, score);
    ASSERT_EQ(score.size(), 3u);
    EXPECT_GT(score[0], score[1] + 20.0);
    EXPECT_GT(score[0], score[2] + 20.0);
    // the sum of each scan scored at the pose it was taken from
    double expected = 0;
    for (int k = 0; k <= 4; ++k) {
        const mrpt::math::TPose2D then{2.0 + 0.5 * k, 2.0, 0.0};
        double l = 0;
        model.logLikelihoods(*scanAt(w, then, k), &then, 1, &l, false);
        expected += l;
    }
    EXPECT_NEAR(score[0], expected, 1e-6 * std::abs(expected));
}

TEST(ScanWindow, KeepsTheLastCapacityScansAndClears) {
    const auto w = lRooms();
    LidarModelOptions o;
    ScanLikelihood model(w.floorplan, o);
    ScanWindow window(2);
    for (int k = 0; k < 5; ++k) window.add(scanAt(w, {2.0, 2.0, 0.0}, k), mrpt::poses::CPose2D());
    EXPECT_EQ(window.size(), 2u);
    window.add(nullptr, mrpt::poses::CPose2D());  // no scan: nothing added
    EXPECT_EQ(window.size(), 2u);
    window.clear();
    std::vector<double> score;
    window.score(model, {{2.0, 2.0, 0.0}}, mrpt::poses::CPose2D(), score);
    ASSERT_EQ(score.size(), 1u);
    EXPECT_EQ(score[0], 0.0);
    ScanWindow off(0);
    off.add(scanAt(w, {2.0, 2.0, 0.0}, 1), mrpt::poses::CPose2D());
    EXPECT_EQ(off.size(), 0u);
}
