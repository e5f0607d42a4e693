// Scan-matched poses: MRPT's ICP against the floor plan recovers a known offset; simp-icp-poses end
// to end on a short simulated LiDAR sequence, and its errors.
#include <gtest/gtest.h>
#include <simp/lidar/IcpPoseTracker.h>
#include <simp/lidar/IcpPosesApp.h>
#include <simp/lidar/ScanPoints.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/LidarSimulator.h>
#include <simp/sim/Office.h>
#include <simp/sim/OfficeLayout.h>
#include <simp/sim/Sequence.h>

#include "common/ErrorOf.h"

#include <filesystem>
#include <sstream>

namespace {

/// An L-shaped room (10 m x 6 m with a 4 m x 2 m corner cut out): every pose is constrained.
simp::world::World lRoom() {
    simp::world::World w;
    auto& g = w.floorplan;
    g.setSize(-0.5, 10.5, -0.5, 6.5, 0.05, 0.5f);
    simp::sim::fillRect(g, {0.0, 0.0, 10.0, 6.0}, false);
    simp::sim::fillRect(g, {6.0, 4.0, 10.15, 6.15}, true);
    simp::sim::fillRect(g, {-0.15, -0.15, 10.15, 0.0}, true);
    simp::sim::fillRect(g, {-0.15, 6.0, 10.15, 6.15}, true);
    simp::sim::fillRect(g, {-0.15, -0.15, 0.0, 6.15}, true);
    simp::sim::fillRect(g, {10.0, -0.15, 10.15, 6.15}, true);
    w.objects.class_names = simp::obs::defaultClassNames();
    return w;
}

std::string outDir(const std::string& name) {
    const auto d = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "lidar" / name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d.string();
}

}  // namespace

TEST(LidarScanPoints, ScanPointsLieOnTheWalls) {
    const auto w = lRoom();
    simp::sim::LidarParams p;
    p.range_std_m = 0.0;
    simp::sim::LidarSimulator lidar(w, p);
    simp::sim::Rng rng(1);
    const auto scan = lidar.scan({3.0, 2.0, 0.0}, {}, 0.0, rng);
    const auto pts = simp::lidar::scanToPoints(scan, 1, 0.0, 30.0);
    ASSERT_GT(pts.size(), 1000u);
    // the ray straight ahead hits the wall at x = 10 m, 7 m ahead of the robot
    float x = 0, y = 0, z = 0;
    pts.getPoint(pts.size() / 2, x, y, z);
    EXPECT_NEAR(x, 7.0, 0.06);
    EXPECT_NEAR(y, 0.0, 0.06);
    EXPECT_GT(simp::lidar::wallSurfacePoints(w.floorplan).size(), 500u);
}

TEST(LidarScanPoints, ReturnsInsideTheFootprintAreLeftOut) {
    // Three rays: 0.1 m (something touching the scanner), 0.3 m and 2 m; the sensor 0.2 m ahead of the
    // robot centre. min_range_m 0.3 keeps the last two, 0 all three; max_range_m 1 drops the 2 m one.
    mrpt::obs::CObservation2DRangeScan scan;
    scan.aperture = static_cast<float>(M_PI / 2);
    scan.rightToLeft = true;
    scan.sensorPose = mrpt::poses::CPose3D(0.2, 0, 0.3, 0, 0, 0);
    scan.resizeScan(3);
    const float ranges[3] = {0.1f, 0.3f, 2.0f};
    for (std::size_t i = 0; i < 3; ++i) {
        scan.setScanRange(i, ranges[i]);
        scan.setScanRangeValidity(i, true);
    }
    EXPECT_EQ(simp::lidar::scanToPoints(scan, 1, 0.3, 30.0).size(), 2u);
    EXPECT_EQ(simp::lidar::scanToPoints(scan, 1, 0.0, 30.0).size(), 3u);
    EXPECT_EQ(simp::lidar::scanToPoints(scan, 1, 0.3, 1.0).size(), 1u);
    const auto far = simp::lidar::scanToPoints(scan, 1, 0.3, 30.0);
    float x = 0, y = 0, z = 0;
    far.getPoint(1, x, y, z);  // the 2 m ray, 45 deg left of the sensor's axis
    EXPECT_NEAR(x, 0.2 + 2.0 * std::cos(M_PI / 4), 1e-5);
    EXPECT_NEAR(y, 2.0 * std::sin(M_PI / 4), 1e-5);
}

TEST(LidarIcp, RecoversAKnownOffset) {
    const auto w = lRoom();
    simp::sim::LidarParams p;
    p.range_std_m = 0.02;
    simp::sim::LidarSimulator lidar(w, p);
    simp::sim::Rng rng(5);
    const mrpt::math::TPose2D truth{3.0, 2.0, 0.3};
    const auto scan = lidar.scan(truth, {}, 0.0, rng);
    simp::lidar::IcpPosesOptions o;
    o.alignment_sigma_m = 0;  // the fixed gate: an accepted alignment is taken as it is
    simp::lidar::IcpPoseTracker tracker(w.floorplan, o);
    tracker.reset({3.06, 1.95, 0.33});  // 0.08 m and 0.03 rad off
    const auto est = tracker.step(mrpt::poses::CPose2D(), &scan);
    EXPECT_EQ(tracker.accepted(), 1u);
    EXPECT_NEAR(est.x, truth.x, 0.03);
    EXPECT_NEAR(est.y, truth.y, 0.03);
    EXPECT_NEAR(est.phi, truth.phi, 0.01);
    // a correction larger than max_correction_m is rejected: the prediction is kept
    o.max_correction_m = 0.02;
    simp::lidar::IcpPoseTracker strict(w.floorplan, o);
    strict.reset({3.06, 1.95, 0.33});
    const auto kept = strict.step(mrpt::poses::CPose2D(), &scan);
    EXPECT_EQ(strict.rejected(), 1u);
    EXPECT_DOUBLE_EQ(kept.x, 3.06);
}

TEST(LidarIcp, APoseThatSlidIsTakenBackByTheUncertaintyGate) {
    // The robot stands still in the L-shaped room; the tracker starts 0.12 m off (a pose that slid),
    // from where one alignment reaches the truth. A fixed gate of 0.05 m rejects every alignment: the
    // error stays for good. The uncertainty gate (0.01 m alignments, 4 sigmas: 0.04 m at first) rejects
    // too at first, but each step's process noise widens it until the walls are believed, and the
    // Kalman gain then brings the pose back.
    const auto w = lRoom();
    simp::sim::LidarParams p;
    p.range_std_m = 0.02;
    simp::sim::LidarSimulator lidar(w, p);
    const mrpt::math::TPose2D truth{3.0, 2.0, 0.3};
    const auto run = [&](double alignment_sigma_m) {
        simp::lidar::IcpPosesOptions o;
        o.alignment_sigma_m = alignment_sigma_m;
        o.max_correction_m = 0.05;  // the fixed gate's (used when alignment_sigma_m = 0)
        simp::lidar::IcpPoseTracker tracker(w.floorplan, o);
        tracker.reset({3.12, 2.0, 0.3});
        simp::sim::Rng rng(8);
        mrpt::math::TPose2D est{};
        for (int k = 0; k < 300; ++k) {
            const auto scan = lidar.scan(truth, {}, 0.0, rng);
            est = tracker.step(mrpt::poses::CPose2D(), &scan);
        }
        return std::make_pair(est, tracker.accepted());
    };
    const auto [fixed, fixed_accepted] = run(0.0);
    EXPECT_EQ(fixed_accepted, 0u);
    EXPECT_NEAR(fixed.x, 3.12, 1e-9);
    const auto [gated, gated_accepted] = run(0.01);
    EXPECT_GT(gated_accepted, 0u);
    EXPECT_LT(std::hypot(gated.x - truth.x, gated.y - truth.y), 0.02);
    EXPECT_NEAR(gated.phi, truth.phi, 0.01);
}

TEST(LidarIcp, CorrectsOnlyAlongTheDirectionsTheWallsConstrain) {
    // A corridor 2 m wide and 40 m long (walls along x only within the scanner's 15 m): the walls fix y
    // and the heading, nothing fixes x.
    simp::world::World w;
    auto& g = w.floorplan;
    g.setSize(-0.5, 40.5, -0.5, 2.5, 0.05, 0.5f);
    simp::sim::fillRect(g, {0.0, 0.0, 40.0, 2.0}, false);
    simp::sim::fillRect(g, {-0.15, -0.15, 40.15, 0.0}, true);
    simp::sim::fillRect(g, {-0.15, 2.0, 40.15, 2.15}, true);
    simp::sim::LidarParams p;
    p.range_std_m = 0.0;
    simp::sim::LidarSimulator lidar(w, p);
    simp::sim::Rng rng(2);
    const mrpt::math::TPose2D truth{20.0, 1.0, 0.0};
    const auto pts = simp::lidar::scanToPoints(lidar.scan(truth, {}, 0.0, rng), 2, 0.3, 15.0);
    simp::lidar::IcpPosesOptions o;
    const simp::lidar::IcpPoseTracker tracker(w.floorplan, o);
    const mrpt::poses::CPose2D predicted(20.0, 1.0, 0.0), aligned(20.08, 0.96, 0.01);
    const auto kept = tracker.constrained(predicted, aligned, pts);
    EXPECT_NEAR(kept.x(), 20.0, 1e-6);   // along the corridor: the prediction
    EXPECT_NEAR(kept.y(), 0.96, 1e-6);   // across it: the alignment
    EXPECT_NEAR(kept.phi(), 0.01, 1e-12);  // the heading of the alignment
    // in the L-shaped room both directions are constrained: the alignment as it is
    const auto room = lRoom();
    simp::sim::LidarSimulator room_lidar(room, p);
    const auto room_pts = simp::lidar::scanToPoints(room_lidar.scan({3.0, 2.0, 0.3}, {}, 0.0, rng), 2, 0.3, 15.0);
    const simp::lidar::IcpPoseTracker room_tracker(room.floorplan, o);
    const mrpt::poses::CPose2D room_aligned(3.0, 2.0, 0.3);
    const auto all = room_tracker.constrained(mrpt::poses::CPose2D(3.06, 1.95, 0.33), room_aligned, room_pts);
    EXPECT_NEAR(all.x(), 3.0, 1e-6);
    EXPECT_NEAR(all.y(), 2.0, 1e-6);
    // min_constraint_points = 0: every direction, also in the corridor
    o.min_constraint_points = 0;
    const simp::lidar::IcpPoseTracker unconstrained(w.floorplan, o);
    EXPECT_NEAR(unconstrained.constrained(predicted, aligned, pts).x(), 20.08, 1e-6);
}

TEST(LidarIcpPosesApp, EndToEndOnASimulatedSequence) {
    simp::sim::OfficeParams op;
    op.rooms = 4;
    const auto world = simp::sim::generateOffice(op, 11);
    const std::string dir = outDir("app");
    simp::world::saveWorld(world, dir + "/W");
    simp::sim::SimParams sp;
    sp.duration_s = 30;
    sp.progress = false;
    sp.lidar.enabled = true;
    simp::sim::simulateSequence(world, sp, 12, dir + "/Q");
    const auto gt = simp::io::readTum(dir + "/Q/groundtruth.tum");
    const auto& s0 = gt.front().pose;
    std::ostringstream start;
    start << s0.x << "," << s0.y << "," << s0.phi;
    simp::lidar::IcpPosesApp app;
    std::ostringstream out;
    ASSERT_TRUE(app.initialize({"--world", dir + "/W", "--rawlog", dir + "/Q/sequence.rawlog", "--initial-pose",
                                start.str(), "--out", dir + "/P.tum", "--gt", dir + "/Q/groundtruth.tum"},
                               out));
    app.run(out);
    EXPECT_EQ(app.poses.size(), gt.size() - 1);
    EXPECT_EQ(app.scans, app.poses.size());
    ASSERT_TRUE(app.metrics && app.metrics->ate_trans_m);
    EXPECT_LT(*app.metrics->ate_trans_m, 0.05) << out.str();
    EXPECT_NE(out.str().find("ATE"), std::string::npos);
}

TEST(LidarIcpPosesApp, BadInputIsNamed) {
    std::ostringstream out;
    using simp_test::errorOf;
    const auto init = [&](const std::vector<std::string>& args) {
        simp::lidar::IcpPosesApp app;
        return errorOf([&] { app.initialize(args, out); });
    };
    EXPECT_NE(init({"--world", "W", "--rawlog", "R", "--out", "P", "--initial-pose", "1,2"})
                  .find("expected 3 numbers"),
              std::string::npos);
    EXPECT_NE(init({"--world", "W", "--rawlog", "R", "--out", "P", "--initial-pose", "1,x,2"})
                  .find("'x' is not a finite number"),
              std::string::npos);
    EXPECT_NE(init({"--world", "W", "--rawlog", "R", "--out", "P"}).find("--initial-pose"),
              std::string::npos);
    EXPECT_NE(init({"--world", "W", "--initial-pose", "1,2,3", "--out", "P"}).find("--rawlog"),
              std::string::npos);
}
