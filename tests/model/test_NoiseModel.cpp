// The centre-noise model (NoiseModel.h): validity, the covariance of its offsets, and the centre
// noise left once an object's own footprint is taken out (withoutFootprint).
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

TEST(NoiseModel, OffsetCovarianceIsSigmaForAGaussianAndSmallerForFlatterShapes) {
    NoiseModel n;
    n.cov_m2 << 0.09, 0.01, 0.01, 0.04;
    n.exponent_b = 2.0;
    EXPECT_TRUE(offsetCovariance(n).isApprox(n.cov_m2, 1e-12));
    // b = 4: E[r^2] / 2 = 2^(1/2) Gamma(1) / Gamma(1/2) / 2 = 1 / sqrt(2 pi)
    n.exponent_b = 4.0;
    EXPECT_TRUE(offsetCovariance(n).isApprox(n.cov_m2 / std::sqrt(2.0 * M_PI), 1e-12));
}

/// The authors' board class model (class_noise.csv at 0.05 m/px: 2.95 x 12.66 px, b = 2): x across
/// the board, y along its length (classNoiseFrameYaw).
NoiseModel boardClassModel() {
    NoiseModel m;
    m.mean_m << -0.046, 0.052;
    m.cov_m2 << 0.1476 * 0.1476, 0.0, 0.0, 0.6328 * 0.6328;
    m.exponent_b = 2.0;
    return m;
}

TEST(NoiseModel, WithoutFootprintTakesTheUniformFootprintOutOfEachAxisOfTheClassFrame) {
    // A 1.8 x 0.15 m board, written with either axis labelling and at any yaw: the class frame
    // follows the longer side, so the result is the same.
    const double across = 0.1476 * 0.1476 - 0.15 * 0.15 / 12, along = 0.6328 * 0.6328 - 1.8 * 1.8 / 12;
    for (const double yaw : {0.0, 0.7, -2.0}) {
        for (const bool long_x : {true, false}) {
            const auto box = long_x ? geometry::makeUprightBox({2, 1, 1.3}, {1.8, 0.15, 1.0}, yaw)
                                    : geometry::makeUprightBox({2, 1, 1.3}, {0.15, 1.8, 1.0}, yaw + M_PI / 2);
            const NoiseModel c = withoutFootprint(boardClassModel(), box, NoiseSource::Class, 0.25);
            EXPECT_NEAR(c.cov_m2(0, 0), across, 1e-9) << "yaw " << yaw;
            EXPECT_NEAR(c.cov_m2(1, 1), along, 1e-9) << "yaw " << yaw;
            EXPECT_NEAR(c.cov_m2(0, 1), 0.0, 1e-12);
            EXPECT_TRUE(c.mean_m.isApprox(boardClassModel().mean_m));  // mu and b are kept
            EXPECT_EQ(c.exponent_b, 2.0);
        }
    }
    // An object's own model is in the box's own frame: the same board with its length along the
    // box x axis and the model's axes swapped accordingly gives the swapped result.
    NoiseModel own = boardClassModel();
    own.cov_m2 << 0.6328 * 0.6328, 0.0, 0.0, 0.1476 * 0.1476;
    const auto box = geometry::makeUprightBox({2, 1, 1.3}, {1.8, 0.15, 1.0}, 0.4);
    const NoiseModel c = withoutFootprint(own, box, NoiseSource::Object, 0.25);
    EXPECT_NEAR(c.cov_m2(0, 0), along, 1e-9);
    EXPECT_NEAR(c.cov_m2(1, 1), across, 1e-9);
}

TEST(NoiseModel, WithoutFootprintFloorsWhereTheExtentExplainsTheSpread) {
    // A flat-topped model (b = 4) narrower along y than a uniform 1.2 m footprint: floored at the
    // fraction of the model's std, Sigma scaled, b kept; fraction 1 returns the model unchanged.
    NoiseModel m;
    m.cov_m2 << 0.09, 0.0, 0.0, 0.09;
    m.exponent_b = 4.0;
    const auto box = geometry::makeUprightBox({0, 0, 0.4}, {0.3, 1.2, 0.8}, 0.0);
    const Eigen::Matrix2d spread = offsetCovariance(m);
    for (const double fraction : {0.25, 0.35}) {
        const NoiseModel c = withoutFootprint(m, box, NoiseSource::Object, fraction);
        EXPECT_NEAR(offsetCovariance(c)(0, 0), spread(0, 0) - 0.3 * 0.3 / 12, 1e-9);
        EXPECT_NEAR(offsetCovariance(c)(1, 1), fraction * fraction * spread(1, 1), 1e-9);
        EXPECT_EQ(c.exponent_b, 4.0);
        EXPECT_TRUE(c.isValid());
    }
    EXPECT_TRUE(withoutFootprint(m, box, NoiseSource::Object, 1.0).cov_m2.isApprox(m.cov_m2, 1e-12));
}

}  // namespace
}  // namespace simp::model
