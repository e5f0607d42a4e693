// The per-class "name:value" lists of the .ini files (libs/io NameValueList.h).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <simp/io/NameValueList.h>

#include <map>
#include <stdexcept>
#include <string>

using ::testing::HasSubstr;

TEST(NameValueList, ClassNamesWithSpacesKeepTheirOrderAndValues) {
    const auto entries = simp::io::parseNameValueList(" potted plant:1.5, desk : -0.25 ,\"sofa\":2", "[x] key");
    ASSERT_EQ(entries.size(), 3u);
    EXPECT_EQ(entries[0].first, "potted plant");
    EXPECT_DOUBLE_EQ(entries[0].second, 1.5);
    EXPECT_EQ(entries[1].first, "desk");
    EXPECT_DOUBLE_EQ(entries[1].second, -0.25);
    EXPECT_EQ(entries[2].first, "sofa");
    EXPECT_DOUBLE_EQ(entries[2].second, 2.0);
}

TEST(NameValueListHostile, OverflowAndGarbageNameTheEntry) {
    EXPECT_THROW(simp::io::parseNameValueList("chair:1e400", "[x] key"), std::invalid_argument);
    try {
        simp::io::parseNameValueList("chair:abc", "[x] key");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_THAT(e.what(), HasSubstr("[x] key: entry 'chair:abc'"));
    }
}

TEST(NameValueList, ValueOrGivesTheListedValueElseTheFallback) {
    const std::map<std::string, double> radius{{"sofa", 1.0}, {"door", 0.0}};
    EXPECT_DOUBLE_EQ(simp::io::valueOr(radius, "sofa", 0.5), 1.0);
    EXPECT_DOUBLE_EQ(simp::io::valueOr(radius, "door", 0.5), 0.0);  // a listed 0 is a value, not "absent"
    EXPECT_DOUBLE_EQ(simp::io::valueOr(radius, "desk", 0.5), 0.5);
    EXPECT_DOUBLE_EQ(simp::io::valueOr(radius, "Sofa", 0.5), 0.5);  // class names are case-sensitive
}
