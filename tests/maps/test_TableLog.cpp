// TableLog (Eq. combined's log) against std::log: the sensor model uses it in its place, so it must
// agree to rounding over every value Eq. combined can take and far beyond, and be std::log itself
// where its table does not apply.
#include <gtest/gtest.h>
#include <simp/maps/TableLog.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

namespace simp::maps {
namespace {

TEST(TableLog, AgreesWithStdLogToRounding) {
    const TableLog table_log;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> combined(1e-6, 2.0), exponent(-700.0, 700.0);
    double worst = 0.0;
    for (int i = 0; i < 400000; ++i) {
        double x = i % 2 ? combined(rng) : std::exp(exponent(rng));
        if (i % 7 == 0) x = std::nextafter(std::ldexp(std::round(std::ldexp(x, 8)), -8), x);  // next to the knots
        const double expected = std::log(x);
        // Error in nats: a few ulp of max(1, |log x|) (rounding of m / c_i - 1 costs ~1e-16 absolute).
        worst = std::max(worst, std::abs(table_log(x) - expected) / std::max(1.0, std::abs(expected)));
    }
    EXPECT_LT(worst, 1e-15);
    EXPECT_NEAR(table_log(1.0), 0.0, 1e-17);
    EXPECT_NEAR(table_log(0.1), std::log(0.1), 3e-16);  // eta's default: the miss floor
}

TEST(TableLog, IsStdLogOutsideTheNormalPositiveDoubles) {
    const TableLog table_log;
    EXPECT_EQ(table_log(0.0), -std::numeric_limits<double>::infinity());
    EXPECT_TRUE(std::isnan(table_log(-1.0)));
    EXPECT_TRUE(std::isnan(table_log(std::numeric_limits<double>::quiet_NaN())));
    EXPECT_EQ(table_log(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
    EXPECT_EQ(table_log(DBL_MIN / 4), std::log(DBL_MIN / 4));  // subnormal
}

}  // namespace
}  // namespace simp::maps
