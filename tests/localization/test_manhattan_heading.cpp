/// The box-yaw heading model: the map's axes, the per-class weights, the likelihood over headings.

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <simp/geometry/Box3D.h>
#include <simp/io/StrictIni.h>
#include <simp/localization/ManhattanHeading.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "TestUtil.h"
#include "common/ErrorOf.h"

using namespace simp::localization;

namespace {

constexpr double kAxis = 0.3;  // rad: the generated world turned off the grid's axes

/// The scenario's world with every object turned to kAxis + (i mod 4) x 90 deg about its centre;
/// the objects of class `off_class` (if >= 0) are turned 0.6 rad (34 deg) off the axes instead.
simp::world::World squareWorld(int off_class = -1) {
    auto w = test::makeWorld();
    for (std::size_t i = 0; i < w.objects.objects.size(); ++i) {
        auto& o = w.objects.objects[i];
        const double yaw = kAxis + (o.class_id == off_class ? 0.6 : 0.0) + 0.5 * M_PI * static_cast<double>(i % 4);
        o.box = simp::geometry::makeUprightBox(o.box.center, o.box.size, yaw);
    }
    return w;
}

std::vector<int> allObjects(const simp::world::World& w) {
    std::vector<int> idx(w.objects.objects.size());
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
    return idx;
}

ManhattanHeadingOptions on() {
    ManhattanHeadingOptions o;
    o.weight = 1.0;
    return o;
}

}  // namespace

TEST(ManhattanHeading, AxesAndClassWeightsComeFromTheMap) {
    const auto w = squareWorld();
    const int off_class = w.objects.objects.front().class_id;
    const auto mixed = squareWorld(off_class);
    const auto map = test::makeMap(w), mixed_map = test::makeMap(mixed);
    const ManhattanHeading model(*map, on()), mixed_model(*mixed_map, on());
    EXPECT_TRUE(model.active());
    EXPECT_NEAR(model.axisRad(), kAxis, 1e-9);
    EXPECT_DOUBLE_EQ(model.alignedFraction(), 1.0);
    EXPECT_DOUBLE_EQ(model.inlierWeight(off_class), 1.0 - on().outlier_fraction);
    // The turned class is not square: its detections say nothing; the others keep their weight.
    EXPECT_DOUBLE_EQ(mixed_model.inlierWeight(off_class), 0.0);
    const int other = std::find_if(mixed.objects.objects.begin(), mixed.objects.objects.end(),
                                   [&](const auto& o) { return o.class_id != off_class; })->class_id;
    EXPECT_DOUBLE_EQ(mixed_model.inlierWeight(other), 1.0 - on().outlier_fraction);
    EXPECT_LT(mixed_model.alignedFraction(), 1.0);
    EXPECT_DOUBLE_EQ(model.inlierWeight(-1), 0.0);  // an unusable detection
}

TEST(ManhattanHeading, PeaksAtTheTrueHeadingModuloAQuarterTurn) {
    const auto w = squareWorld();
    const auto map = test::makeMap(w);
    const ManhattanHeading model(*map, on());
    const mrpt::math::TPose2D robot{3.0, 2.0, 0.4};
    const std::vector<WeightedObservation> obs{{test::observe(w, robot, allObjects(w)), {}}};

    std::vector<mrpt::math::TPose2D> poses;
    for (int d = -200; d <= 200; ++d) poses.push_back({robot.x, robot.y, mrpt::math::wrapToPi(robot.phi + 0.01 * d)});
    std::vector<double> log(poses.size(), 0.0);
    const std::size_t used = model.addLogLikelihoods(obs, false, poses.data(), poses.size(), log.data());
    ASSERT_EQ(used, w.objects.objects.size());
    const std::size_t truth = 200;
    // Within one period about the truth (the others repeat it); the table's step is 0.5 deg, the poses' 0.01 rad.
    const auto best = static_cast<std::size_t>(std::max_element(log.begin() + truth - 70, log.begin() + truth + 71) - log.begin());
    EXPECT_LE(std::abs(static_cast<double>(best) - static_cast<double>(truth)), 1.0);
    // A quarter turn is indistinguishable (157 x 0.01 rad ~ pi / 2, within one step).
    EXPECT_NEAR(log[truth + 157], log[truth], 0.05);
    // Each detection's factor, exact: at the truth every residual is 0, at 0.1 rad off it is 0.1.
    const int cls = w.objects.objects.front().class_id;
    const double at0 = model.detectionLogLikelihood(cls, kAxis, 0.0), at01 = model.detectionLogLikelihood(cls, kAxis, 0.1);
    EXPECT_NEAR(log[truth], at0, 2e-3);  // the mean over the frame's detections
    EXPECT_NEAR(log[truth + 10], at01, 2e-3);
    EXPECT_GT(at0 - at01, 0.3);  // sigma 0.1, w 0.7: about 0.47 nats per frame at 5.7 deg
}

TEST(ManhattanHeading, IsAWeightedMeanPerFrameAndFramesAdd) {
    const auto w = squareWorld();
    const auto map = test::makeMap(w);
    auto options = on();
    options.weight = 0.5;
    const ManhattanHeading model(*map, options);
    const mrpt::math::TPose2D robot{3.0, 2.0, 0.4};
    auto a = test::observe(w, robot, {0, 1, 2});
    auto b = test::observe(w, {3.0, 2.0, 0.3}, {3, 4});  // seen 0.1 rad further left: residual 0.15 at 0.45
    b->timestamp = a->timestamp + std::chrono::milliseconds(100);
    const std::vector<WeightedObservation> obs{{a, {1.0, 0.0, 0.5}}, {b, {}}};
    const mrpt::math::TPose2D pose{3.0, 2.0, 0.45};
    const int cls = w.objects.objects.front().class_id;
    ASSERT_EQ(model.inlierWeight(cls), model.inlierWeight(w.objects.objects[3].class_id));
    const double at005 = model.detectionLogLikelihood(cls, kAxis, 0.05), at015 = model.detectionLogLikelihood(cls, kAxis, 0.15);
    double one = 0.0, per_frame = 0.0;
    EXPECT_EQ(model.addLogLikelihoods(obs, false, &pose, 1, &one), 4u);  // the weight-0 detection is not used
    EXPECT_EQ(model.addLogLikelihoods(obs, true, &pose, 1, &per_frame), 4u);
    // The weighted mean (weights 1, 0.5, 1, 1) over all four, or per frame and the frames added.
    EXPECT_NEAR(one, 0.5 * (1.5 * at005 + 2.0 * at015) / 3.5, 2e-3);
    EXPECT_NEAR(per_frame, 0.5 * (at005 + at015), 2e-3);
}

TEST(ManhattanHeading, StaysOffWithoutAxesOrWeight) {
    auto w = test::makeWorld();
    for (std::size_t i = 0; i < w.objects.objects.size(); ++i) {  // yaws spread evenly over a quarter turn
        auto& o = w.objects.objects[i];
        const double yaw = 0.5 * M_PI * static_cast<double>(i) / static_cast<double>(w.objects.objects.size());
        o.box = simp::geometry::makeUprightBox(o.box.center, o.box.size, yaw);
    }
    const auto map = test::makeMap(w);
    const ManhattanHeading no_axes(*map, on());
    EXPECT_FALSE(no_axes.active());
    EXPECT_LT(no_axes.alignedFraction(), on().min_aligned_fraction);
    const auto square = squareWorld();
    const auto square_map = test::makeMap(square);
    ManhattanHeadingOptions off;
    off.weight = 0.0;
    EXPECT_FALSE(ManhattanHeading(*square_map, off).active());
    const mrpt::math::TPose2D robot{3.0, 2.0, 0.4};
    const std::vector<WeightedObservation> obs{{test::observe(w, robot, allObjects(w)), {}}};
    double log = 1.5;
    EXPECT_EQ(no_axes.addLogLikelihoods(obs, true, &robot, 1, &log), 0u);
    EXPECT_EQ(log, 1.5);
}

TEST(ManhattanHeading, BadOptionsNameTheKey) {
    const simp::io::StrictIni ini("[ManhattanHeading]\noutlier_fraction = 1\n", "x.ini");
    ManhattanHeadingOptions o;
    const std::string err = simp_test::errorOf([&] { o.loadFromConfig(ini); });
    EXPECT_NE(err.find("[ManhattanHeading] outlier_fraction"), std::string::npos) << err;
}
