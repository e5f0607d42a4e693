#pragma once
/// \file Trajectory.h
/// The robot's ground-truth path: it drives through free space from room to room (A* on the
/// grid inflated by its radius, shortcut into waypoints), at 0.2-0.5 m/s, turning in place for
/// large heading changes and now and then spinning on the spot in a room.

#include <mrpt/config/CConfigFileBase.h>
#include <simp/io/OptionTable.h>
#include <simp/io/Tum.h>
#include <simp/sim/Random.h>
#include <simp/sim/Raster.h>
#include <simp/world/World.h>

#include <Eigen/Core>
#include <optional>
#include <cstddef>
#include <string>
#include <vector>

namespace simp::sim {

/// [trajectory] section of sim.ini.
struct TrajectoryParams {
    double robot_radius_m = 0.3;       ///< disc robot radius (m)
    double clearance_m = 0.1;          ///< extra distance kept from obstacles when planning (m)
    double speed_min_mps = 0.2;        ///< forward speed per leg, uniform in [min, max] (m/s)
    double speed_max_mps = 0.5;
    double turn_rate_radps = 0.6;      ///< maximum rotation rate (rad/s)
    double turn_in_place_rad = 0.5;    ///< heading error above which the robot stops and turns (rad)
    double spin_probability = 0.3;     ///< probability of a full turn on the spot at a room goal
    double waypoint_tolerance_m = 0.1; ///< waypoint reached within this distance (m)
    /// Order of the room goals in each round: false = shuffled (a robot going about its errands),
    /// true = coverage (the nearest goal not yet visited this round, a full turn at every goal):
    /// a mapping run that sees every room in the shortest time.
    bool coverage = false;
    /// In coverage, every room is cut into parts of about this size (m, at most 2 x 2) with a goal each.
    double coverage_part_m = 3.0;
    /// In coverage, the turn on the spot at every goal (deg); 0 = 360 / the rig's camera count
    /// (set by the sequence: every bearing then passes through some camera's optical axis).
    /// doc/simulator.md says what the quarter turn of the 4-camera rig changed.
    double coverage_turn_deg = 0.0;
    /// In coverage, further goals bring every part of a room within this distance of a goal
    /// (m, a straight line inside the room; CoverageGoals.h); 0 = the parts' goals only.
    double coverage_reach_m = 2.5;
    /// ... while a further goal brings at least this much room area within reach (m^2).
    double coverage_min_gain_m2 = 1.0;
    /// In coverage, the goals are visited along one short tour (driving distance), the same
    /// every round; false = the nearest goal (straight line) not yet visited this round.
    bool coverage_tour = true;

    /// [trajectory] keys, declared once (SimParams.cpp).
    static const io::OptionTable<TrajectoryParams>& table();
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/// Room goals: for every room id of `rooms` (or, without a room map, for free cells spread
/// over the map), the free cell of `cspace` farthest from obstacles (m, world frame). With
/// part_m > 0, every room's bounding box is cut into about part_m x part_m parts, one goal each.
std::vector<Eigen::Vector2d> roomGoals(const Raster& cspace, const world::RoomMap& rooms, double part_m = 0.0);

/// The kidnapped-robot problem: the robot is lifted once and put down elsewhere.
struct KidnapParams {
    double at_s = -1;             ///< time of the teleport after t0 (s); < 0: no kidnap
    double min_distance_m = 3.0;  ///< the new position is at least this far from the old one (m)
    /// c-space clearance of the new position (m): the robot is put down with this much room
    /// beyond robot_radius_m + clearance_m, not grazing furniture
    double margin_m = 0.1;
};

/// A teleport that happened: the wheels do not turn during step `step` (from pose step-1 to
/// pose step), and pose `step` is `to` instead of the pose the robot drove to.
struct KidnapEvent {
    std::size_t step = 0;          ///< index of the first pose after the teleport (>= 1)
    double t_s = 0;                ///< time stamp of that pose (s)
    double t_from_start_s = 0;     ///< the same from the first pose, step * dt (s; t_s - t0 loses digits to the epoch)
    mrpt::math::TPose2D from, to;  ///< pose `step - 1` (where it was lifted) and pose `step` (m, rad)
};

/// A random pose for a kidnapped robot: uniform over the cells of the largest connected free
/// area of `cspace` (where the room goals are, so the robot can drive on) whose c-space
/// clearance is at least `margin_m` and whose centre is at least `min_distance_m` from `from_m`;
/// heading uniform in [-pi, pi). nullopt when no cell qualifies.
std::optional<mrpt::math::TPose2D> drawKidnapPose(const Raster& cspace, const Eigen::Vector2d& from_m,
                                                  double min_distance_m, double margin_m, Rng& rng);

/// Longest simulated sequence, s (11.6 days): the `--duration` option and [sequence]
/// duration_s are checked against it (1e300 once overflowed the step count, UB).
constexpr double kMaxDuration_s = 1e6;
/// Most poses of one trajectory (32 bytes each: at most 320 MB).
constexpr std::size_t kMaxTrajectorySteps = 10'000'000;

/// Throws std::invalid_argument naming `what` unless 0 < duration_s <= kMaxDuration_s.
void checkDuration(double duration_s, const std::string& what);

/// How far a coverage run got: its goals, how many it reached, and when it had reached them all.
struct CoverageProgress {
    std::size_t goals = 0;      ///< goals of the run (CoverageGoals.h)
    std::size_t reached = 0;    ///< goals reached at least once (the start goal included)
    double all_reached_s = -1;  ///< time from the first pose when the last was first reached (s); < 0: never
};

/// Ground-truth poses every `dt_s` from t0_s for `duration_s` (n = floor(duration / dt) + 1
/// poses). `obstacles` = walls and object footprints of the world the robot drives in.
/// With kidnap.at_s >= 0 the robot is teleported once, at the first pose at or after
/// t0 + at_s (at least pose 1, at most the last one), to drawKidnapPose() drawn from
/// `kidnap_rng` (a stream of its own: `rng` draws the same numbers up to the teleport as
/// without it); the teleport is stored in `*kidnap_event`, and the robot plans from its new pose.
/// A coverage run (p.coverage) reports its progress in `*coverage` when given.
/// \throw std::runtime_error when no goal is reachable (e.g. an empty map) or no pose for the
///        kidnap qualifies; std::invalid_argument when duration_s > kMaxDuration_s, the poses
///        would exceed kMaxTrajectorySteps, or a kidnap lacks kidnap_rng / kidnap_event.
std::vector<io::StampedPose2D> generateTrajectory(const Raster& obstacles, const world::RoomMap& rooms,
                                                  const TrajectoryParams& p, double t0_s, double dt_s,
                                                  double duration_s, Rng& rng, const KidnapParams& kidnap = {},
                                                  Rng* kidnap_rng = nullptr, KidnapEvent* kidnap_event = nullptr,
                                                  CoverageProgress* coverage = nullptr);

}  // namespace simp::sim
