// The LiDAR sensor model (MRPT's likelihood field on the floor plan) alone and times the object model
// (`simp-localize --method lidar|simp+lidar`): a scan from the true pose, fusion where each source
// alone is ambiguous, and a rawlog without scans.
#include <gtest/gtest.h>

#include <algorithm>
#include <simp/localization/FrameLikelihood.h>
#include <simp/localization/ScanLikelihood.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/LidarSimulator.h>
#include <simp/sim/OfficeLayout.h>

#include "TestUtil.h"
#include "common/ErrorOf.h"

namespace {

using simp::localization::LidarModelOptions;
using simp::localization::ScanLikelihood;

/// A 10 m x 6 m room, walls all round: the same from (x, y, phi) and (10 - x, 6 - y, phi + pi).
/// Two identical cabinets (yaw 0): a detection of the first from A is one of the second from C.
simp::world::World symmetricRoom() {
    simp::world::World w;
    auto& g = w.floorplan;
    g.setSize(-0.5, 10.5, -0.5, 6.5, 0.05, 0.5f);
    simp::sim::fillRect(g, {0.0, 0.0, 10.0, 6.0}, false);
    simp::sim::fillRect(g, {-0.15, -0.15, 10.15, 0.0}, true);
    simp::sim::fillRect(g, {-0.15, 6.0, 10.15, 6.15}, true);
    simp::sim::fillRect(g, {-0.15, -0.15, 0.0, 6.15}, true);
    simp::sim::fillRect(g, {10.0, -0.15, 10.15, 6.15}, true);
    auto& m = w.objects;
    m.class_names = simp::obs::defaultClassNames();
    simp::model::NoiseModel nm;
    nm.cov_m2 = Eigen::Matrix2d::Identity() * (0.15 * 0.15);
    m.class_noise.assign(m.class_names.size(), nm);
    const int cabinet = simp::obs::classIndexOf(m.class_names, "cabinet");
    for (const auto& [x, y] : {std::pair{5.0, 2.0}, std::pair{7.5, 4.8}}) {
        simp::world::MapObject o;
        o.id = static_cast<std::int64_t>(m.objects.size() + 1);
        o.class_id = cabinet;
        o.box = simp::geometry::makeUprightBox({x, y, 0.9}, {0.5, 1.0, 1.8}, 0.0);
        m.objects.push_back(o);
    }
    return w;
}

/// The simulated scan (1 cm range noise) of world `w` from `pose`: walls and the objects spanning the scan plane.
mrpt::obs::CObservation2DRangeScan simulatedScan(const simp::world::World& w, const mrpt::math::TPose2D& pose, int seed) {
    simp::sim::LidarParams p;
    p.range_std_m = 0.01;
    simp::sim::LidarSimulator lidar(w, p);
    simp::sim::Rng rng(seed);
    return lidar.scan(pose, {}, 0.0, rng);
}

/// The scan of the walls alone.
mrpt::obs::CObservation2DRangeScan scanFrom(const simp::world::World& w, const mrpt::math::TPose2D& pose) {
    simp::world::World walls_only = w;
    walls_only.objects.objects.clear();
    return simulatedScan(walls_only, pose, 3);
}

}  // namespace

TEST(ScanLikelihood, TruePoseBeatsShiftedAndTurnedPoses) {
    const auto w = symmetricRoom();
    const mrpt::math::TPose2D truth{3.0, 2.0, 0.3};
    const auto scan = scanFrom(w, truth);
    LidarModelOptions o;
    o.weight = 1.0;
    ScanLikelihood model(w.floorplan, o);
    const std::vector<mrpt::math::TPose2D> poses{truth, {3.3, 2.0, 0.3}, {3.0, 2.0, 0.4}, {3.0, 2.2, 0.3}};
    std::vector<double> log(poses.size());
    model.logLikelihoods(scan, poses.data(), poses.size(), log.data());
    for (std::size_t i = 1; i < poses.size(); ++i) EXPECT_GT(log[0], log[i] + 1.0) << "pose " << i;
    // weight scales the log-likelihood
    o.weight = 0.5;
    ScanLikelihood half(w.floorplan, o);
    double l_half = 0;
    half.logLikelihoods(scan, &truth, 1, &l_half);
    EXPECT_NEAR(l_half, 0.5 * log[0], 1e-9);
}

TEST(ScanLikelihood, FusionPrefersTheTruePoseWhereEachSourceAloneIsAmbiguous) {
    const auto w = symmetricRoom();
    const mrpt::math::TPose2D A{3.0, 2.0, 0.0};          // truth: cabinet 1 is 2 m ahead
    const mrpt::math::TPose2D B{7.0, 4.0, M_PI};         // the room's mirror of A: the same scan
    const mrpt::math::TPose2D C{5.5, 4.8, 0.0};          // A + (cabinet 2 - cabinet 1): the same detection
    const std::vector<mrpt::math::TPose2D> poses{A, B, C};
    LidarModelOptions o;
    o.weight = 1.0;
    ScanLikelihood scan_model(w.floorplan, o);
    std::vector<double> scan_log(3), obj_log(3);
    scan_model.logLikelihoods(scanFrom(w, A), poses.data(), 3, scan_log.data());
    const auto map = simp::localization::test::makeMap(w);
    mrpt::obs::CSensoryFrame sf;
    sf.insert(simp::localization::test::observe(w, A, {0}));
    ASSERT_EQ(simp::localization::frameLogLikelihoods(*map, sf, poses.data(), 3, obj_log.data()), 1u);
    // the scan cannot tell A from B, the objects cannot tell A from C
    EXPECT_NEAR(scan_log[0], scan_log[1], 0.05 * std::abs(scan_log[0]) + 1.0);
    EXPECT_GT(scan_log[0], scan_log[2] + 5.0);
    EXPECT_NEAR(obj_log[0], obj_log[2], 1e-6);
    EXPECT_GT(obj_log[0], obj_log[1] + 2.0);
    // together only A explains both
    const double fused_A = scan_log[0] + obj_log[0];
    EXPECT_GT(fused_A, scan_log[1] + obj_log[1] + 2.0);
    EXPECT_GT(fused_A, scan_log[2] + obj_log[2] + 5.0);
}

TEST(ScanLikelihood, MapObjectsSpanningTheScanPlaneExplainTheirReturns) {
    // A cabinet row along the right wall (0.6 m deep, 1.8 m tall), a board above the scan plane, a door.
    auto w = symmetricRoom();
    auto& m = w.objects;
    const auto add = [&](const char* cls, Eigen::Vector3d centre, Eigen::Vector3d size) {
        simp::world::MapObject o;
        o.id = static_cast<std::int64_t>(m.objects.size() + 1);
        o.class_id = simp::obs::classIndexOf(m.class_names, cls);
        o.box = simp::geometry::makeUprightBox(centre, size, 0.0);
        m.objects.push_back(o);
    };
    add("cabinet", {9.7, 3.0, 0.9}, {0.6, 4.0, 1.8});
    add("board", {0.05, 3.0, 1.5}, {0.1, 2.0, 1.0});  // 1.0-2.0 m: above the 0.3 m plane
    add("door", {5.0, 6.0, 1.0}, {0.9, 0.05, 2.0});   // an open leaf: never an obstacle
    const mrpt::math::TPose2D truth{3.0, 2.5, 0.2};
    simp::sim::LidarParams p;
    p.range_std_m = 0.01;
    simp::sim::LidarSimulator lidar(w, p);  // sees the three cabinets
    simp::sim::Rng rng(5);
    const auto scan = lidar.scan(truth, {}, 0.0, rng);
    LidarModelOptions o;
    o.weight = 1.0;
    o.sigma_m = 0.15;
    o.max_corr_distance_m = 0.3;
    o.beam_skip_threshold = 0;  // every return weighed: the contrast is what the objects in the grid explain
    ScanLikelihood plain(w.floorplan, o), with_objects(w.floorplan, o, &w.objects);
    const std::vector<mrpt::math::TPose2D> poses{truth, {3.15, 2.5, 0.2}, {2.85, 2.5, 0.2}, {3.0, 2.65, 0.2}, {3.0, 2.5, 0.3}};
    std::vector<double> lp(poses.size()), lo(poses.size());
    plain.logLikelihoods(scan, poses.data(), poses.size(), lp.data());
    with_objects.logLikelihoods(scan, poses.data(), poses.size(), lo.data());
    EXPECT_EQ(plain.objectsInGrid(), 0u);
    EXPECT_EQ(with_objects.objectsInGrid(), 3u);  // the two cabinets of the room and the row; no board, no door
    // the returns of the furniture are explained: the true pose scores much higher with the objects
    EXPECT_GT(lo[0], lp[0] + 10.0) << lo[0] << " vs " << lp[0];
    for (std::size_t i = 1; i < poses.size(); ++i) EXPECT_GT(lo[0], lo[i] + 2.0) << "pose " << i;
}

namespace {

/// Poses on a grid about `centre`: +-0.15 m in x and y, +-0.05 rad (the spread of a tracking set).
std::vector<mrpt::math::TPose2D> cloudAbout(const mrpt::math::TPose2D& centre) {
    std::vector<mrpt::math::TPose2D> poses;
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j)
            for (int k = -2; k <= 2; ++k) poses.push_back({centre.x + 0.05 * i, centre.y + 0.05 * j, centre.phi + 0.025 * k});
    return poses;
}

/// The room's LiDAR scan from `pose`, cabinets included (the scan sees them; a model without objects does not).
mrpt::obs::CObservation2DRangeScan scanWithCabinets(const simp::world::World& w, const mrpt::math::TPose2D& pose) {
    return simulatedScan(w, pose, 7);
}

}  // namespace

TEST(ScanLikelihood, ReturnsInsideTheRobotFootprintAreNotWeighed) {
    const auto w = symmetricRoom();
    const mrpt::math::TPose2D truth{3.0, 2.0, 0.3};
    const auto scan = scanFrom(w, truth);
    LidarModelOptions o;
    o.weight = 1.0;
    o.beam_skip_threshold = 0;  // the range rule alone
    ScanLikelihood model(w.floorplan, o);
    const std::vector<mrpt::math::TPose2D> poses{truth, {3.3, 2.0, 0.3}, {0.3, 0.3, 0.0}};
    // a person across the sensor: every return 2-5 cm; nothing is weighed (the plain field preferred a pose in a wall)
    auto blocked = scan;
    for (std::size_t i = 0; i < blocked.getScanSize(); ++i) blocked.setScanRange(i, 0.02f + 0.03f * static_cast<float>(i % 2));
    std::vector<double> log(poses.size(), -1.0);
    model.logLikelihoods(blocked, poses.data(), poses.size(), log.data());
    for (const double l : log) EXPECT_EQ(l, 0.0);
    // short returns count as absent: the same value as the scan with those returns invalid
    auto partly = scan, without = scan;
    for (std::size_t i = 100; i < 400; ++i) {
        partly.setScanRange(i, 0.25f);
        without.setScanRangeValidity(i, false);
    }
    std::vector<double> a(poses.size()), b(poses.size());
    model.logLikelihoods(partly, poses.data(), poses.size(), a.data());
    model.logLikelihoods(without, poses.data(), poses.size(), b.data());
    for (std::size_t i = 0; i < poses.size(); ++i) EXPECT_DOUBLE_EQ(a[i], b[i]) << "pose " << i;
    EXPECT_GT(a[0], a[1] + 1.0);
}

TEST(ScanLikelihood, ReturnsTheMapDoesNotExplainAreSkipped) {
    const auto w = symmetricRoom();  // the scan sees two cabinets; the model's grid has walls only
    const mrpt::math::TPose2D truth{3.0, 2.0, 0.0};  // cabinet 1 (0.5 x 1.0 m) 1.75 m ahead, cabinet 2 behind it
    const auto scan = scanWithCabinets(w, truth);
    const auto cloud = cloudAbout(truth);
    LidarModelOptions o;
    o.weight = 1.0;
    ScanLikelihood walls_only(w.floorplan, o), with_objects(w.floorplan, o, &w.objects);
    std::vector<double> log(cloud.size());
    walls_only.logLikelihoods(scan, cloud.data(), cloud.size(), log.data());
    // cabinet 1's front (1.0 m wide at 1.75 m: ~32 deg of 270, ~130 of 1081 returns) and the part of
    // cabinet 2 it does not hide are explained at no pose of the set; the walls at almost all
    const std::size_t skipped = walls_only.lastSkipped();
    EXPECT_GT(skipped, 100u);
    EXPECT_LT(skipped, 300u);
    // with the cabinets in the grid every return is explained: none is skipped
    with_objects.logLikelihoods(scan, cloud.data(), cloud.size(), log.data());
    EXPECT_EQ(with_objects.lastSkipped(), 0u);
    // a set where nothing is explained (off the plan): skipping would leave nothing to weigh, so none is skipped
    const auto wrong = cloudAbout({40.0, 30.0, 1.2});
    std::vector<double> wrong_log(wrong.size());
    walls_only.logLikelihoods(scan, wrong.data(), wrong.size(), wrong_log.data());
    EXPECT_EQ(walls_only.lastSkipped(), 0u);
    // off: nothing skipped
    o.beam_skip_threshold = 0;
    ScanLikelihood no_skip(w.floorplan, o);
    no_skip.logLikelihoods(scan, cloud.data(), cloud.size(), log.data());
    EXPECT_EQ(no_skip.lastSkipped(), 0u);
}

TEST(ScanLikelihood, SkippingTakesAwayThePullOfUnmappedFurniture) {
    // A cabinet row the map lacks along the bottom wall (8 m long, its front 0.55 m from the wall): from
    // (5, 2) facing +x, about 46 of the 109 weighed returns end on it. A pose moved 0.55 m toward the row
    // puts them on the bottom wall (and the top wall's 4 m away off it). Unskipped, the row's returns
    // narrow the truth's lead over that pose; skipped (explained at none of a tracking set's poses),
    // they weigh nothing: the lead grows by what they cost, and the truth is the set's best pose.
    auto w = symmetricRoom();
    auto& m = w.objects.objects;
    m.clear();
    simp::world::MapObject row;
    row.id = 1;
    row.class_id = simp::obs::classIndexOf(w.objects.class_names, "cabinet");
    row.box = simp::geometry::makeUprightBox({5.0, 0.4, 0.9}, {8.0, 0.3, 1.8}, 0.0);
    m.push_back(row);
    const mrpt::math::TPose2D truth{5.0, 2.0, 0.0}, pulled{5.0, 1.45, 0.0};
    const auto scan = scanWithCabinets(w, truth);
    auto poses = cloudAbout(truth);
    poses.push_back(pulled);
    const auto truth_at = static_cast<std::size_t>(std::find_if(poses.begin(), poses.end(), [&](const auto& p) {
                                                      return p.x == truth.x && p.y == truth.y && p.phi == truth.phi;
                                                  }) - poses.begin());
    ASSERT_LT(truth_at, poses.size());
    LidarModelOptions o;
    o.weight = 1.0;
    std::vector<double> log(poses.size());
    o.beam_skip_threshold = 0;
    ScanLikelihood plain(w.floorplan, o);
    plain.logLikelihoods(scan, poses.data(), poses.size(), log.data());
    const double plain_lead = log[truth_at] - log.back();
    o.beam_skip_threshold = 0.3;
    ScanLikelihood skip(w.floorplan, o);
    skip.logLikelihoods(scan, poses.data(), poses.size(), log.data());
    EXPECT_GT(skip.lastSkipped(), 300u);  // the row's returns (of all 1081)
    EXPECT_GT(log[truth_at] - log.back(), plain_lead + 30.0) << "plain lead " << plain_lead;
    const auto best = static_cast<std::size_t>(std::max_element(log.begin(), log.end()) - log.begin());
    EXPECT_NEAR(poses[best].x, truth.x, 0.051);
    EXPECT_NEAR(poses[best].y, truth.y, 0.051);
    EXPECT_NEAR(poses[best].phi, truth.phi, 0.026);
}

TEST(ScanLikelihood, BadOptionsNameTheKey) {
    const simp::io::StrictIni ini("[LidarModel]\nsigma_m = -1\n", "x.ini");
    LidarModelOptions o;
    EXPECT_NE(simp_test::errorOf([&] { o.loadFromConfig(ini); }).find("[LidarModel] sigma_m"), std::string::npos);
}

TEST(ScanLikelihood, RawlogWithoutScansIsAClearErrorForLidarMethods) {
    const auto& s = simp::localization::test::sharedScenario();
    for (const std::string method : {"lidar", "simp+lidar"}) {
        simp::localization::LocalizeApp app;
        const std::string out = simp::localization::test::freshOutputDir("no_scans_" + std::to_string(method.size()));
        const std::string err = simp_test::errorOf([&] {
            simp::localization::test::runApp(app, {"--world", s.world_dir, "--rawlog", s.rawlog_path, "--out", out,
                                                   "--method", method});
        });
        EXPECT_NE(err.find("holds no mrpt::obs::CObservation2DRangeScan"), std::string::npos) << err;
        EXPECT_NE(err.find(s.rawlog_path), std::string::npos) << err;
    }
}
