/// KLD sampling's particle count: Fox's bound on the occupied bins, and the bin counter's paths.

#include <gtest/gtest.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/KldSampleCount.h>

#include <cmath>
#include <set>
#include <tuple>

using namespace simp::localization;

TEST(KldSampleCount, ShrinksWithTheSet) {
    mrpt::slam::TKLDParams kld;
    kld.KLD_minSampleSize = 100;
    kld.KLD_maxSampleSize = 100000;
    mrpt::poses::CPosePDFParticles tight(2000), wide(2000);
    auto& rng = mrpt::random::getRandomGenerator();
    rng.randomize(1);
    for (auto& p : tight.m_particles) p.d = {rng.drawGaussian1D(0, 0.05), rng.drawGaussian1D(0, 0.05), rng.drawGaussian1D(0, 0.02)};
    for (auto& p : wide.m_particles) p.d = {rng.drawUniform(0.0, 20.0), rng.drawUniform(0.0, 10.0), rng.drawUniform(-M_PI, M_PI)};
    const auto n_tight = kldParticleCount(tight, kld), n_wide = kldParticleCount(wide, kld);
    // Fox's bound with MRPT's defaults (0.2 m, 5 deg bins, epsilon 0.02, delta 0.01): a cloud of
    // 5 cm and 1 deg occupies about 20 bins (a few hundred particles), 2000 particles spread over
    // 20 m x 10 m x 2 pi occupy about 2000 (tens of thousands).
    EXPECT_GT(n_tight, kld.KLD_minSampleSize);
    EXPECT_LT(n_tight, 1000u);
    EXPECT_GT(n_wide, 20 * n_tight);
    kld.KLD_maxSampleSize = 3000;
    EXPECT_EQ(kldParticleCount(wide, kld), 3000u);
}

TEST(KldSampleCount, OccupiedBinsAreTheDistinctBins) {
    // Each path of the counter (bitmap for a compact set, sorted keys for a spread-out one, tuples
    // for a particle absurdly far out) against a count of distinct (x, y, phi) bin triples.
    mrpt::slam::TKLDParams kld;
    auto& rng = mrpt::random::getRandomGenerator();
    rng.randomize(7);
    const auto distinct = [&](const mrpt::poses::CPosePDFParticles& pdf) {
        std::set<std::tuple<long, long, long>> s;
        for (const auto& p : pdf.m_particles)
            s.emplace(static_cast<long>(std::floor(p.d.x / kld.KLD_binSize_XY)),
                      static_cast<long>(std::floor(p.d.y / kld.KLD_binSize_XY)),
                      static_cast<long>(std::floor(p.d.phi / kld.KLD_binSize_PHI)));
        return s.size();
    };
    mrpt::poses::CPosePDFParticles compact(3000), spread(3000);
    for (auto& p : compact.m_particles)
        p.d = {rng.drawGaussian1D(-3, 0.3), rng.drawGaussian1D(2, 0.3), rng.drawUniform(-M_PI, M_PI)};
    for (auto& p : spread.m_particles)
        p.d = {rng.drawUniform(-500.0, 500.0), rng.drawUniform(-500.0, 500.0), rng.drawUniform(-M_PI, M_PI)};
    EXPECT_EQ(occupiedBinCount(compact, kld), distinct(compact));
    mrpt::poses::CPosePDFParticles building(3000);  // a building-wide set: the bitmap too
    for (auto& p : building.m_particles)
        p.d = {rng.drawUniform(-30.0, 30.0), rng.drawUniform(-20.0, 20.0), rng.drawUniform(-M_PI, M_PI)};
    EXPECT_EQ(occupiedBinCount(building, kld), distinct(building));
    EXPECT_EQ(occupiedBinCount(spread, kld), distinct(spread));
    spread.m_particles[5].d.x = 1e17;  // bin products beyond 64 bits
    EXPECT_EQ(occupiedBinCount(spread, kld), distinct(spread));
    EXPECT_EQ(occupiedBinCount(mrpt::poses::CPosePDFParticles(0), kld), 0u);
}
