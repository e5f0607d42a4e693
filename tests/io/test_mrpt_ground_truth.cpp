// pf-localization's ground-truth file (simp/io/MrptGroundTruth.h), read back with MRPT's own matrix
// reader (CMatrixDouble::loadFromTextFile, what MonteCarloLocalization_App uses).
#include <gtest/gtest.h>
#include <mrpt/math/CMatrixDynamic.h>
#include <simp/io/MrptGroundTruth.h>

#include <cmath>
#include <filesystem>

TEST(MrptGroundTruth, RowsAreTimeXYPhiAndTimeIsDetectable) {
    const auto dir = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "io";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "gt_mrpt.txt").string();
    std::vector<simp::io::StampedPose2D> poses = {{1700000000.0, {1.5, -2.25, 0.5}},
                                                   {1700000000.1, {1.6, -2.2, 3.0}},
                                                   {1700000001.0, {1.7, -2.1, -3.0}}};
    simp::io::writeMrptGroundTruth(path, poses);
    mrpt::math::CMatrixDouble m;
    m.loadFromTextFile(path);
    ASSERT_EQ(m.rows(), 3);
    ASSERT_EQ(m.cols(), 4);  // "time x y phi", one of the two layouts pf-localization accepts
    // MRPT's rule: column 0 is time when the first two values are not whole numbers.
    EXPECT_NE(std::floor(m(0, 0)), m(0, 0));
    EXPECT_NE(std::floor(m(1, 0)), m(1, 0));
    EXPECT_NEAR(m(0, 0), 1700000000.0, 2e-6);
    EXPECT_NEAR(m(1, 0), 1700000000.1, 1e-6);
    EXPECT_NEAR(m(2, 0), 1700000001.0, 2e-6);
    EXPECT_DOUBLE_EQ(m(0, 1), 1.5);
    EXPECT_DOUBLE_EQ(m(0, 2), -2.25);
    EXPECT_DOUBLE_EQ(m(0, 3), 0.5);
    EXPECT_DOUBLE_EQ(m(2, 3), -3.0);
    EXPECT_DOUBLE_EQ(simp::io::mrptGroundTruthTime(12.5), 12.5);
    EXPECT_THROW(simp::io::writeMrptGroundTruth("/proc/nonexistent/gt.txt", poses), std::exception);
}
