#pragma once
/// \file SimParams.h
/// All knobs of `simp-sim sequence`, one struct per sim.ini section, each section's keys declared
/// once as an io::OptionTable (SimParams.cpp, SensorParams.cpp; doc/simulator.md's key tables).

#include <mrpt/config/CConfigFileBase.h>
#include <simp/sim/SensorParams.h>
#include <simp/sim/Trajectory.h>
#include <simp/sim/WorldChanges.h>

#include <ostream>
#include <string>

namespace simp::sim {

/// [odometry]: wheel odometry at a fixed rate with MRPT's Gaussian motion model
/// (mrpt::obs::CActionRobotMovement2D::TMotionModelOptions::TOptions_GaussianModel fields).
struct OdometryParams {
    double rate_hz = 10;      ///< odometry (and simulation step) rate (Hz)
    double a1 = 0.01;         ///< m/m
    double a2 = 0.001 * 180.0 / M_PI;  ///< m/deg
    double a3 = 1.0 * M_PI / 180.0;    ///< deg/m
    double a4 = 0.05;         ///< deg/deg
    double minStdXY = 0.005;  ///< m
    double minStdPHI = 0.2 * M_PI / 180.0;  ///< rad
    double noise_scale = 1.0; ///< the drawn increment noise is this times the model's std (0 = perfect odometry)

    static const io::OptionTable<OdometryParams>& table();
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

struct SimParams {
    double duration_s = 120;       ///< [sequence] duration_s: simulated time (s)
    double epoch_s = 1700000000.0; ///< [sequence] epoch_s: time stamp of the first pose (s since 1970, UTC)
    bool progress = true;          ///< [sequence] progress: report progress on stderr
    /// [sequence] kidnap_at_s: time after the start (s) at which the robot is teleported once,
    /// unseen by odometry (the kidnapped-robot problem); < 0: never. Must be <= duration_s.
    double kidnap_at_s = -1;
    /// [sequence] kidnap_min_distance_m: the teleport puts the robot at least this far away (m)
    double kidnap_min_distance_m = 3.0;
    TrajectoryParams trajectory;
    OdometryParams odometry;
    CameraParams cameras;
    VisibilityParams visibility;
    DetectorParams detector;
    FalsePositiveParams false_positives;
    PeopleParams people;
    LidarParams lidar;
    ChangeParams changes;

    /// Reads sections sequence, trajectory, odometry, cameras, visibility, detector,
    /// false_positives, people, changes, lidar; missing keys keep defaults; bad values throw naming
    /// section and key. kidnap_at_s <= duration_s is checked by validateKidnap(), once
    /// command-line options have overridden the duration.
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg);
    /// [sequence] keys (the fields above the sub-structs).
    static const io::OptionTable<SimParams>& table();
    /// Every section, readable back as an .ini: what a sequence was simulated with.
    void dumpToTextStream(std::ostream& out) const;

    /// \throw std::invalid_argument naming `what` (the option or key that set kidnap_at_s) when
    /// kidnap_at_s is not finite or lies beyond duration_s.
    void validateKidnap(const std::string& what = "[sequence] kidnap_at_s") const;
};

}  // namespace simp::sim
