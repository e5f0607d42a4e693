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
