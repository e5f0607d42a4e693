// Batch experiments end to end with a stand-in for simp-localize (a shell script that
// copies the ground truth as its estimate and fails for method "o"), resumability, tables.
#include <gtest/gtest.h>
#include <simp/eval/BatchConfig.h>
#include <simp/eval/BatchRunner.h>
#include <simp/eval/BatchTables.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace simp::eval;

namespace {

/// Number of lines of a file (0 when absent).
int lineCount(const fs::path& p) {
    std::ifstream f(p);
    int n = 0;
    for (std::string l; std::getline(f, l);) ++n;
    return n;
}

struct BatchFixture : ::testing::Test {
    fs::path root;  // one folder per test: ctest may run the tests of this file in parallel
    fs::path ini;

    void SetUp() override {
        root = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_batch" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(root);
        fs::create_directories(root / "world");
        for (const char* q : {"Q1", "Q2"}) {
            fs::create_directories(root / q);
            std::ofstream(root / q / "sequence.rawlog") << "";
            std::vector<simp::io::StampedPose2D> gt;
            for (int k = 0; k <= 10; ++k) gt.push_back({static_cast<double>(k), {0.5 * k, 1.0, 0.1}});
            simp::io::writeTum((root / q / "groundtruth.tum").string(), gt);
        }
        const fs::path script = root / "fake-localize.sh";
        std::ofstream(script) << "#!/bin/sh\n"
                                 "while [ $# -gt 0 ]; do\n"
                                 "  case \"$1\" in --out) out=\"$2\"; shift;; --rawlog) rl=\"$2\"; shift;;\n"
                                 "    --method) m=\"$2\"; shift;; esac; shift\n"
                                 "done\n"
                                 "echo \"$out\" >> \"" + (root / "calls.txt").string() + "\"\n"
                                 "[ \"$m\" = o ] && { echo 'method o fails' >&2; exit 3; }\n"
                                 "mkdir -p \"$out\" && cp \"$(dirname \"$rl\")/groundtruth.tum\" \"$out/estimate.tum\"\n";
        fs::permissions(script, fs::perms::owner_all);
        ini = root / "batch.ini";
        std::ofstream(ini) << "[batch]\nworld = " << (root / "world").string() << "\nsequences = "
                           << (root / "Q1").string() << ", " << (root / "Q2").string()
                           << "\nsequence_names = R1 R2\nmethods = simp o\nrepetitions = 2\nfirst_seed = 7\n"
                              "cores = 2\nlocalize_bin = "
                           << script.string() << "\n";
    }
};

}  // namespace

TEST_F(BatchFixture, RunsEveryCombinationAggregatesAndResumes) {
    const auto cfg = loadBatchConfig(ini.string());
    ASSERT_EQ(cfg.sequences.size(), 2u);
    EXPECT_EQ(cfg.sequences[1].name, "R2");
    std::ostringstream progress;
    const auto out = (root / "out").string();
    const auto records = runBatch(cfg, out, progress);
    ASSERT_EQ(records.size(), 8u);  // 2 sequences x 2 methods x 2 seeds
    EXPECT_EQ(lineCount(root / "calls.txt"), 8);
    EXPECT_NE(progress.str().find("8/8 runs"), std::string::npos) << progress.str();
    for (const auto& r : records) {
        if (r.method == "simp") {
            EXPECT_EQ(r.status, "ok") << r.error;
            EXPECT_TRUE(r.success);
            EXPECT_NEAR(*r.ate_trans_m, 0.0, 1e-9);  // the estimate is the ground truth
            EXPECT_NEAR(*r.convergence_time_s, 0.0, 1e-9);
        } else {
            EXPECT_EQ(r.status, "localize_failed");
            EXPECT_NE(r.error.find("status 3"), std::string::npos) << r.error;
            EXPECT_FALSE(r.success);
        }
    }
    EXPECT_TRUE(fs::exists(runDir(out, "R2", "simp", 8) + "/result.json"));
    EXPECT_TRUE(fs::exists(runDir(out, "R2", "simp", 8) + "/localize.log"));

    const auto summary = summarize(cfg, records);
    EXPECT_EQ(summary.cells[0][0].runs, 2);
    EXPECT_DOUBLE_EQ(summary.avg[0].success_rate, 1.0);
    EXPECT_DOUBLE_EQ(summary.avg[1].success_rate, 0.0);
    const auto md = batchMarkdown(cfg, summary);
    EXPECT_NE(md.find("| Method | Map | R1 | R2 | AVG |"), std::string::npos) << md;
    EXPECT_NE(md.find("| Ours | GT | 100% | 100% | 100% |"), std::string::npos) << md;
    EXPECT_NE(md.find("| O-MCL | GT | 0% | 0% | 0% |"), std::string::npos) << md;
    EXPECT_NE(md.find("| Ours | GT | 0.000/0.00 | 0.000/0.00 | 0.000/0.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| O-MCL | GT | -/- | -/- | -/- |"), std::string::npos) << md;
    const auto csv = runsCsv(records);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);

    // Second call: the successful runs are resumed, only the failed ones (no estimate) run again.
    // Off a terminal: one progress line per run.
    std::ostringstream progress2;
    const auto again = runBatch(cfg, out, progress2, /*terminal=*/false);
    EXPECT_EQ(lineCount(root / "calls.txt"), 8 + 4);
    int resumed = 0;
    for (const auto& r : again) resumed += r.resumed ? 1 : 0;
    EXPECT_EQ(resumed, 4);
    const std::string lines = progress2.str();
    EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 8) << lines;
    EXPECT_NE(lines.find("[8/8 runs]"), std::string::npos) << lines;
    EXPECT_NE(lines.find("R1 simp seed 7: resumed, ok, success"), std::string::npos) << lines;
    EXPECT_NE(lines.find("R2 o seed 8: localize_failed"), std::string::npos) << lines;
}

TEST_F(BatchFixture, ConfigErrorsNameTheKey) {
    const auto expectKey = [&](const std::string& text, const std::string& key) {
        const auto p = root / "bad.ini";
        std::ofstream(p) << text;
        try {
            loadBatchConfig(p.string());
            FAIL() << "expected an error about " << key;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
        }
    };
    expectKey("[batch]\nsequences = a\n", "world");
    expectKey("[batch]\nworld = w\n", "sequences");
    expectKey("[batch]\nworld = w\nsequences = a b\nmethods = simp amcl\n", "amcl");
    expectKey("[batch]\nworld = w\nsequences = a b\nsequence_names = A\n", "sequence_names");
    expectKey("[batch]\nworld = w\nsequences = a\nrepetitions = 0\n", "repetitions");
    expectKey("[batch]\nworld = w\nsequences = a\n[metrics]\nconvergence_fraction = 1.5\n", "convergence_fraction");
    EXPECT_THROW(loadBatchConfig((root / "nope.ini").string()), std::runtime_error);
}

TEST_F(BatchFixture, MissingBinaryOrSequenceFailsBeforeRunning) {
    auto cfg = loadBatchConfig(ini.string());
    std::ostringstream progress;
    auto no_bin = cfg;
    no_bin.localize_bin = (root / "no-such-localize").string();
    EXPECT_THROW(runBatch(no_bin, (root / "out").string(), progress), std::runtime_error);
    auto no_seq = cfg;
    no_seq.sequences[0].dir = (root / "Q9").string();
    try {
        runBatch(no_seq, (root / "out").string(), progress);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("Q9"), std::string::npos) << e.what();
    }
    EXPECT_EQ(lineCount(root / "calls.txt"), 0);
}
