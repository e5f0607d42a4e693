#include <simp/localization/KldSampleCount.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

namespace simp::localization {
namespace {

/// z with P(N(0,1) <= z) = p, by bisection on erfc (p in (0.5, 1)).
double standardNormalQuantile(double p) {
    double lo = 0.0, hi = 10.0;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (1.0 - 0.5 * std::erfc(mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

std::size_t occupiedBinCount(const mrpt::poses::CPosePDFParticles& pdf, const mrpt::slam::TKLDParams& kld) {
    const std::size_t n = pdf.m_particles.size();
    if (n == 0) return 0;
    std::vector<long> bx(n), by(n), bp(n);
    long min_x = std::numeric_limits<long>::max(), min_y = min_x, min_p = min_x;
    long max_x = std::numeric_limits<long>::min(), max_y = max_x, max_p = max_x;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& d = pdf.m_particles[i].d;
        bx[i] = static_cast<long>(std::floor(d.x / kld.KLD_binSize_XY));
        by[i] = static_cast<long>(std::floor(d.y / kld.KLD_binSize_XY));
        bp[i] = static_cast<long>(std::floor(d.phi / kld.KLD_binSize_PHI));
        min_x = std::min(min_x, bx[i]), max_x = std::max(max_x, bx[i]);
        min_y = std::min(min_y, by[i]), max_y = std::max(max_y, by[i]);
        min_p = std::min(min_p, bp[i]), max_p = std::max(max_p, bp[i]);
    }
    // Spans as doubles: a particle far out must not overflow the products below.
    const double sx = static_cast<double>(max_x) - static_cast<double>(min_x) + 1.0;
    const double sy = static_cast<double>(max_y) - static_cast<double>(min_y) + 1.0;
    const double sp = static_cast<double>(max_p) - static_cast<double>(min_p) + 1.0;
    const auto key = [&](std::size_t i) {
        return (static_cast<std::uint64_t>(bx[i] - min_x) * static_cast<std::uint64_t>(sy) +
                static_cast<std::uint64_t>(by[i] - min_y)) * static_cast<std::uint64_t>(sp) +
               static_cast<std::uint64_t>(bp[i] - min_p);
    };
    // A bitmap of up to 2 MB + 64 bytes per particle (16 M bins + 512 per particle: a set spread
    // over a building, or a tracked set with a few sensor-resetting particles far off, is one; cleared
    // in microseconds, where sorting 5000 keys takes a fifth of a millisecond).
    if (sx * sy * sp <= 512.0 * static_cast<double>(n) + 16777216.0) {
        std::vector<std::uint64_t> seen((static_cast<std::size_t>(sx * sy * sp) + 63) / 64, 0);
        std::size_t k = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint64_t b = key(i);
            const std::uint64_t bit = std::uint64_t{1} << (b % 64);
            auto& word = seen[b / 64];
            k += (word & bit) == 0;
            word |= bit;
        }
        return k;
    }
    if (sx * sy * sp < 1.8e19) {  // sorted 64-bit keys
        std::vector<std::uint64_t> keys(n);
        for (std::size_t i = 0; i < n; ++i) keys[i] = key(i);
        std::sort(keys.begin(), keys.end());
        return static_cast<std::size_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
    }
    std::vector<std::tuple<long, long, long>> bins(n);  // absurd spreads (far outside any map)
    for (std::size_t i = 0; i < n; ++i) bins[i] = {bx[i], by[i], bp[i]};
    std::sort(bins.begin(), bins.end());
    return static_cast<std::size_t>(std::unique(bins.begin(), bins.end()) - bins.begin());
}

std::size_t kldParticleCount(const mrpt::poses::CPosePDFParticles& pdf, const mrpt::slam::TKLDParams& kld) {
    const double k = static_cast<double>(occupiedBinCount(pdf, kld));
    if (k <= 1) return kld.KLD_minSampleSize;
    const double z = standardNormalQuantile(1.0 - kld.KLD_delta);
    const double a = 2.0 / (9.0 * (k - 1.0));
    const double n = (k - 1.0) / (2.0 * kld.KLD_epsilon) * std::pow(1.0 - a + std::sqrt(a) * z, 3);
    const double per_bin = kld.KLD_minSamplesPerBin * k;
    const double bounded = std::clamp(std::max(n, per_bin), static_cast<double>(kld.KLD_minSampleSize),
                                      static_cast<double>(kld.KLD_maxSampleSize));
    return static_cast<std::size_t>(std::ceil(bounded));
}

}  // namespace simp::localization
