/// The kidnapped-robot metrics on hand-made trajectories whose answers are known.

#include <gtest/gtest.h>
#include <simp/eval/KidnapMetrics.h>

#include <vector>

using namespace simp::eval;
using State = StateSample::State;

namespace {

/// 1 m/s along x from (0, 0) for 30 s at 10 Hz; at t = 10 s the robot is put down 5 m further on.
std::vector<simp::io::StampedPose2D> truth() {
    std::vector<simp::io::StampedPose2D> gt;
    for (int i = 0; i <= 300; ++i) {
        const double t = 0.1 * i;
        gt.push_back({t, {t + (t >= 10.0 ? 5.0 : 0.0), 0.0, 0.0}});
    }
    return gt;
}

/// Steps at 10 Hz: `localized` at the truth before the teleport and from `relocalize_s` on (at
/// `offset_m` from the truth), `lost` in between from `lost_s`; the estimate before `lost_s` stays
/// where odometry takes it (no teleport).
void run(double lost_s, double relocalize_s, double offset_m, std::vector<StateSample>& steps,
         std::vector<simp::io::StampedPose2D>& estimate) {
    for (int i = 0; i <= 300; ++i) {
        const double t = 0.1 * i;
        StateSample s;
        s.t_s = t;
        s.state = t < lost_s ? State::Localized : t < relocalize_s ? State::Lost : State::Localized;
        s.estimate = {t + (t >= relocalize_s ? 5.0 + offset_m : 0.0), 0.0, 0.0};
        steps.push_back(s);
        estimate.push_back({t, s.estimate});
    }
}

}  // namespace

TEST(KidnapMetrics, LostThenRelocalizedAtTheRightPlaceIsASuccess) {
    std::vector<StateSample> steps;
    std::vector<simp::io::StampedPose2D> est;
    run(12.0, 25.0, 0.1, steps, est);
    const auto m = evaluateKidnap(truth(), steps, est, 10.0);
    ASSERT_TRUE(m.lost_after_s);
    EXPECT_NEAR(*m.lost_after_s, 2.0, 1e-9);
    ASSERT_TRUE(m.relocalized_after_s);
    EXPECT_NEAR(*m.relocalized_after_s, 15.0, 1e-9);
    ASSERT_TRUE(m.after);
    EXPECT_TRUE(m.after->success);
    EXPECT_NEAR(*m.after->convergence_time_s, 15.0, 1e-9);  // counted from the teleport
    EXPECT_TRUE(m.success);
}

TEST(KidnapMetrics, EachTimeLimitAndTheBoundsDecide) {
    const auto gt = truth();
    {  // lost too late (6 s > 5 s)
        std::vector<StateSample> steps;
        std::vector<simp::io::StampedPose2D> est;
        run(16.0, 25.0, 0.1, steps, est);
        const auto m = evaluateKidnap(gt, steps, est, 10.0);
        EXPECT_NEAR(*m.lost_after_s, 6.0, 1e-9);
        EXPECT_FALSE(m.success);
    }
    {  // localized again, but 0.5 m off: not relocalized, and the part after never converges
        std::vector<StateSample> steps;
        std::vector<simp::io::StampedPose2D> est;
        run(12.0, 20.0, 0.5, steps, est);
        const auto m = evaluateKidnap(gt, steps, est, 10.0);
        EXPECT_FALSE(m.relocalized_after_s);
        ASSERT_TRUE(m.after);
        EXPECT_FALSE(m.after->converged);
        EXPECT_FALSE(m.success);
    }
    {  // relocalized 21 s after the teleport: too late
        std::vector<StateSample> steps;
        std::vector<simp::io::StampedPose2D> est;
        run(12.0, 31.0 - 0.05, 0.1, steps, est);
        const auto m = evaluateKidnap(gt, steps, est, 10.0);
        EXPECT_FALSE(m.relocalized_after_s);  // the sequence ends at 30 s
        EXPECT_FALSE(m.success);
    }
}

TEST(KidnapMetrics, AKidnapOutsideTheGroundTruthIsAnError) {
    std::vector<StateSample> steps;
    std::vector<simp::io::StampedPose2D> est;
    run(12.0, 25.0, 0.1, steps, est);
    EXPECT_THROW(evaluateKidnap(truth(), steps, est, 45.0), std::invalid_argument);
}
