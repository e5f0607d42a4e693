/// \file test_OptionTable.cpp
/// Options declared once (libs/io OptionTable): loading, range checks, dump, documentation and the
/// unknown-key check all come from the one declaration.
#include "common/ErrorOf.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <simp/io/OptionTable.h>
#include <simp/io/StrictIni.h>

#include <sstream>

using simp::io::OptionTable;
using simp::io::StrictIni;
using simp::io::ValueRange;
using simp_test::errorOf;

namespace {

struct Knobs {
    double gate_m = 1.0;
    double weight = 0.5;
    int count = 10;
    std::string mode = "fast";
};

const OptionTable<Knobs>& table() {
    static const OptionTable<Knobs> t = OptionTable<Knobs>("knobs")
                                            .number("gate_m", &Knobs::gate_m, "m", ValueRange::positive(), "matching gate")
                                            .number("weight", &Knobs::weight, "", ValueRange::between(0, 1), "a weight")
                                            .integer("count", &Knobs::count, ValueRange::atLeast(3), "how many")
                                            .choice("mode", &Knobs::mode, {"fast", "exact"}, "the mode");
    return t;
}

Knobs loaded(const std::string& ini) {
    Knobs k;
    table().load(mrpt::config::CConfigFileMemory(ini), "knobs", k);
    return k;
}

}  // namespace

TEST(OptionTable, LoadsDeclaredKeysAndKeepsDefaultsOfAbsentOnes) {
    const Knobs k = loaded("[knobs]\ngate_m = 2.5\nmode = exact\n");
    EXPECT_DOUBLE_EQ(k.gate_m, 2.5);
    EXPECT_EQ(k.mode, "exact");
    EXPECT_DOUBLE_EQ(k.weight, 0.5);
    EXPECT_EQ(k.count, 10);
}

TEST(OptionTable, RangesAndChoicesNameKeyUnitAndValue) {
    EXPECT_EQ(errorOf([] { loaded("[knobs]\ngate_m = 0\n"); }), "[knobs] gate_m: must be > 0 (m), got 0");
    EXPECT_EQ(errorOf([] { loaded("[knobs]\nweight = 2\n"); }), "[knobs] weight: must be in [0, 1], got 2");
    EXPECT_EQ(errorOf([] { loaded("[knobs]\ncount = 2\n"); }), "[knobs] count: must be >= 3, got 2");
    EXPECT_EQ(errorOf([] { loaded("[knobs]\nmode = slow\n"); }), "[knobs] mode: must be 'fast' or 'exact', got 'slow'");
    Knobs k;
    k.gate_m = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(errorOf([&] { table().validate(k); }).find("[knobs] gate_m: must be > 0 (m)"), std::string::npos);
}

TEST(OptionTable, StrictIniKnowsExactlyTheDeclaredKeys) {
    const StrictIni ini("[knobs]\ngate_m = 2\ncout = 4\n", "k.ini");
    Knobs k;
    table().load(ini, "knobs", k);
    const std::string m = errorOf([&] { ini.checkUnknown(); });
    EXPECT_NE(m.find("k.ini: [knobs] unknown key 'cout'"), std::string::npos) << m;
    for (const auto& key : table().keys()) EXPECT_NE(m.find(key), std::string::npos) << key << " not listed as known: " << m;
    const StrictIni typed("[knobs]\ncount = 3.5\n", "k.ini");
    EXPECT_NE(errorOf([&] { table().load(typed, "knobs", k); }).find("count = '3.5' is not an integer"), std::string::npos);
}

TEST(OptionTable, DumpReadsBackAndDocumentsEveryKey) {
    Knobs k;
    k.gate_m = 0.25, k.count = 7, k.mode = "exact";
    std::ostringstream dump;
    table().dump(k, dump);
    EXPECT_EQ(dump.str(),
              "[knobs]\n"
              "gate_m = 0.25  // matching gate (m)\n"
              "weight = 0.5  // a weight\n"
              "count  = 7  // how many\n"
              "mode   = exact  // the mode\n");
    const Knobs back = loaded(dump.str());
    EXPECT_DOUBLE_EQ(back.gate_m, 0.25);
    EXPECT_EQ(back.count, 7);
    EXPECT_EQ(back.mode, "exact");
    EXPECT_EQ(table().markdown(Knobs{}),
              "| key | default | unit | allowed | meaning |\n|---|---|---|---|---|\n"
              "| `gate_m` | 1 | m | > 0 | matching gate |\n"
              "| `weight` | 0.5 |  | in [0, 1] | a weight |\n"
              "| `count` | 10 |  | >= 3 | how many |\n"
              "| `mode` | `fast` |  | 'fast' or 'exact' | the mode |\n");
}

namespace {

enum class Mode { Slow, Fast };
struct Inner {
    float gain = 0.5f;
};
struct Rig {
    bool enabled = true;
    std::size_t particles = 100;
    Mode mode = Mode::Slow;
    Inner inner;
    std::string names = "a";
    double lo = 1, hi = 2;
};

const OptionTable<Rig>& rigTable() {
    static const OptionTable<Rig> t =
        OptionTable<Rig>("rig")
            .flag("enabled", &Rig::enabled, "on or off")
            .integer("particles", &Rig::particles, ValueRange::between(1, 1e6), "how many")
            .choice("mode", &Rig::mode, std::vector<std::pair<std::string, Mode>>{{"slow", Mode::Slow}, {"fast", Mode::Fast}}, "speed")
            .number("gain", [](auto& r) -> auto& { return r.inner.gain; }, "", ValueRange::aboveUpTo(0, 1), "a member of a member")
            .custom(
                "names", "", "a list", "own syntax: an empty value is allowed",
                [](Rig& r, const std::string& text, const std::string&) { r.names = text; },
                [](const Rig& r, int) { return r.names; }, [](const Rig& r) { return r.names.size() < 5; })
            .number("lo", &Rig::lo, "m", ValueRange::finite(), "lower")
            .number("hi", &Rig::hi, "m", ValueRange::finite(), "upper")
            .rule("lo", [](const Rig& r) { return r.lo < r.hi; }, "be smaller than hi");
    return t;
}

Rig rigFrom(const std::string& ini) {
    Rig r;
    rigTable().load(mrpt::config::CConfigFileMemory(ini), "rig", r);
    return r;
}

}  // namespace

TEST(OptionTable, FlagsEnumsMembersOfMembersAndOwnSyntax) {
    const Rig r = rigFrom("[rig]\nenabled = false\nparticles = 5e3\nmode = fast\ngain = 0.25\nnames =\n");
    EXPECT_FALSE(r.enabled);
    EXPECT_EQ(r.particles, 5000u);  // a whole number may be written 5e3, as the localization loaders took it
    EXPECT_EQ(r.mode, Mode::Fast);
    EXPECT_FLOAT_EQ(r.inner.gain, 0.25f);
    EXPECT_EQ(r.names, "");
    const auto values = rigTable().values(r);
    ASSERT_EQ(values.size(), 7u);
    EXPECT_EQ(values[0], (std::pair<std::string, std::string>{"enabled", "false"}));
    EXPECT_EQ(values[2].second, "fast");
    EXPECT_EQ(values[3].second, "0.25");
}

TEST(OptionTable, StrictWhateverTheSourceAndRulesNameTheKey) {
    // a plain CConfigFileMemory (as MRPT's tools pass) is parsed as strictly as io::StrictIni
    EXPECT_EQ(errorOf([] { rigFrom("[rig]\ngain = 0.5abc\n"); }), "[rig] gain = '0.5abc' is not a finite number");
    EXPECT_EQ(errorOf([] { rigFrom("[rig]\nparticles = 12.5\n"); }), "[rig] particles = '12.5' is not an integer");
    EXPECT_EQ(errorOf([] { rigFrom("[rig]\nparticles = -1\n"); }), "[rig] particles = -1 is out of the integer range");
    EXPECT_EQ(errorOf([] { rigFrom("[rig]\nparticles =\n"); }), "[rig] particles has no value");
    EXPECT_EQ(errorOf([] { rigFrom("[rig]\nenabled = maybe\n"); }), "[rig] enabled: 'maybe' is not a boolean (true/false)");
    EXPECT_EQ(errorOf([] { rigFrom("[rig]\nmode = medium\n"); }), "[rig] mode: must be 'slow' or 'fast', got 'medium'");
    EXPECT_EQ(errorOf([] { rigFrom("[rig]\ngain = 0\n"); }), "[rig] gain: must be in (0, 1], got 0");
    EXPECT_EQ(errorOf([] { rigFrom("[rig]\nnames = abcdef\n"); }), "[rig] names: must be a list, got abcdef");
    EXPECT_EQ(errorOf([] { rigFrom("[rig]\nlo = 3\n"); }), "[rig] lo: must be smaller than hi");
    // the section named is the one read (a map's options live in [<prefix>_likelihoodOpts])
    Rig r;
    EXPECT_EQ(errorOf([&] { rigTable().load(mrpt::config::CConfigFileMemory("[other]\nlo = 3\n"), "other", r); }),
              "[other] lo: must be smaller than hi");
}

TEST(OptionTable, DocumentationPrintsWholeBoundsExactlyAndNamesAnEmptyDefault) {
    struct Seeded {
        unsigned seed = 0;
        std::string model;
        double limit = 1;
    };
    const auto t = OptionTable<Seeded>("s")
                       .integer("seed", &Seeded::seed, ValueRange::between(0, 4294967295.0), "random seed")
                       .choice("model", &Seeded::model, {"", "a"}, "empty = the map's")
                       .number("limit", &Seeded::limit, "", ValueRange::atMost(1), "at most one");
    EXPECT_EQ(t.markdown(Seeded{}),
              "| key | default | unit | allowed | meaning |\n|---|---|---|---|---|\n"
              "| `seed` | 0 |  | in [0, 4294967295] | random seed |\n"
              "| `model` | (empty) |  | '' or 'a' | empty = the map's |\n"
              "| `limit` | 1 |  | <= 1 | at most one |\n");
    EXPECT_EQ(ValueRange::between(1, 1e6).text(), "in [1, 1e+06]");  // %g where it is exact
    Seeded s;
    EXPECT_EQ(errorOf([&] { t.load(mrpt::config::CConfigFileMemory("[s]\nlimit = 2\n"), "s", s); }), "[s] limit: must be <= 1, got 2");
}

TEST(OptionTable, AnEmptyValueDumpsAsQuotesAndReadsBackEmpty) {
    Rig r;
    r.names = "";
    std::ostringstream dump;
    rigTable().dump(r, dump);
    EXPECT_NE(dump.str().find("names     = \"\"  // own syntax"), std::string::npos) << dump.str();
    // written bare, MRPT's parser would hand the comment "// own syntax..." over as the value
    EXPECT_EQ(rigFrom(dump.str()).names, "");
}

TEST(OptionTable, APipeInACellDoesNotSplitTheDocumentationRow) {
    struct Ratio {
        double r = 0.5;
    };
    const auto t = OptionTable<Ratio>("q").number("r", &Ratio::r, "", ValueRange::between(0, 1), "explained share |S| / |D|");
    EXPECT_EQ(t.markdown(Ratio{}),
              "| key | default | unit | allowed | meaning |\n|---|---|---|---|---|\n"
              "| `r` | 0.5 |  | in [0, 1] | explained share \\|S\\| / \\|D\\| |\n");
}
