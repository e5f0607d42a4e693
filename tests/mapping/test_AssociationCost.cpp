#include <gtest/gtest.h>
#include <simp/geometry/Box3DIoU.h>
#include <simp/mapping/AssociationCost.h>

#include <cmath>

using simp::geometry::Box3D;
using simp::geometry::makeUprightBox;
using namespace simp::mapping;

namespace {
simp::model::NoiseModel anisotropic(double sx, double sy, double b = 2.0) {
    simp::model::NoiseModel n;
    n.cov_m2 << sx * sx, 0, 0, sy * sy;
    n.exponent_b = b;
    return n;
}
}  // namespace

/// p_o1 of o1 for a class noise model (class noise frame).
simp::model::ObjectDistribution classP(const Box3D& o1, const simp::model::NoiseModel& n) {
    return simp::model::makeObjectDistribution(o1, n, simp::model::NoiseSource::Class);
}

TEST(AssociationCost, IdenticalBoxesCostZero) {
    const Box3D b = makeUprightBox({1, 2, 0.5}, {1.2, 0.8, 1.0}, 0.3);
    EXPECT_NEAR(associationCost(b, classP(b, anisotropic(0.2, 0.2)), b), 0.0, 1e-12);
}

TEST(AssociationCost, CentreCostIsMahalanobisInTheNoiseFrame) {
    // Object rotated by 90 deg, square footprint (class frame = box frame): its local x is the world y.
    const Box3D o = makeUprightBox({0, 0, 0.5}, {1, 1, 1}, M_PI / 2);
    const auto n = anisotropic(0.1, 0.4);
    const auto cost_at = [&](const simp::model::NoiseModel& noise, double x, double y) {
        const Box3D o2 = makeUprightBox({x, y, 0.5}, {1, 1, 1}, M_PI / 2);
        const double c_iou = 1.0 - simp::geometry::iou3D(o, o2);
        return 2.0 * associationCost(o, classP(o, noise), o2) - c_iou;  // = C_cen = 1 - p_o1(c_o2)
    };
    // One sigma along the object's x (= world y): m = 1 -> exp(-0.5).
    EXPECT_NEAR(cost_at(n, 0, 0.1), 1.0 - std::exp(-0.5), 1e-9);
    // One sigma along the object's y (= world -x): 0.4 m.
    EXPECT_NEAR(cost_at(n, -0.4, 0), 1.0 - std::exp(-0.5), 1e-9);
    // b = 4, m = 2: exp(-0.5 * 2^4).
    EXPECT_NEAR(cost_at(anisotropic(0.1, 0.4, 4.0), 0, 0.2), 1.0 - std::exp(-8.0), 1e-12);
    // The noise mean shifts the expected centre (noise frame).
    auto shifted = n;
    shifted.mean_m = {0.3, 0.0};
    EXPECT_NEAR(cost_at(shifted, 0, 0.3), 0.0, 1e-12);
}

TEST(AssociationCost, AnObjectsOwnNoiseIsReadInItsBoxFrame) {
    // A cabinet 1.6 m long along its x (the class frame is turned by 90 deg) with its own noise,
    // long along the box x (imported maps: the authors' per-object models are in the box frame).
    // A prediction 0.3 m along that axis is one sigma away with the object's frame, but six
    // sigma away if the same numbers were read in the class frame.
    const Box3D o1 = makeUprightBox({0, 0, 0.9}, {1.6, 0.5, 1.8}, 0.0);
    const Box3D o2 = makeUprightBox({0.3, 0, 0.9}, {1.6, 0.5, 1.8}, 0.0);
    const auto own = anisotropic(0.3, 0.05);  // sigma 0.3 m along the box x, 0.05 m across
    const double c_iou = 1.0 - simp::geometry::iou3D(o1, o2);
    const auto p_own = simp::model::makeObjectDistribution(o1, own, simp::model::NoiseSource::Object);
    EXPECT_NEAR(associationCost(o1, p_own, o2), 0.5 * (c_iou + 1.0 - std::exp(-0.5)), 1e-9);
    EXPECT_NEAR(associationCost(o1, classP(o1, own), o2), 0.5 * (c_iou + 1.0 - std::exp(-0.5 * 36.0)), 1e-9);
}

TEST(AssociationCost, CostCombinesIoUAndCentre) {
    const Box3D a = makeUprightBox({0, 0, 0.5}, {1, 1, 1}, 0);
    const Box3D b = makeUprightBox({0.5, 0, 0.5}, {1, 1, 1}, 0);  // IoU = 0.5 / 1.5
    const auto n = anisotropic(0.5, 0.5);                         // m = 1
    const double expected = 0.5 * ((1.0 - 1.0 / 3.0) + (1.0 - std::exp(-0.5)));
    EXPECT_NEAR(associationCost(a, classP(a, n), b), expected, 1e-9);
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
