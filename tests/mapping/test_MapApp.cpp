#include <gtest/gtest.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <simp/eval/Scene3D.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/io/Tum.h>
#include <simp/mapping/MapApp.h>
#include <simp/world/ChangesFile.h>
#include <simp/world/World.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "MappingTestScene.h"

using namespace simp::mapping;
using simp::geometry::makeUprightBox;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kClasses = {"table", "cabinet", "chair"};
const std::vector<test::TrueObject> kTruth = {{0, makeUprightBox({1.4, 3.0, 0.375}, {1.2, 0.8, 0.75}, 0.3)},
                                              {1, makeUprightBox({6.6, 1.0, 0.9}, {0.5, 1.0, 1.8}, 0.0)}};

/// Q/sequence.rawlog and Q/groundtruth.tum of a robot circling the room among `truth`.
void writeSequence(const std::string& q, const std::vector<test::TrueObject>& truth) {
    fs::create_directories(q);
    mrpt::io::CFileOutputStream file(q + "/sequence.rawlog");
    auto arch = mrpt::serialization::archiveFrom(file);
    std::vector<simp::io::StampedPose2D> traj;
    std::mt19937 rng(42);
    constexpr int kSteps = 80;
    mrpt::poses::CPose2D prev;
    for (int s = 0; s < kSteps; ++s) {
        const double a = 2.0 * M_PI * s / kSteps, t = 1.6e9 + 0.2 * s;
        const mrpt::poses::CPose2D p(4.0 + 1.2 * std::cos(a), 3.0 + 1.2 * std::sin(a), a + M_PI / 2);
        traj.push_back({t, p.asTPose()});
        mrpt::obs::CActionCollection acts;
        mrpt::obs::CActionRobotMovement2D move;
        move.timestamp = mrpt::Clock::fromDouble(t);
        move.computeFromOdometry(s == 0 ? mrpt::poses::CPose2D() : p - prev, {});
        acts.insert(move);
        mrpt::obs::CSensoryFrame sf;
        for (auto& o : test::observe(truth, kClasses, mrpt::poses::CPose3D(p), rng)) {
            auto ptr = simp::obs::CObservationObjects3D::Create(o);
            ptr->timestamp = mrpt::Clock::fromDouble(t);
            sf.insert(ptr);
        }
        arch << acts << sf;
        prev = p;
    }
    simp::io::writeTum(q + "/groundtruth.tum", traj);
}

/// W (floor plan + an objects.json whose objects must NOT be used), Q (writeSequence of kTruth)
/// and test.ini.
std::string writeInputs(const std::string& name) {
    const fs::path dir = fs::path(SIMP_TEST_OUTPUT_DIR) / "mapping" / name;
    fs::remove_all(dir);
    fs::create_directories(dir / "Q");
    simp::world::World w;
    w.floorplan = test::makeFloorPlan(8, 6);
    w.objects.class_names = kClasses;
    w.objects.class_noise.resize(kClasses.size());
    simp::model::NoiseModel table_noise;
    table_noise.cov_m2 << 0.04, 0, 0, 0.09;
    w.objects.class_noise[0] = table_noise;
    simp::world::MapObject decoy;  // far from anything observed
    decoy.id = 99;
    decoy.class_id = 2;
    decoy.box = makeUprightBox({7.5, 5.5, 0.45}, {0.5, 0.5, 0.9}, 0.0);
    w.objects.objects.push_back(decoy);
    simp::world::saveWorld(w, (dir / "W").string());
    writeSequence((dir / "Q").string(), kTruth);
    // The shipped ini disables chairs, keeps tables from 1 m and cabinets from confidence 0.9:
    // the test detections (confidence 0.9f) use a test ini.
    std::ofstream ini(dir / "test.ini");
    ini << "[mapping]\nclass_min_confidence = table:0.5, cabinet:0.5\nclass_min_range_m = table:0, cabinet:0\n";
    return dir.string();
}

void checkOutput(const std::string& out) {
    const simp::world::World m = simp::world::loadWorld(out);
    EXPECT_TRUE(fs::exists(fs::path(out) / "map.png"));
    EXPECT_EQ(m.objects.class_names, kClasses);
    ASSERT_TRUE(m.objects.class_noise[0].has_value());  // W's class noise copied
    EXPECT_NEAR(m.objects.class_noise[0]->cov_m2(1, 1), 0.09, 1e-12);
    for (const auto& o : m.objects.objects) EXPECT_NE(o.id, 99);  // W's objects are not used
    for (const auto& t : kTruth) {
        double best = 1e9;
        for (const auto& o : m.objects.objects)
            if (o.class_id == t.class_id) best = std::min(best, (o.box.center - t.box.center).head<2>().norm());
        EXPECT_LT(best, 0.05) << kClasses[t.class_id];
    }
    EXPECT_FALSE(m.rooms.empty());  // the segmented rooms are written
}

/// Runs `app` as simp-map with `args` (after the program name); returns its log.
std::string runMapApp(MapApp& app, const std::vector<std::string>& args) {
    std::vector<std::string> all = {"simp-map"};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<const char*> argv;
    for (const auto& a : all) argv.push_back(a.c_str());
    std::ostringstream log;
    app.log = &log;
    if (!app.initialize(static_cast<int>(argv.size()), argv.data())) {
        ADD_FAILURE() << "simp-map did not accept its arguments";
        return {};
    }
    app.run();
    return log.str();
}

}  // namespace

TEST(MapApp, BuildsTheMapOfASmallRawlogEndToEnd) {
    const std::string dir = writeInputs("end_to_end");
    const std::string test_ini = dir + "/test.ini";
    const std::string out = dir + "/M";
    const std::string scene = dir + "/map.3Dscene";
    MapApp app;
    const std::string log = runMapApp(app, {"--world", dir + "/W", "--rawlog", dir + "/Q/sequence.rawlog", "--poses",
                                            dir + "/Q/groundtruth.tum", "--out", out, "--config", test_ini, "--3dscene", scene});
    EXPECT_EQ(app.framesMapped(), 80u);
    EXPECT_NE(log.find("objects written"), std::string::npos);
    checkOutput(out);

    // --3dscene: the floor plan, a labelled box per built object, the poses file as ground truth.
    const auto loaded = simp::eval::loadScene(scene);
    EXPECT_TRUE(loaded->getByName(simp::eval::scene_names::kFloorplan));
    const auto objects = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(
        loaded->getByName(simp::eval::scene_names::kObjects));
    ASSERT_TRUE(objects);
    const auto built = simp::world::loadWorld(out).objects.objects.size();
    ASSERT_GT(built, 0u);
    EXPECT_EQ(objects->size(), 2 * built);  // a CBox and a CText each
    const auto gt = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(
        loaded->getByName(simp::eval::scene_names::kGroundTruth));
    ASSERT_TRUE(gt);
    EXPECT_EQ(gt->getLineCount() + 1, simp::io::readTum(dir + "/Q/groundtruth.tum").size());
    EXPECT_FALSE(loaded->getByName(simp::eval::scene_names::kParticles));
}

TEST(MapApp, UpdatesAnEarlierMapAndReportsWhatChanged) {
    const std::string dir = writeInputs("update_end_to_end");
    const std::vector<std::string> common = {"--world", dir + "/W", "--config", dir + "/test.ini"};
    const auto with = [&](std::vector<std::string> a) {
        a.insert(a.end(), common.begin(), common.end());
        return a;
    };
    MapApp first, second;
    runMapApp(first, with({"--rawlog", dir + "/Q/sequence.rawlog", "--poses", dir + "/Q/groundtruth.tum", "--out", dir + "/M0"}));
    // A second session after the cabinet was taken away.
    writeSequence(dir + "/Q2", {kTruth[0]});
    const std::string log = runMapApp(second, with({"--rawlog", dir + "/Q2/sequence.rawlog", "--poses", dir + "/Q2/groundtruth.tum",
                                            "--update", dir + "/M0", "--out", dir + "/M"}));
    EXPECT_NE(log.find("1 removed, 0 moved, 0 added, 0 doors closed"), std::string::npos) << log;
    for (const char* f : {"changes.json", "changes.png", "update_evidence.tsv", "objects.json"})
        EXPECT_TRUE(fs::exists(fs::path(dir) / "M" / f)) << f;
    const auto changes = simp::world::loadChangesFile(dir + "/M/changes.json");
    ASSERT_EQ(changes.size(), 1u);
    EXPECT_EQ(changes[0].kind, "removed");
    EXPECT_EQ(changes[0].class_name, "cabinet");
    // The report names the map its ids are of (simp-eval changes relates them to the truth's world).
    EXPECT_TRUE(fs::equivalent(simp::world::readChangesFile(dir + "/M/changes.json").before_world, dir + "/M0"));
    EXPECT_EQ(simp::world::loadWorld(dir + "/M").objects.objects.size(), 1u);  // the table stays
}

TEST(MapApp, OdometryOnlyUsesTheRawlogOdometry) {
    const std::string dir = writeInputs("odometry_only");
    MapAppArgs a;
    a.world_dir = dir + "/W";
    a.rawlog_path = dir + "/Q/sequence.rawlog";
    a.poses_path = dir + "/Q/groundtruth.tum";
    a.out_dir = dir + "/M";
    a.config_path = dir + "/test.ini";
    a.odometry_only = true;
    MapApp app;
    std::ostringstream log;
    app.log = &log;
    app.initialize(a);
    app.run();
    // Exact odometry from the first pose reproduces the poses: the same map.
    checkOutput(a.out_dir);
}

TEST(MapApp, BadInputGivesClearErrors) {
    const std::string dir = writeInputs("bad_input");
    MapAppArgs a;
    a.world_dir = dir + "/W";
    a.rawlog_path = dir + "/Q/missing.rawlog";
    a.poses_path = dir + "/Q/groundtruth.tum";
    a.out_dir = dir + "/M";
    MapApp app;
    try {
        app.initialize(a);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.rawlog"), std::string::npos);
    }
    a.rawlog_path = dir + "/Q/sequence.rawlog";
    a.config_path = dir + "/nope.ini";
    EXPECT_THROW(app.initialize(a), std::invalid_argument);  // io::StrictIni: a bad argument
    // Poses that do not overlap the rawlog's time span.
    a.config_path.clear();
    simp::io::writeTum(dir + "/late.tum", {{2e9, {0, 0, 0}}, {2e9 + 1, {0, 0, 0}}});
    a.poses_path = dir + "/late.tum";
    std::ostringstream log;
    app.log = &log;
    app.initialize(a);
    try {
        app.run();
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("late.tum"), std::string::npos);
    }
    const char* help[] = {"simp-map", "--help"};
    std::cout.setstate(std::ios::failbit);  // keep the usage text out of the test log
    EXPECT_FALSE(app.initialize(2, help));
    std::cout.clear();
    const char* bad[] = {"simp-map", "--world"};
    std::cerr.setstate(std::ios::failbit);
    EXPECT_THROW(app.initialize(2, bad), std::invalid_argument);
    std::cerr.clear();
}
