/// \file SimParams.cpp
/// The keys of [office], [sequence], [trajectory], [odometry] and [changes], declared once
/// (io::OptionTable; the sensor sections are in SensorParams.cpp), and the whole sim.ini loaded.
#include <simp/io/StrictNumber.h>
#include <simp/sim/OfficeLayout.h>
#include <simp/sim/SimParams.h>

#include <cmath>
#include <stdexcept>

namespace simp::sim {
namespace {
using io::ValueRange;
}  // namespace

const io::OptionTable<OfficeParams>& OfficeParams::table() {
    using O = OfficeParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("office")
            .integer("rooms", &O::rooms, ValueRange::finite(), "number of rooms, in [1, 2000] (used when `size_m2` <= 0; `--rooms` overrides)")
            .number("size_m2", &O::size_m2, "m^2", ValueRange::atMost(1e6), "target floor area; > 0 overrides `rooms` (`--size-m2` overrides)")
            .number("resolution_m", &O::resolution_m, "m", ValueRange::positive(), "grid cell size of floorplan.png / rooms.png")
            .number("wall_thickness_m", &O::wall_thickness_m, "m", ValueRange::positive(), "wall thickness")
            .number("corridor_width_m", &O::corridor_width_m, "m", ValueRange::positive(), "corridor clear width")
            .number("door_width_m", &O::door_width_m, "m", ValueRange::positive(), "door gap width")
            .number("room_width_min_m", &O::room_width_min_m, "m", ValueRange::positive(), "room extent along the corridor, uniform in [min, max]; >= `door_width_m` + 0.8")
            .number("room_width_max_m", &O::room_width_max_m, "m", ValueRange::finite(), "the same, maximum")
            .number("room_depth_min_m", &O::room_depth_min_m, "m", ValueRange::positive(), "room extent away from the corridor, uniform in [min, max]")
            .number("room_depth_max_m", &O::room_depth_max_m, "m", ValueRange::finite(), "the same, maximum")
            .integer("max_rooms_per_side", &O::max_rooms_per_side, ValueRange::atLeast(1), "rooms along one side of one corridor before another corridor is started")
            .number("kitchen_every_n_rooms", &O::kitchen_every_n_rooms, "", ValueRange::positive(), "one kitchen per this many rooms (at least one from 4 rooms)")
            .number("meeting_fraction", &O::meeting_fraction, "", ValueRange::fraction(), "fraction of the remaining rooms that are meeting rooms")
            .rule("rooms", [](const O& o) { return o.size_m2 > 0 || (o.rooms >= 1 && o.rooms <= 2000); }, "be in [1, 2000] when size_m2 <= 0")
            .rule("room_width_max_m", [](const O& o) { return o.room_width_max_m >= o.room_width_min_m; }, "be >= room_width_min_m")
            .rule("room_depth_max_m", [](const O& o) { return o.room_depth_max_m >= o.room_depth_min_m; }, "be >= room_depth_min_m")
            .rule("room_width_min_m", [](const O& o) { return o.room_width_min_m >= o.door_width_m + 0.8; },
                  "leave room for the door (>= door_width_m + 0.8)");
    return t;
}

const io::OptionTable<SimParams>& SimParams::table() {
    using O = SimParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("sequence")
            .number("duration_s", &O::duration_s, "s", ValueRange::aboveUpTo(0, kMaxDuration_s), "simulated time (`--duration` overrides)")
            .number("epoch_s", &O::epoch_s, "s", ValueRange{0, 4e9, false, true}, "time stamp of the first pose (since 1970-01-01 UTC): simulated time, never the wall clock")
            .flag("progress", &O::progress, "progress lines on stderr")
            .number("kidnap_at_s", &O::kidnap_at_s, "s", ValueRange::finite(), "the robot is teleported once at this time after the start (<= `duration_s`), unseen by odometry; < 0: never (`--kidnap-at` overrides)")
            .number("kidnap_min_distance_m", &O::kidnap_min_distance_m, "m", ValueRange::between(0, 1000), "the teleport puts the robot at least this far away");
    return t;
}

const io::OptionTable<TrajectoryParams>& TrajectoryParams::table() {
    using O = TrajectoryParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("trajectory")
            .number("robot_radius_m", &O::robot_radius_m, "m", ValueRange::atLeast(0), "disc robot radius")
            .number("clearance_m", &O::clearance_m, "m", ValueRange::atLeast(0), "extra distance kept from obstacles when planning")
            .number("speed_min_mps", &O::speed_min_mps, "m/s", ValueRange::positive(), "forward speed, drawn per leg: minimum")
            .number("speed_max_mps", &O::speed_max_mps, "m/s", ValueRange::positive(), "forward speed: maximum")
            .number("turn_rate_radps", &O::turn_rate_radps, "rad/s", ValueRange::positive(), "maximum rotation rate")
            .number("turn_in_place_rad", &O::turn_in_place_rad, "rad", ValueRange::finite(), "heading error above which the robot stops and turns in place")
            .number("spin_probability", &O::spin_probability, "", ValueRange::fraction(), "probability of a full turn on the spot on reaching a room goal")
            .choice("visit_order", &O::coverage, std::vector<std::pair<std::string, bool>>{{"shuffled", false}, {"coverage", true}},
                    "room goals of each round shuffled (errands) or coverage (goals that bring every room within reach, visited in turn with a turn on the spot at each: a mapping run; `--coverage`)")
            .number("coverage_part_m", &O::coverage_part_m, "m", ValueRange::positive(), "coverage: each room's bounding box is cut into parts of about this size (at most 2 x 2), one goal each")
            .number("coverage_turn_deg", &O::coverage_turn_deg, "deg", ValueRange::between(0, 360),
                    "coverage: the turn on the spot at every goal; 0 = 360 / [cameras] count (each bearing passes a camera's axis)")
            .number("coverage_reach_m", &O::coverage_reach_m, "m", ValueRange::atLeast(0),
                    "coverage: further goals bring every part of a room within this distance of a goal (a straight line inside the room); 0 = the parts' goals only")
            .number("coverage_min_gain_m2", &O::coverage_min_gain_m2, "m^2", ValueRange::positive(),
                    "coverage: a further goal is added while it brings at least this much room area within reach")
            .choice("coverage_order", &O::coverage_tour, std::vector<std::pair<std::string, bool>>{{"nearest", false}, {"tour", true}},
                    "coverage: goals visited along one short tour by driving distance, the same every round (tour), or the nearest goal not yet visited, as the crow flies (nearest)")
            .number("waypoint_tolerance_m", &O::waypoint_tolerance_m, "m", ValueRange::positive(), "a waypoint is reached within this distance")
            .rule("speed_max_mps", [](const O& o) { return o.speed_max_mps >= o.speed_min_mps; }, "be >= speed_min_mps");
    return t;
}

const io::OptionTable<OdometryParams>& OdometryParams::table() {
    using O = OdometryParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("odometry")
            .number("rate_hz", &O::rate_hz, "Hz", ValueRange::aboveUpTo(0, 1000), "odometry (and simulation step) rate")
            .number("a1", &O::a1, "m/m", ValueRange::atLeast(0), "MRPT's Gaussian motion model (TOptions_GaussianModel)")
            .number("a2", &O::a2, "m/deg", ValueRange::atLeast(0), "the same")
            .number("a3", &O::a3, "deg/m", ValueRange::atLeast(0), "the same")
            .number("a4", &O::a4, "deg/deg", ValueRange::atLeast(0), "the same")
            .number("minStdXY", &O::minStdXY, "m", ValueRange::atLeast(0), "the same")
            .number("minStdPHI", &O::minStdPHI, "rad", ValueRange::atLeast(0), "the same")
            .number("noise_scale", &O::noise_scale, "", ValueRange::atLeast(0), "the drawn increment noise is this times the model's std (0 = perfect odometry)");
    return t;
}

const io::OptionTable<ChangeParams>& ChangeParams::table() {
    using O = ChangeParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("changes")
            .number("fraction", &O::fraction, "", ValueRange::fraction(), "fraction of the non-door objects that change: a third removed, moved, added (`--changes` overrides)")
            .number("shift_min_m", &O::shift_min_m, "m", ValueRange::atLeast(0), "a moved object is shifted by a distance in [min, max]")
            .number("shift_max_m", &O::shift_max_m, "m", ValueRange::finite(), "the same, maximum")
            .number("rotation_std_deg", &O::rotation_std_deg, "deg", ValueRange::atLeast(0), "and rotated by N(0, std)")
            .number("door_close_fraction", &O::door_close_fraction, "", ValueRange::atMost(1), "fraction of doors closed (gap blocked, door object kept); < 0: the same as `fraction`")
            .number("passage_radius_m", &O::passage_radius_m, "m", ValueRange::atMost(10), "a moved or added object never cuts off floor a disc of this radius reaches (every room keeps a way in; it may take its own footprint grown by the radius and 2 m^2 of pocket); < 0: the robot's radius + clearance of [trajectory]; 0 = off")
            .rule("shift_max_m", [](const O& o) { return o.shift_max_m >= o.shift_min_m; }, "be >= shift_min_m");
    return t;
}

void OfficeParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void OfficeParams::validate() const { table().validate(*this); }
void TrajectoryParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void OdometryParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void ChangeParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }

void SimParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg) {
    table().load(cfg, "sequence", *this);
    trajectory.loadFromConfig(cfg, "trajectory");
    odometry.loadFromConfig(cfg, "odometry");
    cameras.loadFromConfig(cfg, "cameras");
    visibility.loadFromConfig(cfg, "visibility");
    detector.loadFromConfig(cfg, "detector");
    false_positives.loadFromConfig(cfg, "false_positives");
    people.loadFromConfig(cfg, "people");
    lidar.loadFromConfig(cfg, "lidar");
    changes.loadFromConfig(cfg, "changes");
}

void SimParams::dumpToTextStream(std::ostream& out) const {
    table().dump(*this, out);
    TrajectoryParams::table().dump(trajectory, out);
    OdometryParams::table().dump(odometry, out);
    CameraParams::table().dump(cameras, out);
    VisibilityParams::table().dump(visibility, out);
    DetectorParams::table().dump(detector, out);
    FalsePositiveParams::table().dump(false_positives, out);
    PeopleParams::table().dump(people, out);
    LidarParams::table().dump(lidar, out);
    ChangeParams::table().dump(changes, out);
}

void SimParams::validateKidnap(const std::string& what) const {
    if (!std::isfinite(kidnap_at_s)) throw std::invalid_argument(what + " must be a finite number of seconds");
    if (kidnap_at_s > duration_s)
        throw std::invalid_argument(what + ": " + io::numberText(kidnap_at_s) + " s is beyond the duration of " +
                                    io::numberText(duration_s) + " s");
}

}  // namespace simp::sim
