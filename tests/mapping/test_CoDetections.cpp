// CoDetections.h: frames in which two objects took a detection each, and the duplicate rules that
// consult them (MappingOptions distinct_codetected_frames).
#include <gtest/gtest.h>
#include <simp/mapping/CoDetections.h>
#include <simp/mapping/ObjectMapBuilder.h>

#include "MappingTestScene.h"

using namespace simp::mapping;
using simp::geometry::makeUprightBox;

TEST(CoDetections, SharedFramesAndTheirUnion) {
    const FrameSerials a{1, 4, 7, 9}, b{2, 4, 9, 12};
    EXPECT_EQ(sharedFrames(a, b), 2);
    EXPECT_EQ(sharedFrames(a, {}), 0);
    EXPECT_EQ(unionOfFrames(a, b), (FrameSerials{1, 2, 4, 7, 9, 12}));
}

TEST(CoDetections, CountsAreSymmetricAndFollowMerges) {
    CoDetections c;
    c.add(1, 2, 3);
    c.add(2, 1, 1);
    c.add(1, 1, 5);  // an object with itself: ignored
    c.add(3, 2, 2);
    c.add(1, 3, 0);  // nothing
    EXPECT_EQ(c.count(1, 2), 4);
    EXPECT_EQ(c.count(2, 1), 4);
    EXPECT_EQ(c.count(1, 1), 0);
    EXPECT_EQ(c.count(1, 3), 0);
    // 3 merged into 1: 1 was seen beside 2 in 4 + 2 frames; the pair (1, 3) itself is gone.
    c.add(1, 3, 7);
    c.absorb(1, 3);
    EXPECT_EQ(c.count(1, 2), 6);
    EXPECT_EQ(c.count(2, 1), 6);
    EXPECT_EQ(c.count(1, 3), 0);
    EXPECT_EQ(c.count(2, 3), 0);
    c.forget(2);
    EXPECT_EQ(c.count(1, 2), 0);
}

namespace {

const std::vector<std::string> kCabinetClasses = {"cabinet"};

/// Cabinets in the builder's map after a robot drove 40 steps past two cabinets of a row (0.9 m
/// wide, side by side, centres 0.9 m apart) at 2.5 m, facing them: every frame that sees one sees both.
std::size_t cabinetsOfARow(const MappingOptions& opts) {
    ObjectMapBuilder b(opts);
    b.setFloorPlan(test::makeFloorPlan(8, 6), {});
    b.setMap(test::emptyMapOf(kCabinetClasses));
    const std::vector<test::TrueObject> row = {{0, makeUprightBox({5.0, 2.55, 0.9}, {0.5, 0.88, 1.8}, 0.0)},
                                               {0, makeUprightBox({5.0, 3.45, 0.9}, {0.5, 0.88, 1.8}, 0.0)}};
    std::mt19937 rng(17);
    for (int s = 0; s < 40; ++s) {
        const mrpt::poses::CPose3D pose(2.5 + 0.02 * s, 3.0, 0, 0.01 * (s % 5), 0, 0);
        for (const auto& o : test::observe(row, kCabinetClasses, pose, rng)) b.insert(o, pose);
    }
    b.flush();
    return b.confirmedMap().objects.size();
}

}  // namespace

TEST(CoDetections, TouchingNeighboursDetectedSideBySideStayTwo) {
    // With a centre radius of 1.0 m (the authors' value for sofas), the duplicate rules alone make
    // the two cabinets 0.9 m apart one object; detected side by side in every frame, they are two.
    auto opts = test::testOptions();
    opts.duplicate_center_radius_m = 1.0;
    ASSERT_EQ(opts.distinct_codetected_frames, 3);
    EXPECT_EQ(cabinetsOfARow(opts), 2u);
    opts.distinct_codetected_frames = 0;  // off: the authors' rules
    EXPECT_EQ(cabinetsOfARow(opts), 1u);
}
