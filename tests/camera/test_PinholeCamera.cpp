/// The one pinhole camera: MRPT intrinsics + pose; projection and placement on a robot.
#include <gtest/gtest.h>
#include <simp/camera/BoxProjection.h>
#include <simp/camera/PinholeCamera.h>
#include <simp/obs/CObservationObjects3D.h>

using namespace simp::camera;

TEST(PinholeCamera, DefaultsAreTheAuthorsIntrinsics) {
    const PinholeCamera c;
    EXPECT_EQ(c.widthPx(), 640);
    EXPECT_EQ(c.heightPx(), 480);
    EXPECT_DOUBLE_EQ(c.fx(), 380.07);
    EXPECT_DOUBLE_EQ(c.fy(), 379.66);
    EXPECT_DOUBLE_EQ(c.cx(), 324.47);
    EXPECT_DOUBLE_EQ(c.cy(), 237.79);
    EXPECT_EQ(c.K()(2, 2), 1.0);
    EXPECT_EQ(c.K()(0, 1), 0.0);
}

TEST(PinholeCamera, ProjectsAPointOnTheOpticalAxisToThePrincipalPoint) {
    PinholeCamera c;
    c.intrinsics = makeIntrinsics(800, 600, 500, 400, 410, 290);
    const Eigen::Vector2d px = c.project(Eigen::Vector3d(0, 0, 3));
    EXPECT_DOUBLE_EQ(px.x(), 410);
    EXPECT_DOUBLE_EQ(px.y(), 290);
    // 1 m right at 2 m depth: fx / 2 px right of cx.
    EXPECT_DOUBLE_EQ(c.project(Eigen::Vector3d(1, 0, 2)).x(), 410 + 250);
    EXPECT_TRUE(c.inImage({800, 600}));
    EXPECT_FALSE(c.inImage({800.5, 10}));
    EXPECT_FALSE(c.inImage({-0.1, 10}));
}

TEST(PinholeCamera, OnRobotLooksAlongTheRobotHeading) {
    // A forward camera 0.63 m high on a robot at (2, 1) heading +y: the optical axis is world +y.
    const PinholeCamera c = PinholeCamera::onRobot(mrpt::math::TPose2D(2, 1, M_PI / 2),
                                                   simp::obs::cameraPoseOnRobot(0, 0, 0.63, 0), defaultIntrinsics());
    EXPECT_TRUE(c.world_T_camera.translation().isApprox(Eigen::Vector3d(2, 1, 0.63), 1e-12));
    EXPECT_TRUE(c.world_T_camera.linear().col(2).isApprox(Eigen::Vector3d(0, 1, 0), 1e-12));   // z forward
    EXPECT_TRUE(c.world_T_camera.linear().col(1).isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));  // y down
    // A point 3 m ahead at camera height projects to the principal point.
    const Eigen::Vector3d p = c.world_T_camera.inverse() * Eigen::Vector3d(2, 4, 0.63);
    EXPECT_NEAR(c.project(p).x(), c.cx(), 1e-9);
    EXPECT_NEAR(c.project(p).y(), c.cy(), 1e-9);
}

TEST(PinholeCamera, SetIntrinsicsKeepsTheSkew) {
    PinholeCamera c;
    Eigen::Matrix3d K;
    K << 400, 2, 320, 0, 410, 240, 0, 0, 1;
    c.setIntrinsics(K, 320, 200);
    EXPECT_EQ(c.K(), K);
    EXPECT_EQ(c.widthPx(), 320);
    EXPECT_EQ(c.heightPx(), 200);
}

TEST(BoxProjection, TruncationOfABoxHalfOutsideTheImage) {
    // Camera at the origin looking along world +x; a 1 m cube 4 m ahead whose centre projects onto
    // the left image border (u = 0): half of its projected box lies outside.
    PinholeCamera c;
    c.intrinsics = makeIntrinsics(640, 480, 400, 400, 320, 240);
    c.world_T_camera.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
    const double y_left = 4.0 * 320.0 / 400.0;  // world y of the left border at 4 m depth
    const auto box = simp::geometry::makeUprightBox({4.0, y_left, 0}, {0.01, 1.0, 1.0}, 0.0);
    const ProjectedBox p = projectBox(c, box);
    ASSERT_TRUE(p.visible_in_front);
    EXPECT_NEAR(p.truncation, 0.5, 1e-3);
    EXPECT_DOUBLE_EQ(p.bbox_trunc(0), 0.0);
}

TEST(PinholeCamera, AnImageTakesItsOwnIntrinsicsElseTheFallbackAtItsSize) {
    const auto fallback = makeIntrinsics(0, 0, 380, 379, 324, 237);
    const auto own = imageIntrinsics(makeIntrinsics(640, 480, 500, 501, 300, 200), 800, 600, fallback);
    EXPECT_EQ(own.ncols, 800u);
    EXPECT_EQ(own.nrows, 600u);
    EXPECT_DOUBLE_EQ(own.fx(), 500);
    EXPECT_DOUBLE_EQ(own.fy(), 501);
    EXPECT_DOUBLE_EQ(own.cx(), 300);
    EXPECT_DOUBLE_EQ(own.cy(), 200);
    const auto none = imageIntrinsics(std::nullopt, 320, 240, fallback);
    EXPECT_EQ(none.ncols, 320u);
    EXPECT_EQ(none.nrows, 240u);
    EXPECT_DOUBLE_EQ(none.fx(), 380);
    EXPECT_DOUBLE_EQ(none.cy(), 237);
}
