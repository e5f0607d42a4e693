#include "SyntheticScenario.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/geometry/Box3D.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/ObjectClasses.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <random>

namespace simp::localization::test {
namespace {

constexpr double kRes = 0.05;
constexpr double kT0 = 1000.0;       // s (t = 0 would be MRPT's invalid timestamp)
constexpr double kFrameDt = 0.2;     // s, 5 Hz
constexpr double kSpeed = 0.45;      // m/s
constexpr double kMissProbability = 0.15;          // a visible object is not detected
constexpr double kFalsePositiveProbability = 0.3;  // per camera frame: one detection of nothing

void wallRect(mrpt::maps::COccupancyGridMap2D& g, double x0, double y0, double x1, double y1) {
    for (double x = x0; x <= x1 + 1e-9; x += kRes / 2)
        for (double y = y0; y <= y1 + 1e-9; y += kRes / 2) {
            const int cx = g.x2idx(x), cy = g.y2idx(y);
            if (cx >= 0 && cy >= 0 && cx < static_cast<int>(g.getSizeX()) && cy < static_cast<int>(g.getSizeY()))
                g.setCell(cx, cy, 0.0f);
        }
}

world::MapObject object(std::int64_t id, const std::string& cls, double x, double y, double lx, double ly, double h,
                        double yaw) {
    world::MapObject o;
    o.id = id;
    o.class_id = obs::classIndexOf(obs::defaultClassNames(), cls);
    o.box = geometry::makeUprightBox({x, y, h / 2}, {lx, ly, h}, yaw);
    return o;
}

Eigen::Isometry3d robotToWorld(const mrpt::math::TPose2D& p) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translate(Eigen::Vector3d(p.x, p.y, 0));
    T.rotate(Eigen::AngleAxisd(p.phi, Eigen::Vector3d::UnitZ()));
    return T;
}

Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& p) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.matrix() = p.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
    return T;
}

bool lineOfSight(const mrpt::maps::COccupancyGridMap2D& g, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const double len = (b - a).norm();
    for (double s = 0; s < len; s += kRes / 2) {
        const Eigen::Vector2d p = a + (b - a) * (s / len);
        if (g.getPos(p.x(), p.y()) < 0.5f) return false;
    }
    return true;
}

std::vector<mrpt::math::TPose2D> groundTruthPath() {
    const std::vector<Eigen::Vector2d> wp{{2.0, 2.0}, {3.2, 6.5}, {4.2, 4.0}, {6.5, 4.0}, {7.8, 7.0},
                                          {8.6, 6.5}, {11.2, 6.5}, {12.0, 3.0}, {11.0, 1.5}};
    std::vector<mrpt::math::TPose2D> path;
    const double step = kSpeed * kFrameDt;
    for (std::size_t i = 0; i + 1 < wp.size(); ++i) {
        const Eigen::Vector2d d = wp[i + 1] - wp[i];
        const double heading = std::atan2(d.y(), d.x());
        const int n = static_cast<int>(std::ceil(d.norm() / step));
        for (int k = 0; k < n; ++k) {
            const Eigen::Vector2d p = wp[i] + d * (static_cast<double>(k) / n);
            path.push_back({p.x(), p.y(), heading});
        }
    }
    path.push_back({wp.back().x(), wp.back().y(), path.back().phi});
    return path;
}

}  // namespace

world::World makeWorld() {
    world::World w;
    auto& g = w.floorplan;
    g.setSize(-0.5, 14.5, -0.5, 9.5, kRes, 0.5f);
    for (unsigned y = 0; y < g.getSizeY(); ++y)  // free inside the building, unknown outside
        for (unsigned x = 0; x < g.getSizeX(); ++x) {
            const double wx = g.idx2x(x), wy = g.idx2y(y);
            g.setCell(x, y, (wx > 0 && wx < 14 && wy > 0 && wy < 9) ? 1.0f : 0.5f);
        }
    wallRect(g, -0.1, -0.1, 14.1, 0.0);  // outer walls
    wallRect(g, -0.1, 9.0, 14.1, 9.1);
    wallRect(g, -0.1, -0.1, 0.0, 9.1);
    wallRect(g, 14.0, -0.1, 14.1, 9.1);
    wallRect(g, 5.0, 0.0, 5.1, 3.5);  // room 1 | room 2, door y in [3.5, 4.5]
    wallRect(g, 5.0, 4.5, 5.1, 9.0);
    wallRect(g, 9.5, 0.0, 9.6, 6.0);  // room 2 | rooms 3-4, door y in [6, 7]
    wallRect(g, 9.5, 7.0, 9.6, 9.0);
    wallRect(g, 9.6, 4.5, 11.5, 4.6);  // room 3 / room 4, door x in [11.5, 12.5]
    wallRect(g, 12.5, 4.5, 14.0, 4.6);

    auto& m = w.objects;
    m.class_names = obs::defaultClassNames();
    m.class_noise.assign(m.class_names.size(), std::nullopt);
    model::NoiseModel nm;
    nm.cov_m2 = Eigen::Matrix2d::Identity() * (0.15 * 0.15);
    for (auto& n : m.class_noise) n = nm;
    int id = 1;
    // room 1 (x 0..5)
    m.objects.push_back(object(id++, "desk", 1.0, 0.6, 1.4, 0.7, 0.75, 0.0));
    m.objects.push_back(object(id++, "chair", 1.2, 1.3, 0.5, 0.5, 0.9, 1.2));
    m.objects.push_back(object(id++, "cabinet", 4.6, 1.0, 0.5, 1.0, 1.8, 0.0));
    m.objects.push_back(object(id++, "board", 0.08, 5.0, 0.1, 2.0, 1.2, 0.0));
    m.objects.push_back(object(id++, "potted plant", 4.5, 8.5, 0.4, 0.4, 1.0, 0.0));
    m.objects.push_back(object(id++, "sofa", 2.5, 8.5, 2.0, 0.8, 0.8, 0.0));
    // room 2 (x 5..9.5)
    m.objects.push_back(object(id++, "table", 7.2, 2.0, 1.6, 0.9, 0.75, 0.3));
    m.objects.push_back(object(id++, "chair", 6.4, 1.6, 0.5, 0.5, 0.9, 0.0));
    m.objects.push_back(object(id++, "chair", 8.0, 2.6, 0.5, 0.5, 0.9, 2.0));
    m.objects.push_back(object(id++, "drawers", 9.2, 8.5, 0.5, 0.6, 0.7, 0.0));
    m.objects.push_back(object(id++, "board", 7.0, 8.92, 2.5, 0.1, 1.2, 0.0));
    m.objects.push_back(object(id++, "cabinet", 5.4, 8.2, 0.6, 1.2, 1.8, 0.0));
    // room 3 (x 9.5..14, y 4.5..9)
    m.objects.push_back(object(id++, "desk", 13.4, 8.0, 0.7, 1.4, 0.75, 0.0));
    m.objects.push_back(object(id++, "chair", 12.8, 7.6, 0.5, 0.5, 0.9, 0.5));
    m.objects.push_back(object(id++, "potted plant", 10.0, 8.6, 0.4, 0.4, 1.0, 0.0));
    m.objects.push_back(object(id++, "sofa", 13.5, 5.5, 0.8, 1.8, 0.8, 0.0));
    // room 4 (x 9.5..14, y 0..4.5)
    m.objects.push_back(object(id++, "table", 12.0, 1.0, 1.2, 0.8, 0.75, 0.0));
    m.objects.push_back(object(id++, "cabinet", 13.7, 3.5, 0.5, 1.0, 1.8, 0.0));
    m.objects.push_back(object(id++, "drawers", 10.0, 0.4, 0.6, 0.5, 0.7, 0.0));
    m.objects.push_back(object(id++, "chair", 12.6, 1.8, 0.5, 0.5, 0.9, 3.0));
    return w;
}

Scenario makeScenario(const std::string& dir, std::uint32_t seed) {
    namespace fs = std::filesystem;
    Scenario sc;
    sc.world = makeWorld();
    sc.world_dir = (fs::path(dir) / "world").string();
    sc.rawlog_path = (fs::path(dir) / "sequence.rawlog").string();
    sc.rawlog_obs_only_path = (fs::path(dir) / "sequence_obs.rawlog").string();
    sc.groundtruth_path = (fs::path(dir) / "groundtruth.tum").string();
    fs::create_directories(dir);
    world::saveWorld(sc.world, sc.world_dir);

    std::mt19937 rng(seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    std::vector<mrpt::poses::CPose3D> cams;
    for (int c = 0; c < 4; ++c) cams.push_back(obs::cameraPoseOnRobot(0.1, 0.0, 0.5, c * M_PI / 2));

    const auto path = groundTruthPath();
    mrpt::io::CFileGZOutputStream out_af(sc.rawlog_path), out_obs(sc.rawlog_obs_only_path);
    auto arch_af = mrpt::serialization::archiveFrom(out_af);
    auto arch_obs = mrpt::serialization::archiveFrom(out_obs);
    mrpt::poses::CPose2D odometry;  // noisy odometry integrated from the noisy increments
    for (std::size_t f = 0; f < path.size(); ++f) {
        const double t = kT0 + kFrameDt * static_cast<double>(f);
        const auto stamp = mrpt::Clock::fromDouble(t);
        sc.groundtruth.push_back({t, path[f]});

        // Odometry: the true increment with 3 % scale noise and small additive noise.
        mrpt::poses::CPose2D incr;
        if (f > 0) {
            const mrpt::poses::CPose2D d = mrpt::poses::CPose2D(path[f]) - mrpt::poses::CPose2D(path[f - 1]);
            incr = mrpt::poses::CPose2D(d.x() * (1 + 0.03 * n01(rng)) + 0.003 * n01(rng), d.y() + 0.003 * n01(rng),
                                        d.phi() * (1 + 0.03 * n01(rng)) + 0.003 * n01(rng));
        }
        odometry = odometry + incr;
        mrpt::obs::CActionRobotMovement2D mv;
        mv.computeFromOdometry(incr, mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
        mv.timestamp = stamp;
        mrpt::obs::CActionCollection acts;
        acts.insert(mv);

        auto odo_obs = mrpt::obs::CObservationOdometry::Create();
        odo_obs->odometry = odometry;
        odo_obs->timestamp = stamp;
        odo_obs->sensorLabel = "ODOMETRY";
        arch_obs << *odo_obs;

        mrpt::obs::CSensoryFrame sf;
        const Eigen::Isometry3d T_wr = robotToWorld(path[f]);
        for (int c = 0; c < 4; ++c) {
            auto o = obs::CObservationObjects3D::Create();
            o->timestamp = stamp;
            o->sensorLabel = "CAMERA_" + std::to_string(c);
            o->setCameraPose(cams[c]);
            o->setClassNames(obs::defaultClassNames());
            const Eigen::Isometry3d T_cw = (T_wr * toIsometry(cams[c])).inverse();
            for (const auto& mo : sc.world.objects.objects) {
                const Eigen::Vector3d c_cam = T_cw * mo.box.center;
                if (c_cam.z() < 0.3 || c_cam.z() > 7.0) continue;
                if (std::abs(std::atan2(c_cam.x(), c_cam.z())) > 0.87) continue;  // ~100 deg horizontal FOV
                if (!lineOfSight(sc.world.floorplan, {path[f].x, path[f].y}, mo.box.center.head<2>())) continue;
                if (uni(rng) < kMissProbability) continue;
                // Detector noise: centre (m), size (relative) and yaw (rad), in the world frame.
                geometry::Box3D noisy = mo.box;
                noisy.center += Eigen::Vector3d(0.08 * n01(rng), 0.08 * n01(rng), 0.03 * n01(rng));
                for (int k = 0; k < 3; ++k) noisy.size[k] *= std::max(0.5, 1.0 + 0.1 * n01(rng));
                noisy.R = Eigen::AngleAxisd(0.1 * n01(rng), Eigen::Vector3d::UnitZ()).toRotationMatrix() * noisy.R;
                obs::Detection3D d;
                d.class_id = static_cast<std::uint16_t>(mo.class_id);
                d.confidence = 0.9f;
                d.box_in_camera = noisy.transformed(T_cw);
                o->addDetection(d);
            }
            if (uni(rng) < kFalsePositiveProbability) {
                // A detection of a random map class where there is no object, in front of the camera.
                const auto& objs = sc.world.objects.objects;
                const int cls = objs[static_cast<std::size_t>(uni(rng) * objs.size()) % objs.size()].class_id;
                const double depth = 1.0 + 4.0 * uni(rng), lateral = (uni(rng) - 0.5) * depth;
                geometry::Box3D fp;
                fp.center = Eigen::Vector3d(lateral, 0.0, depth);
                fp.size = Eigen::Vector3d(0.6, 0.8, 0.6);
                obs::Detection3D d;
                d.class_id = static_cast<std::uint16_t>(cls);
                d.confidence = 0.9f;
                d.box_in_camera = fp;
                o->addDetection(d);
            }
            sf.insert(o);
            arch_obs << *o;
        }
        arch_af << acts << sf;
    }
    io::writeTum(sc.groundtruth_path, sc.groundtruth);
    sc.duration_s = sc.groundtruth.back().t_s - sc.groundtruth.front().t_s;
    return sc;
}

}  // namespace simp::localization::test
