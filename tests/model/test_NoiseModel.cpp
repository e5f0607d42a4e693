// The centre-noise model's validity (NoiseModel.h).
#include <gtest/gtest.h>
#include <simp/model/NoiseModel.h>

#include <cmath>

namespace simp::model {
namespace {

TEST(NoiseModel, Validity) {
    NoiseModel n;
    EXPECT_TRUE(n.isValid());
    n.cov_m2 << 0.04, 0.01, 0.01, 0.04;
    EXPECT_TRUE(n.isValid());
    n.cov_m2 << 0.04, 0.05, 0.05, 0.04;  // indefinite
    EXPECT_FALSE(n.isValid());
    n.cov_m2 << 0.04, 0.01, 0.02, 0.04;  // not symmetric
    EXPECT_FALSE(n.isValid());
    n = NoiseModel{};
    n.exponent_b = 0;
    EXPECT_FALSE(n.isValid());
    n = NoiseModel{};
    n.mean_m.x() = std::nan("");
    EXPECT_FALSE(n.isValid());
}

}  // namespace
}  // namespace simp::model
