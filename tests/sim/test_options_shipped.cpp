/// \file test_options_shipped.cpp
/// The simulator's .ini keys are declared once (io::OptionTable per sim.ini section): config_ini/sim.ini
/// and no .ini give the pinned values (tests/data/options/shipped_values.txt), doc/simulator.md's key
/// tables are the declarations, the dump reads back, and bad values are rejected naming file, section and key.
#include "common/ErrorOf.h"
#include "common/ShippedOptions.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <simp/sim/OfficeLayout.h>
#include <simp/sim/SimApp.h>
#include <simp/sim/SimParams.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using simp::sim::OfficeParams;
using simp::sim::SimParams;

namespace {

/// Calls f(section, table, options-of-p) for every section of sim.ini.
template <class F>
void forEachSection(const OfficeParams& office, const SimParams& p, F&& f) {
    using namespace simp::sim;
    f(OfficeParams::table(), office);
    f(SimParams::table(), p);
    f(TrajectoryParams::table(), p.trajectory);
    f(OdometryParams::table(), p.odometry);
    f(CameraParams::table(), p.cameras);
    f(VisibilityParams::table(), p.visibility);
    f(DetectorParams::table(), p.detector);
    f(FalsePositiveParams::table(), p.false_positives);
    f(PeopleParams::table(), p.people);
    f(LidarParams::table(), p.lidar);
    f(ChangeParams::table(), p.changes);
}

void expectPinned(const std::string& file, const OfficeParams& office, const SimParams& p) {
    forEachSection(office, p, [&](const auto& table, const auto& options) {
        std::string report;
        EXPECT_TRUE(simp_test::matchesPinned(file, table, options, report)) << report;
    });
}

std::string simError(const std::string& ini_text, const std::string& command = "sequence") {
    const auto dir = std::filesystem::temp_directory_path() / ("simp_sim_options_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string ini = (dir / "bad.ini").string();
    std::ofstream(ini) << ini_text;
    simp::sim::SimApp app;
    std::ostringstream out;
    const std::vector<std::string> args = command == "world"
                                              ? std::vector<std::string>{"world", "--builtin", "office", "--seed", "1", "--out", (dir / "w").string(), "--config", ini}
                                              : std::vector<std::string>{"sequence", "--world", (dir / "none").string(), "--seed", "1", "--out", (dir / "q").string(), "--config", ini};
    const std::string e = simp_test::errorOf([&] {
        if (app.initialize(args, out)) app.run(out);
    });
    std::filesystem::remove_all(dir);
    return e;
}

}  // namespace

TEST(SimOptionsShipped, EveryIniGivesThePinnedValues) {
    expectPinned("(defaults)", OfficeParams{}, SimParams{});
    const simp::io::StrictIni cfg(simp_test::shippedIni("sim.ini"));
    OfficeParams office;
    SimParams p;
    office.loadFromConfig(cfg, "office");
    p.loadFromConfig(cfg);
    EXPECT_NO_THROW(cfg.checkUnknown());
    expectPinned("sim.ini", office, p);
}

TEST(SimOptionsShipped, DocumentedKeyTablesAreTheDeclarations) {
    const std::string doc = simp_test::docText("simulator.md");
    forEachSection(OfficeParams{}, SimParams{}, [&](const auto& table, const auto& defaults) {
        const std::string md = table.markdown(defaults);
        EXPECT_NE(doc.find("### `[" + table.section() + "]`\n\n" + md), std::string::npos)
            << "doc/simulator.md should hold under ### `[" << table.section() << "]`:\n" << md;
    });
}

TEST(SimOptionsShipped, TheDumpReadsBackToTheSameValues) {
    SimParams p;
    p.duration_s = 33.25;
    p.trajectory.coverage = true;
    p.visibility.max_range_m[3] = 2.5;
    p.lidar.beams = 541;
    std::ostringstream dump;
    p.dumpToTextStream(dump);
    SimParams back;
    back.loadFromConfig(mrpt::config::CConfigFileMemory(dump.str()));
    EXPECT_EQ(back.duration_s, 33.25);
    EXPECT_TRUE(back.trajectory.coverage);
    EXPECT_EQ(back.visibility.max_range_m[3], 2.5);
    EXPECT_EQ(back.lidar.beams, 541);
    std::ostringstream again;
    back.dumpToTextStream(again);
    EXPECT_EQ(again.str(), dump.str());
}

TEST(SimOptionsShipped, BadValuesNameFileSectionAndKey) {
    EXPECT_NE(simError("[office]\nroom_width_max_m = 1\n", "world").find("bad.ini: [office] room_width_max_m: must be >= room_width_min_m"),
              std::string::npos);
    EXPECT_NE(simError("[office]\nrooms = 0\n", "world").find("bad.ini: [office] rooms: must be in [1, 2000]"), std::string::npos);
    EXPECT_NE(simError("[trajectory]\nspeed_min_mps = 0\n").find("bad.ini: [trajectory] speed_min_mps: must be > 0 (m/s), got 0"),
              std::string::npos);
    EXPECT_NE(simError("[odometry]\na3 = -1\n").find("bad.ini: [odometry] a3: must be >= 0 (deg/m), got -1"), std::string::npos);
    EXPECT_NE(simError("[cameras]\nfy = 0\n").find("bad.ini: [cameras] fy: must be > 0 (px), got 0"), std::string::npos);
    EXPECT_NE(simError("[cameras]\nwidth_px = 0\n").find("bad.ini: [cameras] width_px: must be in [1, 100000] (px), got 0"),
              std::string::npos);
    EXPECT_NE(simError("[visibility]\nmin_range_m = 1 -2\n").find("bad.ini: [visibility] min_range_m: '-2' is not a number >= 0"),
              std::string::npos);
    EXPECT_NE(simError("[false_positives]\nrange_max_m = 0.5\n").find("bad.ini: [false_positives] range_max_m: must be >= range_min_m"),
              std::string::npos);
    EXPECT_NE(simError("[changes]\ndoor_close_fraction = 2\n").find("bad.ini: [changes] door_close_fraction: must be <= 1, got 2"),
              std::string::npos);
    EXPECT_NE(simError("[lidar]\nx_m = 10\n").find("bad.ini: [lidar] x_m: must be in (-10, 10) (m), got 10"), std::string::npos);
    EXPECT_NE(simError("[detector]\nmin_confidence =\n").find("bad.ini: [detector] min_confidence has no value"), std::string::npos);
    EXPECT_NE(simError("[people]\nspeed = 1\n").find("[people] unknown key 'speed'"), std::string::npos);
}
