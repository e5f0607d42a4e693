/// config_ini/batch.ini names the directories the main demo writes: a small simp-demo run (the same
/// layout as `simp-demo --out demo_out`, the README's demo command) into a temporary root, then every
/// path of batch.ini, with its `demo_out/` prefix put under that root, is loaded as the batch loads it,
/// and the batch runs as shipped from a folder laid out like the project root after the demo.

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <simp/demo/DemoApp.h>
#include <simp/eval/BatchConfig.h>
#include <simp/eval/BatchRunner.h>
#include <simp/eval/MapMetrics.h>
#include <simp/io/Tum.h>
#include <simp/world/World.h>

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace {

/// `path` (relative to the project root) with the demo's output folder "demo_out" replaced by `root`.
fs::path underDemoRoot(const std::string& path, const fs::path& root) {
    const std::string prefix = "demo_out/";
    EXPECT_EQ(path.rfind(prefix, 0), 0u) << path << " is not in the demo's output folder";
    return root / path.substr(prefix.size());
}

/// Changes the working directory for its lifetime.
class WorkingDirectory {
   public:
    explicit WorkingDirectory(const fs::path& dir) : m_old(fs::current_path()) { fs::current_path(dir); }
    ~WorkingDirectory() { fs::current_path(m_old); }

   private:
    fs::path m_old;
};

}  // namespace

TEST(DemoBatch, BatchIniNamesTheDirectoriesTheDemoWrites) {
    // The README's demo command runs `.ci/setup.sh demo` = `simp-demo --out demo_out` from the project root.
    const fs::path root = fs::path(SIMP_TEST_OUTPUT_DIR) / "demo_batch" / "demo_out";
    fs::remove_all(root.parent_path());  // also the config_ini link and batch_out (the batch resumes runs)
    simp::demo::DemoApp demo;
    std::ostringstream log;
    // Small and fast, same layout: default number of runs (R1..R3), short sequences, few particles.
    ASSERT_TRUE(demo.initialize({"--out", root.string(), "--rooms", "3", "--mapping-duration", "30", "--duration", "8",
                                 "--particles", "200"},
                                log));
    demo.run(log);
    ASSERT_EQ(demo.runs.size(), 3u) << "the demo's default run count changed: update batch.ini's sequences";

    const auto cfg = simp::eval::loadBatchConfig(std::string(SIMP_SOURCE_DIR) + "/config_ini/batch.ini");
    // The map: a world directory the batch's simp-localize runs load.
    const auto world = simp::world::loadWorld(underDemoRoot(cfg.world, root).string());
    EXPECT_GT(world.objects.objects.size(), 10u);
    ASSERT_EQ(cfg.sequences.size(), demo.runs.size());
    for (std::size_t k = 0; k < cfg.sequences.size(); ++k) {
        EXPECT_EQ(cfg.sequences[k].name, demo.runs[k].name);
        const fs::path q = underDemoRoot(cfg.sequences[k].dir, root);
        EXPECT_TRUE(fs::is_regular_file(q / "sequence.rawlog")) << q;
        // 8 s of ground truth at the simulator's 10 Hz.
        EXPECT_GE(simp::io::readTum((q / "groundtruth.tum").string()).size(), 70u) << q;
    }
    // The localization config is the project's, relative to the project root.
    EXPECT_TRUE(fs::is_regular_file(fs::path(SIMP_SOURCE_DIR) / cfg.localize_config)) << cfg.localize_config;

    // The batch itself, paths as shipped, from a folder laid out like the project root after the demo
    // (demo_out/ and config_ini/); fewer runs and particles than shipped to stay quick.
    const fs::path project = root.parent_path();
    fs::create_directory_symlink(fs::path(SIMP_SOURCE_DIR) / "config_ini", project / "config_ini");
    WorkingDirectory cd(project);
    auto quick = simp::eval::loadBatchConfig("config_ini/batch.ini");
    quick.methods = {"simp", "edt"};
    quick.repetitions = 1;
    quick.particles = 300;
    std::ostringstream progress;
    const auto records = simp::eval::runBatch(quick, "batch_out", progress, false);  // simp-localize next to this test
    ASSERT_EQ(records.size(), 6u) << progress.str();
    for (const auto& r : records) {
        EXPECT_EQ(r.status, "ok") << r.sequence << " " << r.method << ": " << r.error;
        EXPECT_NEAR(r.duration_s, 8.0, 0.5) << r.sequence;  // the demo's --duration
    }
}

TEST(DemoBatch, EvalDefaultsEqualBatchIniMetrics) {
    // simp-eval traj / map without --config use these defaults; batch.ini must say the same.
    const std::string ini = std::string(SIMP_SOURCE_DIR) + "/config_ini/batch.ini";
    const auto cfg = simp::eval::loadBatchConfig(ini);
    const simp::eval::TrajMetricsParams d;
    EXPECT_EQ(cfg.metrics.max_trans_m, d.max_trans_m);
    EXPECT_EQ(cfg.metrics.max_rot_rad, d.max_rot_rad);
    EXPECT_EQ(cfg.metrics.max_outside_s, d.max_outside_s);
    EXPECT_EQ(cfg.metrics.convergence_fraction, d.convergence_fraction);
    const mrpt::config::CConfigFile file(ini);
    EXPECT_EQ(file.read_double("map_metrics", "max_center_dist_m", -1), simp::eval::MapMatchParams{}.max_center_dist_m);
}
