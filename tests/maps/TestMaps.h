#pragma once
/// \file TestMaps.h
/// Small synthetic object maps and detections made from a known pose, for the maps tests.

#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/world/ObjectMapData.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace simp::maps::test {

inline model::NoiseModel noise(double sx, double sy, double b, double mx = 0.0, double my = 0.0) {
    model::NoiseModel n;
    n.mean_m = {mx, my};
    n.cov_m2 = Eigen::Vector2d(sx * sx, sy * sy).asDiagonal();
    n.exponent_b = b;
    return n;
}

inline world::MapObject object(std::int64_t id, const world::ObjectMapData& m, const std::string& cls, double x,
                               double y, double yaw, double lx, double ly, double h) {
    world::MapObject o;
    o.id = id;
    o.class_id = m.classId(cls);
    o.box = geometry::makeUprightBox({x, y, 0.5 * h}, {lx, ly, h}, yaw);
    return o;
}

/// Five objects of four classes, placed without symmetry; zero-mean class noise (so the
/// likelihood of detections equal to the map boxes peaks exactly at the true pose).
inline world::ObjectMapData smallMap() {
    world::ObjectMapData m;
    m.class_names = obs::defaultClassNames();
    m.class_noise.assign(m.class_names.size(), std::nullopt);
    m.class_noise[m.classId("chair")] = noise(0.20, 0.15, 2.0);
    m.class_noise[m.classId("table")] = noise(0.30, 0.20, 4.0);
    m.class_noise[m.classId("cabinet")] = noise(0.25, 0.10, 2.0);
    m.class_noise[m.classId("door")] = noise(0.30, 0.10, 2.0);
    m.objects.push_back(object(1, m, "chair", 2.0, 1.0, 0.3, 0.5, 0.5, 0.9));
    m.objects.push_back(object(2, m, "table", 4.0, -1.0, 0.3, 1.6, 0.8, 0.75));
    m.objects.push_back(object(3, m, "cabinet", 0.0, 3.0, 1.2, 1.0, 0.45, 1.8));
    m.objects.push_back(object(4, m, "door", 5.0, 3.0, 1.5708, 0.9, 0.1, 2.0));
    m.objects.push_back(object(5, m, "chair", -1.0, -2.0, -0.7, 0.5, 0.5, 0.9));
    return m;
}

inline mrpt::poses::CPose3D pose3D(const mrpt::math::TPose2D& p) { return mrpt::poses::CPose3D(p.x, p.y, 0, p.phi, 0, 0); }

inline Eigen::Isometry3d isometry(const mrpt::poses::CPose3D& p) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = p.getRotationMatrix().asEigen();
    T.translation() = Eigen::Vector3d(p.x(), p.y(), p.z());
    return T;
}

/// One observation (camera 1 m high, looking forward, no tilt) whose detections are exactly
/// the boxes of the listed map objects, seen from the robot at `truth`.
inline obs::CObservationObjects3D detect(const world::ObjectMapData& m, const mrpt::math::TPose2D& truth,
                                         const std::vector<std::size_t>& objects, float confidence = 0.9f) {
    obs::CObservationObjects3D o;
    o.setCameraPose(obs::cameraPoseOnRobot(0.1, 0.0, 1.0, 0.0));
    const Eigen::Isometry3d camera_T_world = (isometry(pose3D(truth)) * isometry(o.cameraPose())).inverse();
    std::vector<obs::Detection3D> dets;
    for (const std::size_t i : objects) {
        obs::Detection3D d;
        const auto& obj = m.objects.at(i);
        d.class_id = static_cast<std::uint16_t>(obs::classIndexOf(o.classNames(), m.class_names.at(obj.class_id)));
        d.confidence = confidence;
        d.box_in_camera = obj.box.transformed(camera_T_world);
        dets.push_back(d);
    }
    o.setDetections(dets);
    return o;
}

/// smallMap()'s classes and noise with one axis-aligned chair (0.5 x 0.5 m at (2, 1); class
/// noise sigma 0.2 x 0.15 m, b = 2): the hand-computed cases of the sensor model tests.
inline world::ObjectMapData oneChairMap() {
    auto m = smallMap();
    m.objects = {object(1, m, "chair", 2.0, 1.0, 0.0, 0.5, 0.5, 0.9)};
    return m;
}

/// Detection k of `o` prepared by a sensor model value type (its class looked up by name).
template <typename Model>
auto prepared(const Model& model, const world::ObjectMapData& m, const obs::CObservationObjects3D& o, std::size_t k) {
    const int cls = m.classId(o.classNameOf(o.detections().at(k)));
    return model.prepare(cls, o.boxInRobot(k), o.footprintInRobot(k));
}

}  // namespace simp::maps::test
