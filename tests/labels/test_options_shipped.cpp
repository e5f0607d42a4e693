/// \file test_options_shipped.cpp
/// [simp-labels] keys are declared once (LabelOptions::table()): the example .ini and no .ini give the
/// pinned values (tests/data/options/shipped_values.txt), doc/labels.md's key table is the declaration,
/// and bad values are rejected naming file, section and key.
#include "common/ErrorOf.h"
#include "common/ShippedOptions.h"

#include <gtest/gtest.h>
#include <simp/labels/LabelGenerator.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <simp/labels/LabelsApp.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using simp::labels::LabelOptions;

namespace {

const std::string kExample = std::string(SIMP_SOURCE_DIR) + "/tests/data/detector_io/simp-labels.ini";

/// The message of `simp-labels ... --config INI` with `ini_text`.
std::string labelsError(const std::string& ini_text) {
    const auto dir = std::filesystem::temp_directory_path() / ("simp_labels_options_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string ini = (dir / "bad.ini").string();
    std::ofstream(ini) << ini_text;
    const std::vector<std::string> args{"simp-labels", "--world", "w", "--frames", "f.json", "--detections2d", "d.csv", "--out", "l.json", "--config", ini};
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    simp::labels::LabelsApp app;
    std::ostringstream out;
    const std::string e = simp_test::errorOf([&] { app.initialize(static_cast<int>(argv.size()), argv.data(), out); });
    std::filesystem::remove_all(dir);
    return e;
}

}  // namespace

TEST(LabelOptionsShipped, EveryIniGivesThePinnedValues) {
    const auto& table = LabelOptions::table();
    std::string report;
    EXPECT_TRUE(simp_test::matchesPinned("(defaults)", table, LabelOptions{}, report)) << report;
    const simp::io::StrictIni cfg(kExample);
    LabelOptions o;
    cfg.loadChecked([&](const simp::io::StrictIni& c) { o.loadFromConfigFile(c, "simp-labels"); });
    EXPECT_TRUE(simp_test::matchesPinned("simp-labels.ini", table, o, report)) << report;
}

TEST(LabelOptionsShipped, DocumentedKeyTableIsTheDeclaration) {
    const std::string table = LabelOptions::table().markdown(LabelOptions{});
    EXPECT_NE(simp_test::docText("labels.md").find(table), std::string::npos) << "doc/labels.md should hold:\n" << table;
}

TEST(LabelOptionsShipped, BadValuesNameFileSectionAndKey) {
    EXPECT_NE(labelsError("[simp-labels]\niou_threshold = 0\n").find("bad.ini: [simp-labels] iou_threshold: must be in (0, 1], got 0"),
              std::string::npos);
    EXPECT_NE(labelsError("[simp-labels]\nvisibility_pixel_step = 0\n").find("bad.ini: [simp-labels] visibility_pixel_step: must be >= 1 (px), got 0"),
              std::string::npos);
    EXPECT_NE(labelsError("[simp-labels]\nnear_m = abc\n").find("bad.ini: [simp-labels] near_m = 'abc' is not a finite number"),
              std::string::npos);
    EXPECT_NE(labelsError("[simp-labels]\nkeep_unmatched = perhaps\n").find("bad.ini: [simp-labels] keep_unmatched"), std::string::npos);
    EXPECT_NE(labelsError("[simp-labels]\nvisibility_range = 3\n").find("unknown key 'visibility_range'"), std::string::npos);
    // the dump reads back
    LabelOptions o;
    o.visibility.pixel_step = 7;
    std::ostringstream dump;
    o.dumpToTextStream(dump);
    LabelOptions back;
    back.loadFromConfigFile(mrpt::config::CConfigFileMemory(dump.str()), "simp-labels");
    EXPECT_EQ(back.visibility.pixel_step, 7);
}
