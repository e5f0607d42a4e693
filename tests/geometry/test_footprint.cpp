/// Tests of simp/geometry/Footprint.h: the ground footprint of upright and tilted boxes.
#include <simp/geometry/Footprint.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace simp::geometry {
namespace {

TEST(Footprint, UprightBoxIsItsRectangle) {
    const Box3D b = makeUprightBox({1, 2, 0.4}, {2.0, 1.0, 0.8}, 0.3);
    const ConvexPolygon f = footprint(b);
    ASSERT_EQ(f.n, 4u);
    EXPECT_NEAR(f.area(), 2.0, 1e-12);
    EXPECT_TRUE(f.centroid().isApprox(Eigen::Vector2d(1, 2)));
    EXPECT_NEAR(iou(f, makeRectangle({1, 2}, 2.0, 1.0, 0.3)), 1.0, 1e-12);
}

TEST(Footprint, BoxTiltedAboutX) {
    // W = 2 along x, H = 1 and L = 3 in the tilted yz plane: tilted by theta about x the
    // footprint is W by (H |cos theta| + L |sin theta|).
    const double theta = M_PI / 6;
    Box3D b;
    b.size = {2.0, 1.0, 3.0};
    b.R = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitX()).toRotationMatrix();
    const ConvexPolygon f = footprint(b);
    const double width = std::cos(theta) + 3.0 * std::sin(theta);
    ASSERT_EQ(f.n, 4u);
    EXPECT_NEAR(f.area(), 2.0 * width, 1e-12);
    EXPECT_NEAR(iou(f, makeRectangle({0, 0}, 2.0, width, 0.0)), 1.0, 1e-12);
}

TEST(Footprint, GeneralTiltMatchesTheProjectedArea) {
    // The shadow of a box on the xy plane has area sum_k |R(2,k)| * (area of the faces normal
    // to box axis k) = |R(2,0)| H L + |R(2,1)| W L + |R(2,2)| W H (each face pair covers it once).
    std::mt19937_64 rng(3);
    std::normal_distribution<double> n01;
    std::uniform_real_distribution<double> size(0.2, 2.0);
    for (int trial = 0; trial < 200; ++trial) {
        Box3D b;
        b.center = {n01(rng), n01(rng), n01(rng)};
        b.size = {size(rng), size(rng), size(rng)};
        b.R = Eigen::Quaterniond(n01(rng), n01(rng), n01(rng), n01(rng)).normalized().toRotationMatrix();
        const double W = b.size[0], H = b.size[1], L = b.size[2];
        const double expected =
            std::abs(b.R(2, 0)) * H * L + std::abs(b.R(2, 1)) * W * L + std::abs(b.R(2, 2)) * W * H;
        const ConvexPolygon f = footprint(b);
        EXPECT_LE(f.n, 6u);  // a box's shadow is at most a hexagon
        EXPECT_NEAR(f.area(), expected, 1e-10) << "trial " << trial;
        EXPECT_TRUE(f.centroid().isApprox(b.center.head<2>(), 1e-9));
    }
}

}  // namespace
}  // namespace simp::geometry
