#pragma once
/// Test worlds built in code for the mapping tests: floor plans, a camera rig and a
/// detection simulator with seeded noise (no dependency on the simulator library).

#include <mrpt/img/TCamera.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/geometry/Box3D.h>
#include <simp/mapping/MappingOptions.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/world/ObjectMapData.h>

#include <cmath>
#include <random>
#include <vector>

namespace simp::mapping::test {

/// A rectangular floor [0, width] x [0, height] with boundary walls (one cell thick) and,
/// when wall_x > 0, an inner wall at x = wall_x with a door opening [door_y0, door_y1] (m).
inline mrpt::maps::COccupancyGridMap2D makeFloorPlan(double width, double height, double wall_x = -1,
                                                     double door_y0 = 0, double door_y1 = 0, double res = 0.05) {
    mrpt::maps::COccupancyGridMap2D g(-0.5f, static_cast<float>(width + 0.5), -0.5f, static_cast<float>(height + 0.5),
                                      static_cast<float>(res));
    // Walls two cells thick: the cells on both sides of each wall line.
    const int wall_cx = wall_x > 0 ? g.x2idx(wall_x) : -10;
    const int x0 = g.x2idx(0.0), x1 = g.x2idx(width), y0 = g.y2idx(0.0), y1 = g.y2idx(height);
    for (int cy = 0; cy < static_cast<int>(g.getSizeY()); ++cy)
        for (int cx = 0; cx < static_cast<int>(g.getSizeX()); ++cx) {
            const double y = g.idx2y(cy);
            const bool outside = cx < x0 - 1 || cy < y0 - 1 || cx > x1 || cy > y1;
            const bool boundary = !outside && (cx <= x0 || cy <= y0 || cx >= x1 - 1 || cy >= y1 - 1);
            const bool inner = (cx == wall_cx || cx == wall_cx - 1) && !(y > door_y0 && y < door_y1);
            g.setCell(cx, cy, outside ? 0.5f : (boundary || inner) ? 0.0f : 1.0f);
        }
    return g;
}

/// The authors' 4-camera rig: forward, right, back, left at 0.63 m.
inline std::vector<mrpt::poses::CPose3D> cameraRig() {
    std::vector<mrpt::poses::CPose3D> rig;
    for (int c = 0; c < 4; ++c) rig.push_back(obs::cameraPoseOnRobot(0.1 * std::cos(-c * M_PI / 2), 0.1 * std::sin(-c * M_PI / 2), 0.63, -c * M_PI / 2));
    return rig;
}

inline mrpt::img::TCamera intrinsics() {
    mrpt::img::TCamera K;
    K.ncols = 640;
    K.nrows = 480;
    K.setIntrinsicParamsFromValues(380.07, 379.66, 324.47, 237.79);
    return K;
}

struct TrueObject {
    int class_id = 0;       ///< index into the observation's class list
    geometry::Box3D box;    ///< world, upright
};

struct DetectionNoise {
    double center_sigma_m = 0.05;  ///< per horizontal axis
    double size_rel_sigma = 0.03;
    double yaw_sigma_rad = 0.03;
};

/// One observation per rig camera at `robot_pose`: a detection for each true object whose
/// centre projects into the image at a distance in [0.3, max_range_m] (no occlusion test).
inline std::vector<obs::CObservationObjects3D> observe(const std::vector<TrueObject>& truth,
                                                       const std::vector<std::string>& class_names,
                                                       const mrpt::poses::CPose3D& robot_pose, std::mt19937& rng,
                                                       const DetectionNoise& noise = {}, double max_range_m = 5.0) {
    std::normal_distribution<double> n01(0.0, 1.0);
    std::vector<obs::CObservationObjects3D> out;
    const mrpt::img::TCamera K = intrinsics();
    for (const auto& cam_on_robot : cameraRig()) {
        obs::CObservationObjects3D o;
        o.setClassNames(class_names);
        o.setCameraPose(cam_on_robot);
        o.setIntrinsics(K);
        o.setImageSize(640, 480);
        const mrpt::poses::CPose3D world_T_cam = robot_pose + cam_on_robot;
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.linear() = world_T_cam.getRotationMatrix().asEigen();
        T.translation() = Eigen::Vector3d(world_T_cam.x(), world_T_cam.y(), world_T_cam.z());
        const Eigen::Isometry3d cam_T_world = T.inverse();
        for (const auto& t : truth) {
            geometry::Box3D b = t.box;
            b.center.x() += noise.center_sigma_m * n01(rng);
            b.center.y() += noise.center_sigma_m * n01(rng);
            for (int k = 0; k < 3; ++k) b.size[k] *= 1.0 + noise.size_rel_sigma * n01(rng);
            b.R = Eigen::AngleAxisd(noise.yaw_sigma_rad * n01(rng), Eigen::Vector3d::UnitZ()) * b.R;
            const geometry::Box3D bc = b.transformed(cam_T_world);
            const Eigen::Vector3d c = bc.center;
            if (c.z() < 0.3 || c.norm() > max_range_m) continue;
            const double u = K.fx() * c.x() / c.z() + K.cx(), v = K.fy() * c.y() / c.z() + K.cy();
            if (u < 0 || v < 0 || u >= 640 || v >= 480) continue;
            obs::Detection3D d;
            d.class_id = static_cast<std::uint16_t>(t.class_id);
            d.confidence = 0.9f;
            d.box_in_camera = bc;
            o.addDetection(d);
        }
        out.push_back(std::move(o));
    }
    return out;
}

/// Options for tests: every class enabled with range [0, 6] m and confidence >= 0.5.
/// An empty map of these classes, without noise models.
inline world::ObjectMapData emptyMapOf(const std::vector<std::string>& classes) {
    world::ObjectMapData m;
    m.class_names = classes;
    m.class_noise.resize(classes.size());
    return m;
}

inline MappingOptions testOptions() {
    MappingOptions o;
    o.per_class.clear();
    o.default_filter = ClassFilter{0.5, 0.0, 6.0};
    return o;
}

}  // namespace simp::mapping::test
