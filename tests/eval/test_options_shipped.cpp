/// \file test_options_shipped.cpp
/// simp-eval batch's keys are declared once ([batch] BatchConfig::table(), [metrics] trajMetricsTable(),
/// [map_metrics] mapMetricsTable()): config_ini/batch.ini and no .ini give the pinned values
/// (tests/data/options/shipped_values.txt), doc/evaluation.md's key tables are the declarations, the
/// dump names every key, and bad values name the file, section and key.
#include "common/ErrorOf.h"
#include "common/ShippedOptions.h"

#include <gtest/gtest.h>
#include <simp/eval/BatchConfig.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using simp::eval::BatchConfig;

namespace {

template <class F>
void forEachSection(const BatchConfig& c, F&& f) {
    f(BatchConfig::table(), c);
    f(simp::eval::trajMetricsTable(), c.metrics);
    f(simp::eval::mapMetricsTable(), c.map_metrics);
}

void expectPinned(const std::string& file, const BatchConfig& c) {
    forEachSection(c, [&](const auto& table, const auto& options) {
        std::string report;
        EXPECT_TRUE(simp_test::matchesPinned(file, table, options, report)) << report;
    });
}

std::filesystem::path scratch() {
    const auto dir = std::filesystem::temp_directory_path() / ("simp_batch_options_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

std::string batchError(const std::string& ini_text) {
    const auto p = scratch() / "bad.ini";
    std::ofstream(p) << ini_text;
    return simp_test::errorOf([&] { simp::eval::loadBatchConfig(p.string()); });
}

}  // namespace

TEST(BatchOptionsShipped, EveryIniGivesThePinnedValues) {
    expectPinned("(defaults)", BatchConfig{});
    expectPinned("batch.ini", simp::eval::loadBatchConfig(simp_test::shippedIni("batch.ini")));
}

TEST(BatchOptionsShipped, DocumentedKeyTablesAreTheDeclarations) {
    const std::string doc = simp_test::docText("evaluation.md");
    forEachSection(BatchConfig{}, [&](const auto& table, const auto& defaults) {
        const std::string md = table.markdown(defaults);
        EXPECT_NE(doc.find("#### `[" + table.section() + "]`\n\n" + md), std::string::npos)
            << "doc/evaluation.md should hold under #### `[" << table.section() << "]`:\n" << md;
    });
}

TEST(BatchOptionsShipped, TheDumpNamesEveryKey) {
    const BatchConfig c = simp::eval::loadBatchConfig(simp_test::shippedIni("batch.ini"));
    const std::string dump = c.dump();
    for (const auto& key : BatchConfig::table().keys()) EXPECT_NE(dump.find("\n" + key + " "), std::string::npos) << key;
    EXPECT_NE(dump.find("sequence_names        = R1 R2 R3  // "), std::string::npos) << dump;
    EXPECT_NE(dump.find("[metrics]\n"), std::string::npos) << dump;
    EXPECT_NE(dump.find("classes           = board, cabinet,"), std::string::npos) << dump;
}

TEST(BatchOptionsShipped, BadValuesNameFileSectionAndKey) {
    const std::string ok = "[batch]\nworld = w\nsequences = a\n";
    EXPECT_NE(batchError(ok + "first_seed = -1\n").find("bad.ini: [batch] first_seed: must be in [0, 2147483647], got -1"),
              std::string::npos);
    EXPECT_NE(batchError(ok + "methods = simp amcl\n").find("bad.ini: [batch] methods: unknown method 'amcl'"), std::string::npos);
    EXPECT_NE(batchError(ok + "maps = m\nmap_ground_truths = a b\n").find("bad.ini: [batch] map_ground_truths: must hold one"),
              std::string::npos);
    EXPECT_NE(batchError(ok + "[metrics]\nmax_rot_rad = 7\n").find("bad.ini: [metrics] max_rot_rad: must be in [1e-06, 6.28319] (rad), got 7"),
              std::string::npos);
    EXPECT_NE(batchError(ok + "[map_metrics]\nmax_center_dist_m = x\n").find("bad.ini: [map_metrics] max_center_dist_m = 'x' is not a finite number"),
              std::string::npos);
    EXPECT_NE(batchError("[batch]\nsequences = a\n").find("bad.ini: [batch] world: must be set"), std::string::npos);
    std::filesystem::remove_all(scratch());
}
