/// The one strict number parser and .ini policy of the apps (io::StrictNumber, io::StrictIni).

#include "common/ErrorOf.h"

#include <gtest/gtest.h>
#include <mrpt/slam/TKLDParams.h>
#include <simp/io/StrictIni.h>
#include <simp/io/StrictNumber.h>

#include <functional>
#include <stdexcept>
#include <string>

using namespace simp::io;

namespace {
using simp_test::errorOf;
}  // namespace

TEST(StrictNumber, WholeFiniteTokensOnly) {
    EXPECT_EQ(parseFiniteNumber(" 2.5 "), 2.5);
    EXPECT_EQ(parseFiniteNumber("-1e3"), -1000.0);
    for (const char* bad : {"", "abc", "3x", "1e300000", "inf", "nan", "0x10", "1,5", "- 1"})
        EXPECT_FALSE(parseFiniteNumber(bad)) << bad;
    EXPECT_EQ(parseWholeInteger("-5"), -5);
    for (const char* bad : {"-5.0", "5e3", "99999999999999999999", "", "+", "1 2"})
        EXPECT_FALSE(parseWholeInteger(bad)) << bad;
    EXPECT_NE(errorOf([] { parseNumber("1e300", "option --duration", 0, 1e6); }).find("option --duration: 1e300 must be in [0, 1e+06]"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parseInteger("-1", "option --frames", 1, 100); }).find("option --frames: -1 must be in [1, 100]"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parseInteger("2.5", "option --frames", 1, 100); }).find("is not an integer"), std::string::npos);
    EXPECT_TRUE(parseBool("Yes", "k"));
    EXPECT_NE(errorOf([] { parseBool("maybe", "k"); }).find("'maybe' is not a boolean"), std::string::npos);
}

TEST(StrictIni, SyntaxErrorsNameFileAndLine) {
    EXPECT_NE(errorOf([] { StrictIni("", "a.ini"); }).find("a.ini: no [section]"), std::string::npos);
    EXPECT_NE(errorOf([] { StrictIni("x = 1\n[s]\n", "a.ini"); }).find("a.ini:1: key 'x' is outside any [section]"),
              std::string::npos);
    EXPECT_NE(errorOf([] { StrictIni("[s]\nhello world\n", "a.ini"); }).find("a.ini:2:"), std::string::npos);
    EXPECT_NE(errorOf([] { StrictIni("[s]\nx=1\nx=2\n", "a.ini"); }).find("set twice"), std::string::npos);
    EXPECT_NE(errorOf([] { StrictIni(std::string("[s]\nx=\0", 7), "a.ini"); }).find("NUL"), std::string::npos);
    EXPECT_NE(errorOf([] { StrictIni("/nonexistent/x.ini"); }).find("does not exist"), std::string::npos);
    EXPECT_NE(errorOf([] { StrictIni("/tmp"); }).find("is not a regular file"), std::string::npos);
    EXPECT_EQ(errorOf([] { StrictIni("; comment\n# c\n// c\n[s] ; c\nx = 1 // c\n", "a.ini"); }), "");
}

TEST(StrictIni, MrptOptionStructsAreCheckedThroughTheirDefaults) {
    // MRPT's read_int would read "abc" as 0 and its own checks would never see it.
    const StrictIni bad("[KLD_options]\nKLD_maxSampleSize = abc\n", "k.ini");
    mrpt::slam::TKLDParams kld;
    const std::string m = errorOf([&] { kld.loadFromConfigFile(bad, "KLD_options"); });
    EXPECT_NE(m.find("k.ini: [KLD_options] KLD_maxSampleSize = 'abc' is not an integer"), std::string::npos) << m;
    const StrictIni frac("[KLD_options]\nKLD_delta = 0.02x\n", "k.ini");
    EXPECT_NE(errorOf([&] { kld.loadFromConfigFile(frac, "KLD_options"); }).find("KLD_delta"), std::string::npos);
    // The keys the struct read are the known ones.
    const StrictIni typo("[KLD_options]\nKLD_maxSampleSise = 5\n", "k.ini");
    kld.loadFromConfigFile(typo, "KLD_options");
    EXPECT_NE(errorOf([&] { typo.checkUnknown(); }).find("k.ini: [KLD_options] unknown key 'KLD_maxSampleSise'"),
              std::string::npos);
    const StrictIni good("[KLD_options]\nKLD_maxSampleSize = 500\n[other]\nx = 1\n", "k.ini");
    kld.loadFromConfigFile(good, "KLD_options");
    EXPECT_EQ(kld.KLD_maxSampleSize, 500u);
    EXPECT_NE(errorOf([&] { good.checkUnknown(); }).find("k.ini: unknown section [other]"), std::string::npos);
    EXPECT_EQ(errorOf([&] { good.checkUnknown({"other"}); }), "");
}

TEST(StrictIni, TypedReadsWithRanges) {
    const StrictIni ini("[a]\nx = 5\ny = -5.0\nb = maybe\n", "r.ini");
    EXPECT_EQ(ini.readNumber("a", "x", 0, 0, 10), 5.0);
    EXPECT_EQ(ini.readNumber("a", "absent", 7, 0, 10), 7.0);
    EXPECT_NE(errorOf([&] { ini.readInteger("a", "y", 0, 0, 10); }).find("r.ini: [a] y: '-5.0' is not an integer"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { ini.readNumber("a", "x", 0, 6, 10); }).find("must be in [6, 10]"), std::string::npos);
    EXPECT_NE(errorOf([&] { ini.readBool("a", "b", false); }).find("r.ini: [a] b"), std::string::npos);
}
