// prepareDetection: what every sensor model computes once per detection.
#include <gtest/gtest.h>
#include <simp/geometry/Footprint.h>
#include <simp/maps/PreparedDetection.h>

#include <cmath>

namespace simp::maps {
namespace {

TEST(PreparedDetection, CentreFootprintAreaRadiusAndRectangle) {
    // A 0.6 x 0.4 m box 3 m ahead and 4 m left of the robot (5 m away), turned by 0.3 rad.
    const geometry::Box3D box = geometry::makeUprightBox({3.0, 4.0, 0.4}, {0.6, 0.4, 0.8}, 0.3);
    const auto d = prepareDetection(2, box, geometry::footprint(box), 0.0, 0.5);
    EXPECT_EQ(d.map_class, 2);
    EXPECT_DOUBLE_EQ(d.center_robot_m.x(), 3.0);
    EXPECT_DOUBLE_EQ(d.center_robot_m.y(), 4.0);
    EXPECT_NEAR(d.area_m2, 0.24, 1e-12);
    EXPECT_NEAR(d.radius_m, std::hypot(0.3, 0.2), 1e-12);  // half diagonal
    ASSERT_TRUE(d.is_rect);
    EXPECT_NEAR(2 * d.rect_robot.hx * 2 * d.rect_robot.hy, 0.24, 1e-12);
    EXPECT_EQ(d.offsets_robot.n, d.footprint_robot.n);
    EXPECT_EQ(d.noise_inv_scale2, 1.0);  // range growth off
    EXPECT_EQ(d.weight, 0.5);
}

TEST(PreparedDetection, RangeGrowthFromTheReferenceRange) {
    const geometry::Box3D box = geometry::makeUprightBox({3.0, 4.0, 0.4}, {0.6, 0.4, 0.8}, 0.0);
    // 5 m away, reference 2 m: s = 2.5, 1 / s^2 = 0.16; reference 10 m: closer than it, s = 1.
    EXPECT_NEAR(prepareDetection(0, box, geometry::footprint(box), 2.0, 1.0).noise_inv_scale2, 0.16, 1e-15);
    EXPECT_EQ(prepareDetection(0, box, geometry::footprint(box), 10.0, 1.0).noise_inv_scale2, 1.0);
}

}  // namespace
}  // namespace simp::maps
