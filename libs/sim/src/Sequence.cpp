#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>
#include <simp/io/MrptGroundTruth.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/sim/DetectionModel.h>
#include <simp/sim/LidarSimulator.h>
#include <simp/sim/People.h>
#include <simp/sim/Sequence.h>
#include <simp/sim/Visibility.h>
#include <simp/world/JsonRead.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace simp::sim {
namespace {

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel(const OdometryParams& p) {
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m;
    m.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
    m.gaussianModel = {p.a1, p.a2, p.a3, p.a4, p.minStdXY, p.minStdPHI};
    return m;
}

/// Odometry increment = true increment (+) noise drawn from the model's own covariance.
mrpt::obs::CActionRobotMovement2D odometryAction(const mrpt::poses::CPose2D& true_increment, const OdometryParams& p,
                                                 double t_s, Rng& rng) {
    const auto model = motionModel(p);
    mrpt::obs::CActionRobotMovement2D truth;
    truth.computeFromOdometry(true_increment, model);
    const auto [cov, mean] = truth.poseChange->getCovarianceAndMean();
    const Eigen::Matrix3d C = cov.asEigen() + Eigen::Matrix3d::Identity() * 1e-15;
    const Eigen::Matrix3d L = C.llt().matrixL();
    const Eigen::Vector3d e = p.noise_scale * (L * Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal()));
    const mrpt::poses::CPose2D noisy(true_increment.x() + e.x(), true_increment.y() + e.y(), true_increment.phi() + e.z());
    mrpt::obs::CActionRobotMovement2D act;
    act.computeFromOdometry(noisy, model);
    act.timestamp = mrpt::Clock::fromDouble(t_s);
    return act;
}

nlohmann::ordered_json poseToJson(const mrpt::math::TPose2D& p) {
    return nlohmann::ordered_json{{"x", p.x}, {"y", p.y}, {"phi", p.phi}};
}

/// Q/kidnap.json (doc/formats.md): where evaluation finds the teleport without reading the code.
void saveKidnapJson(const KidnapEvent& k, const std::string& path) {
    nlohmann::ordered_json j;
    j["format"] = "simp-kidnap";
    j["version"] = 1;
    j["t_s"] = k.t_s;
    j["t_from_start_s"] = k.t_from_start_s;
    j["step"] = k.step;
    j["from"] = poseToJson(k.from);
    j["to"] = poseToJson(k.to);
    j["jump_m"] = std::hypot(k.to.x - k.from.x, k.to.y - k.from.y);
    world::writeJsonFile(j, path);
}

/// A walking person as an object box (not in any map).
world::MapObject personBox(const mrpt::math::TPose2D& pose, const Eigen::Vector3d& size, int person_class) {
    world::MapObject o;
    o.id = -1;
    o.class_id = person_class;
    o.box = geometry::makeUprightBox({pose.x, pose.y, 0.5 * size.z()}, size, pose.phi);
    return o;
}

}  // namespace

SequenceSummary simulateSequence(const world::World& map_world, const SimParams& params, std::uint64_t seed,
                                 const std::string& out_dir, const std::string& map_world_dir) {
    if (map_world.floorplan.getSizeX() == 0 || map_world.floorplan.getSizeY() == 0)
        throw std::runtime_error("simulateSequence: the world has an empty floor plan");
    if (map_world.objects.class_names.empty()) throw std::runtime_error("simulateSequence: the world has no class list");
    Rng master(seed);
    Rng rng_changes(master.split()), rng_traj(master.split()), rng_people(master.split()), rng_det(master.split()),
        rng_odo(master.split());
    const std::uint64_t noise_seed = master.split();  // persistent detection errors (doc/simulator.md)
    // split after all others: a sequence without a kidnap draws exactly what it drew before
    Rng rng_kidnap(master.split());
    Rng rng_lidar(master.split());  // after the kidnap's: a sequence without scans is as before
    params.validateKidnap();
    SequenceSummary summary;

    // the world of this sequence (long-term change) and what the robot must drive around
    ChangeParams change_params = params.changes;
    if (change_params.passage_radius_m < 0)
        change_params.passage_radius_m = params.trajectory.robot_radius_m + params.trajectory.clearance_m;
    const world::World w = applyChanges(map_world, change_params, rng_changes, &summary.changes);
    const auto& names = w.objects.class_names;
    const int person_class = w.objects.classId("person");
    const Raster walls = wallRaster(w.floorplan);
    std::vector<world::MapObject> ever_standing = map_world.objects.objects;  // drawn into the plan, or standing now
    ever_standing.insert(ever_standing.end(), w.objects.objects.begin(), w.objects.objects.end());
    const camera::FloorPlanGrid camera_walls = cameraWalls(w.floorplan, ever_standing, names, params.visibility.self_margin_m);
    SceneVisibility visibility(camera_walls, params.visibility);
    const Raster obstacles = drivingObstacles(w);

    const double dt = 1.0 / params.odometry.rate_hz;
    KidnapEvent kidnap;
    CoverageProgress coverage;
    const KidnapParams kidnap_params{params.kidnap_at_s, params.kidnap_min_distance_m};
    TrajectoryParams trajectory = params.trajectory;
    if (trajectory.coverage_turn_deg <= 0) trajectory.coverage_turn_deg = 360.0 / params.cameras.count;
    const auto traj = generateTrajectory(obstacles, w.rooms, trajectory, params.epoch_s, dt, params.duration_s,
                                         rng_traj, kidnap_params, &rng_kidnap, &kidnap, &coverage);
    if (kidnap_params.at_s >= 0) summary.kidnap = kidnap;
    if (trajectory.coverage) summary.coverage = coverage;
    const std::size_t jump_step = summary.kidnap ? kidnap.step : 0;  // 0: no teleport (pose 0 is the start)
    std::vector<double> times;
    for (const auto& p : traj) times.push_back(p.t_s);
    for (std::size_t k = 1; k < traj.size(); ++k)
        if (k != jump_step)
            summary.path_length_m += std::hypot(traj[k].pose.x - traj[k - 1].pose.x, traj[k].pose.y - traj[k - 1].pose.y);
    const auto people = person_class >= 0 ? simulatePeople(obstacles, w.rooms, params.people, times, rng_people)
                                          : std::vector<std::vector<mrpt::math::TPose2D>>{};
    std::vector<Eigen::Vector3d> person_size;
    for (std::size_t i = 0; i < people.size(); ++i)
        person_size.emplace_back(rng_people.uniform(0.4, 0.55), rng_people.uniform(0.3, 0.4), rng_people.uniform(1.6, 1.9));

    // the camera rig
    const auto& cam = params.cameras;
    std::vector<mrpt::poses::CPose3D> robot_T_camera;
    for (int i = 0; i < cam.count; ++i) {
        const double yaw = (cam.first_yaw_deg + 360.0 * i / cam.count) * M_PI / 180.0;
        robot_T_camera.push_back(obs::cameraPoseOnRobot(cam.mount_radius_m * std::cos(yaw), cam.mount_radius_m * std::sin(yaw),
                                                        cam.height_m, yaw, cam.pitch_down_deg * M_PI / 180.0));
    }
    mrpt::img::TCamera K = cam.intrinsics;  // written into every observation
    K.cameraName = "simp-sim";
    const int camera_every = std::max(1, static_cast<int>(std::lround(params.odometry.rate_hz / cam.rate_hz)));
    model::NoiseModel person_noise;
    person_noise.cov_m2 = Eigen::Matrix2d::Identity() * std::pow(params.detector.default_noise_std_m, 2);

    if (!mrpt::system::directoryExists(out_dir) && !mrpt::system::createDirectory(out_dir))
        throw std::runtime_error("cannot create output folder '" + out_dir + "'");
    const std::string rawlog_path = out_dir + "/sequence.rawlog";
    mrpt::io::CFileOutputStream file;
    if (!file.open(rawlog_path)) throw std::runtime_error("cannot write '" + rawlog_path + "'");
    auto arch = mrpt::serialization::archiveFrom(file);

    // the 2D LiDAR ([lidar]; doc/lidar.md): at most one scan per odometry step
    std::optional<LidarSimulator> lidar;
    if (params.lidar.enabled) lidar.emplace(w, params.lidar);
    const auto lidar_every = static_cast<std::size_t>(
        std::max(1L, std::lround(params.odometry.rate_hz / params.lidar.rate_hz)));

    std::vector<world::MapObject> scene = w.objects.objects;
    const std::size_t n_static = scene.size();
    int last_pct = -1;
    for (std::size_t k = 1; k < traj.size(); ++k) {
        const double t = traj[k].t_s;
        // the teleport's step: the wheels did not turn, the odometry shows no jump (its noise is drawn as always)
        const mrpt::poses::CPose2D inc = k == jump_step
                                             ? mrpt::poses::CPose2D()
                                             : mrpt::poses::CPose2D(traj[k].pose) - mrpt::poses::CPose2D(traj[k - 1].pose);
        mrpt::obs::CActionCollection acts;
        acts.insert(odometryAction(inc, params.odometry, t, rng_odo));
        mrpt::obs::CSensoryFrame sf;
        if (k % static_cast<std::size_t>(camera_every) == 0) {
            scene.resize(n_static);
            for (std::size_t i = 0; i < people.size(); ++i) scene.push_back(personBox(people[i][k], person_size[i], person_class));
            for (int c = 0; c < cam.count; ++c) {
                const camera::PinholeCamera view = camera::PinholeCamera::onRobot(traj[k].pose, robot_T_camera[static_cast<std::size_t>(c)], cam.intrinsics);
                auto ob = std::make_shared<obs::CObservationObjects3D>();
                ob->sensorLabel = "CAMERA_" + std::to_string(c);
                ob->timestamp = mrpt::Clock::fromDouble(t);
                ob->setCameraPose(robot_T_camera[static_cast<std::size_t>(c)]);
                ob->setIntrinsics(K);
                ob->setImageSize(K.ncols, K.nrows);
                ob->setClassNames(names);
                std::vector<obs::Detection3D> dets;
                for (const auto& v : visibility.visible(view, scene, names)) {
                    const auto& o = scene[v.index];
                    const bool is_person = v.index >= n_static;
                    const auto noise = is_person ? person_noise : centreNoiseOf(noiseFor(w.objects, o, params.detector), o, params.detector);
                    if (auto d = detectObject(view, o, noise, names.size(), params.detector, rng_det, noise_seed)) {
                        dets.push_back(*d);
                        ++(is_person ? summary.person_detections : summary.true_detections);
                    }
                }
                const int n_fp = rng_det.poisson(params.false_positives.rate_per_frame);
                for (int f = 0; f < n_fp; ++f)
                    if (auto d = phantomDetection(view, walls, names, params.false_positives, params.detector, rng_det)) {
                        dets.push_back(*d);
                        ++summary.phantom_detections;
                    }
                ob->setDetections(dets);
                sf.insert(ob);
                ++summary.camera_frames;
            }
        }
        if (lidar && k % lidar_every == 0) {
            std::vector<world::MapObject> walkers;
            for (std::size_t i = 0; i < people.size(); ++i) walkers.push_back(personBox(people[i][k], person_size[i], person_class));
            sf.insert(std::make_shared<mrpt::obs::CObservation2DRangeScan>(lidar->scan(traj[k].pose, walkers, t, rng_lidar)));
            ++summary.scans;
        }
        arch << acts << sf;
        ++summary.steps;
        const int pct = static_cast<int>(100 * k / (traj.size() - 1));
        if (params.progress && pct / 10 != last_pct / 10) {
            std::cerr << "simp-sim: simulated " << (t - params.epoch_s) << " s of " << params.duration_s << " s (" << pct
                      << " %)\n";
            last_pct = pct;
        }
    }
    file.close();
    io::writeTum(out_dir + "/groundtruth.tum", traj);
    io::writeMrptGroundTruth(out_dir + "/groundtruth_mrpt.txt", traj);  // for pf-localization (doc/plugin.md)
    world::saveWorld(w, out_dir + "/world");
    saveChangesJson(summary.changes, w.objects.class_names, out_dir + "/changes.json", map_world_dir);
    const std::string kidnap_path = out_dir + "/kidnap.json";
    if (summary.kidnap) saveKidnapJson(*summary.kidnap, kidnap_path);
    else if (mrpt::system::fileExists(kidnap_path) && !mrpt::system::deleteFile(kidnap_path))  // not from an older run
        throw std::runtime_error("cannot remove the stale '" + kidnap_path + "'");
    writeOverviewPng(w, traj, out_dir + "/overview.png", jump_step);
    return summary;
}

}  // namespace simp::sim
