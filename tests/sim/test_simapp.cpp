// The simp-sim command line and sim.ini: bad input gives a clear message naming the option/key.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <simp/sim/SimApp.h>
#include <simp/sim/SimParams.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

std::string errorOf(const std::vector<std::string>& args) {
    simp::sim::SimApp app;
    std::ostringstream out;
    try {
        if (app.initialize(args, out)) app.run(out);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(SimApp, BadCommandLines) {
    EXPECT_NE(errorOf({"world", "--builtin", "office", "--out", "x"}).find("--seed"), std::string::npos);
    EXPECT_NE(errorOf({"world", "--builtin", "castle", "--seed", "1", "--out", "x"}).find("castle"), std::string::npos);
    EXPECT_NE(errorOf({"world", "--seed", "-3", "--out", "x"}).find("--seed"), std::string::npos);
    EXPECT_NE(errorOf({"sequence", "--world", "w", "--seed", "1", "--out", "q", "--changes", "1.5"}).find("--changes"),
              std::string::npos);
    EXPECT_NE(errorOf({"sequence", "--world", "w", "--seed", "1", "--out", "q", "--duration", "abc"}).find("--duration"),
              std::string::npos);
    EXPECT_NE(errorOf({"sequence", "--seed", "1", "--out", "q", "--bogus", "1"}).find("--bogus"), std::string::npos);
    EXPECT_NE(errorOf({"sequence", "--world", "/nonexistent/w", "--seed", "1", "--out", "q"}).find("/nonexistent/w"),
              std::string::npos);
    EXPECT_NE(errorOf({"world", "--seed", "1", "--out", "q", "--config", "/nonexistent.ini"}).find("/nonexistent.ini"),
              std::string::npos);
    EXPECT_NE(errorOf({"dance"}).find("dance"), std::string::npos);
    std::ostringstream help;
    simp::sim::SimApp app;
    EXPECT_FALSE(app.initialize({"sequence", "--help"}, help));
    EXPECT_NE(help.str().find("--changes"), std::string::npos);
    EXPECT_NE(help.str().find("--kidnap-at"), std::string::npos);
}

TEST(SimApp, BadKidnapTimesAreNamed) {
    const std::vector<std::string> base = {"sequence", "--world", "w", "--seed", "1", "--out", "q", "--duration", "20"};
    const auto withKidnap = [&](const std::string& v) {
        auto args = base;
        args.insert(args.end(), {"--kidnap-at", v});
        return errorOf(args);
    };
    // negative, not finite, not a number, beyond the duration (checked before the world is read)
    for (const char* v : {"-1", "nan", "inf", "ten", "20.5"}) {
        const std::string e = withKidnap(v);
        EXPECT_NE(e.find("--kidnap-at"), std::string::npos) << v << ": " << e;
    }
    EXPECT_NE(withKidnap("20.5").find("beyond the duration"), std::string::npos);
    // the .ini key: named as such, and checked against the duration the command line sets
    const auto dir = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "sim" / "app_kidnap_ini";
    std::filesystem::create_directories(dir);
    const std::string ini = (dir / "kidnap.ini").string();
    std::ofstream(ini) << "[sequence]\nkidnap_at_s = 30\n";
    auto args = base;
    args.insert(args.end(), {"--config", ini});
    EXPECT_NE(errorOf(args).find("[sequence] kidnap_at_s"), std::string::npos) << errorOf(args);
    args.insert(args.end(), {"--kidnap-at", "25"});  // the option overrides the key and is named
    EXPECT_NE(errorOf(args).find("option --kidnap-at"), std::string::npos) << errorOf(args);
}

TEST(SimApp, KidnapEndToEnd) {
    const auto dir = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "sim" / "app_kidnap";
    std::filesystem::remove_all(dir);
    const std::string w = (dir / "w").string(), q = (dir / "q").string();
    EXPECT_EQ(errorOf({"world", "--builtin", "office", "--seed", "3", "--out", w, "--rooms", "4"}), "");
    simp::sim::SimApp app;
    std::ostringstream out;
    ASSERT_TRUE(app.initialize({"sequence", "--world", w, "--seed", "4", "--out", q, "--duration", "6", "--kidnap-at", "3"}, out));
    app.run(out);
    EXPECT_NE(out.str().find("kidnapped at t = 3 s (step 30)"), std::string::npos) << out.str();
    for (const char* f : {"kidnap.json", "changes.json", "groundtruth.tum"})
        EXPECT_TRUE(std::filesystem::exists(dir / "q" / f)) << f;
}

TEST(SimApp, IniValuesAreCheckedByKey) {
    const auto errorOfIni = [](const std::string& text) -> std::string {
        mrpt::config::CConfigFileMemory cfg(text);
        simp::sim::SimParams p;
        try {
            p.loadFromConfig(cfg);
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_EQ(errorOfIni(""), "");
    EXPECT_NE(errorOfIni("[detector]\ndetection_probability = 2\n").find("detection_probability"), std::string::npos);
    EXPECT_NE(errorOfIni("[visibility]\nmax_range_m = 1 2 3\n").find("max_range_m"), std::string::npos);
    EXPECT_NE(errorOfIni("[cameras]\ncount = 0\n").find("count"), std::string::npos);
    EXPECT_NE(errorOfIni("[changes]\nfraction = -0.1\n").find("fraction"), std::string::npos);
    EXPECT_NE(errorOfIni("[sequence]\nkidnap_at_s = nan\n").find("kidnap_at_s"), std::string::npos);
    EXPECT_NE(errorOfIni("[sequence]\nkidnap_min_distance_m = -1\n").find("kidnap_min_distance_m"), std::string::npos);
    EXPECT_EQ(errorOfIni("[sequence]\nkidnap_at_s = -1\n"), "");  // negative: off
    EXPECT_NE(errorOfIni("[detector]\nmin_centre_noise_fraction = 0\n").find("min_centre_noise_fraction"),
              std::string::npos);
    EXPECT_NE(errorOfIni("[detector]\nnoise_model_includes_extent = maybe\n").find("noise_model_includes_extent"),
              std::string::npos);
    // the shipped sim.ini loads
    mrpt::config::CConfigFileMemory shipped;
    const std::string path = std::string(SIMP_SOURCE_DIR) + "/config_ini/sim.ini";
    ASSERT_TRUE(std::filesystem::exists(path));
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    EXPECT_EQ(errorOfIni(s.str()), "");
}

TEST(SimApp, WorldThenSequenceEndToEnd) {
    const auto dir = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "sim" / "app";
    std::filesystem::remove_all(dir);
    const std::string w = (dir / "w").string(), q = (dir / "q").string();
    EXPECT_EQ(errorOf({"world", "--builtin", "office", "--seed", "3", "--out", w, "--rooms", "3"}), "");
    EXPECT_EQ(errorOf({"sequence", "--world", w, "--seed", "4", "--out", q, "--duration", "5", "--changes", "0.2"}), "");
    for (const char* f : {"sequence.rawlog", "groundtruth.tum", "world/objects.json", "overview.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / "q" / f)) << f;
}

namespace {

TEST(SimApp, ACoverageRunSaysWhetherItReachedEveryGoal) {
    const auto dir = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "sim" / "app_coverage";
    std::filesystem::remove_all(dir);
    const std::string w = (dir / "w").string();
    EXPECT_EQ(errorOf({"world", "--builtin", "office", "--seed", "3", "--out", w, "--rooms", "3"}), "");
    const auto run = [&](const char* duration) {
        simp::sim::SimApp app;
        std::ostringstream out;
        EXPECT_TRUE(app.initialize({"sequence", "--world", w, "--seed", "4", "--out", (dir / duration).string(), "--duration",
                                    duration, "--coverage"}, out));
        app.run(out);
        return out.str();
    };
    const std::string cut_short = run("20");
    EXPECT_NE(cut_short.find("warning: coverage: "), std::string::npos) << cut_short;
    EXPECT_NE(cut_short.find("goals reached in 20 s"), std::string::npos) << cut_short;
    const std::string long_enough = run("600");
    EXPECT_NE(long_enough.find("simp-sim: coverage: all "), std::string::npos) << long_enough;
    EXPECT_EQ(long_enough.find("warning"), std::string::npos) << long_enough;
}

}  // namespace
