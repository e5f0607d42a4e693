// The LiDAR sensor model (MRPT's likelihood field on the floor plan) alone and times the object model
// (`simp-localize --method lidar|simp+lidar`): a scan from the true pose, fusion where each source
// alone is ambiguous, and a rawlog without scans.
#include <gtest/gtest.h>
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

mrpt::obs::CObservation2DRangeScan scanFrom(const simp::world::World& w, const mrpt::math::TPose2D& pose) {
    simp::world::World walls_only = w;
    walls_only.objects.objects.clear();
    simp::sim::LidarParams p;
    p.range_std_m = 0.01;
    simp::sim::LidarSimulator lidar(walls_only, p);
    simp::sim::Rng rng(3);
    return lidar.scan(pose, {}, 0.0, rng);
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
