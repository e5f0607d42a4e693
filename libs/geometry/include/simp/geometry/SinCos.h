#pragma once
/// \file SinCos.h
/// sin and cos of one angle without a libm call, for the loops that turn every particle's heading
/// into a rotation (the sensor model's batch, the particle summary): libm's sincos was about 7 %
/// of a whole localization run.

#include <cmath>
#include <cstdint>
#include <cstring>

namespace simp::geometry {

/// sin(x) and cos(x): x = k pi/2 + r with k the integer nearest to 2 x / pi, r reduced with pi/2 in
/// three parts (Cody-Waite: the first two products are exact for |k| < 2^20), |r| <= pi/4, and the
/// Taylor series of sin r to degree 15 and of cos r to degree 16 (remainders < 1e-17), evaluated
/// in independent halves (Estrin). Absolute error about 2e-16 (tests/geometry/test_sin_cos.cpp).
/// For |x| >= 1e5, NaN and infinities: std::sin and std::cos.
inline void sinCos(double x, double& sin_x, double& cos_x) {
    if (!(std::abs(x) < 1e5)) {
        sin_x = std::sin(x);
        cos_x = std::cos(x);
        return;
    }
    constexpr double kShift = 0x1.8p52;  // adding and removing it rounds to the nearest integer
    const double shifted = x * 0x1.45f306dc9c883p-1 + kShift;  // 2 / pi
    std::uint64_t k_bits;
    std::memcpy(&k_bits, &shifted, sizeof k_bits);
    const double k = shifted - kShift;
    const double r = ((x - k * 0x1.921fb544p0) - k * 0x1.0b4611a6p-34) - k * 0x1.3198a2e037073p-69;
    const double r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    const double sin_r = r * ((1.0 - r2 * (1.0 / 6)) + r4 * ((1.0 / 120) - r2 * (1.0 / 5040)) +
                              r8 * (((1.0 / 362880) - r2 * (1.0 / 39916800)) +
                                    r4 * ((1.0 / 6227020800) - r2 * (1.0 / 1307674368000))));
    const double cos_r = (1.0 - r2 * 0.5) + r4 * ((1.0 / 24) - r2 * (1.0 / 720)) +
                         r8 * (((1.0 / 40320) - r2 * (1.0 / 3628800)) + r4 * ((1.0 / 479001600) - r2 * (1.0 / 87178291200)) +
                               r8 * (1.0 / 20922789888000));
    switch (k_bits & 3) {  // the quadrant: k mod 4 (two's complement low bits)
        case 0: sin_x = sin_r; cos_x = cos_r; break;
        case 1: sin_x = cos_r; cos_x = -sin_r; break;
        case 2: sin_x = -sin_r; cos_x = -cos_r; break;
        default: sin_x = -cos_r; cos_x = sin_r; break;
    }
}

}  // namespace simp::geometry
