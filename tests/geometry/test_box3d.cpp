/// Tests of simp/geometry/Box3D.h: corner numbering, frame changes, validity,
/// upright boxes and the canonical upright re-expression.
#include <simp/geometry/Box3D.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace simp::geometry {
namespace {

constexpr double kTol = 1e-12;

Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<double> n01;
    Eigen::Quaterniond q(n01(rng), n01(rng), n01(rng), n01(rng));
    return q.normalized().toRotationMatrix();
}

/// True when every corner of a has a corner of b within tol (and vice versa): same solid.
bool sameCornerSet(const Box3D& a, const Box3D& b, double tol) {
    const auto ca = a.corners(), cb = b.corners();
    auto covered = [tol](const std::array<Eigen::Vector3d, 8>& x, const std::array<Eigen::Vector3d, 8>& y) {
        for (const auto& p : x) {
            bool found = false;
            for (const auto& q : y) found = found || (p - q).norm() <= tol;
            if (!found) return false;
        }
        return true;
    };
    return covered(ca, cb) && covered(cb, ca);
}

TEST(Box3D, CornerNumberingAxisAligned) {
    Box3D b;
    b.center = {1, 2, 3};
    b.size = {2, 4, 6};  // half extents (1, 2, 3): the box spans [0,2] x [0,4] x [0,6]
    const auto c = b.corners();
    EXPECT_TRUE(c[0].isApprox(Eigen::Vector3d(0, 0, 0)));
    EXPECT_TRUE(c[1].isApprox(Eigen::Vector3d(2, 0, 0)));  // bit 0: +x
    EXPECT_TRUE(c[2].isApprox(Eigen::Vector3d(0, 4, 0)));  // bit 1: +y
    EXPECT_TRUE(c[3].isApprox(Eigen::Vector3d(2, 4, 0)));
    EXPECT_TRUE(c[4].isApprox(Eigen::Vector3d(0, 0, 6)));  // bit 2: +z
    EXPECT_TRUE(c[7].isApprox(Eigen::Vector3d(2, 4, 6)));
    EXPECT_DOUBLE_EQ(b.volume(), 48.0);
}

TEST(Box3D, CornerNumberingRotated) {
    // Yaw 90 deg: box x -> frame y, box y -> frame -x.
    const Box3D b = makeUprightBox({1, 2, 3}, {2, 4, 6}, M_PI / 2);
    const auto c = b.corners();
    // Corner 1 = center + R (1, -2, -3) = center + (2, 1, -3).
    EXPECT_NEAR((c[1] - Eigen::Vector3d(3, 3, 0)).norm(), 0.0, kTol);
    // Corner 6 = center + R (-1, 2, 3) = center + (-2, -1, 3).
    EXPECT_NEAR((c[6] - Eigen::Vector3d(-1, 1, 6)).norm(), 0.0, kTol);
    // Opposite corners are symmetric about the centre.
    for (int i = 0; i < 8; ++i) EXPECT_NEAR((c[i] + c[7 - i] - 2 * b.center).norm(), 0.0, kTol);
}

TEST(Box3D, TransformedMovesCornersRigidly) {
    std::mt19937_64 rng(7);
    Box3D b;
    b.center = {0.5, -1.0, 2.0};
    b.size = {0.4, 0.9, 1.7};
    b.R = randomRotation(rng);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = randomRotation(rng);
    T.translation() = Eigen::Vector3d(3, -2, 1);
    const Box3D t = b.transformed(T);
    const auto c0 = b.corners(), c1 = t.corners();
    for (int i = 0; i < 8; ++i) EXPECT_NEAR((T * c0[i] - c1[i]).norm(), 0.0, 1e-12) << "corner " << i;
    EXPECT_TRUE(t.size.isApprox(b.size));
    EXPECT_TRUE(t.isValid());
}

TEST(Box3D, IsValid) {
    Box3D ok;
    EXPECT_TRUE(ok.isValid());
    Box3D nan_center = ok;
    nan_center.center.x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(nan_center.isValid());
    Box3D inf_size = ok;
    inf_size.size.y() = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(inf_size.isValid());
    Box3D zero_size = ok;
    zero_size.size.z() = 0.0;
    EXPECT_FALSE(zero_size.isValid());
    Box3D negative_size = ok;
    negative_size.size.x() = -1.0;
    EXPECT_FALSE(negative_size.isValid());
    Box3D reflection = ok;
    reflection.R(2, 2) = -1.0;  // orthonormal but det -1
    EXPECT_FALSE(reflection.isValid());
    Box3D sheared = ok;
    sheared.R(0, 1) = 1e-3;
    EXPECT_FALSE(sheared.isValid());
    EXPECT_TRUE(sheared.isValid(1e-2));  // within a looser tolerance
}

TEST(Box3D, MakeUprightBoxAndYaw) {
    for (const double yaw : {0.0, 0.3, -1.2, 2.9, -3.0}) {
        const Box3D b = makeUprightBox({1, 2, 0.5}, {2.0, 1.0, 0.8}, yaw);
        EXPECT_TRUE(b.isValid());
        EXPECT_NEAR(yawOf(b), yaw, kTol);
        EXPECT_TRUE(b.R.col(2).isApprox(Eigen::Vector3d::UnitZ()));
        EXPECT_NEAR(b.R(0, 0), std::cos(yaw), kTol);
        EXPECT_NEAR(b.R(1, 0), std::sin(yaw), kTol);
        EXPECT_TRUE(b.size.isApprox(Eigen::Vector3d(2.0, 1.0, 0.8)));
    }
}

TEST(Box3D, CanonicalizeUprightCameraBox) {
    // A camera-convention box: H along the box y axis, which points down (-z) in the world.
    Box3D cam;
    cam.center = {1, 2, 0.4};
    cam.size = {0.5, 0.8, 1.2};  // (W, H, L)
    cam.R.col(0) = Eigen::Vector3d(0, -1, 0);
    cam.R.col(1) = Eigen::Vector3d(0, 0, -1);
    cam.R.col(2) = Eigen::Vector3d(1, 0, 0);
    ASSERT_TRUE(cam.isValid());
    const Box3D up = canonicalizeUpright(cam);
    EXPECT_TRUE(up.isValid());
    EXPECT_TRUE(up.R.col(2).isApprox(Eigen::Vector3d::UnitZ()));
    EXPECT_DOUBLE_EQ(up.size.z(), 0.8);  // the height H is now the local z extent
    EXPECT_DOUBLE_EQ(up.volume(), cam.volume());
    EXPECT_TRUE(up.center.isApprox(cam.center));
    EXPECT_TRUE(sameCornerSet(cam, up, 1e-12));
}

TEST(Box3D, CanonicalizeUprightKeepsTheSolidForRandomRotations) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> size(0.1, 3.0);
    for (int trial = 0; trial < 500; ++trial) {
        Box3D b;
        b.center = {size(rng), -size(rng), size(rng)};
        b.size = {size(rng), size(rng), size(rng)};
        b.R = randomRotation(rng);
        const Box3D up = canonicalizeUpright(b);
        ASSERT_TRUE(up.isValid()) << "trial " << trial;
        EXPECT_TRUE(sameCornerSet(b, up, 1e-9)) << "trial " << trial;
        // The new z is the most vertical axis and points up.
        EXPECT_GE(up.R(2, 2), 0.0);
        EXPECT_GE(up.R(2, 2) + 1e-15, std::abs(up.R(2, 0)));
        EXPECT_GE(up.R(2, 2) + 1e-15, std::abs(up.R(2, 1)));
        // Idempotent.
        const Box3D twice = canonicalizeUpright(up);
        EXPECT_TRUE(twice.R.isApprox(up.R));
        EXPECT_TRUE(twice.size.isApprox(up.size));
    }
}

TEST(Box3D, ContainsPointUsesTheClosedBox) {
    const Box3D b = makeUprightBox({0, 0, 0}, {2, 1, 1}, M_PI / 2);  // long side along frame y
    EXPECT_TRUE(containsPoint(b, {0.0, 0.99, 0.0}));
    EXPECT_FALSE(containsPoint(b, {0.99, 0.0, 0.0}));
    EXPECT_TRUE(containsPoint(b, {0.5, 0.0, 0.5}));  // on a face corner edge, closed
}

}  // namespace
}  // namespace simp::geometry
