// Map quality end to end (doc/results.md): simulator world + one ground-truth-posed sequence ->
// simp-map's builder -> simp::eval::evaluateMap against the world, over the paper's Table I classes.
#include <gtest/gtest.h>
#include <simp/eval/MapMetrics.h>
#include <simp/mapping/MapApp.h>
#include <simp/sim/SimApp.h>
#include <simp/world/SimpFormat.h>
#include <simp/world/World.h>

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace {

/// Fresh output directory for one test.
fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(SIMP_TEST_OUTPUT_DIR) / "mapping" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void simulate(const std::vector<std::string>& args, std::ostream& log) {
    simp::sim::SimApp app;
    if (app.initialize(args, log)) app.run(log);
}

/// simp-map's app on world W with the sequence Q (known poses) and config_ini/mapping.ini, into M.
void buildMap(simp::mapping::MapApp& app, const std::string& W, const std::string& Q, const std::string& M,
              std::ostream& log) {
    simp::mapping::MapAppArgs a;
    a.world_dir = W;
    a.rawlog_path = Q + "/sequence.rawlog";
    a.poses_path = Q + "/groundtruth.tum";
    a.out_dir = M;
    a.config_path = std::string(SIMP_SOURCE_DIR) + "/config_ini/mapping.ini";
    app.log = &log;
    app.initialize(a);
    app.run();
}

/// The built map M against the world W over the paper's Table I classes (the authors' mapper
/// disables door, box, chair, person).
simp::eval::MapMetrics evaluateOnPaperClasses(const std::string& W, const std::string& M) {
    simp::eval::MapMatchParams p;
    p.classes = {"board", "cabinet", "desk", "drawers", "fire extinguisher", "oven", "potted plant", "sink", "sofa",
                 "table"};
    return simp::eval::evaluateMap(simp::world::loadWorld(W).objects, simp::world::loadWorld(M).objects, p);
}

}  // namespace

TEST(MapQuality, BuiltInOfficeKnownPoses) {
    const fs::path dir = freshDir("quality");
    const std::string W = (dir / "W").string(), Q = (dir / "Q").string(), M = (dir / "M").string();
    std::ostringstream log;
    simulate({"world", "--builtin", "office", "--rooms", "4", "--seed", "7", "--out", W}, log);
    // a mapping run: every room visited, a full turn in each part of it (simp-sim --coverage)
    simulate({"sequence", "--world", W, "--seed", "7", "--duration", "240", "--coverage", "--out", Q}, log);
    simp::mapping::MapApp app;
    buildMap(app, W, Q, M, log);
    const simp::eval::MapMetrics m = evaluateOnPaperClasses(W, M);
    std::cout << "map quality: IoU " << m.iou << ", precision " << m.precision << ", recall " << m.recall << "\n";
    // The paper's known-poses map (Table I, KP): IoU 0.67, Pr 0.96, Rc 0.94. What the method
    // reaches here (2026-11-22, this 4-room world, seed and coverage run, calibrated simulator
    // noise, class bias removed): IoU 0.75, Pr 0.98, Rc 0.93 over the classes present
    // (doc/results.md has the mean over eight worlds). Asserted ~0.08 below the measured values,
    // so that a regression is caught.
    EXPECT_GT(m.iou, 0.67);
    EXPECT_GT(m.recall, 0.85);
    EXPECT_GT(m.precision, 0.90);
}

TEST(MapQuality, AuthorsOfficeSimulatedDetections) {
    // The paper's own floor (../shared/data/simp-office, read-only; skipped when absent): its GT
    // map as the world, simulated detections along a coverage run, the default mapping options.
    const std::string office = std::string(SIMP_SHARED_DATA_DIR) + "/simp-office";
    if (!fs::exists(office + "/global_variance.json"))
        GTEST_SKIP() << "simp-office data not found at " << office << " (optional, read-only authors' data)";
    const fs::path dir = freshDir("quality_office");
    const std::string W = (dir / "W").string(), Q = (dir / "Q").string(), M = (dir / "M").string();
    simp::world::saveWorld(simp::world::importSimpMap(office), W);
    std::ostringstream log;
    simulate({"sequence", "--world", W, "--seed", "1", "--duration", "1200", "--coverage", "--out", Q}, log);
    simp::mapping::MapApp app;
    buildMap(app, W, Q, M, log);
    // Their Map.png draws the furniture: wall_align = auto switches the floor-plan prior off.
    EXPECT_FALSE(app.builder().wallAlignmentActive());
    EXPECT_NE(log.str().find("wall alignment is off"), std::string::npos);
    const simp::eval::MapMetrics m = evaluateOnPaperClasses(W, M);
    std::cout << "authors' office: IoU " << m.iou << ", precision " << m.precision << ", recall " << m.recall << "\n";
    // Measured with seed 1 (2026-11-22, class bias removed): IoU 0.82, Pr 0.94, Rc 0.91
    // (doc/results.md has the mean of six seeds; the paper's KP map: 0.67 / 0.96 / 0.94).
    // Asserted ~0.08 below.
    EXPECT_GT(m.iou, 0.74);
    EXPECT_GT(m.precision, 0.86);
    EXPECT_GT(m.recall, 0.84);
}
