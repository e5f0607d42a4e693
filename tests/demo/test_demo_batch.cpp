/// config_ini/batch.ini names the directories the main demo writes: a small simp-demo run (the same
/// layout as `simp-demo --out demo_out`, the README's demo command) into a temporary root, then every
/// path of batch.ini, with its `demo_out/` prefix put under that root, is loaded as the batch loads it,
/// and the batch runs as shipped (simp-eval batch, in-process: paper and robust rows, the built map's
/// Table I, the figures) from a folder laid out like the project root after the demo.

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <simp/demo/DemoApp.h>
#include <simp/eval/BatchConfig.h>
#include <simp/eval/BatchFigures.h>
#include <simp/eval/FigureColors.h>
#include <simp/eval/Report.h>
#include <simp/eval/BatchRunner.h>
#include <simp/eval/EvalApp.h>
#include <simp/eval/MapMetrics.h>
#include <simp/io/Tum.h>
#include <simp/world/World.h>

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

/// `path` (relative to the project root) with the demo's output folder "demo_out" replaced by `root`.
fs::path underDemoRoot(const std::string& path, const fs::path& root) {
    const std::string prefix = "demo_out/";
    EXPECT_EQ(path.rfind(prefix, 0), 0u) << path << " is not in the demo's output folder";
    return root / path.substr(prefix.size());
}

std::string readText(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/// `text` with the line `from` replaced by `to` (the line must be there).
std::string replaceLine(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find("\n" + from + "\n");
    EXPECT_NE(at, std::string::npos) << "batch.ini has no line '" << from << "'";
    if (at != std::string::npos) text.replace(at + 1, from.size(), to);
    return text;
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
    // The localization configs are the project's, relative to the project root: the paper's filter and
    // the robust default, as rows side by side (issue #13).
    const auto variants = cfg.variants();
    ASSERT_EQ(variants.size(), 2u);
    EXPECT_EQ(variants[0].name, "paper");
    EXPECT_EQ(variants[1].name, "robust");
    for (const auto& v : variants) EXPECT_TRUE(fs::is_regular_file(fs::path(SIMP_SOURCE_DIR) / v.config)) << v.config;
    // The built map the demo wrote, against the demo's ground truth.
    ASSERT_EQ(cfg.batchMaps().size(), 1u);
    EXPECT_TRUE(fs::is_directory(underDemoRoot(cfg.batchMaps()[0].dir, root))) << cfg.batchMaps()[0].dir;
    EXPECT_TRUE(fs::is_directory(underDemoRoot(cfg.batchMaps()[0].ground_truth, root)));

    // The batch itself, paths as shipped, from a folder laid out like the project root after the demo
    // (demo_out/ and config_ini/); one method, one seed and fewer particles than shipped to stay quick.
    const fs::path project = root.parent_path();
    fs::create_directory_symlink(fs::path(SIMP_SOURCE_DIR) / "config_ini", project / "config_ini");
    WorkingDirectory cd(project);
    std::string quick = readText("config_ini/batch.ini");
    quick = replaceLine(quick, "methods = simp edt d o", "methods = simp");
    quick = replaceLine(quick, "repetitions = 5", "repetitions = 1");
    quick = replaceLine(quick, "particles = 0", "particles = 300");
    std::ofstream("quick.ini") << quick;
    simp::eval::EvalApp app;  // simp-localize next to this test, as next to simp-eval
    const char* argv[] = {"simp-eval", "batch", "--config", "quick.ini", "--out", "batch_out"};
    app.initialize(6, argv);
    std::ostringstream out, progress;
    ASSERT_EQ(app.run(out, progress), 0) << progress.str();

    const std::string runs = readText("batch_out/runs.csv");
    EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 1 + 6) << runs;  // 3 sequences x 2 configs
    for (const char* v : {"paper", "robust"})
        for (const char* q : {"R1", "R2", "R3"}) {
            const std::string dir = simp::eval::runDir("batch_out", q, "simp", 1, v);
            EXPECT_TRUE(fs::is_regular_file(dir + "/estimate.tum")) << dir << "\n" << readText(dir + "/localize.log");
            EXPECT_NE(runs.find(std::string(q) + ",simp,1,ok,"), std::string::npos) << runs;
        }
    const std::string tables = readText("batch_out/tables.md");
    EXPECT_NE(tables.find("| Ours (paper) | GT |"), std::string::npos) << tables;
    EXPECT_NE(tables.find("| Ours (robust) | GT |"), std::string::npos) << tables;
    // Table I of the built map: the numbers the demo printed for it (same classes, same matching).
    const std::string avg = "| built | " + simp::eval::fmt(demo.map_iou, 2) + " | " +
                            simp::eval::fmt(demo.map_precision, 2) + " | " + simp::eval::fmt(demo.map_recall, 2) + " |";
    EXPECT_NE(tables.find(avg), std::string::npos) << avg << "\n" << tables;
    EXPECT_NE(readText("batch_out/maps.csv").find("\nbuilt,\"AVG\","), std::string::npos);
    // The figures: success per row and sequence, error over time per row (2 rows = 2 panels).
    using L = simp::eval::BatchFigureLayout;
    const cv::Mat success = cv::imread("batch_out/success.png");
    EXPECT_EQ(success.cols, L::kFigureWidth);
    EXPECT_EQ(success.rows, L::kTop + L::kSuccessHeight + L::kBottom);
    const cv::Mat errors = cv::imread("batch_out/error_over_time.png");
    EXPECT_EQ(errors.cols, L::kFigureWidth);
    EXPECT_EQ(errors.rows, 2 * (L::kTop + L::kPanelHeight + L::kBottom));
    // Not blank: inside the plots, the error curves of the runs that localized, in their sequence's colour.
    const cv::Mat3b e3 = errors;
    int coloured = 0;
    for (int panel = 0; panel < 2; ++panel)
        for (int y = 1; y < L::kPanelHeight; ++y)
            for (int x = 1; x < L::kPlotWidth; ++x)
                for (int k = 0; k < 3; ++k) {
                    const auto c = simp::eval::seriesColor(static_cast<std::size_t>(k));
                    coloured += e3(panel * (L::kTop + L::kPanelHeight + L::kBottom) + L::kTop + y, L::kLeft + x) ==
                                cv::Vec3b(static_cast<uchar>(c[0]), static_cast<uchar>(c[1]), static_cast<uchar>(c[2]));
                }
    std::size_t localized = 0;
    for (const char* v : {"paper", "robust"})
        for (const char* q : {"R1", "R2", "R3"})
            localized += fs::file_size(simp::eval::runDir("batch_out", q, "simp", 1, v) + "/estimate.tum") > 0;
    EXPECT_GT(localized, 0u) << tables;
    EXPECT_GT(coloured, 100 * static_cast<int>(localized)) << localized << " runs localized";
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
