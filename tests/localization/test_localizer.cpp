/// The online localizer and its parts: state transitions, detection-driven injection, pruning without teleported weight, and a kidnapped robot
/// end to end on the synthetic scenario.

#include "SyntheticScenario.h"
#include "TestUtil.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/DetectionPoseSampler.h>
#include <simp/localization/LocalizationState.h>
#include <simp/localization/Localizer.h>
#include <simp/localization/RawlogSequence.h>
#include <simp/obs/ObjectClasses.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

using namespace simp::localization;
using namespace simp::localization::test;


TEST(StateMonitor, GlobalToLocalizedToLostToLocalized) {
    StateParams p;
    StateMonitor m(p);
    EXPECT_EQ(m.state(), LocalizationState::Global);
    const FitWindow::Fit good{0.8, 10, 1.0, p.lost_window}, bad{0.0, 10, 0.0, p.lost_window}, unknown{1.0, 2, 1.0, 2};
    // Concentrated and explaining, but only after localized_min_updates such updates.
    for (std::size_t i = 1; i < p.localized_min_updates; ++i)
        EXPECT_EQ(m.update(0.95, 0.1, good, true), LocalizationState::Global);
    EXPECT_EQ(m.update(0.95, 0.1, good, true), LocalizationState::Localized);
    // Too few detections to judge: no change; the last detections unexplained: lost.
    EXPECT_EQ(m.update(0.95, 0.1, unknown, true), LocalizationState::Localized);
    EXPECT_EQ(m.update(0.95, 0.1, bad, true), LocalizationState::Lost);
    // A split set is lost too.
    m.reset(LocalizationState::Localized);
    EXPECT_EQ(m.update(p.lost_min_weight / 2, 0.1, good, true), LocalizationState::Lost);
    // Back: the same test as from global; a spread-out or unexplaining set does not qualify.
    for (int i = 0; i < 5; ++i) EXPECT_EQ(m.update(0.95, 1.0, good, true), LocalizationState::Lost);
    for (int i = 0; i < 5; ++i) EXPECT_EQ(m.update(0.95, 0.1, bad, true), LocalizationState::Lost);
    for (std::size_t i = 0; i < p.localized_min_updates; ++i) m.update(0.95, 0.1, good, true);
    EXPECT_EQ(m.state(), LocalizationState::Localized);
}

TEST(FitWindow, ExplainsDetectionsAtTheRightPoseOnly) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    FitWindow fit;
    const mrpt::math::TPose2D robot(3.0, 2.0, 0.4);
    // Two frames, the robot moved 0.5 m between them (odometry frame = world frame shifted).
    const mrpt::poses::CPose2D odo0(10, 10, 0), odo1 = odo0 + mrpt::poses::CPose2D(0.5, 0, 0);
    const mrpt::math::TPose2D robot1 = (mrpt::poses::CPose2D(robot) + mrpt::poses::CPose2D(0.5, 0, 0)).asTPose();
    fit.add(*map, observe(w, robot, {0, 1, 2}), odo0, 0.0);
    fit.add(*map, observe(w, robot1, {3, 4}), odo1, 1.0);
    const auto right = fit.evaluate(*map, mrpt::poses::CPose2D(robot1), odo1, 1.0);
    EXPECT_EQ(right.scored, 5u);
    EXPECT_DOUBLE_EQ(right.fraction, 1.0);
    const auto wrong = fit.evaluate(*map, mrpt::poses::CPose2D(robot1) + mrpt::poses::CPose2D(3.0, 2.0, 1.0), odo1, 1.0);
    EXPECT_LT(wrong.fraction, 0.5);
}

TEST(FitWindow, TheLostTestCountsDetectionsExplainedWithinItsTolerance) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    StateParams p;
    p.lost_window = 4;
    const mrpt::math::TPose2D robot(3.0, 2.0, 0.4);
    const mrpt::poses::CPose2D odo(robot);
    const auto fitAt = [&](double tolerance_m, const mrpt::poses::CPose2D& estimate) {
        StateParams q = p;
        q.lost_tolerance_m = tolerance_m;
        q.lost_tolerance_rad = tolerance_m > 0 ? 0.1 : 0.0;
        FitWindow fit(q);
        fit.add(*map, observe(w, robot, {0, 1, 2, 3}), odo, 0.0);
        return fit.evaluate(*map, estimate, odo, 0.0);
    };
    // 0.3 m off: at the estimate alone most of the exact detections are unexplained (class noise
    // 0.15 m); within a tolerance that reaches back to the truth, all of them.
    const mrpt::poses::CPose2D off(robot.x + 0.3, robot.y, robot.phi);  // the grid is along x and y
    const auto strict = fitAt(0.0, off), tolerant = fitAt(0.3, off);
    ASSERT_EQ(strict.recent_scored, 4u);
    EXPECT_LT(strict.recent_fraction, 0.5);
    EXPECT_DOUBLE_EQ(tolerant.recent_fraction, 1.0);
    EXPECT_DOUBLE_EQ(tolerant.fraction, strict.fraction);  // only the lost test is tolerant
    // Far off (a kidnap): no pose within the tolerance explains them either.
    EXPECT_DOUBLE_EQ(fitAt(0.3, odo + mrpt::poses::CPose2D(3.0, 2.0, 1.0)).recent_fraction, 0.0);
}

TEST(FitWindow, CountsTheDistinctObjectsItExplains) {
    // Desk, chair and cabinet, then the chair, the cabinet and the board again from 0.5 m further:
    // six detections of four objects (exact boxes: the two views of one object coincide in the
    // odometry frame).
    const auto w = makeWorld();
    const auto map = makeMap(w);
    FitWindow fit;
    const mrpt::math::TPose2D robot(3.0, 2.0, 0.4);
    const mrpt::poses::CPose2D odo0(10, 10, 0), odo1 = odo0 + mrpt::poses::CPose2D(0.5, 0, 0);
    const mrpt::poses::CPose2D robot1 = mrpt::poses::CPose2D(robot) + mrpt::poses::CPose2D(0.5, 0, 0);
    fit.add(*map, observe(w, robot, {0, 1, 2}), odo0, 0.0);
    fit.add(*map, observe(w, robot1.asTPose(), {1, 2, 3}), odo1, 1.0);
    EXPECT_EQ(fit.evaluate(*map, robot1, odo1, 1.0).scored, 6u);
    EXPECT_EQ(fit.explainedObjects(*map, robot1, odo1, 0.75), 4u);
    // Elsewhere (3.6 m and 1 rad away) no detection lands on an object of its class.
    EXPECT_EQ(fit.explainedObjects(*map, robot1 + mrpt::poses::CPose2D(3.0, 2.0, 1.0), odo1, 0.75), 0u);
}

TEST(DetectionPoseSampler, DrawsPosesThatPutTheDetectionOnAnObjectOfItsClass) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    const FreeSpace free_space(w.floorplan, 0.7);
    DetectionPoseSamplerParams p;
    p.position_std_m = 0.0;
    p.heading_std_rad = 0.0;
    const DetectionPoseSampler sampler(*map, free_space, p);
    const mrpt::math::TPose2D robot(3.0, 2.0, 0.4);
    auto& rng = mrpt::random::getRandomGenerator();
    rng.randomize(5);
    const auto poses = sampler.sample({{observe(w, robot, {0}), {}}}, 200, rng);
    ASSERT_GT(poses.size(), 20u);
    // Every pose explains the detection (its centre on an object of the class), and the true pose is
    // among them (the object's own box, exact detection).
    const auto obs = observe(w, robot, {0});
    std::size_t near_truth = 0;
    for (const auto& x : poses) {
        EXPECT_TRUE(free_space.isFree(x.x, x.y));
        const auto log_p = map->detectionLogLikelihood(*obs, 0, x);
        ASSERT_TRUE(log_p.has_value());
        EXPECT_GT(*log_p, std::log(2 * map->likelihoodOptions.eta)) << x.x << " " << x.y << " " << x.phi;
        near_truth += std::hypot(x.x - robot.x, x.y - robot.y) < 0.2 &&
                      std::abs(mrpt::math::wrapToPi(x.phi - robot.phi)) < 0.1;
    }
    EXPECT_GT(near_truth, 0u);
}

TEST(ObjectMcl, PruningNeverTeleportsWeight) {
    // A tracked set (all weight near one pose) whose odometry pushes part of it into a wall: the
    // pruned particles are redrawn with the smallest weight, so the weight stays where it was.
    const auto w = makeWorld();
    const auto map = makeMap(w);
    auto free_space = std::make_shared<FreeSpace>(w.floorplan, 0.7);
    ObjectMcl mcl(map);
    mcl.setFreeSpace(free_space);
    mcl.params.prune_keeps_weight = false;
    mrpt::random::getRandomGenerator().randomize(3);
    mcl.resetAround({0.3, 4.5, M_PI}, 0.2, 0.05, 1000);  // next to the left outer wall (x = 0)
    mrpt::bayes::CParticleFilter::TParticleFilterOptions pf;
    mrpt::obs::CActionRobotMovement2D mv;
    auto mm = mrpt::obs::CActionRobotMovement2D::TMotionModelOptions();
    mm.gaussianModel = {0.0, 0.0, 0.0, 0.0, 0.001, 0.001};
    mv.computeFromOdometry(mrpt::poses::CPose2D(0.25, 0, 0), mm);  // towards the wall
    mrpt::obs::CActionCollection acts;
    acts.insert(mv);
    mcl.predict(&acts, pf);
    ASSERT_GT(mcl.lastPrunedCount(), 100u);
    double in_cluster = 0, total = 0;
    for (const auto& p : mcl.m_particles) {
        const double wgt = std::exp(p.log_w);
        total += wgt;
        if (std::hypot(p.d.x - 0.05, p.d.y - 4.5) < 1.0) in_cluster += wgt;
    }
    EXPECT_GT(in_cluster / total, 0.999);
}

namespace {

/// The synthetic scenario's kidnap: its frames up to t = 20 s (before `cut`), then, without an
/// odometry jump, those from t = 30 s (`resume`) on: the robot was carried about the distance it
/// drives in 10 s.
struct KidnapCut {
    std::size_t cut = 0, resume = 0;
};

KidnapCut kidnapCut(const RawlogSequence& seq) {
    const double t0 = seq.frames.front().t_s;
    KidnapCut k;
    while (seq.frames[k.cut].t_s - t0 < 20.0) ++k.cut;
    k.resume = k.cut;
    while (seq.frames[k.resume].t_s - t0 < 30.0) ++k.resume;
    return k;
}

/// The kidnap tests' localizer on the scenario: 2000 particles, pruned particles dropped, seed 7, searching.
std::unique_ptr<Localizer> kidnapLocalizer(const Scenario& sc, LocalizerOptions opts) {
    opts.experiment.particles_count = 2000;
    opts.experiment.filter.prune_keeps_weight = false;
    mrpt::random::getRandomGenerator() = mrpt::random::CRandomGenerator(7);
    auto loc = std::make_unique<Localizer>(makeMap(sc.world), sc.world.floorplan, opts);
    loc->startGlobal();
    return loc;
}

}  // namespace

TEST(Localizer, KidnappedRobotIsLostThenLocalizedAgain) {
    const Scenario& sc = sharedScenario();
    const RawlogSequence seq = loadRawlogSequence(sc.rawlog_path);
    const auto [cut, resume] = kidnapCut(seq);
    auto owned = kidnapLocalizer(sc, LocalizerOptions{});
    Localizer& loc = *owned;
    const double jump = translationError(sc.groundtruth[cut].pose, sc.groundtruth[resume].pose);
    ASSERT_GT(jump, 1.0);
    StepRecord rec;
    for (std::size_t f = 0; f < cut; ++f) rec = loc.step(seq.frames[f].t_s, seq.frames[f].odometry_increment, *seq.frames[f].observations);
    ASSERT_EQ(rec.state, LocalizationState::Localized);
    ASSERT_LT(translationError(rec.estimate, sc.groundtruth[cut - 1].pose), 0.3);
    double lost_after = -1, localized_after = -1;
    for (std::size_t f = resume; f < seq.frames.size(); ++f) {
        const double t = seq.frames[f].t_s - seq.frames[resume].t_s;
        rec = loc.step(seq.frames[f].t_s, f == resume ? mrpt::poses::CPose2D() : seq.frames[f].odometry_increment,
                       *seq.frames[f].observations);
        if (lost_after < 0 && rec.state != LocalizationState::Localized) lost_after = t;
        if (lost_after >= 0 && localized_after < 0 && rec.state == LocalizationState::Localized) {
            localized_after = t;
            EXPECT_LT(translationError(rec.estimate, sc.groundtruth[f].pose), 0.3);
            EXPECT_LT(headingError(rec.estimate, sc.groundtruth[f].pose), M_PI / 4);
        }
    }
    EXPECT_GE(lost_after, 0.0) << "never lost";
    EXPECT_LE(lost_after, 5.0);
    EXPECT_GE(localized_after, 0.0) << "never localized again";
    EXPECT_LE(localized_after, 20.0);
}

namespace {

/// The kidnap of KidnappedRobotIsLostThenLocalizedAgain with `lost_detection_power`: over the
/// `lost` updates whose detections the filter's own set weighed with nothing injected or resampled,
/// the largest count of particles whose log-weight changed otherwise than the common normalization
/// shift (the median change), minus the particles pruned at that update (a pruned particle gets
/// the smallest weight whatever the detections say). <= 0: the detections changed no weight.
long largestWeightChangeWhileLost(double lost_detection_power, std::size_t& lost_updates) {
    const Scenario& sc = sharedScenario();
    const RawlogSequence seq = loadRawlogSequence(sc.rawlog_path);
    const auto [cut, resume] = kidnapCut(seq);
    LocalizerOptions opts;
    opts.experiment.lost_detection_power = lost_detection_power;
    auto owned = kidnapLocalizer(sc, opts);
    Localizer& loc = *owned;
    for (std::size_t f = 0; f < cut; ++f) loc.step(seq.frames[f].t_s, seq.frames[f].odometry_increment, *seq.frames[f].observations);
    EXPECT_EQ(loc.state(), LocalizationState::Localized);
    long largest = std::numeric_limits<long>::min();
    lost_updates = 0;
    for (std::size_t f = resume; f < seq.frames.size(); ++f) {
        const auto before = loc.state();
        const auto particles_before = loc.filter().m_particles;
        const std::size_t won = loc.challengersWon();
        const auto rec = loc.step(seq.frames[f].t_s, f == resume ? mrpt::poses::CPose2D() : seq.frames[f].odometry_increment,
                                  *seq.frames[f].observations);
        const auto& after = loc.filter().m_particles;
        // Weighed in `lost` (the state before the step's update), nothing injected, not resampled
        // (the weights carry over only when the effective sample size stayed above MRPT's BETA), the
        // same set.
        if (!rec.updated || before != LocalizationState::Lost || rec.detections == 0 || rec.injected > 0 ||
            loc.challengersWon() != won ||  // the challenger's set replaced the own one
            after.size() != particles_before.size() || !(rec.ess > loc.options().pf.BETA * static_cast<double>(rec.particles)))
            continue;
        std::vector<double> change(after.size());
        for (std::size_t i = 0; i < after.size(); ++i) change[i] = after[i].log_w - particles_before[i].log_w;
        auto sorted = change;
        std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
        const double shift = sorted[sorted.size() / 2];
        long changed = 0;
        for (const double c : change) changed += std::abs(c - shift) > 1e-9;
        ++lost_updates;
        largest = std::max(largest, changed - static_cast<long>(rec.pruned));
    }
    return largest;
}

}  // namespace

TEST(Localizer, WhileLostTheOwnSetWeighsDetectionsWithTheLostPower) {
    // Kidnapped, the set explains little of what it sees (most particles score every detection at
    // the floor eta: the same change), yet fully weighed the detections change the weights of some
    // particles beyond the pruned ones; at power 0 only the pruned particles' weights change.
    std::size_t updates_full = 0, updates_none = 0;
    const long full = largestWeightChangeWhileLost(1.0, updates_full);
    const long none = largestWeightChangeWhileLost(0.0, updates_none);
    ASSERT_GT(updates_full, 3u);
    ASSERT_GT(updates_none, 3u);
    EXPECT_GT(full, 0);
    EXPECT_LE(none, 0);
}

TEST(FitWindow, CountsObjectsOnceWithAnObjectRadius) {
    const auto w = makeWorld();
    const auto map = makeMap(w);
    const mrpt::math::TPose2D robot(3.0, 2.0, 0.4);
    const mrpt::poses::CPose2D odo(10, 10, 0);
    StateParams per_detection;
    StateParams per_object;
    per_object.object_radius_m = 1.0;
    FitWindow a(per_detection), b(per_object);
    // Object 0 seen in four frames from the same place, object 1 once.
    for (int k = 0; k < 4; ++k) {
        a.add(*map, observe(w, robot, {0}), odo, 0.1 * k);
        b.add(*map, observe(w, robot, {0}), odo, 0.1 * k);
    }
    a.add(*map, observe(w, robot, {1}), odo, 0.5);
    b.add(*map, observe(w, robot, {1}), odo, 0.5);
    const auto fa = a.evaluate(*map, mrpt::poses::CPose2D(robot), odo, 0.5);
    const auto fb = b.evaluate(*map, mrpt::poses::CPose2D(robot), odo, 0.5);
    EXPECT_EQ(fa.scored, 5u);
    EXPECT_EQ(fb.scored, 2u);
    EXPECT_DOUBLE_EQ(fb.fraction, 1.0);
    // Elsewhere: both objects unexplained, each counted once in the lost test's recent window.
    const auto wrong = b.evaluate(*map, mrpt::poses::CPose2D(robot) + mrpt::poses::CPose2D(3.0, 2.0, 1.0), odo, 0.5);
    EXPECT_EQ(wrong.recent_scored, 2u);
    EXPECT_DOUBLE_EQ(wrong.recent_fraction, 0.0);
}

TEST(FitWindow, KeepsOnlyDetectionsTheSensorModelCanScore) {
    // A class without noise model (chair: object 1) is skipped by the simp model; its detections
    // must not take the window's slots (they did: twelve of them pushed every scorable one out).
    auto w = makeWorld();
    const int chair = w.objects.classId("chair");
    ASSERT_GE(chair, 0);
    w.objects.class_noise[static_cast<std::size_t>(chair)].reset();
    auto map = std::make_shared<simp::maps::CObjectMap>();
    map->likelihoodOptions.skip_classes_without_noise = true;
    map->setData(w.objects);
    ASSERT_EQ(map->likelihoodOptions.unmodelled_noise_std_m, 0.0);  // the plugin's default: the paper's
    const mrpt::math::TPose2D robot(3.0, 2.0, 0.4);
    const mrpt::poses::CPose2D odo(10, 10, 0);
    StateParams p;
    p.fit_window = 12;
    FitWindow fit(p);
    fit.add(*map, observe(w, robot, {0, 2, 3, 4, 5}), odo, 0.0);
    for (int k = 0; k < 12; ++k) fit.add(*map, observe(w, robot, {1}), odo, 0.1 + 0.01 * k);
    EXPECT_EQ(fit.size(), 5u);
    EXPECT_EQ(fit.evaluate(*map, mrpt::poses::CPose2D(robot), odo, 0.3).scored, 5u);
    EXPECT_EQ(map->usableClassOf(*observe(w, robot, {1}), 0), -1);

    // Scored with an isotropic model instead: the chair counts, and the window fills with it.
    map->likelihoodOptions.unmodelled_noise_std_m = 0.3;
    EXPECT_EQ(map->usableClassOf(*observe(w, robot, {1}), 0), chair);
    FitWindow with_chairs(p);
    with_chairs.add(*map, observe(w, robot, {0, 2, 3, 4, 5}), odo, 0.0);
    for (int k = 0; k < 12; ++k) with_chairs.add(*map, observe(w, robot, {1}), odo, 0.1 + 0.01 * k);
    const auto f = with_chairs.evaluate(*map, mrpt::poses::CPose2D(robot), odo, 0.3);
    EXPECT_EQ(f.scored, 12u);
    EXPECT_DOUBLE_EQ(f.fraction, 1.0);  // exact boxes at the true pose: every chair detection explained
}

namespace {
/// Per-axis position std and heading std of the weighted particle set.
std::pair<double, double> spreadOf(const ObjectMcl& mcl) {
    double sw = 0, mx = 0, my = 0, ms = 0, mc = 0;
    for (std::size_t i = 0; i < mcl.m_particles.size(); ++i) {
        const double w = std::exp(mcl.m_particles[i].log_w);
        const auto& d = mcl.m_particles[i].d;
        sw += w, mx += w * d.x, my += w * d.y, ms += w * std::sin(d.phi), mc += w * std::cos(d.phi);
    }
    mx /= sw, my /= sw;
    const double mphi = std::atan2(ms, mc);
    double vxy = 0, vphi = 0;
    for (std::size_t i = 0; i < mcl.m_particles.size(); ++i) {
        const double w = std::exp(mcl.m_particles[i].log_w) / sw;
        const auto& d = mcl.m_particles[i].d;
        vxy += w * 0.5 * ((d.x - mx) * (d.x - mx) + (d.y - my) * (d.y - my));
        const double dphi = mrpt::math::wrapToPi(d.phi - mphi);
        vphi += w * dphi * dphi;
    }
    return {std::sqrt(vxy), std::sqrt(vphi)};
}
}  // namespace

TEST(Localizer, SpreadFloorWidensACollapsedSetThatThenFindsTheTruth) {
    // A set collapsed (5 mm, 0.1 deg) onto a pose 0.4 m and 0.1 rad off the truth: the situation of
    // a search that ended on the few particles of a biased place.
    const Scenario& sc = sharedScenario();
    const RawlogSequence seq = loadRawlogSequence(sc.rawlog_path);
    const auto map = makeMap(sc.world);
    struct Result {
        std::pair<double, double> first_spread;  ///< after the first update
        double within_at_s = -1;                 ///< first time the estimate is within 0.2 m
        double final_error_m = 0;
    };
    const auto run = [&](double floor_xy, double floor_phi) {
        LocalizerOptions opts;
        opts.experiment.particles_count = 2000;
        opts.experiment.min_spread_xy_m = floor_xy;
        opts.experiment.min_spread_phi_rad = floor_phi;
        mrpt::random::getRandomGenerator() = mrpt::random::CRandomGenerator(3);
        Localizer loc(map, sc.world.floorplan, opts);
        const auto start = (mrpt::poses::CPose2D(sc.groundtruth.front().pose) + mrpt::poses::CPose2D(0.4, 0.0, 0.1)).asTPose();
        loc.startAt(start, 0.005, 0.002);
        const double t0 = seq.frames.front().t_s;
        Result r;
        for (std::size_t f = 0; f < seq.frames.size() && seq.frames[f].t_s - t0 < 15.0; ++f) {
            const auto rec = loc.step(seq.frames[f].t_s, seq.frames[f].odometry_increment, *seq.frames[f].observations);
            if (f == 0) r.first_spread = spreadOf(loc.filter());
            r.final_error_m = translationError(rec.estimate, sc.groundtruth[f].pose);
            if (r.within_at_s < 0 && r.final_error_m < 0.2) r.within_at_s = seq.frames[f].t_s - t0;
        }
        return r;
    };
    // The first update (the first frame always updates) brings the set up to the floor (the
    // measured std is a sample of 2000: within a few per cent); without it the set stays as tight.
    const Result on = run(0.10, 0.05), off = run(0.0, 0.0);
    EXPECT_NEAR(on.first_spread.first, 0.10, 0.01);
    EXPECT_NEAR(on.first_spread.second, 0.05, 0.005);
    EXPECT_LT(off.first_spread.first, 0.02);
    // The widened set follows the detections onto the truth and stays there. (Without the floor the
    // motion noise widens the set too, about 1 cm per update; on this short synthetic run it gets
    // there 0.4 s later, too close to assert; the battery measures the difference.)
    ASSERT_GE(on.within_at_s, 0.0) << "never within 0.2 m";
    EXPECT_LT(on.final_error_m, 0.2);
    std::printf("within 0.2 m after %.1f s with the floor, %.1f s without\n", on.within_at_s, off.within_at_s);
}

TEST(Localizer, LocalResettingMovesASetStuckBesideTheTruth) {
    // A tight set (no spread floor) 0.35 m and 0.08 rad off the truth: the neighbouring mode the
    // battery's biased runs sat on, too far for the motion noise to carry it over soon. The fit
    // window prefers a pose near the truth; local resetting draws particles there and the set moves.
    // A filter's run hangs on its random draws: compared over eight seeds, by the median time.
    const Scenario& sc = sharedScenario();
    const RawlogSequence seq = loadRawlogSequence(sc.rawlog_path);
    const auto map = makeMap(sc.world);
    const auto run = [&](double local_margin, double local_fraction, unsigned seed, std::size_t& injected) {
        LocalizerOptions opts;
        opts.experiment.particles_count = 2000;
        opts.state.local_margin = local_margin;
        opts.resetting.local_fraction = local_fraction;
        opts.experiment.min_spread_xy_m = 0;
        opts.experiment.min_spread_phi_rad = 0;
        mrpt::random::getRandomGenerator() = mrpt::random::CRandomGenerator(seed);
        Localizer loc(map, sc.world.floorplan, opts);
        const auto start = (mrpt::poses::CPose2D(sc.groundtruth.front().pose) + mrpt::poses::CPose2D(0.0, 0.35, 0.08)).asTPose();
        loc.startAt(start, 0.03, 0.01);
        const double t0 = seq.frames.front().t_s;
        double within_at_s = -1;
        for (std::size_t f = 0; f < seq.frames.size() && seq.frames[f].t_s - t0 < 20.0; ++f) {
            const auto rec = loc.step(seq.frames[f].t_s, seq.frames[f].odometry_increment, *seq.frames[f].observations);
            injected += rec.injected;
            if (within_at_s < 0 && translationError(rec.estimate, sc.groundtruth[f].pose) < 0.2) within_at_s = seq.frames[f].t_s - t0;
        }
        return within_at_s < 0 ? 1e9 : within_at_s;
    };
    std::size_t injected_on = 0, injected_off = 0;
    std::vector<double> on, off;
    for (unsigned seed = 1; seed <= 8; ++seed) {
        on.push_back(run(7.0, 0.1, seed, injected_on));
        off.push_back(run(0.0, 0.0, seed, injected_off));
    }
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    };
    std::printf("within 0.2 m after a median %.1f s with local resetting (%zu particles drawn), %.1f s without\n",
                median(on), injected_on, median(off));
    EXPECT_GT(injected_on, 0u);
    EXPECT_EQ(injected_off, 0u);
    for (const double t : on) ASSERT_LT(t, 1e9) << "never within 0.2 m";
    EXPECT_LT(median(on), median(off));
}

TEST(Localizer, AfterLocalizingABetterPoseNearbyEndsLocalizedButDrawsNothing) {
    // Local draws move a set that settled beside the truth during the search. Once the filter has
    // localized by its own test, a better pose nearby was mostly changed furniture pulling a right
    // set, so it only ends `localized`. A low local_margin makes the climb end it often; every other
    // source of injected particles is off, so `injected` counts the local draws alone. Started at
    // the truth, the filter is `localized` by assumption: it still draws until its own test says so.
    const Scenario& sc = sharedScenario();
    const RawlogSequence seq = loadRawlogSequence(sc.rawlog_path);
    LocalizerOptions opts;
    opts.experiment.particles_count = 2000;
    opts.state.local_margin = 3.0;  // the shipped local_entry_margin: staying as strict as entering
    opts.resetting.global_fraction = 0;
    opts.resetting.lost_fraction = 0;
    opts.resetting.localized_fraction = 0;
    opts.search.enabled = false;
    opts.challenger.enabled = false;
    mrpt::random::getRandomGenerator() = mrpt::random::CRandomGenerator(3);
    Localizer loc(makeMap(sc.world), sc.world.floorplan, opts);
    loc.startAt(sc.groundtruth.front().pose, 0.1, 0.05);  // localized by assumption, not by its test
    bool entered = false;
    std::size_t drawn_before = 0, drawn_after = 0, ends_after = 0;
    LocalizationState previous = loc.state();
    for (const auto& f : seq.frames) {
        const auto rec = loc.step(f.t_s, f.odometry_increment, *f.observations);
        (entered ? drawn_after : drawn_before) += rec.injected;
        if (entered && previous == LocalizationState::Localized && rec.state == LocalizationState::Global &&
            rec.local_gain >= opts.state.local_margin)
            ++ends_after;
        if (rec.state == LocalizationState::Localized && previous != LocalizationState::Localized) entered = true;
        previous = rec.state;
    }
    std::printf("drawn before localized %zu, after %zu; localized ended by a better pose nearby %zu times\n",
                drawn_before, drawn_after, ends_after);
    ASSERT_TRUE(entered) << "never localized";
    ASSERT_GT(ends_after, 0u) << "the climb never ended localized: the test checks nothing";
    EXPECT_GT(drawn_before, 0u);  // before, the draws still move the set
    EXPECT_EQ(drawn_after, 0u);
}
