/// Which detections vote on the heading: their object's yaw against the other objects', in the
/// odometry frame, over DetectionNovelty's tracks.

#include <gtest/gtest.h>
#include <simp/geometry/Box3D.h>
#include <simp/localization/YawConsensus.h>

#include <cmath>
#include <vector>

#include "TestUtil.h"

using namespace simp::localization;

namespace {

/// The scenario's world with every object square to the grid's axes (yaw i x 90 deg), object
/// `turned` (if >= 0) turned `by` rad off them.
simp::world::World gridSquareWorld(int turned = -1, double by = 0.0) {
    auto w = test::makeWorld();
    for (std::size_t i = 0; i < w.objects.objects.size(); ++i) {
        auto& o = w.objects.objects[i];
        const double yaw = 0.5 * M_PI * static_cast<double>(i % 4) + (static_cast<int>(i) == turned ? by : 0.0);
        o.box = simp::geometry::makeUprightBox(o.box.center, o.box.size, yaw);
    }
    return w;
}

ManhattanHeadingOptions consensusOptions() {
    ManhattanHeadingOptions o;
    o.weight = 0.5;
    o.consensus_tolerance_rad = 0.1;
    o.consensus_window_s = 10.0;
    o.consensus_min_tracks = 2;
    o.consensus_min_detections = 1;  // every detection a track's first (the rule has a test of its own)
    return o;
}

struct ConsensusRig {
    DetectionNovelty novelty;
    YawConsensus consensus;
    /// Heading weights of the detections of objects `idx` of `seen` from `robot` at t_s; the odometry
    /// frame is the world turned by `odometry_offset` (a heading error of the odometry is no matter).
    std::vector<double> frame(const ManhattanHeading& model, const simp::world::World& seen, const mrpt::math::TPose2D& robot,
                              const std::vector<int>& idx, double t_s, double odometry_offset = 0.0) {
        auto obs = test::observe(seen, robot, idx);
        const mrpt::poses::CPose2D odo = mrpt::poses::CPose2D(0, 0, odometry_offset) + mrpt::poses::CPose2D(robot);
        std::vector<TrackedDetection> tracked;
        novelty.weigh(*obs, odo, t_s, &tracked);
        return consensus.weigh(model, *obs, tracked, odo, t_s);
    }
};

}  // namespace

TEST(YawConsensus, ATurnedObjectDoesNotVoteTheOthersDo) {
    const auto square = gridSquareWorld();
    const auto map = test::makeMap(square);
    const ManhattanHeading model(*map, consensusOptions());
    ASSERT_TRUE(model.active());
    const auto turned = gridSquareWorld(2, 0.25);  // moved furniture turned 14 deg: as the map has it nowhere
    ConsensusRig rig;
    const auto w = rig.frame(model, turned, {3.0, 2.0, 0.4}, {0, 1, 2, 3}, 0.0, 0.7);
    ASSERT_EQ(w.size(), 4u);
    EXPECT_EQ(w[2], 0.0);
    for (int k : {0, 1, 3}) EXPECT_EQ(w[static_cast<std::size_t>(k)], 1.0) << k;  // first sights: tempering weight 1
    // Turned by less than the tolerance (a detector's yaw error): it votes.
    ConsensusRig near;
    EXPECT_EQ(near.frame(model, gridSquareWorld(2, 0.05), {3.0, 2.0, 0.4}, {0, 1, 2, 3}, 0.0)[2], 1.0);
}

TEST(YawConsensus, ALoneObjectDoesNotVoteUntilOthersAreSeen) {
    const auto square = gridSquareWorld();
    const auto map = test::makeMap(square);
    const ManhattanHeading model(*map, consensusOptions());
    ConsensusRig rig;
    EXPECT_EQ(rig.frame(model, square, {3.0, 2.0, 0.4}, {0}, 0.0), std::vector<double>{0.0});
    // Two more objects a second later, the robot turned: each has two others (in the window).
    const auto w = rig.frame(model, square, {3.2, 2.0, 1.1}, {1, 3}, 1.0);
    EXPECT_EQ(w, (std::vector<double>{1.0, 1.0}));
    // Past the window the first object no longer counts: one other each, under consensus_min_tracks.
    ConsensusRig late;
    late.frame(model, square, {3.0, 2.0, 0.4}, {0}, 0.0);
    EXPECT_EQ(late.frame(model, square, {3.2, 2.0, 1.1}, {1, 3}, 10.5), (std::vector<double>{0.0, 0.0}));
}

TEST(YawConsensus, WithoutTracksNothingVotes) {
    const auto square = gridSquareWorld();
    const auto map = test::makeMap(square);
    const ManhattanHeading model(*map, consensusOptions());
    DetectionNoveltyParams off;
    off.decorrelation_distance_m = 0.0;
    off.unmapped_min_detections = 0;  // DetectionNovelty keeps no tracks
    DetectionNovelty novelty(off);
    YawConsensus consensus;
    auto obs = test::observe(square, {3.0, 2.0, 0.4}, {0, 1, 2, 3});
    std::vector<TrackedDetection> tracked;
    novelty.weigh(*obs, mrpt::poses::CPose2D(3.0, 2.0, 0.4), 0.0, &tracked);
    EXPECT_TRUE(tracked.empty());
    EXPECT_EQ(consensus.weigh(model, *obs, tracked, mrpt::poses::CPose2D(3.0, 2.0, 0.4), 0.0), std::vector<double>(4, 0.0));
}

TEST(YawConsensus, TheHeadingModelUsesTheHeadingWeights) {
    const auto square = gridSquareWorld();
    const auto map = test::makeMap(square);
    const ManhattanHeading model(*map, consensusOptions());
    const mrpt::math::TPose2D robot{3.0, 2.0, 0.4}, pose{3.0, 2.0, 0.45};
    auto obs = test::observe(square, robot, {0, 1, 2});
    double all = 0.0, one = 0.0;
    EXPECT_EQ(model.addLogLikelihoods({{obs, {1.0, 1.0, 1.0}, {}}}, true, &pose, 1, &all), 3u);
    EXPECT_EQ(model.addLogLikelihoods({{obs, {1.0, 1.0, 1.0}, {0.0, 1.0, 0.0}}}, true, &pose, 1, &one), 1u);
    EXPECT_NEAR(one, all, 1e-9);  // every residual is the same here: the mean of one is the mean of three
}

TEST(YawConsensus, OnlyObjectsSeenRepeatedlyVoteOrCount) {
    const auto square = gridSquareWorld();
    const auto map = test::makeMap(square);
    auto options = consensusOptions();
    options.consensus_min_detections = 3;
    const ManhattanHeading model(*map, options);
    ConsensusRig rig;
    // Frames 1 and 2: nobody has 3 detections yet.
    EXPECT_EQ(rig.frame(model, square, {3.0, 2.0, 0.4}, {0, 1, 2}, 0.0), std::vector<double>(3, 0.0));
    EXPECT_EQ(rig.frame(model, square, {3.0, 2.0, 0.4}, {0, 1, 2}, 0.1), std::vector<double>(3, 0.0));
    // Frame 3: each has 3 and two others with 3 (an immediate repeat: tempering weight min_weight).
    const auto third = rig.frame(model, square, {3.0, 2.0, 0.4}, {0, 1, 2}, 0.2);
    for (double w : third) EXPECT_EQ(w, DetectionNoveltyParams{}.min_weight);
    // A newcomer seen once does not vote, and the others still do.
    const auto fourth = rig.frame(model, square, {3.0, 2.0, 0.4}, {0, 1, 2, 3}, 0.3);
    EXPECT_EQ(fourth[3], 0.0);
    EXPECT_GT(fourth[0], 0.0);
}
