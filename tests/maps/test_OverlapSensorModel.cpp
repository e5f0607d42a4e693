// OverlapSensorModel (O-MCL: footprint overlap, no noise model) as a value type, at hand-computed cases.
#include <gtest/gtest.h>
#include <simp/maps/OverlapSensorModel.h>

#include "TestMaps.h"

#include <cmath>
#include <stdexcept>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;

TEST(OverlapSensorModel, KnownShiftGivesTheHandComputedValue) {
    // Two 0.5 m squares shifted by 0.2 m: IoU = 0.3 / 0.7 = 3/7, p = IoU exp(IoU - 1) + (1 - IoU) 0.1,
    // log p = -1.206760321070311.
    const auto data = test::oneChairMap();
    const OverlapSensorModel model(data, OverlapSensorModelParams{});
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const auto det = test::prepared(model, data, o, 0);
    ASSERT_TRUE(det.has_value());
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0.2, 0, 0)), -1.2067603210703108, 1e-12);
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0, 0, 0)), 0.0, 1e-12);  // IoU = 1
    EXPECT_EQ(model.logLikelihood(*det, TPose2D(0.5, 0, 0)), std::log(0.1));  // touching: IoU = 0
    EXPECT_EQ(model.logLikelihood(*det, TPose2D(3.0, 0, 0)), std::log(0.1));
}

TEST(OverlapSensorModel, TheBestOverlapOfTheClassCounts) {
    // A second chair 0.3 m to the right of the first: the detection shifted 0.2 m towards it
    // overlaps it by IoU 0.4 / 0.6 = 2/3, more than the first's 3/7.
    auto data = test::oneChairMap();
    data.objects.push_back(test::object(2, data, "chair", 2.3, 1.0, 0.0, 0.5, 0.5, 0.9));
    const OverlapSensorModel model(data, OverlapSensorModelParams{});
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const auto det = test::prepared(model, data, o, 0);
    ASSERT_TRUE(det.has_value());
    const double iou = 2.0 / 3.0;
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0.2, 0, 0)), std::log(iou * std::exp(iou - 1.0) + (1 - iou) * 0.1),
                1e-12);
}

TEST(OverlapSensorModel, ScoresEveryClassWithAnObject) {
    auto data = test::oneChairMap();
    data.class_noise.assign(data.class_noise.size(), std::nullopt);  // no noise model needed
    const OverlapSensorModel model(data, OverlapSensorModelParams{});
    EXPECT_TRUE(model.scoresClass(data.classId("chair")));
    EXPECT_FALSE(model.scoresClass(data.classId("table")));
    EXPECT_FALSE(model.scoresClass(-1));
    EXPECT_FALSE(model.empty());
    EXPECT_THROW(OverlapSensorModel(data, OverlapSensorModelParams{0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace simp::maps
