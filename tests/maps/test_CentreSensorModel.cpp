// CentreSensorModel (D-MCL: the centre by m_p alone) as a value type, at hand-computed cases.
#include <gtest/gtest.h>
#include <simp/maps/CentreSensorModel.h>

#include "TestMaps.h"

#include <cmath>
#include <stdexcept>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;

TEST(CentreSensorModel, KnownShiftGivesTheHandComputedValue) {
    // 0.2 m along the chair's x (sigma 0.2 m): p_o = exp(-0.5), p = p_o + (1 - p_o) 0.1,
    // log p = -0.437145276526270; the shape does not matter.
    const auto data = test::oneChairMap();
    const CentreSensorModel model(data, CentreSensorModelParams{});
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const auto det = test::prepared(model, data, o, 0);
    ASSERT_TRUE(det.has_value());
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0.2, 0, 0)), -0.4371452765262696, 1e-12);
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0, 0, 0)), 0.0, 1e-12);
    // Turning the robot about the detection's centre changes nothing (isotropic in the shape).
    const double a = 0.7, c = std::cos(a), s = std::sin(a);
    const TPose2D turned(2.0 - (c * 2.0 - s * 1.0), 1.0 - (s * 2.0 + c * 1.0), a);
    EXPECT_NEAR(model.logLikelihood(*det, turned), 0.0, 1e-12);
    EXPECT_EQ(model.logLikelihood(*det, TPose2D(1.5, 0, 0)), std::log(0.1));  // beyond the support
}

TEST(CentreSensorModel, BatchIsTheWeightedSumOfThePairs) {
    const auto data = test::smallMap();
    const CentreSensorModel model(data, CentreSensorModelParams{});
    const auto o = test::detect(data, TPose2D(1.0, 0.5, 0.4), {1, 2});
    auto d0 = *test::prepared(model, data, o, 0);
    auto d1 = *test::prepared(model, data, o, 1);
    d0.weight = 0.25;
    const PreparedDetection dets[] = {d0, d1};
    const TPose2D poses[] = {{1.0, 0.5, 0.4}, {1.2, 0.4, 0.3}};
    double sums[] = {0.0, -1.0};
    model.accumulateLogLikelihoods(dets, 2, poses, 2, sums);
    for (std::size_t i = 0; i < 2; ++i)
        EXPECT_EQ(sums[i], (i == 0 ? 0.0 : -1.0) + (0.25 * model.logLikelihood(d0, poses[i]) +
                                                     1.0 * model.logLikelihood(d1, poses[i])));
}

TEST(CentreSensorModel, NeedsANoiseModelPerClass) {
    auto data = test::oneChairMap();
    data.class_noise[static_cast<std::size_t>(data.classId("chair"))].reset();
    EXPECT_THROW(CentreSensorModel(data, CentreSensorModelParams{}), std::invalid_argument);
    CentreSensorModelParams isotropic;
    isotropic.mp.unmodelled_noise_std_m = 0.2;  // the chair gets sigma 0.2 m both ways
    const CentreSensorModel model(data, isotropic);
    EXPECT_TRUE(model.scoresClass(data.classId("chair")));
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const auto det = test::prepared(model, data, o, 0);
    ASSERT_TRUE(det.has_value());
    // 0.2 m along y is one sigma too: the same value as 0.2 m along x above.
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0, 0.2, 0)), -0.4371452765262696, 1e-12);
}

}  // namespace
}  // namespace simp::maps
