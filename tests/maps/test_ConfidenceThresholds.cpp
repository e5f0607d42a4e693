#include <gtest/gtest.h>
#include <simp/maps/ConfidenceThresholds.h>

namespace simp::maps {
namespace {

TEST(ConfidenceThresholds, PaperDefaults) {
    const auto& t = paperConfidenceThresholds();
    EXPECT_EQ(t.size(), 14u);
    EXPECT_DOUBLE_EQ(t.at("door"), 0.5);
    EXPECT_DOUBLE_EQ(t.at("drawers"), 0.4);
    EXPECT_DOUBLE_EQ(t.at("sofa"), 0.8);
    EXPECT_DOUBLE_EQ(t.at("fire extinguisher"), 0.7);
}

TEST(ConfidenceThresholds, ParsesNamesWithSpacesAndRoundTrips) {
    const auto t = parseConfidenceThresholds(" chair:0.3, potted plant : 0.9,fire extinguisher:1", "here");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_DOUBLE_EQ(t.at("chair"), 0.3);
    EXPECT_DOUBLE_EQ(t.at("potted plant"), 0.9);
    EXPECT_DOUBLE_EQ(t.at("fire extinguisher"), 1.0);
    EXPECT_EQ(parseConfidenceThresholds(formatConfidenceThresholds(t), "again"), t);
    EXPECT_TRUE(parseConfidenceThresholds("", "empty").empty());
}

TEST(ConfidenceThresholds, BadEntriesNameTheWhereAndTheEntry) {
    const auto expectError = [](const std::string& text, const std::string& fragment) {
        try {
            parseConfidenceThresholds(text, "[sec] confidence_thresholds");
            ADD_FAILURE() << "no error for '" << text << "'";
        } catch (const std::invalid_argument& e) {
            const std::string msg = e.what();
            EXPECT_NE(msg.find("[sec] confidence_thresholds"), std::string::npos) << msg;
            EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
        }
    };
    expectError("chair 0.3", "chair 0.3");
    expectError("chair:abc", "abc");
    expectError("chair:1.5", "[0, 1]");
    expectError(":0.5", "empty class name");
    expectError("chair:0.2, chair:0.4", "twice");
    expectError("chair:nan", "chair");
}

}  // namespace
}  // namespace simp::maps
