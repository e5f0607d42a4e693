#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/Angle.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::vector<double> anglesToTry() {
    // Within one turn, at the branch edges (0, +-0, +-pi, +-2 pi and their neighbours), several
    // turns away, and tiny angles, where (a + pi) - pi is not a.
    std::vector<double> a = {0.0, -0.0, M_PI, -M_PI, 2 * M_PI, -2 * M_PI, 1e-20, -1e-20, 3 * M_PI, -3 * M_PI, 1e6, -1e6};
    for (double base : {0.0, M_PI, -M_PI, 2 * M_PI, -2 * M_PI}) {
        a.push_back(std::nextafter(base, 10.0));
        a.push_back(std::nextafter(base, -10.0));
    }
    auto& rng = mrpt::random::getRandomGenerator();
    rng.randomize(3);
    for (int i = 0; i < 20000; ++i) a.push_back(rng.drawUniform(-20.0, 20.0));
    return a;
}

}  // namespace

TEST(Angle, WrapToPiHasMrptsBits) {
    for (const double a : anglesToTry()) {
        EXPECT_TRUE(sameBits(simp::localization::wrapToPi(a), mrpt::math::wrapToPi(a))) << "a = " << a;
        EXPECT_TRUE(sameBits(simp::localization::wrapTo2Pi(a), mrpt::math::wrapTo2Pi(a))) << "a = " << a;
    }
}

TEST(Angle, WrapToPiStaysWithinOneTurn) {
    for (const double a : anglesToTry()) {
        const double w = simp::localization::wrapToPi(a);
        EXPECT_GE(w, -M_PI - 1e-12);
        EXPECT_LE(w, M_PI + 1e-12);
        EXPECT_NEAR(std::remainder(w - a, 2 * M_PI), 0.0, 1e-9 * std::max(1.0, std::abs(a)));
    }
}
