// geometry::sinCos against std::sin and std::cos: the particle loops use it in their place, so it
// must agree with them to rounding over every heading a particle can have, and fall back to them
// where its reduction does not hold.
#include <gtest/gtest.h>
#include <simp/geometry/SinCos.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace {

TEST(SinCos, AgreesWithLibmToRoundingOverHeadingsAndBeyond) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> heading(-M_PI, M_PI), wide(-1e5, 1e5);
    double worst = 0.0;
    for (int i = 0; i < 400000; ++i) {
        double x = i % 2 ? heading(rng) : wide(rng);
        if (i % 5 == 0) x = std::nextafter(std::round(x / M_PI_2) * M_PI_2, x);  // quadrant borders
        double s = 0, c = 0;
        simp::geometry::sinCos(x, s, c);
        worst = std::max({worst, std::abs(s - std::sin(x)), std::abs(c - std::cos(x))});
    }
    // Each result is a rounded value of magnitude <= 1: a few ulp of 1 (2.2e-16) is rounding.
    EXPECT_LT(worst, 5e-16);
}

TEST(SinCos, ExactAtZeroAndLibmOutsideItsRange) {
    double s = 1, c = 0;
    simp::geometry::sinCos(0.0, s, c);
    EXPECT_EQ(s, 0.0);
    EXPECT_EQ(c, 1.0);
    for (const double x : {1e5, -3e7, 1e300}) {
        simp::geometry::sinCos(x, s, c);
        EXPECT_EQ(s, std::sin(x));
        EXPECT_EQ(c, std::cos(x));
    }
    simp::geometry::sinCos(std::numeric_limits<double>::quiet_NaN(), s, c);
    EXPECT_TRUE(std::isnan(s) && std::isnan(c));
    simp::geometry::sinCos(std::numeric_limits<double>::infinity(), s, c);
    EXPECT_TRUE(std::isnan(s) && std::isnan(c));
}

}  // namespace
