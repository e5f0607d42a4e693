// Several localization configs in one batch (issue #13: paper and robust rows side by side):
// the .ini keys, the old single key, the rows and run folders they give.
#include <gtest/gtest.h>
#include <simp/eval/BatchConfig.h>
#include <simp/eval/BatchRunner.h>
#include <simp/eval/BatchTables.h>

#include "common/ErrorOf.h"

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace simp::eval;

namespace {

fs::path testDir() {
    const fs::path d = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_batch_variants" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(d);
    return d;
}

BatchConfig load(const std::string& keys) {
    const fs::path ini = testDir() / "batch.ini";
    std::ofstream(ini) << "[batch]\nworld = w\nsequences = q/R1 q/R2\nmethods = simp edt\n" << keys << "\n";
    return loadBatchConfig(ini.string());
}

RunRecord record(const std::string& seq, const std::string& method, const std::string& variant, bool success,
                 double ate_m) {
    RunRecord r;
    r.sequence = seq, r.method = method, r.variant = variant, r.success = success, r.converged = success;
    if (success) r.ate_trans_m = ate_m, r.ate_rot_rad = ate_m / 10, r.convergence_time_s = 2.0;
    r.duration_s = 10;
    return r;
}

}  // namespace

TEST(BatchVariants, TheOldSingleKeyKeepsItsRowsAndFolders) {
    const auto cfg = load("localize_config = config_ini/simp.ini");
    const auto v = cfg.variants();
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(v[0].name, "");
    EXPECT_EQ(v[0].config, "config_ini/simp.ini");
    EXPECT_EQ(runDir("out", "R1", "simp", 3, v[0].name), "out/runs/R1/simp/seed3");
    const auto cmd = localizeCommand(cfg, "bin", cfg.sequences[0], v[0], "edt", 3, "o");
    EXPECT_EQ(std::count(cmd.begin(), cmd.end(), "config_ini/simp.ini"), 1);
    const auto s = summarize(cfg, {});
    ASSERT_EQ(s.rows.size(), 2u);
    EXPECT_EQ(s.rows[0].label(), "Ours");
    EXPECT_EQ(s.rows[1].label(), "EDT-MCL");
    EXPECT_TRUE(load("").variants()[0].config.empty());  // no config at all: simp-localize's defaults
}

TEST(BatchVariants, SeveralConfigsGiveRowsSideBySide) {
    const auto cfg = load("localize_configs = c/simp-paper.ini, c/simp.ini\nlocalize_config_names = paper robust");
    const auto v = cfg.variants();
    ASSERT_EQ(v.size(), 2u);
    EXPECT_EQ(v[1].name, "robust");
    EXPECT_EQ(v[1].config, "c/simp.ini");
    EXPECT_EQ(runDir("out", "R1", "d", 1, "paper"), "out/runs/R1/paper/d/seed1");
    const auto cmd = localizeCommand(cfg, "bin", cfg.sequences[1], v[0], "simp", 1, "o");
    EXPECT_EQ(std::count(cmd.begin(), cmd.end(), "c/simp-paper.ini"), 1);

    // paper: 1 of 2 runs succeed on R1, robust: both, ATE 0.1 m / 0.2 m.
    const std::vector<RunRecord> records{
        record("R1", "simp", "paper", true, 0.2),  record("R1", "simp", "paper", false, 0),
        record("R1", "simp", "robust", true, 0.1), record("R1", "simp", "robust", true, 0.1),
        record("R2", "simp", "paper", true, 0.2),  record("R2", "simp", "robust", true, 0.1),
        record("R1", "edt", "paper", false, 0),    record("R2", "edt", "robust", true, 0.3)};
    const auto s = summarize(cfg, records);
    ASSERT_EQ(s.rows.size(), 4u);
    EXPECT_EQ(s.rows[0].label(), "Ours (paper)");
    EXPECT_EQ(s.rows[1].label(), "Ours (robust)");
    EXPECT_EQ(s.rows[2].label(), "EDT-MCL (paper)");
    EXPECT_EQ(s.rows[3].label(), "EDT-MCL (robust)");
    EXPECT_DOUBLE_EQ(s.cells[0][0].success_rate, 0.5);
    EXPECT_DOUBLE_EQ(s.avg[0].success_rate, 0.75);
    EXPECT_DOUBLE_EQ(s.avg[1].success_rate, 1.0);
    const std::string md = batchMarkdown(cfg, s);
    EXPECT_NE(md.find("| Ours (paper) | GT | 50% | 100% | 75% |\n| Ours (robust) | GT | 100% | 100% | 100% |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| EDT-MCL (robust) | GT | -/- | 0.030/0.30 | 0.030/0.30 |"), std::string::npos) << md;
    const std::string csv = summaryCsv(cfg, s);
    EXPECT_NE(csv.find("simp,GT,AVG,3,3,1.000000,0.010000,0.100000,2.000000,robust\n"), std::string::npos) << csv;
    EXPECT_NE(runsCsv(records).find(",\"\",robust\n"), std::string::npos);

    // The variant is in result.json, and results written before it existed still read.
    const auto back = runRecordFromJson(toJson(records[2]), "r.json");
    EXPECT_EQ(back.variant, "robust");
    auto old = toJson(records[2]);
    old.erase("variant");
    EXPECT_EQ(runRecordFromJson(old, "old.json").variant, "");
}

TEST(BatchVariants, DefaultNamesAreFileStemsAndKeysAreChecked) {
    const auto v = load("localize_configs = config_ini/simp-paper.ini config_ini/simp.ini").variants();
    EXPECT_EQ(v[0].name, "simp-paper");
    EXPECT_EQ(v[1].name, "simp");
    const auto error = [](const std::string& keys) { return simp_test::errorOf([&] { load(keys); }); };
    std::string e = error("localize_config = a.ini\nlocalize_configs = b.ini c.ini");
    EXPECT_NE(e.find("[batch] localize_configs"), std::string::npos) << e;
    EXPECT_NE(e.find("must not be given with [batch] localize_config"), std::string::npos) << e;
    e = error("localize_configs = a.ini b.ini\nlocalize_config_names = one");
    EXPECT_NE(e.find("[batch] localize_config_names: 1 names for 2"), std::string::npos) << e;
    e = error("localize_configs = x/a.ini y/a.ini");
    EXPECT_NE(e.find("two entries are named 'a'"), std::string::npos) << e;
    e = error("localize_config_names = p");
    EXPECT_NE(e.find("given without [batch] localize_configs"), std::string::npos) << e;
}
