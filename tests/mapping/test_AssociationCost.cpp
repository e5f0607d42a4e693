#include <gtest/gtest.h>
#include <simp/geometry/Box3DIoU.h>
#include <simp/mapping/AssociationCost.h>

#include <cmath>

using simp::geometry::Box3D;
using simp::geometry::makeUprightBox;
using namespace simp::mapping;

namespace {
simp::world::NoiseModel anisotropic(double sx, double sy, double b = 2.0) {
    simp::world::NoiseModel n;
    n.cov_m2 << sx * sx, 0, 0, sy * sy;
    n.exponent_b = b;
    return n;
}
}  // namespace

TEST(AssociationCost, IdenticalBoxesCostZero) {
    const Box3D b = makeUprightBox({1, 2, 0.5}, {1.2, 0.8, 1.0}, 0.3);
    EXPECT_NEAR(associationCost(b, anisotropic(0.2, 0.2), b), 0.0, 1e-12);
}

TEST(AssociationCost, CenterScoreIsMahalanobisInTheObjectFrame) {
    // Object rotated by 90 deg: its local x is the world y.
    const Box3D o = makeUprightBox({0, 0, 0.5}, {1, 1, 1}, M_PI / 2);
    const auto n = anisotropic(0.1, 0.4);
    // One sigma along the object's x (= world y): m = 1 -> exp(-0.5).
    EXPECT_NEAR(centerScore(o, n, {0, 0.1, 0.5}), std::exp(-0.5), 1e-9);
    // One sigma along the object's y (= world -x): 0.4 m.
    EXPECT_NEAR(centerScore(o, n, {-0.4, 0, 0.5}), std::exp(-0.5), 1e-9);
    // b = 4, m = 2: exp(-0.5 * 2^4).
    EXPECT_NEAR(centerScore(o, anisotropic(0.1, 0.4, 4.0), {0, 0.2, 0.5}), std::exp(-8.0), 1e-12);
    // The class mean shifts the expected centre (object frame).
    auto shifted = n;
    shifted.mean_m = {0.3, 0.0};
    EXPECT_NEAR(centerScore(o, shifted, {0, 0.3, 0.5}), 1.0, 1e-12);
}

TEST(AssociationCost, CostCombinesIoUAndCentre) {
    const Box3D a = makeUprightBox({0, 0, 0.5}, {1, 1, 1}, 0);
    const Box3D b = makeUprightBox({0.5, 0, 0.5}, {1, 1, 1}, 0);  // IoU = 0.5 / 1.5
    const auto n = anisotropic(0.5, 0.5);                         // m = 1
    const double expected = 0.5 * ((1.0 - 1.0 / 3.0) + (1.0 - std::exp(-0.5)));
    EXPECT_NEAR(associationCost(a, n, b), expected, 1e-9);
}

TEST(AssociationCost, ClosestEquivalentKeepsTheSolid) {
    const Box3D b = makeUprightBox({1, 1, 1}, {1, 2, 3}, 0.0);
    const Eigen::Matrix3d ref = Eigen::AngleAxisd(1.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Box3D e = closestEquivalent(b, ref);
    EXPECT_NEAR(simp::geometry::yawOf(e), M_PI / 2, 1e-12);
    EXPECT_DOUBLE_EQ(e.size.x(), 2.0);
    EXPECT_DOUBLE_EQ(e.size.y(), 1.0);
    EXPECT_DOUBLE_EQ(e.size.z(), 3.0);
    EXPECT_NEAR(simp::geometry::iou3D(b, e), 1.0, 1e-9);
}

TEST(AssociationCost, MergeIsTheWeightedAverage) {
    const Box3D a = makeUprightBox({0, 0, 0.5}, {1.0, 2.0, 1.0}, 0.0);
    const Box3D p = makeUprightBox({0.4, 0.8, 0.5}, {1.4, 2.4, 1.0}, 0.4);
    const Box3D m = mergeBoxes(a, 3, p, 1);
    EXPECT_NEAR(m.center.x(), 0.1, 1e-12);
    EXPECT_NEAR(m.center.y(), 0.2, 1e-12);
    EXPECT_NEAR(m.size.x(), 1.1, 1e-12);
    EXPECT_NEAR(m.size.y(), 2.1, 1e-12);
    // Equal weights of two rotations about z: the SVD mean is the mid angle.
    EXPECT_NEAR(simp::geometry::yawOf(mergeBoxes(a, 1, p, 1)), 0.2, 1e-9);
}

TEST(AssociationCost, MergeAlignsEquivalentRepresentations) {
    // The same object seen with W and L swapped (yaw + 90 deg) must not rotate the map object.
    const Box3D a = makeUprightBox({0, 0, 0.5}, {1.0, 2.0, 1.0}, 0.0);
    const Box3D p = makeUprightBox({0, 0, 0.5}, {2.0, 1.0, 1.0}, M_PI / 2 + 0.02);
    const Box3D m = mergeBoxes(a, 1, p, 1);
    EXPECT_NEAR(simp::geometry::yawOf(m), 0.01, 1e-9);
    EXPECT_NEAR(m.size.x(), 1.0, 1e-12);
    EXPECT_NEAR(m.size.y(), 2.0, 1e-12);
}
