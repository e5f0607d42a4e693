// The heading change of an earlier map object over a session (SessionTurn.h): measured against
// the earlier box modulo the box's symmetry, significant only when the windows agree.
#include <gtest/gtest.h>
#include <simp/mapping/SessionTurn.h>

#include <cmath>
#include <random>

using namespace simp::mapping;
using simp::geometry::makeUprightBox;

namespace {
constexpr double kDeg = M_PI / 180.0;
const auto kBefore = makeUprightBox({2.0, 1.0, 0.9}, {1.0, 0.4, 1.8}, 0.3);

/// `n` windows of the box at `yaw` plus Gaussian heading noise of `std_rad`; every other window
/// reports the same solid with its sides swapped and turned by 90 deg.
std::vector<SessionBox> windowsAt(double yaw, double std_rad, int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    std::vector<SessionBox> w;
    for (int k = 0; k < n; ++k) {
        const double y = yaw + std_rad * n01(rng);
        w.push_back({k % 2 ? makeUprightBox({2.0, 1.0, 0.9}, {0.4, 1.0, 1.8}, y + M_PI / 2)
                           : makeUprightBox({2.0, 1.0, 0.9}, {1.0, 0.4, 1.8}, y),
                     1.0 + k % 3});
    }
    return w;
}
}  // namespace

TEST(SessionTurn, AnObjectAtItsEarlierHeadingHasNoTurn) {
    const TurnEstimate t = estimateTurn(kBefore, windowsAt(0.3, 0.1, 40, 1));
    EXPECT_EQ(t.windows, 40);
    // 0.1 rad of noise per window over 40 windows: a standard error of about 0.1 / sqrt(40) = 0.9 deg.
    EXPECT_NEAR(t.std_error_rad, 0.1 / std::sqrt(40.0), 0.006);
    EXPECT_LT(std::abs(t.turn_rad), 3 * t.std_error_rad);
    EXPECT_FALSE(isTurned(t, 5, 10 * kDeg, 3));
}

TEST(SessionTurn, ATurnIsMeasuredWhicheverWayTheBoxIsReported) {
    for (const double turn_deg : {-35.0, -12.0, 20.0, 40.0}) {
        const TurnEstimate t = estimateTurn(kBefore, windowsAt(0.3 + turn_deg * kDeg, 0.1, 30, 2));
        EXPECT_NEAR(t.turn_rad / kDeg, turn_deg, 3 * t.std_error_rad / kDeg + 0.5) << turn_deg;
        EXPECT_TRUE(isTurned(t, 5, 10 * kDeg, 3)) << turn_deg;
        EXPECT_GT(t.concentration, 0.8);
    }
    // Turned by 90 deg: the same solid, no turn.
    EXPECT_LT(std::abs(estimateTurn(kBefore, windowsAt(0.3 + M_PI / 2, 0.05, 30, 3)).turn_rad), 2 * kDeg);
}

TEST(SessionTurn, FewWindowsSmallTurnsAndScatteredHeadingsAreNoTurn) {
    EXPECT_FALSE(isTurned(estimateTurn(kBefore, windowsAt(0.3 + 30 * kDeg, 0.05, 4, 4)), 5, 10 * kDeg, 3));
    EXPECT_FALSE(isTurned(estimateTurn(kBefore, windowsAt(0.3 + 6 * kDeg, 0.02, 40, 5)), 5, 10 * kDeg, 3));
    // A round object: the detector's heading is anything.
    const TurnEstimate round = estimateTurn(kBefore, windowsAt(0.3, 10.0, 60, 6));
    EXPECT_LT(round.concentration, kMinTurnConcentration);
    EXPECT_FALSE(isTurned(round, 5, 10 * kDeg, 3));
    // Off: min turn 0.
    EXPECT_FALSE(isTurned(estimateTurn(kBefore, windowsAt(0.3 + 30 * kDeg, 0.05, 30, 7)), 5, 0.0, 3));
    EXPECT_EQ(estimateTurn(kBefore, {}).windows, 0);
}
