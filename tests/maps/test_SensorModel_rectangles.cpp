// The sensor model's rectangle path (separating axes, then clipping in the map object's frame,
// geometry/OrientedRect.h) gives the same likelihoods as the generic convex clipping
// (geometry::iou on world polygons) up to rounding, for Simp and O, on rectangular and
// non-rectangular (tilted-box) footprints, at random and at hand-picked exact poses.
#include <gtest/gtest.h>
#include <simp/geometry/Footprint.h>
#include <simp/maps/IouScore.h>
#include <simp/maps/SensorModel.h>

#include "TestMaps.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;

/// Chairs and tables of random size and yaw in 8 m x 8 m, plus tilted ones (hexagonal footprints).
world::ObjectMapData randomMap(unsigned seed) {
    auto m = test::smallMap();
    m.objects.clear();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> upos(-4, 4), uyaw(-M_PI, M_PI), uside(0.2, 1.8);
    for (int i = 0; i < 40; ++i)
        m.objects.push_back(test::object(i, m, i % 2 ? "chair" : "table", upos(rng), upos(rng), uyaw(rng), uside(rng),
                                         uside(rng), 0.8));
    for (int i = 0; i < 6; ++i) {  // tilted: not a rectangle on the ground
        auto o = test::object(100 + i, m, i % 2 ? "chair" : "table", upos(rng), upos(rng), 0.0, 0.6, 0.9, 0.8);
        o.box.R = (Eigen::AngleAxisd(uyaw(rng), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()))
                      .toRotationMatrix();
        m.objects.push_back(o);
    }
    return m;
}

/// The map footprints of the Simp or O model.
const MapFootprints& footprintsOf(const SensorModel& model) {
    if (const auto* simp = std::get_if<SimpSensorModel>(&model.model())) return simp->footprints();
    return std::get<OverlapSensorModel>(model.model()).footprints();
}

/// log p of Simp or O at `pose` recomputed with the generic clipping (geometry::iou of the
/// world polygons), the same m_p lookup and the same equations.
double reference(const SensorModel& model, const world::ObjectMapData& data, const PreparedDetection& det,
                 const TPose2D& pose) {
    const double c = std::cos(pose.phi), s = std::sin(pose.phi), eta = model.params().eta;
    const geometry::ConvexPolygon fp = det.footprint_robot.transformed(c, s, {pose.x, pose.y});
    const double wx = c * det.center_robot_m.x() - s * det.center_robot_m.y() + pose.x;
    const double wy = s * det.center_robot_m.x() + c * det.center_robot_m.y() + pose.y;
    if (model.params().type == SensorModelType::Simp) {
        const auto hit = model.probabilityMap().lookup(det.map_class, wx, wy, det.noise_inv_scale2);
        if (hit.object < 0) return std::log(eta);
        const double iou = geometry::iou(fp, footprintsOf(model).objects[static_cast<std::size_t>(hit.object)].polygon);
        return std::log(hit.p * std::exp(iou - 1.0) + (1.0 - hit.p) * eta);
    }
    double best = 0.0;
    for (std::size_t o = 0; o < data.objects.size(); ++o)
        if (data.objects[o].class_id == det.map_class)
            best = std::max(best, geometry::iou(fp, footprintsOf(model).objects[o].polygon));
    if (best <= 0.0) return std::log(eta);
    return std::log(best * std::exp(best - 1.0) + (1.0 - best) * eta);
}

class Rectangles : public ::testing::TestWithParam<SensorModelType> {};

TEST_P(Rectangles, EqualGenericClippingAtRandomAndExactPoses) {
    const auto data = randomMap(7);
    SensorModelParams params;
    params.type = GetParam();
    const SensorModel model(data, params);
    std::size_t rect_objects = 0;
    for (const auto& f : footprintsOf(model).objects) rect_objects += f.is_rect ? 1 : 0;
    EXPECT_EQ(rect_objects, 40u);  // the upright boxes, not the tilted ones

    std::mt19937 rng(8);
    std::uniform_real_distribution<double> u(-1, 1), uyaw(-M_PI, M_PI);
    std::size_t compared = 0, on_object = 0;
    for (std::size_t i = 0; i < data.objects.size(); ++i) {
        // The detection: map object i seen from a robot at `truth` (robot frame), as an
        // upright box (rectangle) or as the object's own, possibly tilted, box.
        const TPose2D truth(data.objects[i].box.center.x() - 1.5, data.objects[i].box.center.y() + 0.4, uyaw(rng));
        const Eigen::Isometry3d robot_T_world = test::isometry(test::pose3D(truth)).inverse();
        const geometry::Box3D box = data.objects[i].box.transformed(robot_T_world);
        const auto det = model.prepare(data.objects[i].class_id, box, geometry::footprint(box));
        ASSERT_TRUE(det.has_value());
        EXPECT_EQ(det->is_rect, i < 40);
        std::vector<TPose2D> poses = {truth};  // IoU = 1 exactly
        // The detection shifted by exactly its length or width along its own axes: touching footprints.
        const double yaw = truth.phi + std::atan2(box.R(1, 0), box.R(0, 0));
        for (const double k : {-1.0, 1.0}) {
            const double lx = box.size.x(), ly = box.size.y();
            poses.emplace_back(truth.x + k * lx * std::cos(yaw), truth.y + k * lx * std::sin(yaw), truth.phi);
            poses.emplace_back(truth.x - k * ly * std::sin(yaw), truth.y + k * ly * std::cos(yaw), truth.phi);
            poses.emplace_back(truth.x, truth.y, truth.phi + k * M_PI / 2);  // turned about the robot
        }
        for (int j = 0; j < 400; ++j)  // tracking-like: around the truth; then farther
            poses.emplace_back(truth.x + 0.3 * u(rng) * (j < 200 ? 1 : 4), truth.y + 0.3 * u(rng) * (j < 200 ? 1 : 4),
                               truth.phi + 0.3 * u(rng) * (j < 200 ? 1 : 10));
        std::vector<double> batch(poses.size(), 0.0);
        model.accumulateLogLikelihoods(&*det, 1, poses.data(), poses.size(), batch.data());
        for (std::size_t p = 0; p < poses.size(); ++p) {
            const double expected = reference(model, data, *det, poses[p]);
            ASSERT_NEAR(model.logLikelihood(*det, poses[p]), expected, 1e-12) << "object " << i << " pose " << p;
            ASSERT_NEAR(batch[p], expected, 1e-12) << "object " << i << " pose " << p;
            ++compared;
            on_object += expected > std::log(params.eta) + 1e-9 ? 1 : 0;
        }
        EXPECT_NEAR(model.logLikelihood(*det, truth), reference(model, data, *det, truth), 1e-12);
    }
    EXPECT_GT(compared, 18000u);
    EXPECT_GT(on_object, compared / 4);  // mostly pairs that clip, not the eta floor
}

TEST(IouScore, EqualsExpWithinAFewUlp) {
    const IouScore score;
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i <= 200000; ++i) {
        // Random values, the table's knots j/256 and their neighbours, and the ends 0 and 1.
        double iou = i < 100000 ? u(rng) : (i - 100000) / 1562.5;
        if (i % 3 == 0) iou = std::nextafter(std::floor(iou * 256) / 256, 2.0);
        iou = std::clamp(iou, 0.0, 1.0);
        const double expected = std::exp(iou - 1.0);
        worst = std::max(worst, std::abs(score(iou) - expected) / expected);
    }
    EXPECT_LT(worst, 5e-16);  // ~2 ulp
    EXPECT_EQ(score(1.0), std::exp(0.0));
    EXPECT_EQ(score(0.0), std::exp(-1.0));
    EXPECT_EQ(score(-0.5), std::exp(-1.0));  // clamped like the IoU itself
}

TEST(IouScore, WithAYawPenaltyEqualsExpOfTheSumWithinAFewUlp) {
    const IouScore score;
    std::mt19937_64 rng(10);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 200000; ++i) {
        const double iou = u(rng), penalty = i % 4 == 0 ? 0.0 : u(rng);
        const double expected = std::exp(iou - 1.0 - penalty);
        worst = std::max(worst, std::abs(score(iou, penalty) - expected) / expected);
    }
    // One rounding more than the plain score: iou - penalty + 1 before the split.
    EXPECT_LT(worst, 8e-16);
    EXPECT_EQ(score(0.0, 1.0), std::exp(-2.0));
    EXPECT_EQ(score(1.0, 0.0), 1.0);
    EXPECT_EQ(score(0.5, 3.0), score(0.5, 1.0));  // the penalty is at most 1 nat
}

INSTANTIATE_TEST_SUITE_P(SimpAndO, Rectangles, ::testing::Values(SensorModelType::Simp, SensorModelType::O),
                         [](const auto& info) { return toString(info.param); });

}  // namespace
}  // namespace simp::maps
