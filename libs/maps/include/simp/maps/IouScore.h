#pragma once
/// \file IouScore.h
/// Eq. iouscore, p_g = exp(-(1 - IoU)), without a libm call: it runs once per clipped
/// (particle x detection) pair, where std::exp was about a tenth of the sensor model's time.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace simp::maps {

/// p_g(IoU) = exp(IoU - 1) for IoU in [0, 1]: exp(j/64 - 1) from a table (filled by std::exp)
/// times exp(f), 0 <= f < 1/64, by its Taylor series to degree 7 (remainder < 1e-19). IoU = j/64
/// + f splits exactly (scaling by 64 is exact), so the result is within a few ulp of std::exp
/// (tests/maps/test_SensorModel_rectangles.cpp).
class IouScore {
   public:
    IouScore() {
        for (std::size_t j = 0; j < m_table.size(); ++j) m_table[j] = std::exp(static_cast<double>(j) / kSteps - 1.0);
    }
    double operator()(double iou) const {
        const double x = std::clamp(iou, 0.0, 1.0) * kSteps;
        const int j = static_cast<int>(x);
        const double f = (x - j) * (1.0 / kSteps);
        const double series =
            1.0 + f * (1.0 + f * (1.0 / 2 + f * (1.0 / 6 + f * (1.0 / 24 + f * (1.0 / 120 + f * (1.0 / 720 + f * (1.0 / 5040)))))));
        return m_table[static_cast<std::size_t>(j)] * series;
    }

   private:
    static constexpr double kSteps = 64.0;
    std::array<double, 65> m_table{};
};

}  // namespace simp::maps
