// The simulator's centre noise from a footprint-heatmap noise model (centreNoiseOf): the model's
// spread minus the object's own extent (doc/simulator.md "Detection noise").
#include <gtest/gtest.h>
#include <simp/model/NoiseFrame.h>
#include <simp/sim/DetectionModel.h>
#include <simp/sim/Random.h>

#include <cmath>

namespace {

simp::world::MapObject boardAt(double yaw) {
    simp::world::MapObject o;
    o.id = 1;
    o.class_id = 3;
    // 1.8 m long along its local x, 0.15 m deep: the noise frame puts y along the 1.8 m side
    o.box = simp::geometry::makeUprightBox({2.0, 1.0, 1.3}, {1.8, 0.15, 1.0}, yaw);
    return o;
}

simp::model::NoiseModel boardModel() {
    // the authors' board row of class_noise.csv: sx = 2.95 px, sy = 12.66 px at 0.05 m/px, b = 2
    simp::model::NoiseModel m;
    m.mean_m << -0.046, 0.052;
    m.cov_m2 << std::pow(0.1476, 2), 0.0, 0.0, std::pow(0.6328, 2);
    m.exponent_b = 2.0;
    return m;
}

}  // namespace

TEST(SimCentreNoise, SubtractsTheFootprintVariancePerAxis) {
    const simp::sim::DetectorParams p;  // noise_model_includes_extent = true, floor 0.25
    ASSERT_TRUE(p.noise_model_includes_extent);
    for (const double yaw : {0.0, 0.7, M_PI / 2}) {  // the result is in the noise frame: yaw-independent
        const auto c = simp::sim::centreNoiseOf(boardModel(), boardAt(yaw), p);
        // across: 0.1476^2 - 0.15^2 / 12; along: 0.6328^2 - 1.8^2 / 12 (uniform footprint)
        EXPECT_NEAR(c.cov_m2(0, 0), std::pow(0.1476, 2) - 0.15 * 0.15 / 12, 1e-9) << "yaw " << yaw;
        EXPECT_NEAR(c.cov_m2(1, 1), std::pow(0.6328, 2) - 1.8 * 1.8 / 12, 1e-9) << "yaw " << yaw;
        EXPECT_NEAR(c.cov_m2(0, 1), 0.0, 1e-12);
        EXPECT_TRUE(c.mean_m.isApprox(boardModel().mean_m));  // mu and b are kept
        EXPECT_EQ(c.exponent_b, 2.0);
    }
}

TEST(SimCentreNoise, FloorsWhereTheExtentExplainsTheSpreadAndKeepsTheShape) {
    // A flat-topped model (b = 4) whose spread along y is less than a uniform 1.2 m footprint's:
    // the std is floored at min_centre_noise_fraction of the model's; Sigma scales, b stays.
    simp::model::NoiseModel m;
    m.cov_m2 << 0.09, 0.0, 0.0, 0.09;
    m.exponent_b = 4.0;
    simp::world::MapObject o;
    o.id = 2;
    o.box = simp::geometry::makeUprightBox({0, 0, 0.4}, {0.3, 1.2, 0.8}, 0.0);
    simp::sim::DetectorParams p;
    p.min_centre_noise_fraction = 0.25;
    const auto c = simp::sim::centreNoiseOf(m, o, p);
    const Eigen::Matrix2d model_cov = simp::model::offsetCovariance(m);  // 0.09 * E[r^2] / 2 = 0.09 * 0.40 per axis
    const Eigen::Matrix2d centre_cov = simp::model::offsetCovariance(c);
    EXPECT_NEAR(centre_cov(0, 0), model_cov(0, 0) - 0.3 * 0.3 / 12, 1e-9);
    EXPECT_NEAR(centre_cov(1, 1), 0.25 * 0.25 * model_cov(1, 1), 1e-9);
    EXPECT_EQ(c.exponent_b, 4.0);
}

TEST(SimCentreNoise, OffWhenTheModelIsAlreadyACentreModel) {
    simp::sim::DetectorParams p;
    p.noise_model_includes_extent = false;
    const auto c = simp::sim::centreNoiseOf(boardModel(), boardAt(0.3), p);
    EXPECT_TRUE(c.cov_m2.isApprox(boardModel().cov_m2));
}

TEST(SimCentreNoise, DrawnOffsetsHaveTheCentreCovariance) {
    // End to end through centreOffsetInWorld at the reference distance with per-frame noise only:
    // the sample covariance in the noise frame is the reduced one (4 standard errors).
    simp::sim::DetectorParams p;
    p.persistent_variance_fraction = 0.0;
    const auto o = boardAt(0.0);
    const auto c = simp::sim::centreNoiseOf(boardModel(), o, p);
    simp::camera::PinholeCamera view;
    view.world_T_camera = Eigen::Isometry3d::Identity();
    view.world_T_camera.translation() = Eigen::Vector3d(2.0, 1.0 - p.reference_distance_m, 0.63);
    simp::sim::Rng rng(9);
    const int n = 20000;
    double s_along = 0;
    const double yaw_n = simp::model::classNoiseFrameYaw(o.box);
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector2d e = Eigen::Rotation2Dd(-yaw_n) * (simp::sim::centreOffsetInWorld(view, o, c, p, 1, rng) -
                                                                 Eigen::Rotation2Dd(yaw_n) * c.mean_m);
        s_along += e.y() * e.y();
    }
    const double expected = c.cov_m2(1, 1);
    EXPECT_NEAR(s_along / n, expected, 4 * expected * std::sqrt(2.0 / n));
    EXPECT_LT(expected, 0.5 * boardModel().cov_m2(1, 1));  // the extent was most of the model's spread
}
