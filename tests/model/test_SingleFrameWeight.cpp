// Eq. singw: the geometric mean of a frame's per-detection likelihoods.
#include <gtest/gtest.h>
#include <simp/model/SingleFrameWeight.h>

#include <cmath>

namespace simp::model {
namespace {

TEST(SingleFrameWeight, IsTheLogOfTheGeometricMean) {
    // p = (0.5, 0.2, 0.8): (0.5 * 0.2 * 0.8)^(1/3) = 0.08^(1/3)
    const double sum_log = std::log(0.5) + std::log(0.2) + std::log(0.8);
    EXPECT_NEAR(std::exp(singwLog(sum_log, 3)), std::cbrt(0.08), 1e-12);
    EXPECT_DOUBLE_EQ(singwLog(std::log(0.3), 1), std::log(0.3));
    // K equal likelihoods weigh like one: the weight does not shrink with the number of detections.
    EXPECT_NEAR(singwLog(7 * std::log(0.3), 7), std::log(0.3), 1e-15);
}

}  // namespace
}  // namespace simp::model
