#include <gtest/gtest.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/poses/CPoseRandomSampler.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/GaussianMotionSampler.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace {

bool sameBits(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) {
    return std::memcmp(&a.x, &b.x, sizeof(double)) == 0 && std::memcmp(&a.y, &b.y, sizeof(double)) == 0 &&
           std::memcmp(&a.phi, &b.phi, sizeof(double)) == 0;
}

/// The action's pose PDF for an odometry increment with MRPT's Gaussian model.
mrpt::poses::CPosePDFGaussian odometryPdf(const mrpt::poses::CPose2D& increment) {
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions mm;
    mm.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
    mm.gaussianModel.a1 = 0.15, mm.gaussianModel.a4 = 0.15;
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(increment, mm);
    mrpt::poses::CPosePDFGaussian g;
    g.copyFrom(*mv.poseChange);
    return g;
}

}  // namespace

TEST(GaussianMotionSampler, MovesParticlesAsMrptsSamplerAndComposition) {
    // Same seed, same particles: MRPT's CPoseRandomSampler + CPose2D::operator+ and the sampler
    // give the same bits, for increments forward, turning, backwards and zero.
    for (const auto& inc : {mrpt::poses::CPose2D(0.1, 0.0, 0.0), mrpt::poses::CPose2D(0.05, 0.01, 0.3),
                            mrpt::poses::CPose2D(-0.2, 0.0, -3.0), mrpt::poses::CPose2D(0, 0, 0)}) {
        const auto pdf = odometryPdf(inc);
        auto& rng = mrpt::random::getRandomGenerator();
        rng.randomize(11);
        std::vector<mrpt::math::TPose2D> start(500);
        for (auto& p : start) p = {rng.drawUniform(-10.0, 10.0), rng.drawUniform(-5.0, 5.0), rng.drawUniform(-4.0, 4.0)};

        // A fresh generator, not randomize(): std::normal_distribution keeps a spare draw across a
        // reseed, so the two runs would start from whatever an earlier test left behind.
        rng = mrpt::random::CRandomGenerator(5);
        mrpt::poses::CPoseRandomSampler mrpt_sampler;
        mrpt_sampler.setPosePDF(pdf);
        std::vector<mrpt::math::TPose2D> expected;
        mrpt::poses::CPose2D drawn;
        for (const auto& p : start) {
            mrpt_sampler.drawSample(drawn);
            expected.push_back((mrpt::poses::CPose2D(p) + drawn).asTPose());
        }
        rng = mrpt::random::CRandomGenerator(5);
        const simp::localization::GaussianMotionSampler sampler(pdf);
        for (std::size_t i = 0; i < start.size(); ++i) {
            const auto moved = sampler.move(start[i]);
            ASSERT_TRUE(sameBits(moved, expected[i])) << "particle " << i << ": " << moved.asString() << " vs "
                                                      << expected[i].asString();
        }
    }
}

TEST(GaussianMotionSampler, IncrementsHaveTheModelsMeanAndSpread) {
    const auto pdf = odometryPdf(mrpt::poses::CPose2D(0.5, 0.0, 0.2));
    mrpt::random::getRandomGenerator().randomize(2);
    const simp::localization::GaussianMotionSampler sampler(pdf);
    const int n = 20000;
    double sx = 0, sy = 0, sp = 0, sxx = 0, spp = 0;
    for (int i = 0; i < n; ++i) {
        const auto d = sampler.drawIncrement();
        sx += d.x, sy += d.y, sp += d.phi, sxx += d.x * d.x, spp += d.phi * d.phi;
    }
    const double mx = sx / n, mp = sp / n;
    // Standard error of a mean of 20000 samples: std / 141; 5 of them.
    EXPECT_NEAR(mx, pdf.mean.x(), 5 * std::sqrt(pdf.cov(0, 0)) / 141);
    EXPECT_NEAR(sy / n, pdf.mean.y(), 5 * std::sqrt(pdf.cov(1, 1)) / 141);
    EXPECT_NEAR(mp, pdf.mean.phi(), 5 * std::sqrt(pdf.cov(2, 2)) / 141);
    EXPECT_NEAR(sxx / n - mx * mx, pdf.cov(0, 0), 0.05 * pdf.cov(0, 0));
    EXPECT_NEAR(spp / n - mp * mp, pdf.cov(2, 2), 0.05 * pdf.cov(2, 2));
}
