#include <gtest/gtest.h>
#include <simp/model/NoiseFrame.h>
#include <simp/geometry/Box3D.h>
#include <simp/mapping/AssociationCost.h>
#include <simp/mapping/DetectionBox.h>

#include <cmath>

using simp::geometry::Box3D;

TEST(DetectionBox, DetectorAxesBecomeTheObjectFrame) {
    // An upright world box (W = 1.6 along world x rotated by 30 deg, L = 0.8, H = 0.75) written in
    // the detector's convention: local x = W, local y = H pointing down, local z = L.
    const double yaw = 30.0 * M_PI / 180.0;
    const Box3D truth = simp::geometry::makeUprightBox({2.0, 1.0, 0.375}, {1.6, 0.8, 0.75}, yaw);
    Box3D det;
    det.center = truth.center;
    det.R.col(0) = truth.R.col(0);
    det.R.col(1) = -truth.R.col(2);
    det.R.col(2) = truth.R.col(1);
    det.size = {1.6, 0.75, 0.8};
    ASSERT_NEAR(det.R.determinant(), 1.0, 1e-12);
    const Box3D o = simp::mapping::objectBoxFromDetection(det);
    EXPECT_TRUE((o.R - truth.R).isZero(1e-12));
    EXPECT_TRUE((o.size - truth.size).isZero(1e-12));
    EXPECT_NEAR(simp::geometry::yawOf(o), yaw, 1e-12);
    // the noise frame: y along the longer side (x here), so its yaw is the box yaw + 90 deg,
    // the same for the equivalent frame with x and y swapped
    EXPECT_NEAR(simp::model::classNoiseFrameYaw(o), yaw + M_PI / 2, 1e-12);
    const Box3D swapped = simp::geometry::makeUprightBox(truth.center, {0.8, 1.6, 0.75}, yaw + M_PI / 2);
    EXPECT_NEAR(std::remainder(simp::model::classNoiseFrameYaw(swapped) - (yaw + M_PI / 2), M_PI), 0.0, 1e-12);
}
