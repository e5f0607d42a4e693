/// Detections of skipped frames, moved into the robot frame of the next update.

#include <gtest/gtest.h>
#include <simp/geometry/Box3D.h>
#include <simp/localization/SkippedDetections.h>
#include <simp/obs/ObjectClasses.h>

using namespace simp::localization;

TEST(SkippedDetections, KeepTheirWorldBoxesAtTheUpdatePose) {
    // A detection taken at robot pose A, the update at B = A (+) motion: the moved detection seen
    // from B is the same world box as the original seen from A.
    const mrpt::poses::CPose2D last_update(2.0, 1.0, 0.3);
    const mrpt::poses::CPose2D motion_to_frame(0.06, 0.01, 0.02), motion_to_update(0.12, 0.02, 0.05);
    auto o = simp::obs::CObservationObjects3D::Create();
    o->setCameraPose(simp::obs::cameraPoseOnRobot(0.1, 0, 0.6, M_PI / 2));
    o->setClassNames(simp::obs::defaultClassNames());
    simp::obs::Detection3D d;
    d.class_id = 4;
    d.box_in_camera.center = Eigen::Vector3d(0.3, 0.2, 3.0);
    d.box_in_camera.size = Eigen::Vector3d(1.2, 0.7, 0.8);
    o->addDetection(d);
    SkippedDetections buf;
    buf.add({{o, {0.25}}}, motion_to_frame);
    EXPECT_EQ(buf.size(), 1u);
    const auto merged = buf.merge({}, motion_to_update);
    EXPECT_EQ(buf.size(), 0u);
    ASSERT_EQ(merged.size(), 1u);
    const auto moved = merged[0].obs;
    ASSERT_TRUE(moved);
    ASSERT_EQ(merged[0].weights.size(), 1u);  // the detection keeps its weight
    EXPECT_EQ(merged[0].weights[0], 0.25);

    const mrpt::poses::CPose3D world_T_frame(last_update + motion_to_frame);
    const mrpt::poses::CPose3D world_T_update(last_update + motion_to_update);
    const auto a = o->boxInWorld(0, world_T_frame), b = moved->boxInWorld(0, world_T_update);
    EXPECT_LT((a.center - b.center).norm(), 1e-9);
    EXPECT_LT((a.R - b.R).norm(), 1e-9);
    // The original observation is not modified.
    EXPECT_LT((o->cameraPose().asVectorVal() - simp::obs::cameraPoseOnRobot(0.1, 0, 0.6, M_PI / 2).asVectorVal()).norm(),
              1e-12);
}

TEST(SkippedDetections, EmptyBufferReturnsTheFrameItself) {
    SkippedDetections buf;
    auto o = simp::obs::CObservationObjects3D::Create();
    const auto merged = buf.merge({{o, {}}}, mrpt::poses::CPose2D(1, 0, 0));
    ASSERT_EQ(merged.size(), 1u);
    EXPECT_EQ(merged[0].obs, o);
}
