#pragma once
/// \file Random.h
/// The simulator's random source: one seeded std::mt19937_64 and portable samplers written on
/// top of its raw 64-bit output (the std:: distributions are implementation-defined, these are
/// not), so a seed gives the same numbers with any standard library.

#include <simp/model/NoiseModel.h>

#include <Eigen/Core>
#include <cstdint>
#include <random>

namespace simp::sim {

class Rng {
   public:
    explicit Rng(std::uint64_t seed) : m_engine(seed) {}

    /// Uniform in [0, 1).
    double uniform();
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform integer in [0, n); n > 0.
    std::size_t index(std::size_t n);
    /// True with probability p.
    bool bernoulli(double p) { return uniform() < p; }
    /// Normal N(mean, std^2) (Box-Muller).
    double normal(double mean = 0.0, double std = 1.0);
    /// Gamma(shape, 1) (Marsaglia-Tsang; shape > 0).
    double gamma(double shape);
    /// Poisson(lambda) (Knuth's product method; lambda small).
    int poisson(double lambda);
    /// A seed for an independent sub-stream (so adding draws in one part leaves another unchanged).
    std::uint64_t split() { return m_engine(); }

   private:
    std::mt19937_64 m_engine;
};

/// Draws a detected box centre offset (m) in the object's ground frame from `model`:
/// density exp(-0.5 m^b) with m the Mahalanobis distance for Sigma, shifted by mu
/// (paper Eq. perclassdist; b = 2 is the Gaussian). Sampled exactly: the radius r in whitened
/// space has 0.5 r^b ~ Gamma(2/b, 1), the direction is uniform. Its covariance is
/// model::offsetCovariance(model).
Eigen::Vector2d sampleCentreOffset(const model::NoiseModel& model, Rng& rng);

}  // namespace simp::sim
