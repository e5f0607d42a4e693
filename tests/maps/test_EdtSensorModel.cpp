// EdtSensorModel (EDT-MCL: beam-end model of the detection centre) as a value type.
#include <gtest/gtest.h>
#include <simp/maps/EdtSensorModel.h>

#include "TestMaps.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;

TEST(EdtSensorModel, ValuesFollowTheBeamEndModel) {
    const auto data = test::oneChairMap();
    const EdtSensorModel model(data, EdtSensorModelParams{});  // sigma 0.3 m, clamp 2 m, eta 0.1
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const auto det = test::prepared(model, data, o, 0);
    ASSERT_TRUE(det.has_value());
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0.1, 0, 0)), 0.0, 1e-12);  // centre inside: d = 0, p_hit = 1
    // Far away: d clamped to 2 m, p_hit = exp(-4 / 0.18), log p = -2.302585090983778.
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(50, 0, 0)), -2.3025850909837775, 1e-12);
    // In between: the formula on the raster's distance (0.25 m up to two cells).
    const double d = model.edt().distance(det->map_class, 2.5, 1.0);
    EXPECT_NEAR(d, 0.25, 0.1);
    const double p_hit = std::exp(-d * d / (2 * 0.3 * 0.3));
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(0.5, 0, 0)), std::log(p_hit + (1 - p_hit) * 0.1), 1e-12);
}

TEST(EdtSensorModel, RangeGrowthWidensSigma) {
    // Centre sqrt(5) m away, reference 1 m: sigma -> sqrt(5) sigma; at the 2 m clamp
    // p_hit = exp(-4 / 0.18 / 5), log p = -2.202113116293790.
    const auto data = test::oneChairMap();
    EdtSensorModelParams params;
    params.noise_reference_range_m = 1.0;
    const EdtSensorModel model(data, params);
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const auto det = test::prepared(model, data, o, 0);
    ASSERT_TRUE(det.has_value());
    EXPECT_NEAR(model.logLikelihood(*det, TPose2D(50, 0, 0)), -2.2021131162937904, 1e-12);
}

TEST(EdtSensorModel, ScoresEveryClassWithAnObjectAndChecksItsParameters) {
    const auto data = test::oneChairMap();
    const EdtSensorModel model(data, EdtSensorModelParams{});
    EXPECT_TRUE(model.scoresClass(data.classId("chair")));
    EXPECT_FALSE(model.scoresClass(data.classId("table")));
    EXPECT_FALSE(model.empty());
    for (const std::string key : {"edt_sigma_m", "edt_max_distance_m", "edt_resolution_m"}) {
        EdtSensorModelParams p;
        (key == "edt_sigma_m" ? p.sigma_m : key == "edt_max_distance_m" ? p.max_distance_m : p.resolution_m) = 0.0;
        try {
            EdtSensorModel m(data, p);
            ADD_FAILURE() << key << " = 0 accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace simp::maps
