/// ObjectMcl's replacements of MRPT's particle-set accessors give MRPT's results exactly.

#include "SyntheticScenario.h"
#include "TestUtil.h"

#include <gtest/gtest.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/ObjectMcl.h>

#include <cmath>
#include <cstring>
#include <vector>

using namespace simp::localization;
using namespace simp::localization::test;

namespace {

/// A set of n particles with random poses and log-weights, the same for the same seed.
void fill(ObjectMcl& mcl, std::size_t n, unsigned seed) {
    auto& rng = mrpt::random::getRandomGenerator();
    rng.randomize(seed);
    mcl.m_particles.resize(n);
    for (auto& p : mcl.m_particles) {
        p.d = {rng.drawUniform(0.0, 10.0), rng.drawUniform(0.0, 8.0), rng.drawUniform(-M_PI, M_PI)};
        p.log_w = rng.drawUniform(-30.0, 0.0);
    }
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(ObjectMcl, SubstitutionEqualsMrpts) {
    const auto map = makeMap(makeWorld());
    // Sorted (resampling), unsorted, fewer and more particles than before.
    const std::vector<std::vector<size_t>> cases = {
        {0, 0, 1, 3, 3, 3, 7, 9}, {9, 2, 2, 0, 5}, {4, 4, 4}, {1, 8, 0, 0, 2, 9, 9, 3, 5, 6, 7, 7, 7, 4}};
    for (const auto& idx : cases) {
        ObjectMcl ours(map), theirs(map);
        fill(ours, 10, 5);
        fill(theirs, 10, 5);
        ours.performSubstitution(idx);
        theirs.mrpt::poses::CPosePDFParticles::performSubstitution(idx);  // MRPT's own
        ASSERT_EQ(ours.m_particles.size(), theirs.m_particles.size());
        for (std::size_t k = 0; k < ours.m_particles.size(); ++k) {
            const auto &a = ours.m_particles[k], &b = theirs.m_particles[k];
            EXPECT_TRUE(sameBits(a.d.x, b.d.x) && sameBits(a.d.y, b.d.y) && sameBits(a.d.phi, b.d.phi) &&
                        sameBits(a.log_w, b.log_w))
                << "particle " << k;
        }
    }
}

TEST(ObjectMcl, EssEqualsMrpts) {
    const auto map = makeMap(makeWorld());
    ObjectMcl mcl(map);
    fill(mcl, 500, 9);
    EXPECT_TRUE(sameBits(mcl.ESS(), mcl.mrpt::poses::CPosePDFParticles::ESS()));
}

namespace {

/// x of the particles weighted by their weights.
double weightedMeanX(const ObjectMcl& mcl) {
    double sw = 0, sx = 0;
    for (const auto& p : mcl.m_particles) sw += std::exp(p.log_w), sx += std::exp(p.log_w) * p.d.x;
    return sx / sw;
}

/// n particles evenly on x in [0, 10], log-weight -x: the weighted mean of x is about 1, and 0.5
/// if the weights count twice (weights e^-2x).
double meanAfterResampling(bool resets_weights, double& mean_before, double& ess_after) {
    const auto map = makeMap(makeWorld());
    ObjectMcl mcl(map);
    mcl.params.resample_resets_weights = resets_weights;
    const std::size_t n = 2000;
    mcl.m_particles.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = 10.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(n);
        mcl.m_particles[i].d = {x, 1.0, 0.0};
        mcl.m_particles[i].log_w = -x;
    }
    mean_before = weightedMeanX(mcl);
    mrpt::random::getRandomGenerator().randomize(3);
    mrpt::bayes::CParticleFilter::TParticleFilterOptions pf;
    pf.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
    mcl.resample(pf);
    EXPECT_EQ(mcl.m_particles.size(), n);
    ess_after = mcl.ESS();
    return weightedMeanX(mcl);
}

}  // namespace

// Resampling draws copies in proportion to the weights; the copies must then weigh the same, or the
// weights count twice (MRPT 2.5's performResampling leaves them as they were).
TEST(ObjectMcl, ResamplingLeavesEqualWeightsAndTheSameDistribution) {
    double before = 0, ess = 0;
    const double after = meanAfterResampling(true, before, ess);
    EXPECT_NEAR(before, 1.0, 0.01);
    EXPECT_NEAR(ess, 1.0, 1e-9);  // every weight the same (up to the rounding of the sum)
    // Systematic resampling of 2000 particles: the copies' distribution function is within 1/2000
    // of the weights' everywhere, so the mean moves by at most the range / 2000.
    EXPECT_NEAR(after, before, 10.0 / 2000);
}

TEST(ObjectMcl, ResamplingThatKeepsTheWeightsCountsThemTwice) {
    double before = 0, ess = 0;
    const double after = meanAfterResampling(false, before, ess);
    EXPECT_LT(ess, 0.9);
    EXPECT_NEAR(after, 0.5, 0.02);  // the mean under weights e^-2x
}
