/// Eq. singw over all cameras of a frame, and the batch weighing of ObjectMcl against
/// MRPT's per-particle path.

#include "SyntheticScenario.h"
#include "TestUtil.h"

#include <gtest/gtest.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/FrameLikelihood.h>
#include <simp/localization/ObjectMcl.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/ObjectClasses.h>

#include <cmath>

using namespace simp::localization;
using namespace simp::localization::test;

namespace {

/// One frame of 3 cameras with 2 + 0 + 3 detections of map objects seen from `robot`.
mrpt::obs::CSensoryFrame makeFrame(const simp::world::World& w, const mrpt::math::TPose2D& robot) {
    mrpt::obs::CSensoryFrame sf;
    const std::vector<std::vector<int>> per_cam{{0, 1}, {}, {2, 6, 7}};
    for (std::size_t c = 0; c < per_cam.size(); ++c) {
        auto o = simp::obs::CObservationObjects3D::Create();
        const auto cam = simp::obs::cameraPoseOnRobot(0.1, 0, 0.5, static_cast<double>(c) * M_PI / 2);
        o->setCameraPose(cam);
        o->setClassNames(simp::obs::defaultClassNames());
        const mrpt::poses::CPose3D world_T_cam = mrpt::poses::CPose3D(mrpt::poses::CPose2D(robot)) + cam;
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.matrix() = world_T_cam.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
        for (int idx : per_cam[c]) {
            simp::obs::Detection3D d;
            d.class_id = static_cast<std::uint16_t>(w.objects.objects[idx].class_id);
            d.confidence = 0.95f;
            d.box_in_camera = w.objects.objects[idx].box.transformed(T.inverse());
            o->addDetection(d);
        }
        sf.insert(o);
    }
    return sf;
}

}  // namespace

TEST(FrameLikelihood, IsTheGeometricMeanOverAllDetectionsOfAllCameras) {
    const auto w = test::makeWorld();
    auto map = std::make_shared<simp::maps::CObjectMap>();
    map->likelihoodOptions.yaw_sigma_rad = 0.0;  // the paper's Eq. combined: each factor in [eta, 1]
    map->setData(w.objects);
    const mrpt::math::TPose2D robot{3.0, 2.0, 0.4};
    const auto sf = makeFrame(w, robot);
    const std::vector<mrpt::math::TPose2D> poses{robot, {3.3, 2.1, 0.5}, {8.0, 6.0, -2.0}};

    std::vector<double> got(poses.size());
    const std::size_t K = frameLogLikelihoods(*map, sf, poses.data(), poses.size(), got.data());
    EXPECT_EQ(K, 5u);  // all cameras count, not one camera's mean times the camera count
    for (std::size_t i = 0; i < poses.size(); ++i) {
        double sum = 0;
        std::size_t k = 0;
        for (const auto& o : sf) {
            const auto& det = dynamic_cast<const simp::obs::CObservationObjects3D&>(*o);
            for (std::size_t j = 0; j < det.size(); ++j) {
                const auto l = map->detectionLogLikelihood(det, j, poses[i]);
                ASSERT_TRUE(l.has_value());
                sum += *l;
                ++k;
            }
        }
        EXPECT_NEAR(got[i], sum / static_cast<double>(k), 1e-9) << "pose " << i;
    }
    // Seen from the true pose, the detections match the map better than from elsewhere.
    EXPECT_GT(got[0], got[2]);
    // Each factor of Eq. combined is in [eta, 1]: so is their geometric mean.
    for (double g : got) {
        EXPECT_LE(g, 1e-12);
        EXPECT_GE(g, std::log(map->likelihoodOptions.eta) - 1e-9);
    }
}

TEST(FrameLikelihood, FrameWithoutDetectionsIsNeutral) {
    const auto w = test::makeWorld();
    const auto map = makeMap(w);
    mrpt::obs::CSensoryFrame sf;
    auto o = simp::obs::CObservationObjects3D::Create();
    o->setClassNames(simp::obs::defaultClassNames());
    sf.insert(o);
    const mrpt::math::TPose2D p{1, 1, 0};
    double l = 42;
    EXPECT_EQ(frameLogLikelihoods(*map, sf, &p, 1, &l), 0u);
    EXPECT_EQ(l, 0.0);
}

TEST(ObjectMcl, BatchWeightsEqualThePerParticlePath) {
    const auto w = test::makeWorld();
    const auto map = makeMap(w);
    const auto sf = makeFrame(w, {3.0, 2.0, 0.4});
    mrpt::random::getRandomGenerator().randomize(5);
    ObjectMcl mcl(map);
    mcl.resetUniformFreeSpace(const_cast<mrpt::maps::COccupancyGridMap2D*>(&w.floorplan), 0.7, 300);
    const auto before = mcl.m_particles;

    mrpt::bayes::CParticleFilter::TParticleFilterOptions pf;
    mcl.prediction_and_update_pfStandardProposal(nullptr, &sf, pf);  // no action: poses unchanged
    ASSERT_EQ(mcl.size(), before.size());
    EXPECT_EQ(mcl.lastDetectionCount(), 5u);
    for (std::size_t i = 0; i < mcl.size(); ++i) {
        ASSERT_EQ(mcl.m_particles[i].d, before[i].d);
        const double single = mcl.PF_SLAM_computeObservationLikelihoodForParticle(
            pf, i, sf, mrpt::poses::CPose3D(mrpt::poses::CPose2D(before[i].d)));
        EXPECT_NEAR(mcl.m_particles[i].log_w - before[i].log_w, single, 1e-12) << i;
    }
}

TEST(ObjectMcl, PrunesParticlesThatLeaveTheFreeSpace) {
    const auto w = test::makeWorld();
    const auto map = makeMap(w);
    mrpt::random::getRandomGenerator().randomize(6);
    ObjectMcl mcl(map);
    auto free_space = std::make_shared<FreeSpace>(w.floorplan, 0.7);
    mcl.setFreeSpace(free_space);
    mcl.resetUniformFreeSpace(const_cast<mrpt::maps::COccupancyGridMap2D*>(&w.floorplan), 0.7, 500);
    // A 30 m jump leaves the 14 m x 9 m building for every particle.
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(mrpt::poses::CPose2D(30, 0, 0), mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
    mrpt::obs::CActionCollection acts;
    acts.insert(mv);
    mrpt::bayes::CParticleFilter::TParticleFilterOptions pf;
    mcl.prediction_and_update_pfStandardProposal(&acts, nullptr, pf);
    EXPECT_EQ(mcl.lastPrunedCount(), 500u);
    for (const auto& p : mcl.m_particles) EXPECT_TRUE(free_space->isFree(p.d.x, p.d.y));
    // Kept weights (the authors' code) ...
    for (std::size_t i = 0; i < mcl.size(); ++i) mcl.m_particles[i].log_w = -0.001 * static_cast<double>(i);
    mcl.prediction_and_update_pfStandardProposal(&acts, nullptr, pf);
    for (std::size_t i = 0; i < mcl.size(); ++i) EXPECT_EQ(mcl.m_particles[i].log_w, -0.001 * static_cast<double>(i));
    // ... or the smallest weight MRPT keeps; with every particle pruned they all get the same one.
    mcl.params.prune_keeps_weight = false;
    mcl.prediction_and_update_pfStandardProposal(&acts, nullptr, pf);
    EXPECT_EQ(mcl.lastPrunedCount(), 500u);
    for (const auto& p : mcl.m_particles) EXPECT_DOUBLE_EQ(p.log_w, -pf.max_loglikelihood_dyn_range);
    mcl.params.prune_outside_free_space = false;
    mcl.prediction_and_update_pfStandardProposal(&acts, nullptr, pf);
    EXPECT_EQ(mcl.lastPrunedCount(), 0u);
}

TEST(FrameLikelihood, PerFrameMultipliesTheGeometricMeansOfEachTimestamp) {
    const auto w = test::makeWorld();
    const auto map = makeMap(w);
    const mrpt::math::TPose2D robot{3.0, 2.0, 0.4};
    const auto a = makeFrame(w, robot);                 // 5 detections at time t0
 const auto b = makeFrame(w, {3.05, 2.0, 0.42});         // 5 detections, another time
    const mrpt::Clock::time_point t0 = mrpt::Clock::fromDouble(100.0), t1 = mrpt::Clock::fromDouble(100.5);
    mrpt::obs::CSensoryFrame both, only_a;
    for (const auto& o : a) { o->timestamp = t0; both.insert(o); only_a.insert(o); }
    mrpt::obs::CSensoryFrame only_b;
    for (const auto& o : b) {
        o->timestamp = t1;
        both.insert(o);
        only_b.insert(o);
    }
    const std::vector<mrpt::math::TPose2D> poses{robot, {3.3, 2.1, 0.5}, {8.0, 6.0, -2.0}};
    std::vector<double> la(3), lb(3), per_frame(3), pooled(3);
    ASSERT_EQ(frameLogLikelihoods(*map, only_a, poses.data(), 3, la.data()), 5u);
    ASSERT_EQ(frameLogLikelihoods(*map, only_b, poses.data(), 3, lb.data()), 5u);
    EXPECT_EQ(perFrameLogLikelihoods(*map, both, poses.data(), 3, per_frame.data()), 10u);
    EXPECT_EQ(frameLogLikelihoods(*map, both, poses.data(), 3, pooled.data()), 10u);
    for (std::size_t i = 0; i < 3; ++i) {
        // Eq. singw per frame, product over the two frames ...
        EXPECT_NEAR(per_frame[i], la[i] + lb[i], 1e-9) << i;
        // ... where pooling all 10 detections in one mean gives their average (half the evidence).
        EXPECT_NEAR(pooled[i], 0.5 * (la[i] + lb[i]), 1e-9) << i;
    }
    // One timestamp: per-frame and pooled agree.
    std::vector<double> single(3);
    EXPECT_EQ(perFrameLogLikelihoods(*map, only_a, poses.data(), 3, single.data()), 5u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(single[i], la[i], 1e-12);
}

TEST(ObjectMcl, RecoveryInjectsRandomParticlesWhenTheLikelihoodDrops) {
    const auto w = test::makeWorld();
    const auto map = makeMap(w);
    mrpt::random::getRandomGenerator().randomize(7);
    ObjectMcl mcl(map);
    auto free_space = std::make_shared<FreeSpace>(w.floorplan, 0.7);
    mcl.setFreeSpace(free_space);
    mcl.params.recovery_alpha_slow = 0.05;
    mcl.params.recovery_alpha_fast = 0.5;
    const mrpt::math::TPose2D robot{3.0, 2.0, 0.4};
    mcl.resetDeterministic(mrpt::math::TPose2D(robot), 400);  // all particles at the true pose
    mrpt::bayes::CParticleFilter::TParticleFilterOptions pf;
    const auto good = makeFrame(w, robot);
    for (int k = 0; k < 10; ++k) mcl.prediction_and_update_pfStandardProposal(nullptr, &good, pf);
    EXPECT_EQ(mcl.lastInjectedCount(), 0u);  // the likelihood stays as high as it was: w_fast = w_slow
    // The same detections seen from far away: w_avg drops, w_fast falls below w_slow.
    const auto bad = makeFrame(w, {8.0, 6.0, -2.0});
    mcl.prediction_and_update_pfStandardProposal(nullptr, &bad, pf);
    mcl.prediction_and_update_pfStandardProposal(nullptr, &bad, pf);
    EXPECT_GT(mcl.lastInjectedCount(), 0u);
    EXPECT_LT(mcl.lastInjectedCount(), 400u);
    std::size_t moved = 0;
    for (const auto& p : mcl.m_particles) {
        EXPECT_TRUE(std::isfinite(p.log_w));
        if (std::hypot(p.d.x - robot.x, p.d.y - robot.y) > 1e-9) ++moved;
    }
    EXPECT_GE(moved, mcl.lastInjectedCount());
}
