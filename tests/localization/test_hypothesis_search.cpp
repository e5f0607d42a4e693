/// HypothesisSearch: candidate places from the current detections, scored on the fit window, and
/// the rival test of the state built on it.

#include "SyntheticScenario.h"
#include "TestUtil.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <simp/localization/HypothesisSearch.h>

#include <cmath>
#include <limits>

using namespace simp::localization;
using namespace simp::localization::test;

namespace {

HypothesisSearchParams on() {
    HypothesisSearchParams p;
    p.enabled = true;
    return p;
}

/// The synthetic world, its object map and the candidate sampler every search test starts from.
struct SearchWorld {
    const simp::world::World w = makeWorld();
    const std::shared_ptr<simp::maps::CObjectMap> map = makeMap(w);
    const FreeSpace free_space{w.floorplan, 0.7};
    const DetectionPoseSampler sampler{*map, free_space};
};

/// The robot's frames: at `robot`, then after driving 0.6 m and turning, each seeing some objects.
struct Walk {
    FitWindow window;
    std::vector<WeightedObservation> last;
    mrpt::poses::CPose2D odometry_now;
    mrpt::math::TPose2D robot_now;
};

Walk walk(const simp::world::World& w, const simp::maps::CObjectMap& map, const mrpt::math::TPose2D& robot,
          const std::vector<std::vector<int>>& seen) {
    Walk out;
    mrpt::poses::CPose2D odo(5, -3, 0.2), pose(robot);  // the odometry frame is not the world's
    const mrpt::poses::CPose2D step(0.6, 0.0, 0.3);
    for (std::size_t f = 0; f < seen.size(); ++f) {
        if (f > 0) odo = odo + step, pose = pose + step;
        auto obs = observe(w, pose.asTPose(), seen[f]);
        out.window.add(map, obs, odo, static_cast<double>(f));
        out.last = {{obs, {}}};
    }
    out.odometry_now = odo;
    out.robot_now = pose.asTPose();
    return out;
}

}  // namespace

TEST(DetectionPoseSampler, CandidatesIncludeTheTruePoseAndExplainTheDetection) {
    const SearchWorld sw;
    const auto& [w, map, free_space, sampler] = sw;
    const mrpt::math::TPose2D robot(3.0, 2.0, 0.4);
    const auto obs = observe(w, robot, {0});
    const auto cands = sampler.candidates({{obs, {}}}, 10000);
    ASSERT_FALSE(cands.empty());
    bool truth = false;
    for (const auto& c : cands) {
        EXPECT_TRUE(free_space.isFree(c.x, c.y));
        truth |= translationError(c, robot) < 0.05 && headingError(c, robot) < 0.01;
    }
    EXPECT_TRUE(truth);
    EXPECT_EQ(sampler.candidates({{obs, {}}}, 1).size(), 1u);  // capped
}

TEST(HypothesisSearch, FindsTheTruePlaceFromTheWindow) {
    const SearchWorld sw;
    const auto& [w, map, free_space, sampler] = sw;
    const HypothesisSearch search(*map, sampler, on());
    const auto wk = walk(w, *map, {3.0, 2.0, 0.4}, {{0, 1}, {2}, {3, 4}, {0}});
    ASSERT_GE(wk.window.size(), 5u);
    const auto hyps = search.search(wk.window, wk.last, wk.odometry_now);
    ASSERT_FALSE(hyps.empty());
    // The best place is the truth (exact detections: within the refinement's last grid step).
    EXPECT_LT(translationError(hyps.front().pose, wk.robot_now), 0.15);
    EXPECT_LT(headingError(hyps.front().pose, wk.robot_now), 0.1);
    for (std::size_t i = 1; i < hyps.size(); ++i) {
        EXPECT_LE(hyps[i].log_likelihood, hyps[i - 1].log_likelihood);  // best first
        EXPECT_TRUE(search.distinct(hyps[i].pose, hyps.front().pose));
    }
    // The rival test: at the truth no distinct place explains the window as well; at a wrong place
    // the truth is a rival that explains it clearly better.
    const double at_truth = search.rivalAdvantage(wk.window, hyps, wk.robot_now, wk.odometry_now);
    if (!std::isnan(at_truth)) {
        EXPECT_LT(at_truth, -StateParams{}.rival_margin);
    }
    mrpt::math::TPose2D wrong = wk.robot_now;
    wrong.x += 3.0;
    wrong.phi = mrpt::math::wrapToPi(wrong.phi + 1.0);
    EXPECT_GT(search.rivalAdvantage(wk.window, hyps, wrong, wk.odometry_now), StateParams{}.rival_lost_margin);
}

TEST(HypothesisSearch, ThePlaceIsPositionAndHeading) {
    // samePlace: within the distance and the turn (wrapped); the challenger's "near" (agree_distance_m
    // with the search's distinct_heading_rad) and the search's distinct places both use it.
    using mrpt::math::TPose2D;
    const TPose2D p(2.0, 1.0, 0.3);
    EXPECT_TRUE(samePlace(p, p, 1.0, 0.5));
    EXPECT_TRUE(samePlace(p, TPose2D(2.0, 2.0, 0.3), 1.0, 0.5));  // 1.0 m apart: the bound is inclusive
    EXPECT_FALSE(samePlace(p, TPose2D(2.0, 2.01, 0.3), 1.0, 0.5));
    EXPECT_TRUE(samePlace(p, TPose2D(2.0, 1.0, 0.7), 1.0, 0.5));
    // The same position turned by 122 deg (the challenger that replaced a right set in the authors'
    // office, twenty-first session) is another place.
    EXPECT_FALSE(samePlace(p, TPose2D(2.0, 1.0, 0.3 + 122.0 * M_PI / 180.0), 1.0, 0.5));
    EXPECT_TRUE(samePlace(TPose2D(0, 0, 3.1), TPose2D(0, 0, -3.1), 1.0, 0.5));  // 0.08 rad across +-pi
}

TEST(HypothesisSearch, NeedsAWindowAndCanBeTurnedOff) {
    const SearchWorld sw;
    const auto& [w, map, free_space, sampler] = sw;
    const auto small = walk(w, *map, {3.0, 2.0, 0.4}, {{0, 1}});
    EXPECT_TRUE(HypothesisSearch(*map, sampler, on()).search(small.window, small.last, small.odometry_now).empty());
    HypothesisSearchParams off = on();
    off.enabled = false;
    const auto wk = walk(w, *map, {3.0, 2.0, 0.4}, {{0, 1}, {2}, {3, 4}});
    EXPECT_TRUE(HypothesisSearch(*map, sampler, off).search(wk.window, wk.last, wk.odometry_now).empty());
}

TEST(StateMonitor, RivalPlacesBlockLocalizedAndMakeItLost) {
    StateParams p;
    StateMonitor m(p);
    FitWindow::Fit good{0.9, 10, 1.0, 4};
    FitWindow::Fit ambiguous = good;
    ambiguous.rival_advantage = -0.5 * p.rival_margin;  // a distinct place almost as good
    for (int i = 0; i < 10; ++i) EXPECT_EQ(m.update(0.95, 0.1, ambiguous, true), LocalizationState::Global);
    FitWindow::Fit clear = good;
    clear.rival_advantage = -2.0 * p.rival_margin;
    for (std::size_t i = 0; i < p.localized_min_updates; ++i) m.update(0.95, 0.1, clear, true);
    EXPECT_EQ(m.state(), LocalizationState::Localized);
    EXPECT_EQ(m.update(0.95, 0.1, good, true), LocalizationState::Localized);  // not searched: no change
    FitWindow::Fit beaten = good;
    beaten.rival_advantage = p.rival_lost_margin + 0.1;
    EXPECT_EQ(m.update(0.95, 0.1, beaten, true), LocalizationState::Lost);
}

TEST(HypothesisSearch, ClimbFromABiasedPoseReachesTheTruePlace) {
    const SearchWorld sw;
    const auto& [w, map, free_space, sampler] = sw;
    const HypothesisSearch search(*map, sampler, on());
    const auto wk = walk(w, *map, {3.0, 2.0, 0.4}, {{0, 1}, {2}, {3, 4}, {0}});
    // A set sitting 0.45 m and 0.12 rad beside the truth: a neighbouring mode, not a distinct place.
    mrpt::math::TPose2D biased = wk.robot_now;
    biased.x += 0.35;
    biased.y -= 0.28;
    biased.phi = mrpt::math::wrapToPi(biased.phi + 0.12);
    ASSERT_FALSE(search.distinct(biased, wk.robot_now));
    double own = 0;
    const Hypothesis best = search.climb(wk.window, biased, wk.odometry_now, own);
    // exact detections: the climb ends within its last grid step (0.05 m, 0.025 rad) of the truth
    EXPECT_LT(translationError(best.pose, wk.robot_now), 0.1);
    EXPECT_LT(headingError(best.pose, wk.robot_now), 0.05);
    EXPECT_GT(best.log_likelihood - own, 7.0);  // clearly better: the shipped [State] local_margin
    // At the truth there is nothing to gain.
    double own_truth = 0;
    const Hypothesis stay = search.climb(wk.window, wk.robot_now, wk.odometry_now, own_truth);
    EXPECT_LT(stay.log_likelihood - own_truth, 1.0);
    EXPECT_LT(translationError(stay.pose, wk.robot_now), 0.1);
}

TEST(StateMonitor, ABetterPoseNearbyBlocksLocalizedAndEndsIt) {
    StateParams p;
    p.local_margin = 7.0;
    p.local_entry_margin = 0;  // entering and staying by local_margin alone
    StateMonitor m(p);
    FitWindow::Fit good{0.9, 10, 1.0, 4};
    good.local_gain = 0.5 * p.local_margin;
    FitWindow::Fit biased = good;
    biased.local_gain = p.local_margin + 0.5;
    for (int i = 0; i < 10; ++i) EXPECT_EQ(m.update(0.95, 0.1, biased, true), LocalizationState::Global);
    for (std::size_t i = 0; i < p.localized_min_updates; ++i) m.update(0.95, 0.1, good, true);
    EXPECT_EQ(m.state(), LocalizationState::Localized);
    FitWindow::Fit unknown = good;
    unknown.local_gain = std::numeric_limits<double>::quiet_NaN();  // not computed: no change
    EXPECT_EQ(m.update(0.95, 0.1, unknown, true), LocalizationState::Localized);
    // back to searching, not lost: the set is beside the right place, not somewhere else
    EXPECT_EQ(m.update(0.95, 0.1, biased, true), LocalizationState::Global);
    // off: the same fit changes nothing
    StateParams off = p;
    off.local_margin = 0;
    StateMonitor m_off(off);
    for (std::size_t i = 0; i < off.localized_min_updates; ++i) m_off.update(0.95, 0.1, biased, true);
    EXPECT_EQ(m_off.state(), LocalizationState::Localized);
}

TEST(StateMonitor, EnteringLocalizedIsStricterThanStayingWithAnEntryMargin) {
    StateParams p;
    p.local_margin = 10.0;
    p.local_entry_margin = 3.0;
    FitWindow::Fit at_best{0.9, 10, 1.0, p.lost_window};
    at_best.local_gain = 0.5 * p.local_entry_margin;
    FitWindow::Fit beside = at_best;  // a better pose nearby, by more than the entry margin only
    beside.local_gain = 0.5 * (p.local_entry_margin + p.local_margin);
    StateMonitor m(p);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(m.update(0.95, 0.1, beside, true), LocalizationState::Global);
    for (std::size_t i = 0; i < p.localized_min_updates; ++i) m.update(0.95, 0.1, at_best, true);
    EXPECT_EQ(m.state(), LocalizationState::Localized);
    // once localized, the same gain does not end it (hysteresis: local_margin ends it)
    EXPECT_EQ(m.update(0.95, 0.1, beside, true), LocalizationState::Localized);
    // the way back from lost is guarded the same way
    FitWindow::Fit unexplained = at_best;
    unexplained.recent_fraction = 0.0;
    EXPECT_EQ(m.update(0.95, 0.1, unexplained, true), LocalizationState::Lost);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(m.update(0.95, 0.1, beside, true), LocalizationState::Lost);
    for (std::size_t i = 0; i < p.localized_min_updates; ++i) m.update(0.95, 0.1, at_best, true);
    EXPECT_EQ(m.state(), LocalizationState::Localized);
    // 0: entering uses local_margin only, so the same fits localize at once
    StateParams off = p;
    off.local_entry_margin = 0;
    StateMonitor m_off(off);
    for (std::size_t i = 0; i < off.localized_min_updates; ++i) m_off.update(0.95, 0.1, beside, true);
    EXPECT_EQ(m_off.state(), LocalizationState::Localized);
}

TEST(StateMonitor, AnEntryMinimumOffsetLetsABetterPoseCloseByThrough) {
    StateParams p;
    p.local_margin = 10.0;
    p.local_entry_margin = 3.0;
    p.local_entry_min_offset_m = 0.2;
    FitWindow::Fit close{0.9, 10, 1.0, p.lost_window};
    close.local_gain = 0.5 * (p.local_entry_margin + p.local_margin);  // blocks entry by its gain ...
    close.local_offset_m = 0.5 * p.local_entry_min_offset_m;          // ... but is the same place
    FitWindow::Fit apart = close;
    apart.local_offset_m = 2.0 * p.local_entry_min_offset_m;
    StateMonitor m(p);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(m.update(0.95, 0.1, apart, true), LocalizationState::Global);
    for (std::size_t i = 0; i + 1 < p.localized_min_updates; ++i)
        EXPECT_EQ(m.update(0.95, 0.1, close, true), LocalizationState::Global);
    EXPECT_EQ(m.update(0.95, 0.1, close, true), LocalizationState::Localized);
    // 0: any better pose blocks, however close
    StateParams off = p;
    off.local_entry_min_offset_m = 0;
    StateMonitor m_off(off);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(m_off.update(0.95, 0.1, close, true), LocalizationState::Global);
}

TEST(DetectionPoseSampler, PairFitsPlaceTheFrameFromTwoDetectionsWithoutTheirYaw) {
    const SearchWorld sw;
    const auto& [w, map, free_space, sampler] = sw;
    const auto wk = walk(w, *map, {3.0, 2.0, 0.4}, {{0, 1}, {2}, {3, 4}, {0}});
    const auto placed = wk.window.placed();
    ASSERT_EQ(placed.size(), wk.window.size());
    // Exact detections: one of the fits is the odometry frame's pose in the world, so the robot now
    // lands on the truth; the heading comes from the pair, so it holds even with the boxes' yaw
    // ignored (the sampler never reads it here).
    const auto fits = sampler.pairFits(placed, {}, 100000);
    ASSERT_FALSE(fits.empty());
    double best_m = 1e9, best_rad = 1e9;
    for (const auto& f : fits) {
        const auto now = (mrpt::poses::CPose2D(f) + wk.odometry_now).asTPose();
        if (translationError(now, wk.robot_now) < best_m) best_m = translationError(now, wk.robot_now), best_rad = headingError(now, wk.robot_now);
    }
    EXPECT_LT(best_m, 0.05);
    EXPECT_LT(best_rad, 0.01);
    EXPECT_EQ(sampler.pairFits(placed, {}, 3).size(), 3u);  // capped
    DetectionPoseSampler::PairFitParams far;
    far.min_separation_m = 100.0;  // no pair that far apart: nothing
    EXPECT_TRUE(sampler.pairFits(placed, far, 100000).empty());
}

TEST(HypothesisSearch, PairCandidatesFindThePlaceWithoutAUsableDetectionInTheFrame) {
    const SearchWorld sw;
    const auto& [w, map, free_space, sampler] = sw;
    const auto wk = walk(w, *map, {3.0, 2.0, 0.4}, {{0, 1}, {2}, {3, 4}, {0}});
    HypothesisSearchParams p = on();
    p.pair_candidates = 0;
    // Without the current frame's detections there are no single fits: only pairs can find it.
    EXPECT_TRUE(HypothesisSearch(*map, sampler, p).search(wk.window, {}, wk.odometry_now).empty());
    p.pair_candidates = 2000;
    const auto hyps = HypothesisSearch(*map, sampler, p).search(wk.window, {}, wk.odometry_now);
    ASSERT_FALSE(hyps.empty());
    EXPECT_LT(translationError(hyps.front().pose, wk.robot_now), 0.15);
    EXPECT_LT(headingError(hyps.front().pose, wk.robot_now), 0.1);
}
