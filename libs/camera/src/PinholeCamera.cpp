#include <simp/camera/PinholeCamera.h>

namespace simp::camera {

mrpt::img::TCamera makeIntrinsics(int width_px, int height_px, double fx, double fy, double cx, double cy) {
    mrpt::img::TCamera K;
    K.ncols = static_cast<std::uint32_t>(width_px);
    K.nrows = static_cast<std::uint32_t>(height_px);
    K.setIntrinsicParamsFromValues(fx, fy, cx, cy);
    return K;
}

mrpt::img::TCamera defaultIntrinsics() { return makeIntrinsics(640, 480, 380.07, 379.66, 324.47, 237.79); }

mrpt::img::TCamera imageIntrinsics(const std::optional<mrpt::img::TCamera>& given, int width_px, int height_px,
                                   const mrpt::img::TCamera& fallback) {
    const mrpt::img::TCamera& K = given ? *given : fallback;
    return makeIntrinsics(width_px, height_px, K.fx(), K.fy(), K.cx(), K.cy());
}

Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& p) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = p.getRotationMatrix().asEigen();
    T.translation() = Eigen::Vector3d(p.x(), p.y(), p.z());
    return T;
}

void PinholeCamera::setIntrinsics(const Eigen::Matrix3d& K, int width_px, int height_px) {
    intrinsics.intrinsicParams = mrpt::math::CMatrixDouble33(K);
    intrinsics.ncols = static_cast<std::uint32_t>(width_px);
    intrinsics.nrows = static_cast<std::uint32_t>(height_px);
}

PinholeCamera PinholeCamera::onRobot(const mrpt::math::TPose2D& world_T_robot, const mrpt::poses::CPose3D& robot_T_camera,
                                     const mrpt::img::TCamera& intrinsics) {
    const mrpt::poses::CPose3D robot(world_T_robot.x, world_T_robot.y, 0.0, world_T_robot.phi, 0.0, 0.0);
    return onRobot(robot, robot_T_camera, intrinsics);
}

PinholeCamera PinholeCamera::onRobot(const mrpt::poses::CPose3D& world_T_robot, const mrpt::poses::CPose3D& robot_T_camera,
                                     const mrpt::img::TCamera& intrinsics) {
    PinholeCamera c;
    c.intrinsics = intrinsics;
    c.world_T_camera = toIsometry(world_T_robot + robot_T_camera);
    return c;
}

}  // namespace simp::camera
