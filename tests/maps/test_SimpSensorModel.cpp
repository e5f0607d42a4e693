// SimpSensorModel (Eqs. globaldist, iouscore, combined) as a value type, at hand-computed cases.
#include <gtest/gtest.h>

#include <simp/maps/SimpSensorModel.h>

#include "TestMaps.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;

TEST(SimpSensorModel, KnownShiftGivesTheHandComputedValue) {
    // The chair seen from (0, 0, 0); the robot 0.1 m further along x moves the detection by 0.1 m:
    // p_o = exp(-0.5 (0.1 / 0.2)^2) = exp(-0.125), IoU = 0.4 / 0.6 = 2/3, p_g = exp(-1/3),
    // p = p_o p_g + (1 - p_o) 0.1 = 0.644063..., log p = -0.439921512418843.
    const auto data = test::oneChairMap();
    const SimpSensorModel model(data, SimpSensorModelParams{});
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const auto det = test::prepared(model, data, o, 0);
    ASSERT_TRUE(det.has_value());
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0.1, 0, 0)), -0.43992151241884253, 1e-12);
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0, 0, 0)), 0.0, 1e-12);  // p_o = 1, IoU = 1
    // Outside the m_p support (p_o < 1e-4 there) and far outside the raster: exactly eta.
    EXPECT_EQ(model.logLikelihood(*det, TPose2D(1.5, 0, 0)), std::log(0.1));
    EXPECT_EQ(model.logLikelihood(*det, TPose2D(-500, 800, 1)), std::log(0.1));
}

TEST(SimpSensorModel, RangeGrowthWidensTheNoise) {
    // noise_reference_range_m = 1: the centre is sqrt(5) m from the robot, Sigma -> 5 Sigma, so
    // p_o = exp(-0.5 * 0.25 / 5) = exp(-0.025); the IoU term is unchanged: log p = -0.354806550076.
    const auto data = test::oneChairMap();
    SimpSensorModelParams params;
    params.noise_reference_range_m = 1.0;
    const SimpSensorModel model(data, params);
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const auto det = test::prepared(model, data, o, 0);
    ASSERT_TRUE(det.has_value());
    EXPECT_NEAR(det->noise_inv_scale2, 0.2, 1e-15);
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0.1, 0, 0)), -0.35480655007634987, 1e-12);
}

TEST(SimpSensorModel, BatchIsTheWeightedSumOfThePairs) {
    const auto data = test::smallMap();
    const SimpSensorModel model(data, SimpSensorModelParams{});
    const auto o = test::detect(data, TPose2D(1.0, 0.5, 0.4), {0, 1});
    auto d0 = *test::prepared(model, data, o, 0);
    auto d1 = *test::prepared(model, data, o, 1);
    d1.weight = 0.5;
    const PreparedDetection dets[] = {d0, d1};
    const TPose2D poses[] = {{1.0, 0.5, 0.4}, {1.1, 0.45, 0.38}, {0.0, 0.0, 0.0}};
    double sums[] = {2.0, 2.0, 2.0};
    model.accumulateLogLikelihoods(dets, 2, poses, 3, sums);
    for (std::size_t i = 0; i < 3; ++i) {
        const double expected = 2.0 + (1.0 * model.logLikelihood(d0, poses[i]) + 0.5 * model.logLikelihood(d1, poses[i]));
        EXPECT_EQ(sums[i], expected) << "pose " << i;  // the same operations in the same order
    }
    EXPECT_NEAR(sums[0], 2.0, 1e-9);  // both at their maximum, log 1
}

TEST(SimpSensorModel, YawTermScoresATurnedBoxBoundedAndFourFold) {
    // The table of smallMap (1.6 x 0.8 m, yaw 0.3) detected with its centre exact but its box turned
    // by dyaw, seen from the true pose: p_o = 1, so log p = log p_g (+ log of the yaw factor).
    // yaw_sigma_rad = 0.1: the factor is exp(-min(1, 50 d^2)) / m, d = sin(2 dyaw) / 2, m its mean
    // for dyaw ~ N(0, 0.1^2). For small angles d ~ dyaw and m = P(|w| < 2) / sqrt(2) + P(|w| > sqrt 2) / e,
    // w ~ N(0, 1): 0.6749 + 0.0579 = 0.7328 (the sine raises it by about 0.002).
    const auto data = test::smallMap();
    SimpSensorModelParams with_yaw;
    with_yaw.yaw_sigma_rad = 0.1;
    const SimpSensorModel yaw_model(data, with_yaw), paper(data, SimpSensorModelParams{});
    const TPose2D truth(1.0, -2.0, 0.5);
    const auto turned = [&](double dyaw, double lx, double ly) {
        auto d = data;
        d.objects[1] = test::object(2, d, "table", 4.0, -1.0, 0.3 + dyaw, lx, ly, 0.75);
        return test::detect(d, truth, {1});
    };
    const auto yaw_log_factor = [&](double dyaw) {
        const auto o = turned(dyaw, 1.6, 0.8);
        const auto det = test::prepared(paper, data, o, 0);
        EXPECT_TRUE(det.has_value());
        return det ? yaw_model.logLikelihood(*det, truth) - paper.logLikelihood(*det, truth) : 0.0;
    };
    const double log_mean = yaw_log_factor(0.0);  // -log m: the factor at dyaw = 0 is 1 / m
    EXPECT_NEAR(std::exp(-log_mean), 0.7328, 0.004);
    for (const double dyaw : {0.0873, 0.1745, -0.05, 0.6}) {
        const double d = 0.5 * std::sin(2 * dyaw);
        EXPECT_NEAR(yaw_log_factor(dyaw) - log_mean, -std::min(1.0, 50.0 * d * d), 1e-9) << dyaw;
    }
    // A correct association's yaw error costs nothing on average: the mean factor over detector
    // yaws drawn with the model's std is 1 (2000 draws: the factor's std is about 0.3, the mean's 0.007).
    std::mt19937 rng(5);
    std::normal_distribution<double> yaw_noise(0.0, 0.1);
    double mean_factor = 0;
    for (int i = 0; i < 2000; ++i) mean_factor += std::exp(yaw_log_factor(yaw_noise(rng))) / 2000;
    EXPECT_NEAR(mean_factor, 1.0, 0.03);
    // The same solid described turned by 90 deg with its sides swapped: the factor of dyaw = 0.
    const auto o = turned(M_PI / 2, 0.8, 1.6);
    const auto det = test::prepared(paper, data, o, 0);
    ASSERT_TRUE(det.has_value());
    EXPECT_NEAR(yaw_model.logLikelihood(*det, truth) - paper.logLikelihood(*det, truth), log_mean, 1e-9);
    EXPECT_NEAR(paper.logLikelihood(*det, truth), 0.0, 1e-9);

    SimpSensorModelParams bad;
    bad.yaw_sigma_rad = -0.1;
    EXPECT_THROW(SimpSensorModel(data, bad), std::invalid_argument);
}

TEST(SimpSensorModel, ClassesWithoutNoiseModel) {
    auto data = test::smallMap();
    data.class_noise[static_cast<std::size_t>(data.classId("door"))].reset();  // object 4 is a door
    EXPECT_THROW(SimpSensorModel(data, SimpSensorModelParams{}), std::invalid_argument);
    SimpSensorModelParams skip;
    skip.mp.skip_classes_without_noise = true;
    const SimpSensorModel model(data, skip);
    EXPECT_FALSE(model.scoresClass(data.classId("door")));
    EXPECT_TRUE(model.scoresClass(data.classId("chair")));
    EXPECT_FALSE(model.scoresClass(data.classId("sofa")));  // no object
    EXPECT_FALSE(model.scoresClass(-1));
    EXPECT_FALSE(model.empty());
    const auto o = test::detect(data, TPose2D(0, 0, 0), {3});
    EXPECT_FALSE(test::prepared(model, data, o, 0).has_value());
}

TEST(SimpSensorModel, BadParametersNameTheKey) {
    const auto data = test::oneChairMap();
    const auto message = [&](const SimpSensorModelParams& p) {
        try {
            SimpSensorModel m(data, p);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    SimpSensorModelParams p;
    p.eta = 1.0;
    EXPECT_NE(message(p).find("eta"), std::string::npos);
    p = {};
    p.mp.resolution_m = 0.0;
    EXPECT_NE(message(p).find("mp_resolution_m"), std::string::npos);
    p = {};
    p.noise_reference_range_m = -1.0;
    EXPECT_NE(message(p).find("noise_reference_range_m"), std::string::npos);
}

}  // namespace
}  // namespace simp::maps
