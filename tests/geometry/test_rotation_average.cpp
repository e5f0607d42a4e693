/// Tests of simp/geometry/RotationAverage.h: the SVD projection of the weighted mean.
#include <simp/geometry/RotationAverage.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace simp::geometry {
namespace {

Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<double> n01;
    return Eigen::Quaterniond(n01(rng), n01(rng), n01(rng), n01(rng)).normalized().toRotationMatrix();
}

Eigen::Matrix3d rotZ(double angle) { return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

void expectRotation(const Eigen::Matrix3d& R) {
    EXPECT_NEAR((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
}

TEST(RotationAverage, SymmetricPerturbationsAverageToTheCentre) {
    // R0 exp(+-theta [w]x) for three axes: the mean is R0 (I + (1 - cos theta) S) with S
    // symmetric, whose polar factor is R0.
    std::mt19937_64 rng(8);
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::Matrix3d R0 = randomRotation(rng);
        std::vector<Eigen::Matrix3d> Rs;
        for (const Eigen::Vector3d& axis : {Eigen::Vector3d(1, 2, 0).normalized(), Eigen::Vector3d(0, 1, -1).normalized(),
                                          Eigen::Vector3d(3, -1, 2).normalized()})
            for (const double theta : {0.4, -0.4}) Rs.push_back(R0 * Eigen::AngleAxisd(theta, axis).toRotationMatrix());
        const Eigen::Matrix3d mean = averageRotations(Rs, std::vector<double>(Rs.size(), 2.5));
        expectRotation(mean);
        EXPECT_NEAR((mean - R0).norm(), 0.0, 1e-12) << "trial " << trial;
    }
}

TEST(RotationAverage, TwoRotationsAboutOneAxis) {
    // Same axis: the weighted mean of the 2x2 blocks is a scaled rotation by
    // atan2(w2 sin t, w1 + w2 cos t); equal weights give the half angle.
    const double t = 1.1;
    EXPECT_NEAR((averageRotations({rotZ(0.0), rotZ(t)}, {1.0, 1.0}) - rotZ(t / 2)).norm(), 0.0, 1e-12);
    const double w1 = 3.0, w2 = 1.0;
    const double expected = std::atan2(w2 * std::sin(t), w1 + w2 * std::cos(t));
    const Eigen::Matrix3d mean = averageRotations({rotZ(0.0), rotZ(t)}, {w1, w2});
    expectRotation(mean);
    EXPECT_NEAR((mean - rotZ(expected)).norm(), 0.0, 1e-12);
    EXPECT_LT(expected, t / 2);  // the heavier rotation pulls the mean towards itself
}

TEST(RotationAverage, WeightsAreHonoured) {
    std::mt19937_64 rng(9);
    const Eigen::Matrix3d A = randomRotation(rng), B = randomRotation(rng);
    EXPECT_NEAR((averageRotations({A, B}, {1.0, 0.0}) - A).norm(), 0.0, 1e-12);
    EXPECT_NEAR((averageRotations({A, B}, {0.0, 4.0}) - B).norm(), 0.0, 1e-12);
    // Scaling all weights does not change the mean; map update with n_match counts 5 and 2.
    const Eigen::Matrix3d m1 = averageRotations({A, B}, {5.0, 2.0});
    const Eigen::Matrix3d m2 = averageRotations({A, B}, {50.0, 20.0});
    EXPECT_NEAR((m1 - m2).norm(), 0.0, 1e-12);
    expectRotation(m1);
    // Closer (geodesic angle) to the heavier one.
    const double to_a = Eigen::AngleAxisd(m1.transpose() * A).angle();
    const double to_b = Eigen::AngleAxisd(m1.transpose() * B).angle();
    EXPECT_LT(to_a, to_b);
}

TEST(RotationAverage, ResultIsAlwaysARotation) {
    std::mt19937_64 rng(10);
    std::uniform_real_distribution<double> weight(0.1, 5.0);
    for (int trial = 0; trial < 100; ++trial) {
        std::vector<Eigen::Matrix3d> Rs;
        std::vector<double> w;
        for (int i = 0; i < 2 + trial % 5; ++i) {
            Rs.push_back(randomRotation(rng));
            w.push_back(weight(rng));
        }
        expectRotation(averageRotations(Rs, w));
    }
    // A single rotation averages to itself.
    const Eigen::Matrix3d R = randomRotation(rng);
    EXPECT_NEAR((averageRotations({R}, {1.0}) - R).norm(), 0.0, 1e-12);
}

TEST(RotationAverage, BadInputThrows) {
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    EXPECT_THROW(averageRotations({}, {}), std::invalid_argument);
    EXPECT_THROW(averageRotations({I, I}, {1.0}), std::invalid_argument);
    EXPECT_THROW(averageRotations({I, I}, {1.0, -1.0}), std::invalid_argument);
    EXPECT_THROW(averageRotations({I}, {std::numeric_limits<double>::quiet_NaN()}), std::invalid_argument);
    EXPECT_THROW(averageRotations({I, I}, {0.0, 0.0}), std::invalid_argument);
    Eigen::Matrix3d nan = I;
    nan(1, 1) = std::numeric_limits<double>::quiet_NaN();
    try {
        averageRotations({I, nan}, {1.0, 1.0});
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("rotation 1"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace simp::geometry
