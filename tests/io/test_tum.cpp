// TUM reader on broken and hostile files: errors name the file and the line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <simp/io/Tum.h>

#include <filesystem>
#include <fstream>

using ::testing::HasSubstr;

namespace {

std::string tumFile(const std::string& name, const std::string& text) {
    const auto dir = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "io";
    std::filesystem::create_directories(dir);
    const auto path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
}

std::string readError(const std::string& path) {
    try {
        simp::io::readTum(path);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(TumHostile, AbsurdCoordinatesAndTimesAreRejected) {
    const auto far = tumFile("far.tum", "0 1e300 0 0 0 0 0 1\n");
    EXPECT_THAT(readError(far), HasSubstr("far.tum' line 1: coordinate"));
    const auto late = tumFile("late.tum", "1e300 0 0 0 0 0 0 1\n");
    EXPECT_THAT(readError(late), HasSubstr("late.tum' line 1: time stamp"));
    const auto overflow = tumFile("overflow.tum", "0 1e400 0 0 0 0 0 1\n");
    EXPECT_THAT(readError(overflow), HasSubstr("overflow.tum' line 1"));
}

TEST(TumHostile, EmptyFileGivesNoPoses) {
    EXPECT_TRUE(simp::io::readTum(tumFile("empty.tum", "")).empty());
    EXPECT_TRUE(simp::io::readTum(tumFile("comments.tum", "# t x y z qx qy qz qw\n\n")).empty());
}
