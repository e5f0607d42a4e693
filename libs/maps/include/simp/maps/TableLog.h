#pragma once
/// \file TableLog.h
/// The natural logarithm without a libm call, for Eq. combined: it runs once per (particle x
/// detection) pair that hits a map object, where std::log was about a tenth of a whole run.

#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace simp::maps {

/// log(x) for x > 0: x = 2^e m, m in [1, 2); m is divided by the middle c_i of its 1/128-wide
/// interval by multiplying with a stored 1 / c_i (|r| = |m / c_i - 1| < 2^-8), and log(m) =
/// log1p(r) - log(1 / c_i), with log1p(r) by its series to degree 6 (remainder < 3e-18) and
/// log(1 / c_i) from std::log of the stored value itself (so rounding 1 / c_i costs nothing).
/// Absolute error a few 1e-16 for the normal doubles (tests/maps/test_TableLog.cpp): far below
/// anything the sensor model resolves. Zero, negative, subnormal, infinite and NaN arguments go to
/// std::log (same result as it).
class TableLog {
   public:
    TableLog() {
        for (std::size_t i = 0; i < kKnots; ++i) {
            const double knot = 1.0 + (static_cast<double>(i) + 0.5) / kKnots;
            m_inv[i] = 1.0 / knot;
            m_log_inv[i] = std::log(m_inv[i]);
        }
    }

    double operator()(double x) const {
        if (!(x >= DBL_MIN && x <= DBL_MAX)) return std::log(x);
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        const int e = static_cast<int>(bits >> 52) - 1023;  // x > 0: no sign bit
        const std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
        const std::size_t i = static_cast<std::size_t>(mantissa >> (52 - kKnotBits));
        const std::uint64_t m_bits = mantissa | (std::uint64_t{1023} << 52);
        double m;  // in [1, 2)
        std::memcpy(&m, &m_bits, sizeof m);
        const double r = m * m_inv[i] - 1.0;  // |r| < 2^-8
        const double r2 = r * r;
        // log1p(r) = r - r^2/2 + r^3/3 - r^4/4 + r^5/5 - r^6/6 (two halves, shorter dependency chain)
        const double low = r - 0.5 * r2, high = r2 * r * ((1.0 / 3 - 0.25 * r) + r2 * (0.2 - r * (1.0 / 6)));
        const double scaled_e = static_cast<double>(e);
        return (scaled_e * kLn2Hi - m_log_inv[i]) + (low + (high + scaled_e * kLn2Lo));
    }

   private:
    static constexpr int kKnotBits = 7;
    static constexpr std::size_t kKnots = std::size_t{1} << kKnotBits;
    // ln 2 split so that e * kLn2Hi is exact for |e| < 2^11 (kLn2Hi has 42 significant bits).
    static constexpr double kLn2Hi = 0x1.62e42fefa38p-1;
    static constexpr double kLn2Lo = 0x1.ef35793c7673p-45;
    std::array<double, kKnots> m_inv{};
    std::array<double, kKnots> m_log_inv{};
};

}  // namespace simp::maps
