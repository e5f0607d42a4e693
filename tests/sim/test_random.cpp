// Samplers of the simulator's random source: determinism and the detection-noise distribution.
#include <gtest/gtest.h>
#include <simp/sim/Random.h>

#include <cmath>
#include <vector>

using simp::sim::Rng;

TEST(SimRandom, SameSeedSameNumbers) {
    Rng a(42), b(42), c(43);
    bool differs = false;
    for (int i = 0; i < 100; ++i) {
        const double x = a.normal(), y = b.normal(), z = c.normal();
        EXPECT_EQ(x, y);
        differs |= x != z;
    }
    EXPECT_TRUE(differs);
}

TEST(SimRandom, UniformAndGammaMoments) {
    Rng rng(7);
    const int n = 40000;
    double su = 0, sg = 0, sg2 = 0;
    for (int i = 0; i < n; ++i) {
        const double u = rng.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        su += u;
        const double g = rng.gamma(0.5);  // mean 0.5, variance 0.5
        sg += g;
        sg2 += g * g;
    }
    EXPECT_NEAR(su / n, 0.5, 4 * std::sqrt(1.0 / 12 / n));
    EXPECT_NEAR(sg / n, 0.5, 4 * std::sqrt(0.5 / n));
    (void)sg2;
}

/// Mean and covariance of many offsets match the model, within 4 standard errors computed
/// from the samples themselves (Eq. perclassdist; b = 4 has covariance Sigma * E[r^2] / 2).
void checkNoiseModel(const simp::model::NoiseModel& m, std::uint64_t seed) {
    Rng rng(seed);
    const int n = 20000;
    std::vector<Eigen::Vector2d> s(n);
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (auto& x : s) {
        x = simp::sim::sampleCentreOffset(m, rng);
        mean += x;
    }
    mean /= n;
    const Eigen::Matrix2d expected_cov = simp::model::offsetCovariance(m);
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(mean[k], m.mean_m[k], 4 * std::sqrt(expected_cov(k, k) / n)) << "mean " << k;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            double c = 0, c2 = 0;
            for (const auto& x : s) {
                const double p = (x[i] - mean[i]) * (x[j] - mean[j]);
                c += p;
                c2 += p * p;
            }
            c /= n;
            const double se = std::sqrt((c2 / n - c * c) / n);
            EXPECT_NEAR(c, expected_cov(i, j), 4 * se) << "cov " << i << j << " b=" << m.exponent_b;
        }
}

TEST(SimRandom, GaussianNoiseModelMeanAndCovariance) {
    simp::model::NoiseModel m;
    m.mean_m = {-0.06, 0.05};
    m.cov_m2 << 0.04, 0.012, 0.012, 0.09;
    m.exponent_b = 2.0;
    EXPECT_TRUE(simp::model::offsetCovariance(m).isApprox(m.cov_m2));
    checkNoiseModel(m, 11);
}

TEST(SimRandom, FlatGeneralizedGaussianMeanAndCovariance) {
    simp::model::NoiseModel m;
    m.mean_m = {0.2, -0.1};
    m.cov_m2 << 0.1, -0.02, -0.02, 0.03;
    m.exponent_b = 4.0;
    // E[r^2] / 2 for b = 4 is sqrt(2) * Gamma(1) / Gamma(1/2) / 2 = 1 / sqrt(2 pi)
    EXPECT_NEAR(simp::model::offsetCovariance(m)(0, 0), 0.1 / std::sqrt(2 * M_PI), 1e-12);
    checkNoiseModel(m, 12);
}

TEST(SimRandom, RejectsInvalidModel) {
    simp::model::NoiseModel m;
    m.exponent_b = std::nan("");
    Rng rng(1);
    EXPECT_THROW(simp::sim::sampleCentreOffset(m, rng), std::invalid_argument);
    EXPECT_THROW(rng.gamma(-1), std::invalid_argument);
}
