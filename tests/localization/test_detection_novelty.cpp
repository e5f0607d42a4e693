/// DetectionNovelty: tempering of repeated detections, and objects the map does not hold where the
/// robot sees them (judged on FitWindow's last frame, then not scored).

#include "SyntheticScenario.h"
#include "TestUtil.h"

#include <gtest/gtest.h>
#include <simp/localization/DetectionNovelty.h>
#include <simp/localization/LocalizationState.h>

#include <cmath>

using namespace simp::localization;
using namespace simp::localization::test;

TEST(DetectionNovelty, RepeatsFromOnePlaceWeighLittleNewViewpointsFully) {
    const auto w = makeWorld();
    DetectionNoveltyParams p;
    DetectionNovelty n(p);
    const mrpt::math::TPose2D robot(3.0, 2.0, 0.4);
    const mrpt::poses::CPose2D odo(0, 0, 0);
    EXPECT_EQ(n.weigh(*observe(w, robot, {0}), odo, 0.0), std::vector<double>{1.0});  // first sight
    EXPECT_EQ(n.weigh(*observe(w, robot, {0}), odo, 0.2), std::vector<double>{p.min_weight});  // same place
    // Half the decorrelation distance later: half a detection; a whole one: a full detection.
    const auto half = mrpt::poses::CPose2D(0.5 * p.decorrelation_distance_m, 0, 0);
    const mrpt::math::TPose2D robot_half = (mrpt::poses::CPose2D(robot) + half).asTPose();
    EXPECT_NEAR(n.weigh(*observe(w, robot_half, {0}), odo + half, 0.4)[0], 0.5, 1e-9);
    const auto far = half + mrpt::poses::CPose2D(p.decorrelation_distance_m, 0, 0);
    const mrpt::math::TPose2D robot_far = (mrpt::poses::CPose2D(robot) + far).asTPose();
    EXPECT_EQ(n.weigh(*observe(w, robot_far, {0}), odo + far, 0.6)[0], 1.0);
    // Forgotten after the timeout; off when the distance is 0.
    EXPECT_EQ(n.weigh(*observe(w, robot_far, {0}), odo + far, 0.6 + p.track_timeout_s + 1)[0], 1.0);
    DetectionNovelty off(DetectionNoveltyParams{0.0, 0.1, 0.0, 1.0, 20.0});
    off.weigh(*observe(w, robot, {0}), odo, 0.0);
    EXPECT_EQ(off.weigh(*observe(w, robot, {0}), odo, 0.1)[0], 1.0);
}

TEST(DetectionNovelty, ATurnOnTheSpotIsPartlyANewViewWhenViewChangeCounts) {
    const auto w = makeWorld();
    const Eigen::Vector3d desk = w.objects.objects[0].box.center;
    const double turn_rad = 0.1;
    const mrpt::math::TPose2D before(3.0, 2.0, 0.4), after(3.0, 2.0, 0.4 + turn_rad);
    for (const double view_change_weight : {0.0, 0.5}) {
        DetectionNoveltyParams p;
        p.view_change_weight = view_change_weight;
        DetectionNovelty n(p);
        n.weigh(*observe(w, before, {0}), mrpt::poses::CPose2D(before), 0.0);
        const double weight = n.weigh(*observe(w, after, {0}), mrpt::poses::CPose2D(after), 0.2)[0];
        if (view_change_weight == 0.0) {
            EXPECT_EQ(weight, p.min_weight);  // no travel: a repeat
            continue;
        }
        // Turning by a about the robot's centre moves a point at horizontal distance r from it by
        // 2 r sin(a / 2) in every frame fixed on the robot, the camera's included.
        const double r = std::hypot(desk.x() - before.x, desk.y() - before.y);
        EXPECT_NEAR(weight, view_change_weight * 2 * r * std::sin(turn_rad / 2) / p.decorrelation_distance_m, 1e-9);
        EXPECT_GT(weight, 0.2);
        // Travel still counts as before: the larger of the two.
        const mrpt::math::TPose2D ahead(3.0 + std::cos(after.phi), 2.0 + std::sin(after.phi), after.phi);
        EXPECT_EQ(n.weigh(*observe(w, ahead, {0}), mrpt::poses::CPose2D(ahead), 0.4)[0], 1.0);
    }
}

namespace {

/// One frame seen from `robot` (odometry = world here): the desk of `map_world` (index 0) and the
/// cabinet (index 2) of `seen_world`; weighed, added to the window, judged at `estimate`.
std::vector<double> frame(DetectionNovelty& n, FitWindow& fit, const simp::maps::CObjectMap& map,
                          const simp::world::World& seen_world, const mrpt::math::TPose2D& robot,
                          const mrpt::poses::CPose2D& estimate, double t_s) {
    auto obs = observe(seen_world, robot, {0, 2});
    const mrpt::poses::CPose2D odo(robot);
    auto w = n.weigh(*obs, odo, t_s);
    fit.add(map, obs, odo, t_s, &w);
    for (const auto& j : fit.judgeAt(map, estimate, odo, t_s, 0.3, 0.1)) n.judge(*j.obs, j.k, j.odometry_pose, j.explained, t_s);
    return w;
}

}  // namespace

TEST(DetectionNovelty, AnObjectTheEstimateKeepsLeavingUnexplainedIsNoLongerScored) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    auto moved = w;
    moved.objects.objects[2].box.center.y() += 1.5;  // the cabinet at (4.6, 1.0) now 1.5 m away
    DetectionNoveltyParams p;
    p.unmapped_min_detections = 4;
    p.unmapped_min_span_s = 1.0;
    DetectionNovelty n(p);
    FitWindow fit;
    // The robot turns on the spot at (2.8, 2.5) looking at the desk and the cabinet; the estimate is right.
    const auto at = [](double t) { return mrpt::math::TPose2D(2.8, 2.5, -1.57 + 0.05 * t); };
    // Four judged frames over 0.9 s: too short a span yet.
    for (double t : {0.0, 0.3, 0.6, 0.9}) frame(n, fit, *map, moved, at(t), mrpt::poses::CPose2D(at(t)), t);
    EXPECT_EQ(n.unmappedCount(), 0u);
    frame(n, fit, *map, moved, at(1.2), mrpt::poses::CPose2D(at(1.2)), 1.2);
    EXPECT_EQ(n.unmappedCount(), 1u);  // the cabinet; the desk is explained
    const auto weights = frame(n, fit, *map, moved, at(1.5), mrpt::poses::CPose2D(at(1.5)), 1.5);
    ASSERT_EQ(weights.size(), 2u);
    EXPECT_GT(weights[0], 0.0);  // desk: tempered, scored
    EXPECT_EQ(weights[1], 0.0);  // cabinet: not scored, not in the fit window
    EXPECT_EQ(fit.judgeAt(*map, mrpt::poses::CPose2D(at(1.5)), mrpt::poses::CPose2D(at(1.5)), 1.5, 0.3, 0.1).size(), 1u);
    // Judged against an estimate found wrong: forgotten.
    n.clearUnmapped();
    EXPECT_EQ(n.unmappedCount(), 0u);
    EXPECT_GT(n.weigh(*observe(moved, at(1.8), {2}), mrpt::poses::CPose2D(at(1.8)), 1.8)[0], 0.0);
}

TEST(DetectionNovelty, ObjectsWhereTheMapHasThemStayScored) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    DetectionNoveltyParams p;
    p.unmapped_min_detections = 4;
    p.unmapped_min_span_s = 1.0;
    DetectionNoveltyParams p_off = p;
    p_off.unmapped_min_detections = 0;
    DetectionNovelty n(p), off(p_off);
    FitWindow fit, fit_off;
    const auto at = [](double t) { return mrpt::math::TPose2D(2.8, 2.5, -1.57 + 0.05 * t); };
    // Unchanged world, estimate 0.25 m and 0.08 rad off (within the judging tolerance): nothing flagged.
    const mrpt::poses::CPose2D off_by(0.25, -0.2, 0.08);
    for (int i = 0; i <= 10; ++i) {
        const double t = 0.3 * i;
        const auto ws = frame(n, fit, *map, w, at(t), mrpt::poses::CPose2D(at(t)) + off_by, t);
        for (double x : ws) EXPECT_GT(x, 0.0) << "t " << t;
    }
    EXPECT_EQ(n.unmappedCount(), 0u);
    // With the test off a moved object is never flagged.
    auto moved = w;
    moved.objects.objects[2].box.center.y() += 1.5;
    for (int i = 0; i <= 10; ++i) frame(off, fit_off, *map, moved, at(0.3 * i), mrpt::poses::CPose2D(at(0.3 * i)), 0.3 * i);
    EXPECT_EQ(off.unmappedCount(), 0u);
}

TEST(FitWindow, JudgesTheLastFrameAtTheEstimateOrWithinTheTolerance) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    FitWindow fit;
    const mrpt::math::TPose2D robot(2.8, 2.5, -1.57);
    const mrpt::poses::CPose2D odo(robot);
    fit.add(*map, observe(w, robot, {0, 2}), odo, 0.0);
    fit.add(*map, observe(w, robot, {0}), odo, 0.5);
    const std::vector<double> skip_all = {0.0};
    fit.add(*map, observe(w, robot, {2}), odo, 0.5, &skip_all);  // weight 0: not added
    EXPECT_EQ(fit.size(), 3u);
    // Only the frame of t = 0.5 (the desk), explained at the truth.
    const auto right = fit.judgeAt(*map, odo, odo, 0.5, 0.0, 0.0);
    ASSERT_EQ(right.size(), 1u);
    EXPECT_TRUE(right[0].explained);
    // An estimate 0.3 m off along x (the desk's centre noise: about 5 cm along it) explains it only
    // with a tolerance that reaches back to the truth.
    const mrpt::poses::CPose2D shifted(robot.x + 0.3, robot.y, robot.phi);
    EXPECT_FALSE(fit.judgeAt(*map, shifted, odo, 0.5, 0.0, 0.0)[0].explained);
    EXPECT_TRUE(fit.judgeAt(*map, shifted, odo, 0.5, 0.3, 0.0)[0].explained);
}
