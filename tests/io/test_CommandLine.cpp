/// \file test_CommandLine.cpp
/// The one command-line parser (libs/io CommandLine, CommandSet): declarations -> parse, errors, help.
#include <gtest/gtest.h>
#include <simp/io/CommandLine.h>
#include <simp/io/CommandSet.h>

#include <sstream>

#include "common/ErrorOf.h"

using simp::io::CommandLine;
using simp::io::CommandSet;
using simp_test::errorOf;

namespace {

CommandLine localizeLike() {
    CommandLine c("simp-x", "Does x.");
    c.required("world", "W", "world directory")
        .required("out", "O", "output directory")
        .option("particles", "N", "particle count")
        .option("duration", "SEC", "duration")
        .unit("s")
        .option("initial-pose", "POSE", "x,y,phi")
        .flag("quiet", "no progress");
    return c;
}

/// The parse error of `args` against `c` ("" when it parses).
std::string parseError(CommandLine c, const std::vector<std::string>& args) {
    std::ostringstream out;
    return errorOf([&] { c.parse(args, out); });
}

}  // namespace

TEST(CommandLine, ValuesFlagsAndAbsentOptions) {
    CommandLine c = localizeLike();
    std::ostringstream out;
    ASSERT_TRUE(c.parse({"--world", "W", "--out", "O", "--quiet", "--particles", "2000"}, out));
    EXPECT_TRUE(out.str().empty());
    EXPECT_EQ(c.value("world"), "W");
    EXPECT_TRUE(c.has("quiet"));
    EXPECT_EQ(c.value("quiet"), "");
    EXPECT_FALSE(c.has("duration"));
    EXPECT_EQ(c.value("duration"), "");
    EXPECT_EQ(c.integer("particles", 1, 500000), 2000);
    EXPECT_EQ(c.number("duration", 0, 10), std::nullopt);
    // --name=value is the same as --name value; a parse starts afresh
    ASSERT_TRUE(c.parse({"--world=W2", "--out", "O", "--duration=2.5"}, out));
    EXPECT_EQ(c.value("world"), "W2");
    EXPECT_FALSE(c.has("quiet"));
    EXPECT_DOUBLE_EQ(*c.number("duration", 0, 10), 2.5);
}

TEST(CommandLine, ValueStartingWithDashIsAValue) {
    CommandLine c = localizeLike();
    std::ostringstream out;
    ASSERT_TRUE(c.parse({"--world", "W", "--out", "O", "--initial-pose", "-1,2,0", "--duration", "-5"}, out));
    EXPECT_EQ(c.value("initial-pose"), "-1,2,0");
    EXPECT_EQ(errorOf([&] { c.number("duration", 0, 10); }), "option --duration (s): -5 must be in [0, 10]");
}

TEST(CommandLine, UnknownOption) {
    EXPECT_EQ(parseError(localizeLike(), {"--world", "W", "--out", "O", "--foo", "1"}),
              "unknown option '--foo' (see --help)");
    EXPECT_EQ(parseError(localizeLike(), {"-x"}), "unknown option '-x' (see --help)");
    EXPECT_EQ(parseError(localizeLike(), {"--foo=3"}), "unknown option '--foo' (see --help)");
    EXPECT_EQ(parseError(localizeLike(), {"--World", "W"}), "unknown option '--World' (see --help)");  // case matters
}

TEST(CommandLine, MissingValue) {
    EXPECT_EQ(parseError(localizeLike(), {"--world", "W", "--out"}), "option --out needs a value (see --help)");
}

TEST(CommandLine, MissingOrEmptyRequiredOption) {
    EXPECT_EQ(parseError(localizeLike(), {}), "missing required option --world W (see --help)");
    EXPECT_EQ(parseError(localizeLike(), {"--world", "W"}), "missing required option --out O (see --help)");
    EXPECT_EQ(parseError(localizeLike(), {"--world", "", "--out", "O"}), "option --world needs a non-empty value (see --help)");
}

TEST(CommandLine, RepeatedOption) {
    EXPECT_EQ(parseError(localizeLike(), {"--world", "W", "--out", "O", "--world", "V"}),
              "option --world given twice (see --help)");
    EXPECT_EQ(parseError(localizeLike(), {"--world", "W", "--out", "O", "--quiet", "--quiet"}),
              "option --quiet given twice (see --help)");
    CommandLine c("simp-sim sequence");
    c.required("world", "W", "world").alias("world-in");
    EXPECT_EQ(parseError(c, {"--world", "W", "--world-in", "V"}), "option --world (--world-in) given twice (see --help)");
    std::ostringstream out;
    ASSERT_TRUE(c.parse({"--world-in", "V"}, out));
    EXPECT_EQ(c.value("world"), "V");
}

TEST(CommandLine, FlagWithValue) {
    EXPECT_EQ(parseError(localizeLike(), {"--world", "W", "--out", "O", "--quiet=yes"}),
              "option --quiet is a flag and takes no value (see --help)");
    // "--quiet yes": the flag, then a stray argument
    EXPECT_EQ(parseError(localizeLike(), {"--world", "W", "--out", "O", "--quiet", "yes"}),
              "unexpected argument 'yes' (see --help)");
}

TEST(CommandLine, NumbersOutOfRangeOrMalformed) {
    CommandLine c = localizeLike();
    std::ostringstream out;
    auto integerError = [&](const std::string& text) {
        c.parse({"--world", "W", "--out", "O", "--particles", text}, out);
        return errorOf([&] { c.integer("particles", 1, 500000); });
    };
    EXPECT_EQ(integerError("abc"), "option --particles: 'abc' is not an integer");
    EXPECT_EQ(integerError("0"), "option --particles: 0 must be in [1, 500000]");
    EXPECT_EQ(integerError("2000000"), "option --particles: 2000000 must be in [1, 500000]");
    EXPECT_EQ(integerError("1e3"), "option --particles: '1e3' is not an integer in [1, 500000]");
    EXPECT_EQ(integerError("12.5"), "option --particles: '12.5' is not an integer in [1, 500000]");
    EXPECT_EQ(integerError("99999999999999999999"), "option --particles: '99999999999999999999' is not an integer in [1, 500000]");
    EXPECT_EQ(integerError(""), "option --particles: '' is not an integer");
    EXPECT_EQ(integerError(" 42"), "");
    // exact integer bounds, not 9.22337e+18
    c.parse({"--world", "W", "--out", "O", "--particles", "-1"}, out);
    EXPECT_EQ(errorOf([&] { c.integer("particles", 0, 9223372036854775807LL); }),
              "option --particles: -1 must be in [0, 9223372036854775807]");
    c.parse({"--world", "W", "--out", "O", "--duration", "nan"}, out);
    EXPECT_EQ(errorOf([&] { c.number("duration", 0, 10); }), "option --duration (s): 'nan' is not a finite number");
    c.parse({"--world", "W", "--out", "O", "--duration", "1e300"}, out);
    EXPECT_EQ(errorOf([&] { c.number("duration", 0, 10); }), "option --duration (s): 1e300 must be in [0, 10]");
}

TEST(CommandLine, UndeclaredNameIsAProgrammingError) {
    CommandLine c = localizeLike();
    EXPECT_THROW(c.has("partcles"), std::logic_error);
    EXPECT_THROW(CommandLine("x").flag("a", "").flag("a", ""), std::logic_error);
}

TEST(CommandLine, Positionals) {
    CommandLine c("simp-pf", "MRPT's pf-localization.");
    c.positional("CONFIG.ini", "configuration", true).positional("RAWLOG", "dataset", false);
    std::ostringstream out;
    ASSERT_TRUE(c.parse({"a.ini"}, out));
    EXPECT_EQ(c.positionals(), (std::vector<std::string>{"a.ini"}));
    ASSERT_TRUE(c.parse({"a.ini", "b.rawlog"}, out));
    EXPECT_EQ(c.positionals().size(), 2u);
    ASSERT_TRUE(c.parse({"--", "-odd.ini"}, out));  // after --, everything is positional
    EXPECT_EQ(c.positionals().front(), "-odd.ini");
    EXPECT_EQ(parseError(c, {}), "missing argument CONFIG.ini (see --help)");
    EXPECT_EQ(parseError(c, {"a", "b", "c"}), "unexpected argument 'c' (see --help)");
    EXPECT_EQ(parseError(c, {"--verbose"}), "unknown option '--verbose' (see --help)");
}

TEST(CommandLine, HelpWinsAndDocumentsEveryOption) {
    CommandLine c = localizeLike();
    c.notes("At least one of --a, --b.");
    std::ostringstream out;
    EXPECT_FALSE(c.parse({"--bogus", "1", "-h"}, out));  // nothing is checked
    const std::string h = out.str();
    EXPECT_EQ(h, c.help());
    EXPECT_EQ(h.rfind("Usage: simp-x --world W --out O [--particles N] [--duration SEC] [--initial-pose POSE] [--quiet]\nDoes x.\n", 0), 0u) << h;
    for (const auto& o : c.options()) EXPECT_NE(h.find("  --" + o.name), std::string::npos) << o.name;
    EXPECT_NE(h.find("duration (s)"), std::string::npos);
    EXPECT_NE(h.find("-h, --help"), std::string::npos);
    EXPECT_NE(h.find("At least one of --a, --b.\n"), std::string::npos);
    std::ostringstream v;
    EXPECT_THROW(c.parse({"--version"}, v), std::invalid_argument);  // no version declared
    c.version("1.0");
    EXPECT_FALSE(c.parse({"--version"}, v));
    EXPECT_EQ(v.str(), "simp-x 1.0\n");
}

TEST(CommandSet, CommandsOptionsAndHelp) {
    CommandSet s("simp-sim", "The simulator.");
    s.add("world", "writes a world").required("seed", "S", "seed").flag("big", "big world");
    s.add("sequence", "writes a sequence").required("seed", "S", "seed").flag("lidar", "2D scans");
    std::ostringstream out;
    const CommandLine* c = s.parse({"sequence", "--seed", "3", "--lidar"}, out);
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->name(), "simp-sim sequence");
    EXPECT_TRUE(c->has("lidar"));
    EXPECT_EQ(errorOf([&] { s.parse({}, out); }), "missing command: world, sequence (see --help)");
    EXPECT_EQ(errorOf([&] { s.parse({"planet"}, out); }), "unknown command 'planet' (expected world, sequence; see --help)");
    EXPECT_EQ(errorOf([&] { s.parse({"world", "--seed", "1", "--lidar"}, out); }),
              "unknown option '--lidar' for command 'world' (see --help)");
    EXPECT_EQ(errorOf([&] { s.parse({"world"}, out); }), "missing required option --seed S (see --help)");
    for (const std::vector<std::string>& help : {std::vector<std::string>{"--help"}, {"help"}, {"world", "-h"}, {"planet", "--help"}}) {
        std::ostringstream h;
        EXPECT_EQ(s.parse(help, h), nullptr);
        EXPECT_EQ(h.str(), s.help());
    }
    const std::string h = s.help();
    EXPECT_NE(h.find("simp-sim world --seed S [--big]\n      writes a world\n"), std::string::npos) << h;
    EXPECT_NE(h.find("    --lidar"), std::string::npos) << h;
    EXPECT_EQ(h.find("    -h, --help"), std::string::npos) << h;  // listed once, for all commands
    EXPECT_NE(h.find("  -h, --help"), std::string::npos) << h;
}
