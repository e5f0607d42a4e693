/// The challenger of Localizer ([Challenger]): a second particle set that searches while the state
/// is `lost`, replaces the current set only when it explains the detections since `lost` better,
/// and never takes over after a false `lost`. On the synthetic scenario, end to end.

#include "SyntheticScenario.h"
#include "TestUtil.h"

#include <gtest/gtest.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/Localizer.h>
#include <simp/localization/RawlogSequence.h>

#include <cmath>
#include <cstdio>
#include <optional>

using namespace simp::localization;
using namespace simp::localization::test;

namespace {

/// simp.ini's defaults, 2000 particles, and no particles reset from the detections while lost:
/// only the challenger can bring a kidnapped robot back.
LocalizerOptions challengerOnlyOptions(bool challenger) {
    LocalizerOptions opts;
    opts.experiment.particles_count = 2000;
    opts.resetting.lost_fraction = 0.0;
    opts.challenger.enabled = challenger;
    return opts;
}

std::size_t frameAt(const RawlogSequence& seq, double t_rel_s) {
    std::size_t f = 0;
    while (f + 1 < seq.frames.size() && seq.frames[f].t_s - seq.frames.front().t_s < t_rel_s) ++f;
    return f;
}

struct KidnapRun {
    double lost_after = -1, localized_after = -1;
    double worst_error_localized_m = 0;  ///< after the kidnap, over the `localized` steps
    std::size_t started = 0, won = 0;
};

/// Frames [0, cut), then frames [resume, end) with no odometry jump: the robot was carried.
KidnapRun runKidnap(const LocalizerOptions& opts, double cut_s, double resume_s) {
    const Scenario& sc = sharedScenario();
    const RawlogSequence seq = loadRawlogSequence(sc.rawlog_path);
    mrpt::random::getRandomGenerator() = mrpt::random::CRandomGenerator(7);
    Localizer loc(makeMap(sc.world), sc.world.floorplan, opts);
    loc.startGlobal();
    const std::size_t cut = frameAt(seq, cut_s), resume = frameAt(seq, resume_s);
    StepRecord rec;
    for (std::size_t f = 0; f < cut; ++f)
        rec = loc.step(seq.frames[f].t_s, seq.frames[f].odometry_increment, *seq.frames[f].observations);
    EXPECT_EQ(rec.state, LocalizationState::Localized);
    EXPECT_LT(translationError(rec.estimate, sc.groundtruth[cut - 1].pose), 0.3);
    KidnapRun run;
    for (std::size_t f = resume; f < seq.frames.size(); ++f) {
        const double t = seq.frames[f].t_s - seq.frames[resume].t_s;
        rec = loc.step(seq.frames[f].t_s, f == resume ? mrpt::poses::CPose2D() : seq.frames[f].odometry_increment,
                       *seq.frames[f].observations);
        if (run.lost_after < 0 && rec.state != LocalizationState::Localized) run.lost_after = t;
        if (run.lost_after >= 0 && run.localized_after < 0 && rec.state == LocalizationState::Localized)
            run.localized_after = t;
        if (run.localized_after >= 0 && rec.state == LocalizationState::Localized)
            run.worst_error_localized_m =
                std::max(run.worst_error_localized_m, translationError(rec.estimate, sc.groundtruth[f].pose));
    }
    run.started = loc.challengersStarted();
    run.won = loc.challengersWon();
    return run;
}

}  // namespace

TEST(Challenger, BringsAKidnappedRobotBackWhenNothingElseDoes) {
    // Carried from its place at 20 s to where it is at 30 s (ASSERT in the kidnap test of
    // test_localizer.cpp: more than 1 m away).
    const KidnapRun with = runKidnap(challengerOnlyOptions(true), 20.0, 30.0);
    EXPECT_GE(with.lost_after, 0.0) << "never lost";
    EXPECT_LE(with.lost_after, 5.0);
    ASSERT_GE(with.localized_after, 0.0) << "never localized again";
    EXPECT_LE(with.localized_after, 20.0);
    EXPECT_LT(with.worst_error_localized_m, 0.3);  // a `localized` that can be trusted
    EXPECT_GE(with.started, 1u);
    EXPECT_EQ(with.won, 1u);

    // The same run without it: the old set alone does not find the new place in that time.
    const KidnapRun without = runKidnap(challengerOnlyOptions(false), 20.0, 30.0);
    EXPECT_EQ(without.started, 0u);
    EXPECT_TRUE(without.localized_after < 0 || without.localized_after > with.localized_after ||
                without.worst_error_localized_m >= 0.3);
}

TEST(Challenger, AFalseLostNeverHandsTheTrackToIt) {
    // The robot sees nothing it expects for a while (frames of another place, without their odometry),
    // then its own frames again: the current set is right all along and must stay the filter.
    const Scenario& sc = sharedScenario();
    const RawlogSequence seq = loadRawlogSequence(sc.rawlog_path);
    mrpt::random::getRandomGenerator() = mrpt::random::CRandomGenerator(7);
    Localizer loc(makeMap(sc.world), sc.world.floorplan, challengerOnlyOptions(true));
    loc.startGlobal();
    const std::size_t cut = frameAt(seq, 20.0), back = frameAt(seq, 25.0);
    std::size_t elsewhere = 0;  // the frame farthest from where the robot stands
    for (std::size_t f = 0; f + 50 < seq.frames.size(); ++f)
        if (translationError(sc.groundtruth[f].pose, sc.groundtruth[cut].pose) >
            translationError(sc.groundtruth[elsewhere].pose, sc.groundtruth[cut].pose))
            elsewhere = f;
    StepRecord rec;
    for (std::size_t f = 0; f < cut; ++f)
        rec = loc.step(seq.frames[f].t_s, seq.frames[f].odometry_increment, *seq.frames[f].observations);
    ASSERT_EQ(rec.state, LocalizationState::Localized);
    // 5 s of another place's detections, the robot turning on the spot left and right (an update
    // at every frame, back where it was after an even number of frames).
    const double t_cut = seq.frames[cut].t_s;
    bool lost = false;
    for (std::size_t k = 0; k < 50; ++k) {
        const mrpt::poses::CPose2D turn(0, 0, (k % 2 == 0 ? 0.3 : -0.3));
        rec = loc.step(t_cut + 0.1 * static_cast<double>(k), turn, *seq.frames[elsewhere + k].observations);
        lost = lost || rec.state == LocalizationState::Lost;
    }
    ASSERT_TRUE(lost) << "the scene must have made the state lost for this test to say anything";
    ASSERT_GE(loc.challengersStarted(), 1u);
    // Its own frames again, from where it stands (cut), with their odometry, time shifted by 5 s.
    // The set is `localized` again soon, and every `localized` step is right. (Later `lost` steps in
    // this world's detection-poor stretches are false ones of the state test, not of the track: the
    // estimate stays right and no challenger may take over.)
    double localized_again_s = -1;
    for (std::size_t f = cut; f < back + 150 && f < seq.frames.size(); ++f) {
        rec = loc.step(seq.frames[f].t_s + 5.0, seq.frames[f].odometry_increment, *seq.frames[f].observations);
        if (rec.state == LocalizationState::Localized) {
            if (localized_again_s < 0) localized_again_s = seq.frames[f].t_s - seq.frames[cut].t_s;
            EXPECT_LT(translationError(rec.estimate, sc.groundtruth[f].pose), 0.3) << "at frame " << f;
        }
    }
    ASSERT_GE(localized_again_s, 0.0) << "never localized again on its own frames";
    EXPECT_LE(localized_again_s, 5.0);
    EXPECT_EQ(loc.challengersWon(), 0u);
    EXPECT_LT(translationError(rec.estimate, sc.groundtruth[std::min(back + 149, seq.frames.size() - 1)].pose), 0.3);
}

TEST(Challenger, SearchingThePlacesOfTheWindowFindsTheNewPlaceAndOnlyUnambiguously) {
    // reset_by_fit and hypothesis_search: the challenger's resetting draws about the places that
    // explain the detections since `lost` and fades once its estimate explains them; it becomes
    // `localized` only when no other place explains them about as well.
    LocalizerOptions opts = challengerOnlyOptions(true);
    opts.challenger.reset_by_fit = true;
    opts.challenger.hypothesis_search = true;
    const KidnapRun searched = runKidnap(opts, 20.0, 30.0);
    EXPECT_LE(searched.lost_after, 5.0);
    ASSERT_GE(searched.localized_after, 0.0) << "never localized again";
    EXPECT_LE(searched.localized_after, 20.0);
    EXPECT_LT(searched.worst_error_localized_m, 0.3);
    EXPECT_EQ(searched.won, 1u);
    // The same run with a challenger that searches from the current frame alone (the eleventh
    // session's): it finds the place later (measured 13.8 s against 3.8 s).
    LocalizerOptions frame_only = opts;
    frame_only.challenger.reset_by_fit = false;
    frame_only.challenger.hypothesis_search = false;
    const KidnapRun plain = runKidnap(frame_only, 20.0, 30.0);
    std::printf("kidnap: localized again after %.1f s with the search, %.1f s without\n", searched.localized_after,
                plain.localized_after);
    EXPECT_TRUE(plain.localized_after < 0 || plain.localized_after > searched.localized_after);
}

TEST(Challenger, TakesOverOnlyWithItsMarginAtTheSamePlaceToo) {
    ChallengerParams c;  // win_margin 3, replace_max_fit 0.1, min_objects 4, scan_veto_nats 1
    std::size_t asked = 0;
    const auto fit = [&](double f) { return [&asked, f] { ++asked; return f; }; };
    const auto objects = [&](std::size_t n) { return [&asked, n] { ++asked; return n; }; };
    const auto scans = [&](std::optional<double> s) { return [&asked, s] { ++asked; return s; }; };
    const auto views = [&](std::size_t expected, std::size_t seen) {
        return [&asked, expected, seen] { ++asked; return ViewWindow::Recall{expected, seen}; };
    };
    // The same place: the lead decides, and nothing else is scored.
    EXPECT_FALSE(challengerTakesOver(c, true, 0.0, fit(0.9), objects(0), scans(std::nullopt), views(0, 0)));
    EXPECT_FALSE(challengerTakesOver(c, true, 2.9, fit(0.9), objects(0), scans(std::nullopt), views(0, 0)));
    EXPECT_TRUE(challengerTakesOver(c, true, 3.0, fit(0.9), objects(0), scans(-50.0), views(0, 0)));
    EXPECT_EQ(asked, 0u);
    EXPECT_FALSE(challengerTakesOver(c, true, std::nan(""), fit(0.0), objects(9), scans(std::nullopt), views(0, 0)));
    // Elsewhere: the lead, then the current estimate's fit, the objects explained, the scans.
    EXPECT_FALSE(challengerTakesOver(c, false, 2.9, fit(0.0), objects(9), scans(std::nullopt), views(0, 0)));
    EXPECT_EQ(asked, 0u);
    EXPECT_TRUE(challengerTakesOver(c, false, 3.0, fit(0.1), objects(4), scans(std::nullopt), views(0, 0)));
    EXPECT_FALSE(challengerTakesOver(c, false, 30.0, fit(0.11), objects(9), scans(std::nullopt), views(0, 0)));
    EXPECT_FALSE(challengerTakesOver(c, false, 30.0, fit(0.0), objects(3), scans(std::nullopt), views(0, 0)));
    EXPECT_FALSE(challengerTakesOver(c, false, 30.0, fit(0.0), objects(9), scans(-1.01), views(0, 0)));
    EXPECT_TRUE(challengerTakesOver(c, false, 30.0, fit(0.0), objects(9), scans(-0.99), views(0, 0)));
    c.replace_max_fit = 1.0;
    c.min_objects = 0;
    c.min_view_recall = 0.0;
    asked = 0;
    EXPECT_TRUE(challengerTakesOver(c, false, 3.0, fit(1.0), objects(0), scans(std::nullopt), views(0, 0)));
    EXPECT_EQ(asked, 1u);  // only the scans: the other tests are off
}

TEST(Challenger, ElsewhereNeedsTheFramesSinceLostToHaveShownItsPlace) {
    ChallengerParams c;  // min_view_recall 0.1 once 30 views were expected
    std::size_t asked = 0;
    const auto fit = [] { return 0.0; };
    const auto objects = [] { return std::size_t{9}; };
    const auto scans = [] { return std::optional<double>{}; };
    const auto views = [&](std::size_t expected, std::size_t seen) {
        return [&asked, expected, seen] { ++asked; return ViewWindow::Recall{expected, seen}; };
    };
    // A place whose map objects in view the robot did not see: refused.
    EXPECT_FALSE(challengerTakesOver(c, false, 30.0, fit, objects, scans, views(68, 0)));
    EXPECT_FALSE(challengerTakesOver(c, false, 30.0, fit, objects, scans, views(40, 3)));
    // It showed a tenth of them, or too few were expected to judge: the place stands.
    EXPECT_TRUE(challengerTakesOver(c, false, 30.0, fit, objects, scans, views(40, 4)));
    EXPECT_TRUE(challengerTakesOver(c, false, 30.0, fit, objects, scans, views(29, 0)));
    EXPECT_EQ(asked, 4u);
    // The same place is never judged on it; 0 turns it off.
    EXPECT_TRUE(challengerTakesOver(c, true, 30.0, fit, objects, scans, views(68, 0)));
    c.min_view_recall = 0.0;
    EXPECT_TRUE(challengerTakesOver(c, false, 30.0, fit, objects, scans, views(68, 0)));
    EXPECT_EQ(asked, 4u);
}
