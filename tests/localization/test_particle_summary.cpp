/// The reported pose of a particle set: cluster vs mean, covariance, ESS.

#include <gtest/gtest.h>
#include <simp/localization/ParticleSummary.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

using namespace simp::localization;

namespace {

mrpt::poses::CPosePDFParticles twoModes(std::size_t n_a, const mrpt::math::TPose2D& a, std::size_t n_b,
                                        const mrpt::math::TPose2D& b) {
    mrpt::poses::CPosePDFParticles pdf(n_a + n_b);
    for (std::size_t i = 0; i < n_a + n_b; ++i) {
        const auto& c = i < n_a ? a : b;
        const double e = 0.01 * static_cast<double>(i % 7) - 0.03;  // small deterministic spread
        pdf.m_particles[i].d = {c.x + e, c.y - e, c.phi + e};
        pdf.m_particles[i].log_w = 0;
    }
    return pdf;
}

}  // namespace

TEST(ParticleSummary, ClusterStaysOnTheHeavierMode) {
    const auto pdf = twoModes(600, {2, 2, 0.5}, 400, {8, 2, 0.5});
    ExperimentOptions opts;
    const auto s = summarizeParticles(pdf, opts);
    EXPECT_NEAR(s.estimate.x, 2.0, 0.02);
    EXPECT_NEAR(s.estimate.y, 2.0, 0.02);
    EXPECT_NEAR(s.estimate.phi, 0.5, 0.02);
    EXPECT_NEAR(s.cluster_weight, 0.6, 1e-9);
    // The mean falls between the modes (x = 0.6 * 2 + 0.4 * 8), where no particle is.
    EXPECT_NEAR(s.mean.x, 4.4, 0.02);
    EXPECT_NEAR(s.cov(0, 0), 0.6 * 0.4 * 36.0, 0.05);  // variance of a two-point mixture
    opts.estimate_mode = EstimateMode::Mean;
    EXPECT_NEAR(summarizeParticles(pdf, opts).estimate.x, 4.4, 0.02);
}

TEST(ParticleSummary, WeightsDecideTheModeAndTheEss) {
    auto pdf = twoModes(500, {2, 2, 0}, 500, {8, 2, 0});
    for (std::size_t i = 500; i < 1000; ++i) pdf.m_particles[i].log_w = std::log(3.0);  // mode b: 3x heavier
    const auto s = summarizeParticles(pdf, ExperimentOptions());
    EXPECT_NEAR(s.estimate.x, 8.0, 0.02);
    EXPECT_NEAR(s.cluster_weight, 0.75, 1e-9);
    // ESS = 1 / sum w^2 with w = 1/2000 (x500) and 3/2000 (x500): 2000^2 / (500 * 10) = 800.
    EXPECT_NEAR(s.ess, 800.0, 1e-6);
}

TEST(ParticleSummary, HeadingMeanWrapsAroundPi) {
    auto pdf = twoModes(500, {1, 1, M_PI - 0.05}, 500, {1, 1, -M_PI + 0.05});
    const auto s = summarizeParticles(pdf, ExperimentOptions());
    EXPECT_NEAR(std::abs(s.estimate.phi), M_PI, 0.03);
    EXPECT_NEAR(std::abs(s.mean.phi), M_PI, 0.03);
    EXPECT_NEAR(s.cluster_weight, 1.0, 1e-9);
}

TEST(ParticleSummary, FarApartModesGiveTheSameClusterAsNearOnes) {
    // Two modes 3 km apart: the particles' bounding box is too large for the dense bin array, so the
    // peak comes from the sorted bins. The result must be the one of the same set with the modes 6 m
    // apart (dense array), moved by the same offset: the peak search does not depend on the path.
    const auto near = twoModes(600, {2, 2, 0.5}, 400, {8, 2, 0.5});
    const auto far = twoModes(600, {2, 2, 0.5}, 400, {3002, 2, 0.5});
    const auto s_near = summarizeParticles(near, ExperimentOptions());
    const auto s_far = summarizeParticles(far, ExperimentOptions());
    EXPECT_DOUBLE_EQ(s_far.estimate.x, s_near.estimate.x);
    EXPECT_DOUBLE_EQ(s_far.estimate.y, s_near.estimate.y);
    EXPECT_DOUBLE_EQ(s_far.cluster_weight, 0.6);
    // The lighter far mode wins when it is heavier, on the sorted path too.
    auto heavy_far = far;
    for (std::size_t i = 600; i < 1000; ++i) heavy_far.m_particles[i].log_w = std::log(2.0);
    EXPECT_NEAR(summarizeParticles(heavy_far, ExperimentOptions()).estimate.x, 3002.0, 0.02);
}

TEST(ParticleSummary, EqualModesGoToTheSmallestBin) {
    // Ties between bins go to the smallest (x, y, heading) bin, whatever the particle order.
    auto pdf = twoModes(500, {8, 2, 0}, 500, {2, 2, 0});
    EXPECT_NEAR(summarizeParticles(pdf, ExperimentOptions()).estimate.x, 2.0, 0.02);
    pdf = twoModes(500, {2, 2, 0}, 500, {8, 2, 0});
    EXPECT_NEAR(summarizeParticles(pdf, ExperimentOptions()).estimate.x, 2.0, 0.02);
}

TEST(ParticleSummary, NonFinitePoseIsAClearError) {
    auto pdf = twoModes(10, {2, 2, 0}, 10, {8, 2, 0});
    pdf.m_particles[3].d.x = std::numeric_limits<double>::infinity();
    try {
        summarizeParticles(pdf, ExperimentOptions());
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("particle 3"), std::string::npos) << e.what();
    }
}
