/// \file test_options_shipped.cpp
/// Every shipped localization .ini (and no .ini) gives the values the hand-written loaders gave
/// (tests/data/options/shipped_values.txt), now that each key is declared once in an io::OptionTable.
#include "common/ShippedOptions.h"

#include <gtest/gtest.h>
#include <simp/localization/Localizer.h>

using namespace simp::localization;
using simp_test::shippedValues;
using simp_test::valueLines;

namespace {

template <class O>
void expectPinned(const std::string& file, const simp::io::OptionTable<O>& table, const O& options) {
    const auto expected = shippedValues(file, table.section());
    ASSERT_FALSE(expected.empty()) << file << " [" << table.section() << "]";
    EXPECT_EQ(valueLines(file, table.section(), table, options), expected);
}

void expectAllPinned(const std::string& file, const LocalizerOptions& o) {
    expectPinned(file, ExperimentOptions::table(), o.experiment);
    expectPinned(file, MotionModelOptions::table(), o.motion);
    expectPinned(file, stateParamsTable(), o.state);
    expectPinned(file, noveltyParamsTable(), o.novelty);
    expectPinned(file, resettingParamsTable(), o.resetting);
    expectPinned(file, searchParamsTable(), o.search);
    expectPinned(file, challengerParamsTable(), o.challenger);
    expectPinned(file, LidarModelOptions::table(), o.lidar);
    expectPinned(file, ManhattanHeadingOptions::table(), o.heading);
}

}  // namespace

TEST(LocalizeOptionsShipped, EveryIniGivesThePinnedValues) {
    expectAllPinned("(defaults)", LocalizerOptions{});
    for (const char* name : {"simp.ini", "simp-paper.ini"}) {
        SCOPED_TRACE(name);
        const simp::io::StrictIni cfg(simp_test::shippedIni(name));
        LocalizerOptions o;
        loadLocalizerOptions(cfg, o);
        expectAllPinned(name, o);
    }
}

TEST(LocalizeOptionsShipped, SensorModelNamesComeFromTheMethodTable) {
    // model::localizationMethods(): the object models, then the LiDAR ones
    const std::string allowed = ExperimentOptions::table().markdown(ExperimentOptions{});
    EXPECT_NE(allowed.find("'', 'simp', 'edt', 'd', 'o', 'lidar' or 'simp+lidar'"), std::string::npos) << allowed;
}

TEST(LocalizeOptionsShipped, CrossKeyRulesNameTheKey) {
    const simp::io::StrictIni bad("[State]\nfit_window = 4\nfit_min_detections = 5\n", "s.ini");
    StateParams p;
    try {
        loadStateParams(bad, "State", p);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "[State] fit_min_detections: must be <= fit_window");
    }
}

TEST(LocalizeOptionsShipped, DocumentedKeyTablesAreTheDeclarations) {
    // doc/localization.md and doc/lidar.md hold the tables generated from the declarations verbatim
    const std::string experiment = ExperimentOptions::table().markdown(ExperimentOptions{});
    EXPECT_NE(simp_test::docText("localization.md").find(experiment), std::string::npos) << "doc/localization.md should hold:\n"
                                                                                        << experiment;
    const std::string lidar = LidarModelOptions::table().markdown(LidarModelOptions{});
    EXPECT_NE(simp_test::docText("lidar.md").find(lidar), std::string::npos) << "doc/lidar.md should hold:\n" << lidar;
    // the filter's own sections, each under its heading
    const std::string doc = simp_test::docText("localization.md");
    const auto expectUnder = [&](const std::string& heading, const std::string& table) {
        EXPECT_NE(doc.find(heading + "\n\n" + table), std::string::npos)
            << "doc/localization.md should hold under " << heading << ":\n" << table;
    };
    expectUnder("#### `[State]`", stateParamsTable().markdown(StateParams{}));
    expectUnder("#### `[DetectionNovelty]`", noveltyParamsTable().markdown(DetectionNoveltyParams{}));
    expectUnder("#### `[SensorResetting]`", resettingParamsTable().markdown(SensorResettingParams{}));
    expectUnder("#### `[HypothesisSearch]`", searchParamsTable().markdown(HypothesisSearchParams{}));
    expectUnder("#### `[Challenger]`", challengerParamsTable().markdown(ChallengerParams{}));
    expectUnder("#### `[ManhattanHeading]`", ManhattanHeadingOptions::table().markdown(ManhattanHeadingOptions{}));
    expectUnder("Generated from `MotionModelOptions::table()` (`LocalizeOptions.cpp`):", MotionModelOptions::table().markdown(MotionModelOptions{}));
}
