// Eqs. perclassdist / shiftdist: the detection-centre distribution of a map object, p_o(c | l).
#include <gtest/gtest.h>
#include <simp/model/ObjectDistribution.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace simp::model {
namespace {

NoiseModel noise(double sx, double sy, double b, double mx = 0.0, double my = 0.0) {
    NoiseModel n;
    n.mean_m = {mx, my};
    n.cov_m2 = Eigen::Vector2d(sx * sx, sy * sy).asDiagonal();
    n.exponent_b = b;
    return n;
}

TEST(ObjectDistribution, ShiftdistMovesAndRotatesTheClassNoise) {
    // Object at (2, 1) rotated by 90 deg, its longer side along its y (so the noise frame is the box
    // frame); class noise mean (0.1, 0) m, sigma (0.3, 0.1) m in the noise frame.
    const auto box = geometry::makeUprightBox({2.0, 1.0, 0.5}, {0.5, 1.0, 1.0}, M_PI / 2);
    const auto d = makeObjectDistribution(box, noise(0.3, 0.1, 2.0, 0.1, 0.0), NoiseSource::Class);
    EXPECT_NEAR(d.mean_world_m.x(), 2.0, 1e-12);  // mu_o = R_o mu + c_o
    EXPECT_NEAR(d.mean_world_m.y(), 1.1, 1e-12);
    EXPECT_NEAR(d.sigma_x_m, 0.1, 1e-12);  // Sigma_o = R_o Sigma R_o^T swaps the axes
    EXPECT_NEAR(d.sigma_y_m, 0.3, 1e-12);
    EXPECT_DOUBLE_EQ(d.probability(2.0, 1.1), 1.0);  // unnormalized: peak exactly 1
    // One sigma along world y (the object's x): m = 1, p = exp(-0.5).
    EXPECT_NEAR(d.probability(2.0, 1.4), std::exp(-0.5), 1e-12);
    // b = 4: p = exp(-0.5 m^4); m = 2 along world x (sigma 0.1).
    const auto d4 = makeObjectDistribution(box, noise(0.3, 0.1, 4.0, 0.1, 0.0), NoiseSource::Class);
    EXPECT_NEAR(d4.probability(2.2, 1.1), std::exp(-0.5 * 16.0), 1e-15);
}

TEST(ObjectDistribution, NoiseFrameHasItsYAlongTheLongerSide) {
    // A board 1.6 m long along its x axis, facing +y (yaw 0): the noise frame is turned by 90 deg so
    // that the model's y (here sigma 0.3 m, the authors' large scale of boards) lies along the board.
    const auto board = geometry::makeUprightBox({2.0, 1.0, 1.2}, {1.6, 0.05, 1.0}, 0.0);
    EXPECT_NEAR(classNoiseFrameYaw(board), M_PI / 2, 1e-12);
    const auto d = makeObjectDistribution(board, noise(0.1, 0.3, 2.0, 0.0, 0.05), NoiseSource::Class);
    EXPECT_NEAR(d.sigma_x_m, 0.3, 1e-12);  // along the board (world x)
    EXPECT_NEAR(d.sigma_y_m, 0.1, 1e-12);
    EXPECT_NEAR(d.mean_world_m.x(), 2.0 - 0.05, 1e-12);  // mu (0, 0.05) rotated by +90 deg -> (-0.05, 0)
    EXPECT_NEAR(d.mean_world_m.y(), 1.0, 1e-12);
    // The same board described with its long side on y: the same distribution.
    const auto same = geometry::makeUprightBox({2.0, 1.0, 1.2}, {0.05, 1.6, 1.0}, -M_PI / 2);
    const auto d2 = makeObjectDistribution(same, noise(0.1, 0.3, 2.0, 0.0, 0.05), NoiseSource::Class);
    EXPECT_NEAR(d2.sigma_x_m, 0.3, 1e-12);
    EXPECT_NEAR(d2.sigma_y_m, 0.1, 1e-12);
}

TEST(ObjectDistribution, RejectsInvalidNoise) {
    const auto box = geometry::makeUprightBox({0, 0, 0.5}, {1, 1, 1}, 0);
    EXPECT_THROW(makeObjectDistribution(box, noise(0.3, 0.1, 0.0), NoiseSource::Class), std::invalid_argument);
    auto bad = noise(0.3, 0.1, 2.0);
    bad.cov_m2(1, 1) = -1.0;
    EXPECT_THROW(makeObjectDistribution(box, bad, NoiseSource::Object), std::invalid_argument);
}

TEST(ObjectDistribution, SupportRadiusAndSlope) {
    EXPECT_NEAR(std::exp(-0.5 * std::pow(supportMahalanobisRadius(2.0, 1e-4), 2.0)), 1e-4, 1e-12);
    EXPECT_NEAR(std::exp(-0.5 * std::pow(supportMahalanobisRadius(4.0, 1e-4), 4.0)), 1e-4, 1e-12);
    // Gaussian: max |d/dm exp(-m^2/2)| = exp(-1/2) at m = 1.
    EXPECT_NEAR(maxSlopeMahalanobis(2.0), std::exp(-0.5), 1e-12);
    // Numeric check for b = 4.
    double best = 0;
    for (double m = 0; m < 3; m += 1e-4) best = std::max(best, 2.0 * std::pow(m, 3) * std::exp(-0.5 * std::pow(m, 4)));
    EXPECT_NEAR(maxSlopeMahalanobis(4.0), best, 1e-6);
}

TEST(ObjectDistribution, AnObjectsOwnNoiseIsInItsBoxFrame) {
    // A board 1.6 m long along its x axis at yaw 0.3: its own noise (sigma 0.1 m along the box x,
    // 0.3 m along the box y, mean 0.05 m along the box x) is read in the box frame, the class
    // noise in the class frame turned by 90 deg (y along the long side).
    const auto board = geometry::makeUprightBox({2.0, 1.0, 1.2}, {1.6, 0.05, 1.0}, 0.3);
    const auto n = noise(0.1, 0.3, 2.0, 0.05, 0.0);
    const auto own = makeObjectDistribution(board, n, NoiseSource::Object);
    EXPECT_NEAR(own.mean_world_m.x(), 2.0 + 0.05 * std::cos(0.3), 1e-12);
    EXPECT_NEAR(own.mean_world_m.y(), 1.0 + 0.05 * std::sin(0.3), 1e-12);
    // one sigma along the box x from the mean: m = 1
    const Eigen::Vector2d along_x = own.mean_world_m + 0.1 * Eigen::Vector2d(std::cos(0.3), std::sin(0.3));
    EXPECT_NEAR(own.probability(along_x.x(), along_x.y()), std::exp(-0.5), 1e-12);
    // the class frame reads the same numbers turned by 90 deg: that point is at m = 1/3 there
    const auto cls = makeObjectDistribution(board, noise(0.1, 0.3, 2.0), NoiseSource::Class);
    const Eigen::Vector2d from_centre = board.center.head<2>() + 0.1 * Eigen::Vector2d(std::cos(0.3), std::sin(0.3));
    EXPECT_NEAR(cls.probability(from_centre.x(), from_centre.y()), std::exp(-0.5 / 9.0), 1e-12);
}

}  // namespace
}  // namespace simp::model
