/// Tests of simp/geometry/Box3DIoU.h: hand-computed cases, agreement of the upright fast
/// path with the general clipper, and a seeded Monte Carlo check on general rotations.
#include <simp/geometry/Box3DIoU.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace simp::geometry {
namespace {

constexpr double kTol = 1e-12;

Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<double> n01;
    return Eigen::Quaterniond(n01(rng), n01(rng), n01(rng), n01(rng)).normalized().toRotationMatrix();
}

Box3D box(const Eigen::Vector3d& center, const Eigen::Vector3d& size, const Eigen::Matrix3d& R) {
    Box3D b;
    b.center = center;
    b.size = size;
    b.R = R;
    return b;
}

TEST(Box3DIoU, IdenticalIsOne) {
    std::mt19937_64 rng(1);
    const Box3D upright = makeUprightBox({1, 2, 0.5}, {2, 1, 0.8}, 0.7);
    EXPECT_NEAR(iou3D(upright, upright), 1.0, kTol);
    const Box3D general = box({1, 2, 0.5}, {2, 1, 0.8}, randomRotation(rng));
    EXPECT_NEAR(iou3D(general, general), 1.0, kTol);
    EXPECT_NEAR(intersectionVolumeByClipping(general, general), 1.6, kTol);
    EXPECT_NEAR(intersectionVolumeByClipping(upright, upright), 1.6, kTol);
}

TEST(Box3DIoU, DisjointAndTouchingAreZero) {
    const Box3D a = makeUprightBox({0, 0, 0}, {1, 1, 1}, 0.0);
    EXPECT_EQ(iou3D(a, makeUprightBox({3, 0, 0}, {1, 1, 1}, 0.3)), 0.0);
    EXPECT_EQ(iou3D(a, makeUprightBox({0, 0, 1}, {1, 1, 1}, 0.0)), 0.0);  // stacked: shared face
    EXPECT_EQ(iou3D(a, makeUprightBox({1, 0, 0}, {1, 1, 1}, 0.0)), 0.0);  // side by side
    // General path: a cube rotated about a diagonal-ish axis, far away or touching a face.
    std::mt19937_64 rng(2);
    const Eigen::Matrix3d R = randomRotation(rng);
    const Box3D g = box({0, 0, 0}, {1, 1, 1}, R);
    EXPECT_EQ(intersectionVolumeByClipping(g, box(R * Eigen::Vector3d(1, 0, 0), {1, 1, 1}, R)), 0.0);
    EXPECT_EQ(intersectionVolumeByClipping(g, box({0, 5, 0}, {1, 1, 1}, randomRotation(rng))), 0.0);
}

TEST(Box3DIoU, HalfShiftedIsOneThird) {
    // Unit cubes shifted by half a side along one of their axes: inter = 1/2, union = 3/2.
    const Box3D a = makeUprightBox({0, 0, 0}, {1, 1, 1}, 0.4);
    const Box3D b = makeUprightBox(a.R * Eigen::Vector3d(0.5, 0, 0), {1, 1, 1}, 0.4);
    EXPECT_NEAR(iou3D(a, b), 1.0 / 3.0, kTol);
    // The same with a general rotation: the shift is along the cubes' own axis.
    std::mt19937_64 rng(3);
    const Eigen::Matrix3d R = randomRotation(rng);
    const Box3D ga = box({1, -1, 2}, {1, 1, 1}, R);
    const Box3D gb = box(ga.center + R * Eigen::Vector3d(0, 0, 0.5), {1, 1, 1}, R);
    EXPECT_NEAR(iou3D(ga, gb), 1.0 / 3.0, 1e-12);
    EXPECT_NEAR(intersectionVolumeByClipping(ga, gb), 0.5, 1e-12);
}

TEST(Box3DIoU, ContainedIsTheVolumeRatio) {
    std::mt19937_64 rng(4);
    const Box3D big = box({0, 0, 0}, {4, 3, 2}, randomRotation(rng));
    const Box3D small = box({0.2, 0.1, -0.1}, {0.5, 0.4, 0.3}, randomRotation(rng));  // radius 0.35
    EXPECT_NEAR(intersectionVolume(big, small), 0.06, kTol);
    EXPECT_NEAR(iou3D(big, small), 0.06 / 24.0, kTol);
    EXPECT_NEAR(iou3D(small, big), 0.06 / 24.0, kTol);
}

TEST(Box3DIoU, Rotated45DegreesAboutZ) {
    // Footprints: the unit-square case of ConvexPolygonIoU.Rotated45Degrees, inter area
    // 2 sqrt(2) - 2; same heights, so the 3D IoU is 1/sqrt(2) as in 2D.
    const Box3D a = makeUprightBox({0, 0, 0}, {1, 1, 2}, 0.0);
    const Box3D b = makeUprightBox({0, 0, 0}, {1, 1, 2}, M_PI / 4);
    EXPECT_NEAR(intersectionVolume(a, b), 2 * (2 * std::sqrt(2.0) - 2), kTol);
    EXPECT_NEAR(intersectionVolumeByClipping(a, b), 2 * (2 * std::sqrt(2.0) - 2), kTol);
    EXPECT_NEAR(iou3D(a, b), 1 / std::sqrt(2.0), kTol);
    // Half the height overlapping: inter halves, union = 4 - inter / 2.
    const Box3D c = makeUprightBox({0, 0, 1}, {1, 1, 2}, M_PI / 4);
    const double inter = 2 * std::sqrt(2.0) - 2;
    EXPECT_NEAR(iou3D(a, c), inter / (4 - inter), kTol);
}

TEST(Box3DIoU, UprightFastPathAgreesWithClipping) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> size(0.2, 2.0), offset(-1.0, 1.0), yaw(-M_PI, M_PI);
    int overlapping = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const Box3D a = makeUprightBox({offset(rng), offset(rng), offset(rng)}, {size(rng), size(rng), size(rng)}, yaw(rng));
        Box3D b = makeUprightBox({offset(rng), offset(rng), offset(rng)}, {size(rng), size(rng), size(rng)}, yaw(rng));
        // Odd trials: b's vertical axis is its local y (camera convention, H vertical).
        if (trial % 2 == 1) b.R = b.R * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
        const double fast = intersectionVolume(a, b);
        const double general = intersectionVolumeByClipping(a, b);
        EXPECT_NEAR(fast, general, 1e-12 * (1 + a.volume())) << "trial " << trial;
        EXPECT_NEAR(intersectionVolume(b, a), fast, 1e-12 * (1 + a.volume())) << "trial " << trial;
        overlapping += fast > 0.0;
    }
    EXPECT_GT(overlapping, 100);  // the comparison is not only between empty intersections
}

TEST(Box3DIoU, NearlyCoincidentBoxesAreStable) {
    // Faces almost coplanar (rotation by s rad about a random axis and shift by ~s m, s from
    // 1e-16 to 1e-4) stress the clipper's tolerance: the volume moves by O(s) (the wedges cut
    // off are at most ~3 s in relative volume), never by a whole face or a sliver triangle.
    // Also: the same cube with its axes relabelled (identical solid), shifted by a full
    // side (touching faces) and by half a side.
    std::mt19937_64 rng(12);
    std::normal_distribution<double> n01;
    for (int trial = 0; trial < 600; ++trial) {
        Box3D a = box({n01(rng), n01(rng), n01(rng)}, {1.0, 0.7, 0.4}, randomRotation(rng));
        Box3D b = a;
        if (trial % 3 == 0) {  // a cube, and b the same cube with axes (y, z, x)
            a.size = b.size = Eigen::Vector3d::Ones();
            b.R << a.R.col(1), a.R.col(2), a.R.col(0);
        }
        const double s = std::pow(10.0, -16.0 + 12.0 * (trial % 50) / 50.0);
        const Eigen::Vector3d axis = Eigen::Vector3d(n01(rng), n01(rng), n01(rng)).normalized();
        b.R = Eigen::AngleAxisd(s, axis).toRotationMatrix() * b.R;
        b.center += s * Eigen::Vector3d(n01(rng), n01(rng), n01(rng)).normalized();
        double expected = a.volume();
        if (trial % 5 == 1) {  // touching along a's x faces
            b.center += a.size[0] * a.R.col(0);
            expected = 0.0;
        } else if (trial % 5 == 2) {  // half a side along a's y
            b.center += 0.5 * a.size[1] * a.R.col(1);
            expected = 0.5 * a.volume();
        }
        EXPECT_NEAR(intersectionVolumeByClipping(a, b), expected, 10 * s + 1e-12) << "trial " << trial << " s " << s;
        EXPECT_NEAR(intersectionVolume(a, b), expected, 10 * s + 1e-12) << "trial " << trial << " s " << s;
    }
}

TEST(Box3DIoU, FrameInvariant) {
    std::mt19937_64 rng(6);
    const Box3D a = box({0.1, 0.2, 0.3}, {1.0, 0.7, 0.5}, randomRotation(rng));
    const Box3D b = box({0.4, 0.0, 0.1}, {0.8, 0.9, 0.6}, randomRotation(rng));
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = randomRotation(rng);
    T.translation() = Eigen::Vector3d(5, -3, 2);
    const double v = intersectionVolume(a, b);
    EXPECT_GT(v, 0.0);
    EXPECT_NEAR(intersectionVolume(a.transformed(T), b.transformed(T)), v, 1e-12);
    EXPECT_NEAR(intersectionVolume(b, a), v, 1e-12);
}

TEST(Box3DIoU, AgreesWithMonteCarloOnGeneralRotations) {
    // Estimate p = inter / vol(a) as the fraction of M uniform samples of a inside b; the
    // estimate has standard error sqrt(p (1 - p) / M): accept within 4 of them. A correct
    // implementation fails a pair with probability ~6e-5; the seed makes the run reproducible.
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> size(0.3, 1.5), offset(-0.4, 0.4), unit(-0.5, 0.5);
    constexpr int kPairs = 25;
    constexpr int kSamples = 100000;
    for (int pair = 0; pair < kPairs; ++pair) {
        const Box3D a = box({offset(rng), offset(rng), offset(rng)}, {size(rng), size(rng), size(rng)}, randomRotation(rng));
        const Box3D b = box({offset(rng), offset(rng), offset(rng)}, {size(rng), size(rng), size(rng)}, randomRotation(rng));
        int inside = 0;
        for (int s = 0; s < kSamples; ++s) {
            const Eigen::Vector3d local(unit(rng) * a.size[0], unit(rng) * a.size[1], unit(rng) * a.size[2]);
            inside += containsPoint(b, a.center + a.R * local);
        }
        const double p_hat = static_cast<double>(inside) / kSamples;
        const double p = intersectionVolume(a, b) / a.volume();
        const double sigma = std::sqrt(std::max(p * (1 - p), 1.0 / kSamples) / kSamples);
        EXPECT_NEAR(p_hat, p, 4 * sigma) << "pair " << pair << " exact inter " << p * a.volume();
        const double union_volume = a.volume() + b.volume() - p * a.volume();
        EXPECT_NEAR(iou3D(a, b), p * a.volume() / union_volume, 1e-12);
    }
}

TEST(Box3DIoU, InvalidBoxesThrow) {
    const Box3D a = makeUprightBox({0, 0, 0}, {1, 1, 1}, 0.0);
    Box3D nan = a;
    nan.center.y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(iou3D(a, nan), std::invalid_argument);
    Box3D flat = a;
    flat.size.z() = 0.0;
    EXPECT_THROW(iou3D(flat, a), std::invalid_argument);
    Box3D mirrored = a;
    mirrored.R(0, 0) = -1.0;
    try {
        intersectionVolume(a, mirrored);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("second box"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace simp::geometry
