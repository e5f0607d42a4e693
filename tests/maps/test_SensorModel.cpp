// The sensor models (Eqs. globaldist, iouscore, combined and the baselines) on a synthetic map.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <simp/maps/CObjectMap.h>
#include <simp/maps/SensorModel.h>

#include "TestMaps.h"

#include <cmath>
#include <limits>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;

/// A map scoring with `type` and each noise model as given (the paper's equations: no yaw term,
/// mp_centre_noise_floor = 0 unless `centre_noise_floor` says otherwise).
CObjectMap makeMap(const world::ObjectMapData& data, SensorModelType type, double centre_noise_floor = 0.0) {
    CObjectMap map;
    map.likelihoodOptions.sensor_model = type;
    map.likelihoodOptions.mp_centre_noise_floor = centre_noise_floor;
    map.likelihoodOptions.yaw_sigma_rad = 0.0;
    map.setData(data);
    return map;
}

/// Sum over used detections of log p for one pose.
double logSum(const CObjectMap& map, const obs::CObservationObjects3D& o, const TPose2D& pose, std::size_t* used = nullptr) {
    double sum = 0;
    std::size_t u = 0;
    map.accumulateLogLikelihoods(o, &pose, 1, &sum, u);
    if (used) *used = u;
    return sum;
}

const TPose2D kTruth(1.0, 0.5, 0.4);

TEST(SensorModelSimp, PeaksAtTheTruePose) {
    const auto data = test::smallMap();
    const auto map = makeMap(data, SensorModelType::Simp);
    const auto o = test::detect(data, kTruth, {0, 1, 2, 3});
    // Detections equal the map boxes and the noise is zero-mean: at the true pose p_o = 1 and
    // IoU = 1 for each, so p = 1 (Eq. combined) and the log-likelihood is exactly 0, its maximum.
    std::size_t used = 0;
    EXPECT_NEAR(logSum(map, o, kTruth, &used), 0.0, 1e-9);
    EXPECT_EQ(used, 4u);
    // Every other pose of a grid around it (+-1 m, +-0.5 rad) scores strictly less.
    int n = 0;
    for (double dx = -1.0; dx <= 1.0001; dx += 0.1)
        for (double dy = -1.0; dy <= 1.0001; dy += 0.1)
            for (double dphi = -0.5; dphi <= 0.5001; dphi += 0.05) {
                if (std::abs(dx) < 1e-9 && std::abs(dy) < 1e-9 && std::abs(dphi) < 1e-9) continue;
                const TPose2D p(kTruth.x + dx, kTruth.y + dy, kTruth.phi + dphi);
                ASSERT_LT(logSum(map, o, p), -1e-6) << "pose " << p.asString();
                ++n;
            }
    EXPECT_GT(n, 9000);
}

TEST(SensorModelSimp, CombinedMatchesTheEquationsForAKnownShift) {
    // One axis-aligned chair (0.5 x 0.5 m, class noise sigma 0.2 x 0.15 m, b = 2).
    auto data = test::smallMap();
    data.objects = {test::object(1, data, "chair", 2.0, 1.0, 0.0, 0.5, 0.5, 0.9)};
    const auto map = makeMap(data, SensorModelType::Simp);
    const double eta = map.likelihoodOptions.eta;
    const TPose2D truth(0.0, 0.0, 0.0);
    const auto o = test::detect(data, truth, {0});
    for (const double dx : {0.0, 0.05, 0.1, 0.2, 0.3, 0.45}) {
        // Moving the robot by dx along world x moves the detection by dx along the object's x.
        const double p_o = std::exp(-0.5 * (dx / 0.2) * (dx / 0.2));   // Eq. globaldist (one object)
        const double iou = (0.5 - dx) / (0.5 + dx);                      // two 0.5 m squares shifted by dx
        const double p_g = std::exp(-(1.0 - iou));                       // Eq. iouscore
        const double p = p_o * p_g + (1.0 - p_o) * eta;                  // Eq. combined
        const auto got = map.detectionLogLikelihood(o, 0, TPose2D(truth.x + dx, truth.y, truth.phi));
        ASSERT_TRUE(got.has_value());
        EXPECT_NEAR(*got, std::log(p), 1e-9) << "dx = " << dx;
    }
    // No footprint overlap but inside the support: p_g = exp(-1).
    const double dx = 0.6;
    const double p_o = std::exp(-0.5 * (dx / 0.2) * (dx / 0.2));
    EXPECT_NEAR(*map.detectionLogLikelihood(o, 0, TPose2D(dx, 0, 0)), std::log(p_o * std::exp(-1.0) + (1 - p_o) * eta), 1e-12);
    // Beyond the support (p_o < 1e-4 there): exactly eta.
    EXPECT_DOUBLE_EQ(*map.detectionLogLikelihood(o, 0, TPose2D(1.5, 0, 0)), std::log(eta));
    // With the centre noise (mp_centre_noise_floor > 0, model::withoutFootprint) p_o has the model's
    // std less the 0.5 m footprint's: sqrt(0.2^2 - 0.5^2 / 12) = 0.138 m along x (above the floor).
    const auto centre = makeMap(data, SensorModelType::Simp, 0.35);
    const double sigma_x = std::sqrt(0.2 * 0.2 - 0.5 * 0.5 / 12.0);
    for (const double shift : {0.05, 0.1, 0.2, 0.3}) {
        const double pc_o = std::exp(-0.5 * (shift / sigma_x) * (shift / sigma_x));
        const double iou = (0.5 - shift) / (0.5 + shift);
        const double p = pc_o * std::exp(-(1.0 - iou)) + (1.0 - pc_o) * eta;
        EXPECT_NEAR(*centre.detectionLogLikelihood(o, 0, TPose2D(shift, 0, 0)), std::log(p), 1e-9) << "dx = " << shift;
    }
    // Far outside the raster: defined as p_o = 0, so eta.
    EXPECT_DOUBLE_EQ(*map.detectionLogLikelihood(o, 0, TPose2D(-500, 800, 1.0)), std::log(eta));
}

TEST(SensorModelSimp, ShapeTermPrefersTheRightOrientation) {
    // Rotating the robot about the detection's centre keeps p_o of a round (isotropic) noise
    // model but lowers the footprint IoU of an elongated table: p_g alone decides.
    auto data = test::smallMap();
    data.class_noise[data.classId("table")] = test::noise(0.3, 0.3, 2.0);
    data.objects = {test::object(1, data, "table", 2.0, 0.0, 0.0, 1.6, 0.6, 0.75)};
    const auto map = makeMap(data, SensorModelType::Simp);
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const auto& box = o.boxInRobot(0);
    const double at_truth = *map.detectionLogLikelihood(o, 0, TPose2D(0, 0, 0));
    double previous = at_truth;
    for (const double a : {0.1, 0.3, 0.6, 1.0}) {
        // Pose rotated by a about the world point (2, 0) where the detection lands.
        const double c = std::cos(a), s = std::sin(a);
        const Eigen::Vector2d d = box.center.head<2>();
        const TPose2D p(2.0 - (c * d.x() - s * d.y()), 0.0 - (s * d.x() + c * d.y()), a);
        const double v = *map.detectionLogLikelihood(o, 0, p);
        EXPECT_LT(v, previous) << "rotation " << a;
        previous = v;
    }
}

class Baselines : public ::testing::TestWithParam<SensorModelType> {};

TEST_P(Baselines, PreferTheTruePose) {
    const auto data = test::smallMap();
    const auto map = makeMap(data, GetParam());
    const auto o = test::detect(data, kTruth, {0, 1, 2, 3});
    std::size_t used = 0;
    const double at_truth = logSum(map, o, kTruth, &used);
    EXPECT_EQ(used, 4u);
    // Every model reaches its maximum (p = 1 per detection, log 0) at the truth ...
    EXPECT_NEAR(at_truth, 0.0, 1e-9);
    // ... and no pose of the grid scores more; poses at least 0.7 m or 0.3 rad away score less
    // (0.7 m puts the 0.5 m chair's centre >= 0.35 m outside its footprint, whatever the model).
    double best_far = -std::numeric_limits<double>::infinity();
    for (double dx = -1.0; dx <= 1.0001; dx += 0.1)
        for (double dy = -1.0; dy <= 1.0001; dy += 0.1)
            for (double dphi = -0.5; dphi <= 0.5001; dphi += 0.1) {
                const TPose2D p(kTruth.x + dx, kTruth.y + dy, kTruth.phi + dphi);
                const double v = logSum(map, o, p);
                ASSERT_LE(v, at_truth + 1e-9);
                if (std::hypot(dx, dy) >= 0.7 - 1e-9 || std::abs(dphi) >= 0.3 - 1e-9) best_far = std::max(best_far, v);
            }
    EXPECT_LT(best_far, at_truth - 0.05) << toString(GetParam());
}

INSTANTIATE_TEST_SUITE_P(AllModels, Baselines,
                         ::testing::Values(SensorModelType::Simp, SensorModelType::Edt, SensorModelType::D,
                                           SensorModelType::O),
                         [](const auto& info) { return toString(info.param); });

TEST(SensorModelBaselines, ValuesFollowTheirDefinitions) {
    auto data = test::smallMap();
    data.objects = {test::object(1, data, "chair", 2.0, 1.0, 0.0, 0.5, 0.5, 0.9)};
    const auto o = test::detect(data, TPose2D(0, 0, 0), {0});
    const double eta = 0.1;
    const double dx = 0.2;
    // D: p = p_o + (1 - p_o) eta.
    const auto d = makeMap(data, SensorModelType::D);
    const double p_o = std::exp(-0.5 * (dx / 0.2) * (dx / 0.2));
    EXPECT_NEAR(*d.detectionLogLikelihood(o, 0, TPose2D(dx, 0, 0)), std::log(p_o + (1 - p_o) * eta), 1e-9);
    // O: IoU as the association probability: p = IoU exp(-(1 - IoU)) + (1 - IoU) eta.
    const auto om = makeMap(data, SensorModelType::O);
    const double iou = (0.5 - dx) / (0.5 + dx);
    EXPECT_NEAR(*om.detectionLogLikelihood(o, 0, TPose2D(dx, 0, 0)),
                std::log(iou * std::exp(iou - 1.0) + (1 - iou) * eta), 1e-9);
    EXPECT_DOUBLE_EQ(*om.detectionLogLikelihood(o, 0, TPose2D(3.0, 0, 0)), std::log(eta));
    // EDT: centre 0.5 m outside the footprint (0.25 m half side + 0.25): distance 0.25 m up to
    // the raster quantization (query-to-cell-centre and polygon rasterization: 2 cells, 0.1 m).
    const auto e = makeMap(data, SensorModelType::Edt);
    const double sigma = e.likelihoodOptions.edt_sigma_m;
    const double v = *e.detectionLogLikelihood(o, 0, TPose2D(0.5, 0, 0));
    const auto p_edt = [&](double dist) { const double h = std::exp(-dist * dist / (2 * sigma * sigma)); return std::log(h + (1 - h) * eta); };
    EXPECT_LE(v, p_edt(0.25 - 0.1));
    EXPECT_GE(v, p_edt(0.25 + 0.1));
    EXPECT_NEAR(*e.detectionLogLikelihood(o, 0, TPose2D(0.1, 0, 0)), 0.0, 1e-12);  // centre inside: d = 0
    EXPECT_NEAR(*e.detectionLogLikelihood(o, 0, TPose2D(50, 0, 0)), p_edt(e.likelihoodOptions.edt_max_distance_m), 1e-6);
}

TEST(SensorModelSimp, BatchEqualsScalarAndSingw) {
    const auto data = test::smallMap();
    const auto map = makeMap(data, SensorModelType::Simp);
    const auto o = test::detect(data, kTruth, {0, 1, 2, 4});
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> ux(-2, 6), uy(-3, 4), uphi(-M_PI, M_PI);
    std::vector<TPose2D> poses;
    for (int i = 0; i < 500; ++i) poses.emplace_back(ux(rng), uy(rng), uphi(rng));
    std::vector<double> sums(poses.size(), 1.5);  // accumulate adds to what is there
    std::size_t used = 0;
    map.accumulateLogLikelihoods(o, poses.data(), poses.size(), sums.data(), used);
    EXPECT_EQ(used, 4u);
    for (std::size_t i = 0; i < poses.size(); ++i) {
        double expected = 1.5;
        for (std::size_t k = 0; k < o.size(); ++k) expected += *map.detectionLogLikelihood(o, k, poses[i]);
        ASSERT_NEAR(sums[i], expected, 1e-12);
        // Eq. singw through MRPT's interface: the mean of the per-detection logs.
        const double mrpt_value = map.computeObservationLikelihood(o, test::pose3D(poses[i]));
        ASSERT_NEAR(mrpt_value, (expected - 1.5) / 4.0, 1e-12);
    }
}

TEST(SensorModelSimp, CamerasTogetherEqualOneCallPerCameraBitForBit) {
    const auto data = test::smallMap();
    const auto map = makeMap(data, SensorModelType::Simp);
    // Three cameras; the third sees 20 detections (more than one chunk of 16), one is weighted.
    std::vector<std::size_t> many;
    for (int i = 0; i < 20; ++i) many.push_back(static_cast<std::size_t>(i % 5));
    const auto a = test::detect(data, kTruth, {0, 1});
    const auto b = test::detect(data, kTruth, {2});
    const auto c = test::detect(data, kTruth, many);
    const std::vector<double> weights_b = {0.3};
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-0.4, 0.4);
    std::vector<TPose2D> poses;
    for (int i = 0; i < 300; ++i) poses.emplace_back(kTruth.x + u(rng), kTruth.y + u(rng), kTruth.phi + u(rng));
    std::vector<double> separate(poses.size(), -0.5), together(poses.size(), -0.5);
    std::size_t used_separate = 0, used_together = 0;
    map.accumulateLogLikelihoods(a, poses.data(), poses.size(), separate.data(), used_separate);
    map.accumulateLogLikelihoods(b, poses.data(), poses.size(), separate.data(), used_separate, weights_b.data());
    map.accumulateLogLikelihoods(c, poses.data(), poses.size(), separate.data(), used_separate);
    const CObjectMap::WeightedDetections cameras[] = {{&a, nullptr}, {&b, weights_b.data()}, {&c, nullptr}};
    map.accumulateLogLikelihoods(cameras, 3, poses.data(), poses.size(), together.data(), used_together);
    EXPECT_EQ(used_separate, 23u);
    EXPECT_EQ(used_together, 23u);
    for (std::size_t i = 0; i < poses.size(); ++i) ASSERT_EQ(together[i], separate[i]) << "pose " << i;
}

TEST(SensorModelSimp, AZeroWeightDetectionIsNeitherScoredNorCounted) {
    // Exponent 0 marks a detection the filter leaves out (an object the map does not hold there):
    // the sums and the count equal those of the observation without it.
    const auto data = test::smallMap();
    const auto map = makeMap(data, SensorModelType::Simp);
    const auto with = test::detect(data, kTruth, {0, 1, 2});
    const auto without = test::detect(data, kTruth, {0, 2});
    const std::vector<double> weights = {1.0, 0.0, 0.5}, kept = {1.0, 0.5};
    const std::vector<TPose2D> poses = {kTruth, TPose2D(kTruth.x + 0.3, kTruth.y - 0.2, kTruth.phi + 0.1)};
    std::vector<double> a(poses.size(), 0.0), b(poses.size(), 0.0);
    std::size_t used_a = 0, used_b = 0;
    map.accumulateLogLikelihoods(with, poses.data(), poses.size(), a.data(), used_a, weights.data());
    map.accumulateLogLikelihoods(without, poses.data(), poses.size(), b.data(), used_b, kept.data());
    EXPECT_EQ(used_a, 2u);
    EXPECT_EQ(used_b, 2u);
    for (std::size_t i = 0; i < poses.size(); ++i) EXPECT_EQ(a[i], b[i]) << "pose " << i;
}

/// The value type of `name` built directly with the parameters the .ini of SelectedByTheIniKey sets.
template <typename Model>
void expectSameAsTheValueType(const CObjectMap& map, const Model& model, const world::ObjectMapData& data) {
    ASSERT_TRUE(std::holds_alternative<Model>(map.sensorModel()->model()));
    const auto o = test::detect(data, kTruth, {0, 1, 2, 3});
    std::vector<PreparedDetection> dets;
    for (std::size_t k = 0; k < o.size(); ++k) dets.push_back(*test::prepared(model, data, o, k));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ux(-2, 6), uy(-3, 4), uphi(-M_PI, M_PI), u(-0.2, 0.2);
    std::vector<TPose2D> poses;
    for (int i = 0; i < 400; ++i)  // global, then around the truth (most pairs on an object)
        poses.push_back(i < 200 ? TPose2D(ux(rng), uy(rng), uphi(rng)) : TPose2D(kTruth.x + u(rng), kTruth.y + u(rng), kTruth.phi + u(rng)));
    std::vector<double> via_map(poses.size(), 0.0), direct(poses.size(), 0.0);
    std::size_t used = 0;
    map.accumulateLogLikelihoods(o, poses.data(), poses.size(), via_map.data(), used);
    model.accumulateLogLikelihoods(dets.data(), dets.size(), poses.data(), poses.size(), direct.data());
    EXPECT_EQ(used, 4u);
    std::size_t off_floor = 0;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        ASSERT_EQ(via_map[i], direct[i]) << "pose " << i;  // bit for bit
        off_floor += direct[i] > 4 * std::log(0.2) + 1e-9 ? 1 : 0;
    }
    EXPECT_GT(off_floor, 150u);
}

TEST(SensorModelSelection, TheIniKeySelectsTheValueTypeWithItsParameters) {
    const auto data = test::smallMap();
    for (const std::string name : {"simp", "edt", "d", "o"}) {
        SCOPED_TRACE(name);
        mrpt::config::CConfigFileMemory ini("[L]\nsensor_model = " + name +
                                            "\neta = 0.2\nnoise_reference_range_m = 1.5\nmp_resolution_m = 0.04\n"
                                            "edt_sigma_m = 0.4\nedt_resolution_m = 0.04\n"
                                            "mp_centre_noise_floor = 0.3\nyaw_sigma_rad = 0.05\n");
        CObjectMap map;
        map.likelihoodOptions.loadFromConfigFile(ini, "L");
        map.setData(data);
        ObjectProbabilityMap::Options mp;
        mp.resolution_m = 0.04;
        mp.centre_noise_floor = 0.3;
        if (name == "simp") expectSameAsTheValueType(map, SimpSensorModel(data, {0.2, mp, 1.5, 0.05}), data);
        if (name == "d") expectSameAsTheValueType(map, CentreSensorModel(data, {0.2, mp, 1.5}), data);
        if (name == "o") expectSameAsTheValueType(map, OverlapSensorModel(data, {0.2}), data);
        if (name == "edt") expectSameAsTheValueType(map, EdtSensorModel(data, {0.2, 0.4, 2.0, 0.04, 1.5}), data);
    }
}

TEST(SensorModelSelection, EveryParameterOfTheSetIsChecked) {
    // An EDT parameter out of range is an error with the simp model too (as before the split).
    SensorModelParams p;
    p.edt_sigma_m = -1.0;
    EXPECT_THROW(SensorModel(test::smallMap(), p), std::invalid_argument);
    p = {};
    p.type = SensorModelType::O;
    p.mp.min_probability = 0.0;
    EXPECT_THROW(SensorModel(test::smallMap(), p), std::invalid_argument);
    p = {};
    EXPECT_TRUE(SensorModel(test::smallMap(), p).probabilityMap().hasClass(test::smallMap().classId("chair")));
    p.type = SensorModelType::Edt;
    EXPECT_EQ(SensorModel(test::smallMap(), p).probabilityMap().numClasses(), 0u);  // edt has no m_p
}

}  // namespace
}  // namespace simp::maps
