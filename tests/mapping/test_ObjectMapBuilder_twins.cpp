// Twins by support (MappingOptions twin_max_support_ratio): an object made of a few viewpoints'
// detections next to a same-class object seen from everywhere is left out of the written map.
#include <gtest/gtest.h>
#include <simp/mapping/ObjectMapBuilder.h>

#include "MappingTestScene.h"

using namespace simp::mapping;
using simp::geometry::makeUprightBox;

namespace {

const std::vector<std::string> kCabinetClasses = {"table", "cabinet"};

/// An empty map whose cabinets have the spread of the built-in office's class model: 0.23 m across,
/// 0.58 m along the longer side (the class noise frame's y).
simp::world::ObjectMapData cabinetMap() {
    simp::world::ObjectMapData m;
    m.class_names = kCabinetClasses;
    m.class_noise.resize(kCabinetClasses.size());
    simp::model::NoiseModel cabinet;
    cabinet.cov_m2 = Eigen::Vector2d(0.055, 0.334).asDiagonal();
    m.class_noise[1] = cabinet;
    return m;
}

/// The number of cabinets written (confirmedMap) after the robot drove 2 m towards cabinet A
/// (1 m long along x at (5, 3)) in 80 steps, detecting A at every step and B (the same cabinet
/// 0.9 m further along x) at the steps `b_steps`. The options are the defaults of a test but for
/// the authors' per-window support rule (off: B is seen in single steps) and the twin ratio.
std::size_t cabinetsWritten(double twin_ratio, const std::vector<int>& b_steps) {
    auto opts = test::testOptions();
    opts.min_local_support = 0;
    opts.twin_max_support_ratio = twin_ratio;
    ObjectMapBuilder b(opts);
    b.setFloorPlan(test::makeFloorPlan(10, 6), {});
    b.setMap(cabinetMap());
    const test::TrueObject a{1, makeUprightBox({5.0, 3.0, 0.9}, {1.0, 0.5, 1.8}, 0.0)};
    const test::TrueObject twin{1, makeUprightBox({5.9, 3.0, 0.9}, {1.0, 0.5, 1.8}, 0.0)};
    std::mt19937 rng(17);
    const test::DetectionNoise small{0.02, 0.01, 0.01};
    for (int s = 0; s < 80; ++s) {
        const mrpt::poses::CPose3D pose(1.0 + 0.025 * s, 3.0, 0, 0, 0, 0);
        std::vector<test::TrueObject> seen{a};
        if (std::find(b_steps.begin(), b_steps.end(), s) != b_steps.end()) seen.push_back(twin);
        for (const auto& o : test::observe(seen, kCabinetClasses, pose, rng, small)) b.insert(o, pose);
    }
    b.flush();
    std::size_t n_built = 0;
    for (const auto& o : b.map().objects) n_built += o.class_id == 1;
    EXPECT_EQ(n_built, 2u) << "the builder keeps both objects (the duplicate rules do not merge them)";
    std::size_t n = 0;
    for (const auto& o : b.confirmedMap().objects) n += o.class_id == 1;
    return n;
}

}  // namespace

TEST(ObjectMapBuilderTwins, AFewViewpointsNextToAnObjectSeenFromEverywhereAreItsTwin) {
    // B: 3 detections in 2 windows (confirmed by count and windows), A: 80. 3 / 80 < 0.05, and B's
    // centre is 1.6 sigma along A's class model: B is A's twin.
    const std::vector<int> twin_steps{20, 21, 60};
    EXPECT_EQ(cabinetsWritten(0.05, twin_steps), 1u);
    EXPECT_EQ(cabinetsWritten(0.0, twin_steps), 2u);  // the rule off: both written
}

TEST(ObjectMapBuilderTwins, ANeighbourSeenFromTheSamePlacesStays) {
    // B seen at every step like A: a second cabinet, whatever the rule.
    std::vector<int> every_step(80);
    for (int s = 0; s < 80; ++s) every_step[static_cast<std::size_t>(s)] = s;
    EXPECT_EQ(cabinetsWritten(0.05, every_step), 2u);
}
