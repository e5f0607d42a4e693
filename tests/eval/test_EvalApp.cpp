// simp-eval end to end: in-process (EvalApp) and the real binary through std::system.
#include <gtest/gtest.h>
#include <simp/eval/EvalApp.h>
#include <simp/world/ChangesFile.h>
#include <simp/io/Tum.h>
#include <simp/world/SimpFormat.h>
#include <simp/world/World.h>

#include <nlohmann/json.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// Output folder of the running test (ctest may run the tests of this file in parallel).
fs::path testDir() {
    const fs::path d = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_app" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(d);
    return d;
}

/// Runs EvalApp in-process; returns the exit code, standard output in `out`.
int runApp(std::vector<std::string> args, std::string& out) {
    args.insert(args.begin(), "simp-eval");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    simp::eval::EvalApp app;
    app.initialize(static_cast<int>(argv.size()), argv.data());
    std::ostringstream o, e;
    const int code = app.run(o, e);
    out = o.str();
    return code;
}

json lastLineJson(const std::string& text) {
    std::istringstream in(text);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return json::parse(last);
}

/// GT: 20 s along x; estimate 4 m off for 2 s, then 0.1 m off: converged at 2 s, ATE 0.1 m.
void writeTrajectories(const fs::path& gt, const fs::path& est) {
    std::vector<simp::io::StampedPose2D> g, e;
    for (int k = 0; k <= 40; ++k) {
        const double t = 0.5 * k;
        g.push_back({t, {t, 0.0, 0.0}});
        e.push_back({t, {t, t < 2.0 ? 4.0 : 0.1, 0.0}});
    }
    simp::io::writeTum(gt.string(), g);
    simp::io::writeTum(est.string(), e);
}

simp::world::World smallWorld(double shift_m) {
    simp::world::World w;
    simp::world::setGridExactly(w.floorplan, 0, 0, 160, 120, 0.05, 1.0f);
    w.objects.class_names = {"table", "sofa"};
    w.objects.class_noise.resize(2);
    for (int i = 0; i < 3; ++i) {
        simp::world::MapObject o;
        o.id = i;
        o.class_id = i % 2;
        o.box = simp::geometry::makeUprightBox({1.0 + 2.0 * i + shift_m, 2.0, 0.4}, {1.0, 1.0, 0.8}, 0.0);
        w.objects.objects.push_back(o);
    }
    return w;
}

}  // namespace

TEST(EvalApp, TrajInProcessPrintsSummaryAndJson) {
    const fs::path kDir = testDir();
    writeTrajectories(kDir / "gt.tum", kDir / "est.tum");
    std::string out;
    ASSERT_EQ(runApp({"traj", "--gt", (kDir / "gt.tum").string(), "--est", (kDir / "est.tum").string(), "--json",
                      "--png", (kDir / "traj.png").string()},
                     out),
              0);
    EXPECT_NE(out.find("converged: yes, after 2.000 s"), std::string::npos) << out;
    const json j = lastLineJson(out);
    EXPECT_TRUE(j["success"].get<bool>());
    EXPECT_NEAR(j["convergence_time_s"].get<double>(), 2.0, 1e-9);
    EXPECT_NEAR(j["ate_trans_m"].get<double>(), 0.1, 1e-6);
    EXPECT_NEAR(j["duration_s"].get<double>(), 20.0, 1e-9);
    EXPECT_TRUE(fs::exists(kDir / "traj.png"));
}

TEST(EvalApp, RealBinaryTrajJsonAndExitCodes) {
    const fs::path kDir = testDir();
    writeTrajectories(kDir / "gt.tum", kDir / "est.tum");
    const std::string bin = std::string(SIMP_BINARY_DIR) + "/bin/simp-eval";
    ASSERT_TRUE(fs::exists(bin)) << bin;
    const auto out_file = kDir / "stdout.txt";
    const std::string cmd = "'" + bin + "' traj --gt '" + (kDir / "gt.tum").string() + "' --est '" +
                            (kDir / "est.tum").string() + "' --json > '" + out_file.string() + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream f(out_file);
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const json j = lastLineJson(text);
    ASSERT_EQ(j.size(), 6u) << j.dump();
    EXPECT_TRUE(j["success"].is_boolean());
    EXPECT_TRUE(j["converged"].is_boolean());
    EXPECT_TRUE(j["convergence_time_s"].is_number());
    EXPECT_TRUE(j["ate_trans_m"].is_number());
    EXPECT_TRUE(j["ate_rot_rad"].is_number());
    EXPECT_TRUE(j["duration_s"].is_number());
    // bad input: non-zero exit
    const std::string missing = "'" + bin + "' traj --gt /nonexistent/gt.tum --est '" + (kDir / "est.tum").string() +
                                "' --json > /dev/null 2>&1";
    EXPECT_NE(std::system(missing.c_str()), 0);
    const std::string unknown = "'" + bin + "' traj --bogus > /dev/null 2>&1";
    EXPECT_NE(std::system(unknown.c_str()), 0);
}

TEST(EvalApp, MapAndPlotMapOnSavedWorlds) {
    const fs::path kDir = testDir();
    const auto gt_dir = kDir / "gt_world", map_dir = kDir / "map_world";
    simp::world::saveWorld(smallWorld(0.0), gt_dir.string());
    // every object shifted 0.5 m along x: footprint IoU = 0.5 / 1.5 = 1/3 for each
    simp::world::saveWorld(smallWorld(0.5), map_dir.string());
    std::string out;
    ASSERT_EQ(runApp({"map", "--gt", gt_dir.string(), "--map", map_dir.string(), "--json", "--png",
                      (kDir / "map_eval.png").string()},
                     out),
              0);
    EXPECT_NE(out.find("| | sofa | table | AVG |"), std::string::npos) << out;
    const json j = lastLineJson(out);
    EXPECT_NEAR(j["iou"].get<double>(), 1.0 / 3.0, 1e-6);
    EXPECT_NEAR(j["precision"].get<double>(), 1.0, 1e-12);
    EXPECT_NEAR(j["per_class"]["table"]["recall"].get<double>(), 1.0, 1e-12);
    EXPECT_TRUE(fs::exists(kDir / "map_eval.png"));
    ASSERT_EQ(runApp({"plot-map", "--world", gt_dir.string(), "--png", (kDir / "map.png").string()}, out), 0);
    EXPECT_TRUE(fs::exists(kDir / "map.png"));
}

TEST(EvalApp, UsageErrors) {
    const fs::path kDir = testDir();
    std::string out;
    EXPECT_THROW(runApp({"traj", "--gt"}, out), std::invalid_argument);
    EXPECT_THROW(runApp({"traj", "--est", "x"}, out), std::invalid_argument);  // --gt missing
    EXPECT_THROW(runApp({"map", "--gt", "a", "--map", "b", "--max-center-dist", "far"}, out), std::exception);
    EXPECT_THROW(runApp({"plot", "--world", "w"}, out), std::invalid_argument);
    EXPECT_THROW(runApp({"map", "--gt", (kDir / "none").string(), "--map", (kDir / "none").string()}, out),
                 std::runtime_error);
    EXPECT_EQ(runApp({"batch", "--help"}, out), 0);
    EXPECT_NE(out.find("simp-eval batch"), std::string::npos);
}

TEST(EvalApp, AuthorsGroundTruthMapAgainstItselfAndShifted) {
    const fs::path kDir = testDir();
    const fs::path data = fs::path(SIMP_SHARED_DATA_DIR) / "simp-office";
    if (!fs::exists(data / "global_variance.json"))
        GTEST_SKIP() << "the authors' data is not at " << data << " (optional, read-only)";
    auto world = simp::world::importSimpMap(data.string());
    const auto gt_dir = kDir / "office_gt";
    simp::world::saveWorld(world, gt_dir.string());
    std::string out;
    ASSERT_EQ(runApp({"map", "--gt", gt_dir.string(), "--map", gt_dir.string(), "--json"}, out), 0);
    json j = lastLineJson(out);
    EXPECT_NEAR(j["iou"].get<double>(), 1.0, 1e-9);
    EXPECT_NEAR(j["precision"].get<double>(), 1.0, 1e-12);
    EXPECT_NEAR(j["recall"].get<double>(), 1.0, 1e-12);
    // Every footprint shrunk to 0.8 x 0.8 of its sides about its centre: it lies inside the original,
    // so each own-pair footprint IoU is 0.64 and every object still matches itself.
    for (auto& o : world.objects.objects) o.box.size.head<2>() *= 0.8;
    const auto moved_dir = kDir / "office_moved";
    simp::world::saveWorld(world, moved_dir.string());
    ASSERT_EQ(runApp({"map", "--gt", gt_dir.string(), "--map", moved_dir.string(), "--json"}, out), 0);
    j = lastLineJson(out);
    EXPECT_NEAR(j["precision"].get<double>(), 1.0, 1e-12);
    EXPECT_NEAR(j["recall"].get<double>(), 1.0, 1e-12);
    // 0.64 up to a few same-class objects that overlap each other in the authors' map
    EXPECT_NEAR(j["iou"].get<double>(), 0.64, 1e-3);
    // Moved 100 m: outside the floor, nothing matches.
    for (auto& o : world.objects.objects) o.box.center.x() += 100.0;
    simp::world::saveWorld(world, moved_dir.string());
    ASSERT_EQ(runApp({"map", "--gt", gt_dir.string(), "--map", moved_dir.string(), "--json"}, out), 0);
    j = lastLineJson(out);
    EXPECT_EQ(j["recall"].get<double>(), 0.0);
    EXPECT_EQ(j["iou"].get<double>(), 0.0);
    ASSERT_EQ(runApp({"plot-map", "--world", gt_dir.string(), "--png", (kDir / "office_map.png").string()}, out), 0);
}

namespace {

simp::world::ChangeRecord changeOf(const std::string& kind, std::int64_t id, const std::string& cls, double x,
                                   double x_after) {
    simp::world::ChangeRecord c;
    c.kind = kind;
    c.id_before = id;
    c.class_name = cls;
    c.before = simp::geometry::makeUprightBox({x, 2.0, 0.4}, {1.0, 1.0, 0.8}, 0.0);
    if (kind == "moved") c.id_after = id, c.after = simp::geometry::makeUprightBox({x_after, 2.0, 0.4}, {1.0, 1.0, 0.8}, 0.0);
    return c;
}

}  // namespace

TEST(EvalApp, ChangesFindTheIdsOfABuiltMapFromTheFiles) {
    // W: table 0 at x = 1, sofa 1 at x = 3, table 2 at x = 5. M0, a map built of W, has the same
    // objects 0.1 m off under its own ids 100-102. The truth removes table 0 and moves sofa 1; the
    // report (on M0) says the same in M0's ids. Each change file names the world of its ids.
    const fs::path kDir = testDir();
    simp::world::saveWorld(smallWorld(0.0), (kDir / "W").string());
    auto m0 = smallWorld(0.1);
    for (auto& o : m0.objects.objects) o.id += 100;
    simp::world::saveWorld(m0, (kDir / "M0").string());
    fs::create_directories(kDir / "Q");
    fs::create_directories(kDir / "M");
    const auto truth = (kDir / "Q" / "changes.json").string(), report = (kDir / "M" / "changes.json").string();
    simp::world::saveChangesFile({changeOf("removed", 0, "table", 1, 0), changeOf("moved", 1, "sofa", 3, 3.8)}, truth,
                                 (kDir / "W").string());
    const std::vector<simp::world::ChangeRecord> on_m0 = {changeOf("removed", 100, "table", 1.1, 0),
                                                          changeOf("moved", 101, "sofa", 3.1, 3.8)};
    simp::world::saveChangesFile(on_m0, report, (kDir / "M0").string());
    std::string out;
    ASSERT_EQ(runApp({"changes", "--truth", truth, "--report", report, "--json"}, out), 0);
    EXPECT_NE(out.find("matched through their objects"), std::string::npos) << out;
    json j = lastLineJson(out);
    EXPECT_DOUBLE_EQ(j["removed"]["precision"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(j["removed"]["recall"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(j["moved"]["precision"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(j["moved"]["recall"].get<double>(), 1.0);

    // A report that does not name its map is scored by id as it stands: M0's ids are not W's.
    simp::world::saveChangesFile(on_m0, report);
    ASSERT_EQ(runApp({"changes", "--truth", truth, "--report", report, "--json"}, out), 0);
    j = lastLineJson(out);
    EXPECT_DOUBLE_EQ(j["removed"]["precision"].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(j["moved"]["recall"].get<double>(), 0.0);

    // An update of W itself (M0 = W) speaks in W's ids: scored by id, no translation.
    simp::world::saveChangesFile({changeOf("removed", 0, "table", 1, 0), changeOf("moved", 1, "sofa", 3, 3.8)}, report,
                                 (kDir / "W").string());
    ASSERT_EQ(runApp({"changes", "--truth", truth, "--report", report, "--json"}, out), 0);
    EXPECT_EQ(out.find("matched through"), std::string::npos) << out;
    j = lastLineJson(out);
    EXPECT_DOUBLE_EQ(j["removed"]["precision"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(j["moved"]["recall"].get<double>(), 1.0);

    // A named map that is gone: a warning that says what to give, scores by id.
    simp::world::saveChangesFile(on_m0, report, (kDir / "gone").string());
    ASSERT_EQ(runApp({"changes", "--truth", truth, "--report", report, "--json"}, out), 0);
    EXPECT_NE(out.find("warning"), std::string::npos) << out;
    EXPECT_NE(out.find("--before-world W --before-map M0"), std::string::npos) << out;

    // A named folder that is no world: a warning naming what failed, scores by id.
    fs::create_directories(kDir / "not_a_world");
    simp::world::saveChangesFile(on_m0, report, (kDir / "not_a_world").string());
    ASSERT_EQ(runApp({"changes", "--truth", truth, "--report", report, "--json"}, out), 0);
    EXPECT_NE(out.find("cannot be read"), std::string::npos) << out;
    EXPECT_DOUBLE_EQ(lastLineJson(out)["removed"]["precision"].get<double>(), 0.0);
}
