#pragma once
/// \file IouScore.h
/// Eq. iouscore, p_g = exp(-(1 - IoU)), without a libm call: it runs once per clipped
/// (particle x detection) pair, where std::exp was about a tenth of the sensor model's time.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace simp::maps {

/// p_g(IoU) = exp(IoU - 1) for IoU in [0, 1], and with the yaw term exp(IoU - 1 - penalty) for a
/// penalty in [0, 1], in one evaluation: exp(j/256 - 2) from a table (filled by std::exp) times
/// exp(f), 0 <= f < 1/256, by its Taylor series to degree 5 (remainder < 5e-18), evaluated in two
/// independent halves (Estrin): the series is on the critical path of every pair, and without
/// fused multiply-adds a Horner chain of degree 7 cost a fifth of the sensor model's time. IoU =
/// j/256 + f splits exactly (scaling by 256 is exact), so the result is within a few ulp of
/// std::exp (tests/maps/test_SensorModel_rectangles.cpp).
class IouScore {
   public:
    IouScore() {
        for (std::size_t j = 0; j < m_table.size(); ++j) m_table[j] = std::exp(static_cast<double>(j) / kSteps - 2.0);
    }
    /// exp(IoU - 1), the IoU clamped to [0, 1].
    double operator()(double iou) const { return scaled(std::clamp(iou, 0.0, 1.0) * kSteps, kOffsetOfIou); }
    /// exp(IoU - 1 - penalty), both clamped to [0, 1].
    double operator()(double iou, double penalty) const {
        return scaled((std::clamp(iou, 0.0, 1.0) - std::clamp(penalty, 0.0, 1.0) + 1.0) * kSteps, 0);
    }

   private:
    /// exp((x + offset) / kSteps - 2) for x >= 0, x + offset <= 2 kSteps.
    double scaled(double x, int offset) const {
        const int whole = static_cast<int>(x);  // x >= 0: truncation is floor
        const double f = (x - whole) * (1.0 / kSteps);
        const double f2 = f * f;
        // 1 added last: the small terms are summed first, so the sum rounds once at the magnitude of 1.
        const double series = 1.0 + (f + (f2 * (1.0 / 2 + f * (1.0 / 6)) + (f2 * f2) * (1.0 / 24 + f * (1.0 / 120))));
        return m_table[static_cast<std::size_t>(whole + offset)] * series;
    }

    static constexpr double kSteps = 256.0;
    static constexpr int kOffsetOfIou = 256;  ///< table index of exp(-1)
    std::array<double, 2 * 256 + 1> m_table{};
};

}  // namespace simp::maps
