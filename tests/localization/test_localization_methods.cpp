/// \file test_localization_methods.cpp
/// simp-localize and simp-eval batch take the methods of one table (model::localizationMethods()):
/// each is accepted by --method, by [LocalizationExperiment] sensor_model and by [batch] methods, and
/// has its own batch label; an unknown one is refused with the allowed ones named.
#include <gtest/gtest.h>
#include <simp/eval/BatchConfig.h>
#include <simp/io/StrictIni.h>
#include <simp/localization/LocalizeApp.h>
#include <simp/model/LocalizationMethods.h>

#include "common/ErrorOf.h"

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using simp::localization::LocalizeApp;
using simp_test::errorOf;

namespace {

/// simp-localize's arguments up to initialize(): no file is read but the (absent) --config.
void initializeWithMethod(LocalizeApp& app, const std::string& method) {
    app.initialize({"simp-localize", "--world", "w", "--rawlog", "r.rawlog", "--out", "o", "--method", method, "--quiet"});
}

/// A [batch] .ini of its own per test: ctest runs the tests of this file in parallel.
std::string batchIni(const std::string& methods) {
    const fs::path dir = fs::path(SIMP_TEST_OUTPUT_DIR) / "localization_methods" /
                         ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(dir);
    const fs::path ini = dir / "batch.ini";
    std::ofstream(ini) << "[batch]\nworld = w\nsequences = q/R1\nmethods = " << methods << "\n";
    return ini.string();
}

}  // namespace

TEST(LocalizationMethods, EveryMethodIsAcceptedAndHasABatchLabel) {
    std::string all;
    for (const auto& m : simp::model::localizationMethods()) {
        LocalizeApp app;
        initializeWithMethod(app, m.name);
        EXPECT_EQ(app.options.experiment.sensor_model, m.name);
        simp::localization::LocalizerOptions o;
        simp::localization::loadLocalizerOptions(
            simp::io::StrictIni(std::string("[LocalizationExperiment]\nsensor_model = ") + m.name + "\n", "m.ini"), o);
        EXPECT_EQ(o.experiment.sensor_model, m.name);
        EXPECT_EQ(simp::eval::methodLabel(m.name), m.label);
        EXPECT_NE(simp::eval::methodLabel(m.name), m.name) << "no batch label for " << m.name;
        all += std::string(all.empty() ? "" : " ") + m.name;
    }
    EXPECT_EQ(simp::eval::loadBatchConfig(batchIni(all)).methods, simp::model::localizationMethodNames());
}

TEST(LocalizationMethods, AnUnknownMethodIsRefusedNamingTheAllowedOnes) {
    const std::string localize = errorOf([] {
        LocalizeApp app;
        initializeWithMethod(app, "magic");
    });
    EXPECT_EQ(localize, "simp-localize: unknown --method 'magic' (use simp, edt, d, o, lidar or simp+lidar)");
    const std::string batch = errorOf([] { simp::eval::loadBatchConfig(batchIni("simp magic")); });
    EXPECT_NE(batch.find("unknown method 'magic' (known: simp edt d o lidar simp+lidar)"), std::string::npos) << batch;
    for (const auto& m : simp::model::localizationMethodNames()) {
        EXPECT_NE(localize.find(m), std::string::npos) << m;
        EXPECT_NE(batch.find(m), std::string::npos) << m;
    }
}
