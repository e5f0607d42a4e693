// Hand-made trajectories with known convergence time, ATE, divergence and success.
#include <gtest/gtest.h>
#include <simp/eval/TrajectoryMetrics.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using simp::eval::evaluateTrajectory;
using simp::eval::evaluateTrajectoryFiles;
using simp::eval::TrajMetricsParams;
using simp::io::StampedPose2D;

namespace {

/// Ground truth along x at 1 m/s: x = t - t0, y = 0, phi = 0, one pose per second over [t0, t0 + duration].
std::vector<StampedPose2D> straightLine(double t0, int duration_s) {
    std::vector<StampedPose2D> gt;
    for (int k = 0; k <= duration_s; ++k) gt.push_back({t0 + k, {static_cast<double>(k), 0.0, 0.0}});
    return gt;
}

/// Estimate at t (every 0.5 s over [t0, t0 + duration]) = ground truth + (0, dy(t), dphi(t)).
template <class F>
std::vector<StampedPose2D> offsetEstimate(double t0, int duration_s, F offset) {
    std::vector<StampedPose2D> est;
    for (int k = 0; k <= 2 * duration_s; ++k) {
        const double t = 0.5 * k;
        const auto [dy, dphi] = offset(t);
        est.push_back({t0 + t, {t, dy, dphi}});
    }
    return est;
}

constexpr double kOut = 5.0;  // an error far outside the 0.3 m bound

}  // namespace

TEST(TrajectoryMetrics, KnownConvergenceTimeAndAte) {
    // GT starts at t0 = 100 s, lasts 10 s. Before 3 s the estimate is 5 m off; from 3 s on it is
    // 0.1 m off at t = 3.0, 4.0, ... (8 samples) and 0.2 m off at 3.5, 4.5, ... (7 samples), 0.05 rad.
    // ATE_trans = sqrt((8 * 0.1^2 + 7 * 0.2^2) / 15) = sqrt(0.36 / 15) = sqrt(0.024) = 0.154919 m,
    // ATE_rot = 0.05 rad.
    const auto gt = straightLine(100.0, 10);
    const auto est = offsetEstimate(100.0, 10, [](double t) -> std::pair<double, double> {
        if (t < 3.0) return {kOut, 0.0};
        return {std::fmod(t, 1.0) == 0.0 ? 0.1 : 0.2, 0.05};
    });
    const auto m = evaluateTrajectory(gt, est);
    EXPECT_TRUE(m.converged);
    ASSERT_TRUE(m.convergence_time_s.has_value());
    EXPECT_NEAR(*m.convergence_time_s, 3.0, 1e-9);
    EXPECT_NEAR(m.duration_s, 10.0, 1e-12);
    EXPECT_FALSE(m.diverged);
    EXPECT_TRUE(m.success);
    ASSERT_TRUE(m.ate_trans_m && m.ate_rot_rad);
    EXPECT_NEAR(*m.ate_trans_m, std::sqrt(0.024), 1e-9);
    EXPECT_NEAR(*m.ate_rot_rad, 0.05, 1e-9);
    EXPECT_EQ(m.n_estimates_used, 21u);
    EXPECT_EQ(m.n_estimates_ignored, 0u);
}

TEST(TrajectoryMetrics, RotationBoundAloneBlocksConvergence) {
    // Translation perfect, heading 0.8 rad (> pi/4 = 0.785) until 4 s, then 0.7 rad (< pi/4).
    const auto gt = straightLine(0.0, 10);
    const auto est =
        offsetEstimate(0.0, 10, [](double t) -> std::pair<double, double> { return {0.0, t < 4.0 ? 0.8 : 0.7}; });
    const auto m = evaluateTrajectory(gt, est);
    ASSERT_TRUE(m.convergence_time_s);
    EXPECT_NEAR(*m.convergence_time_s, 4.0, 1e-9);
    EXPECT_NEAR(*m.ate_rot_rad, 0.7, 1e-9);
}

TEST(TrajectoryMetrics, AccumulatedOutsideTimeOfExactly1p5sIsNoDivergence) {
    // Converged at 1 s; outside at 5.0, 5.5, 6.0 s: each holds 0.5 s until the next estimate,
    // 1.5 s in total, which does not exceed 1.5 s.
    const auto gt = straightLine(0.0, 20);
    const auto est = offsetEstimate(0.0, 20, [](double t) -> std::pair<double, double> {
        return {(t < 1.0 || (t >= 5.0 && t <= 6.0)) ? kOut : 0.0, 0.0};
    });
    const auto m = evaluateTrajectory(gt, est);
    EXPECT_NEAR(*m.convergence_time_s, 1.0, 1e-9);
    EXPECT_NEAR(m.time_outside_s, 1.5, 1e-12);
    EXPECT_FALSE(m.diverged);
    EXPECT_TRUE(m.success);
    // ATE includes the three outside samples: 39 samples from 1 s to 20 s, three of them 5 m off.
    EXPECT_NEAR(*m.ate_trans_m, std::sqrt(3 * 25.0 / 39.0), 1e-9);
}

TEST(TrajectoryMetrics, AccumulatedOutsideTimeAbove1p5sIsDivergence) {
    // As above, plus one more outside estimate at 12 s: 2.0 s accumulated in separate pieces.
    // The budget runs out at the start of that hold: divergence at 12.0 s.
    const auto gt = straightLine(0.0, 20);
    const auto est = offsetEstimate(0.0, 20, [](double t) -> std::pair<double, double> {
        return {(t < 1.0 || (t >= 5.0 && t <= 6.0) || t == 12.0) ? kOut : 0.0, 0.0};
    });
    const auto m = evaluateTrajectory(gt, est);
    EXPECT_TRUE(m.converged);
    EXPECT_TRUE(m.diverged);
    ASSERT_TRUE(m.divergence_time_s);
    EXPECT_NEAR(*m.divergence_time_s, 12.0, 1e-9);
    EXPECT_NEAR(m.time_outside_s, 2.0, 1e-12);
    EXPECT_FALSE(m.success);
}

TEST(TrajectoryMetrics, ConvergenceAfter95PercentIsNoSuccess) {
    // Duration 20 s: the limit is 0.95 * 20 = 19 s. Converging at 19.5 s fails, at 19.0 s succeeds.
    const auto gt = straightLine(0.0, 20);
    const auto late = evaluateTrajectory(gt, offsetEstimate(0.0, 20, [](double t) -> std::pair<double, double> {
                                             return {t < 19.5 ? kOut : 0.1, 0.0};
                                         }));
    EXPECT_TRUE(late.converged);
    EXPECT_NEAR(*late.convergence_time_s, 19.5, 1e-9);
    EXPECT_FALSE(late.diverged);
    EXPECT_FALSE(late.success);
    EXPECT_NEAR(*late.ate_trans_m, 0.1, 1e-9);  // samples at 19.5 and 20.0, both 0.1 m off

    const auto just_in_time = evaluateTrajectory(
        gt, offsetEstimate(0.0, 20, [](double t) -> std::pair<double, double> { return {t < 19.0 ? kOut : 0.1, 0.0}; }));
    EXPECT_NEAR(*just_in_time.convergence_time_s, 19.0, 1e-9);
    EXPECT_TRUE(just_in_time.success);
}

TEST(TrajectoryMetrics, NeverConvergingHasNoMetrics) {
    const auto gt = straightLine(0.0, 10);
    const auto m =
        evaluateTrajectory(gt, offsetEstimate(0.0, 10, [](double) -> std::pair<double, double> { return {0.31, 0.0}; }));
    EXPECT_FALSE(m.converged);
    EXPECT_FALSE(m.success);
    EXPECT_FALSE(m.convergence_time_s.has_value());
    EXPECT_FALSE(m.ate_trans_m.has_value());
    EXPECT_FALSE(m.ate_rot_rad.has_value());
    EXPECT_NEAR(m.duration_s, 10.0, 1e-12);
}

TEST(TrajectoryMetrics, EstimatesOutsideTheGroundTruthSpanAreIgnored) {
    auto gt = straightLine(0.0, 10);
    std::vector<StampedPose2D> est{{-1.0, {100, 100, 0}}, {2.5, {2.5, 0.0, 0.0}}, {11.0, {100, 100, 0}}};
    const auto m = evaluateTrajectory(gt, est);
    EXPECT_EQ(m.n_estimates_used, 1u);
    EXPECT_EQ(m.n_estimates_ignored, 2u);
    // ground truth interpolated at 2.5 s is (2.5, 0): zero error, converged at 2.5 s
    EXPECT_NEAR(*m.convergence_time_s, 2.5, 1e-12);
    EXPECT_NEAR(*m.ate_trans_m, 0.0, 1e-12);
}

TEST(TrajectoryMetrics, HeadingErrorWrapsAroundPi) {
    // GT heading 3.0 rad at 0 s, -3.0 rad at 1 s: the shortest arc passes through pi, so at 0.5 s the
    // interpolated heading is pi; an estimate of -pi + 0.1 is 0.1 rad off, not 2 pi - 0.1.
    std::vector<StampedPose2D> gt{{0.0, {0, 0, 3.0}}, {1.0, {0, 0, -3.0}}};
    std::vector<StampedPose2D> est{{0.5, {0, 0, -M_PI + 0.1}}};
    const auto m = evaluateTrajectory(gt, est);
    ASSERT_EQ(m.errors.size(), 1u);
    EXPECT_NEAR(m.errors[0].rot_rad, 0.1, 1e-9);
}

TEST(TrajectoryMetrics, BadInputThrows) {
    const auto gt = straightLine(0.0, 10);
    EXPECT_FALSE(evaluateTrajectory(gt, {}).converged);  // no estimate: a failed run, not an error
    EXPECT_THROW(evaluateTrajectory({gt.front()}, gt), std::invalid_argument);
    std::vector<StampedPose2D> late{{50.0, {0, 0, 0}}};
    try {
        evaluateTrajectory(gt, late);
        FAIL() << "no overlap must throw";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("time span"), std::string::npos) << e.what();
    }
}

TEST(TrajectoryMetrics, FileErrorsNameTheFile) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_traj_files";
    fs::create_directories(dir);
    const auto gt = (dir / "gt.tum").string();
    simp::io::writeTum(gt, straightLine(0.0, 10));
    const auto expectMessage = [](auto f, const std::string& needle) {
        try {
            f();
            FAIL() << "expected an exception mentioning " << needle;
        } catch (const std::exception& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    const auto missing = (dir / "missing.tum").string();
    expectMessage([&] { evaluateTrajectoryFiles(gt, missing); }, "missing.tum");
    // An estimate with no pose (a localizer that never claimed one) is a failed run, not an error.
    const auto empty = (dir / "empty.tum").string();
    std::ofstream(empty) << "# no poses\n";
    const auto none = evaluateTrajectoryFiles(gt, empty);
    EXPECT_FALSE(none.converged);
    EXPECT_FALSE(none.success);
    EXPECT_FALSE(none.ate_trans_m.has_value());
    EXPECT_NEAR(none.duration_s, 10.0, 1e-9);
    const auto bad = (dir / "bad.tum").string();
    std::ofstream(bad) << "0 1 2 0 0 0 0 1\n1 1 two 0 0 0 0 1\n";
    expectMessage([&] { evaluateTrajectoryFiles(gt, bad); }, "line 2");
}
