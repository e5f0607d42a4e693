#include <simp/io/StrictIni.h>
#include <simp/io/CommandSet.h>
#include <mrpt/system/filesystem.h>
#include <simp/sim/Office.h>
#include <simp/sim/Sequence.h>
#include <simp/sim/SimApp.h>
#include <simp/sim/Trajectory.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>

namespace simp::sim {
namespace {

/// Command-line ranges (doc/simulator.md): a --seed is any 63-bit value; --rooms and --size-m2 as in
/// [office]; --duration up to the trajectory's limit; --kidnap-at is checked against the duration later.
constexpr std::int64_t kMaxSeed = std::numeric_limits<std::int64_t>::max();

}  // namespace

io::CommandSet SimApp::commandSet() {
    io::CommandSet set("simp-sim", "simp-sim: the SIMP simulator (built-in office world, sequences with odometry and 3D object detections)");
    set.add("world", "writes the world directory W (floorplan.yaml/.png, rooms.png, objects.json)")
        .option("builtin", "office", "the built-in world (only 'office', the default)")
        .required("seed", "S", "every random choice derives from S (same S -> byte-identical files)")
        .required("out", "W", "the world directory to write")
        .option("size-m2", "A", "target floor area (m^2) of the built-in office (excludes --rooms)")
        .option("rooms", "N", "number of rooms of the built-in office, in [1, 2000] (excludes --size-m2)")
        .option("config", "INI", "MRPT .ini with the simulator's knobs (config_ini/sim.ini documents all)");
    set.add("sequence", "writes Q/sequence.rawlog, Q/groundtruth.tum, Q/groundtruth_mrpt.txt (for pf-localization),\n"
                        "Q/world/, Q/changes.json and Q/overview.png (+ Q/kidnap.json with --kidnap-at)")
        .required("world", "W", "the world directory to simulate in")
        .alias("world-in")
        .required("seed", "S", "every random choice derives from S (same S -> byte-identical files)")
        .required("out", "Q", "the sequence directory to write")
        .option("config", "INI", "MRPT .ini with the simulator's knobs (config_ini/sim.ini documents all)")
        .option("duration", "SEC", "simulated time (s), overrides [sequence] duration_s")
        .option("changes", "F", "fraction in [0, 1] of objects removed/moved/added and of doors closed\n"
                                 "(every change is listed in Q/changes.json)")
        .flag("coverage", "visit the rooms nearest-first with a full turn in each (a mapping run);\n"
                          "same as [trajectory] visit_order = coverage")
        .option("kidnap-at", "SEC", "at SEC s after the start (0 <= SEC <= duration) teleport the robot once to a random\n"
                                    "free pose >= [sequence] kidnap_min_distance_m (3 m) away; odometry does not show it,\n"
                                    "Q/groundtruth.tum does; Q/kidnap.json records it. Overrides [sequence] kidnap_at_s")
        .flag("lidar", "also write 2D laser scans (CObservation2DRangeScan, sensorLabel LIDAR) into the\n"
                       "sensory frames; same as [lidar] enabled = true (doc/lidar.md)");
    return set;
}

std::string SimApp::usage() { return commandSet().help(); }

bool SimApp::initialize(const std::vector<std::string>& args, std::ostream& out) {
    io::CommandSet set = commandSet();
    const io::CommandLine* c = set.parse(args, out);
    if (!c) return false;
    command = args.front();
    seed = static_cast<std::uint64_t>(*c->integer("seed", 0, kMaxSeed));
    seed_given = true;
    out_dir = c->value("out");
    config_path = c->value("config");
    if (command == "world") {
        if (c->has("builtin")) builtin = c->value("builtin");
        size_m2 = c->number("size-m2", 1, 1e6);
        if (auto r = c->integer("rooms", 1, 2000)) rooms = static_cast<int>(*r);
        if (builtin != "office") throw std::invalid_argument("option --builtin: unknown world '" + builtin + "' (only 'office')");
        if (size_m2 && rooms) throw std::invalid_argument("options --size-m2 and --rooms exclude each other");
    } else {
        world_dir = c->value("world");
        duration_s = c->number("duration", 1e-3, kMaxDuration_s);
        changes = c->number("changes", 0, 1);
        kidnap_at_s = c->number("kidnap-at", 0, kMaxDuration_s);
        coverage = c->has("coverage");
        lidar = c->has("lidar");
    }
    return true;
}

void SimApp::run(std::ostream& out) {
    // Both commands read the whole .ini (one sim.ini serves both), so every key is checked either way.
    const io::StrictIni cfg(config_path);
    OfficeParams office;
    SimParams p;
    try {
        office.loadFromConfig(cfg, "office");
        p.loadFromConfig(cfg);
    } catch (const std::invalid_argument& e) {
        const std::string m = e.what();
        throw std::invalid_argument(m.rfind(cfg.name(), 0) == 0 ? m : cfg.name() + ": " + m);
    }
    cfg.checkUnknown();
    if (command == "world") {
        OfficeParams& p = office;
        if (rooms) {
            p.rooms = *rooms;
            p.size_m2 = 0;
        }
        if (size_m2) p.size_m2 = *size_m2;
        p.validate();
        const auto g = generateOfficeWithLayout(p, seed);
        world::saveWorld(g.world, out_dir);
        int counts[5] = {0, 0, 0, 0, 0};
        for (const auto& r : g.layout.rooms) ++counts[static_cast<int>(r.type)];
        out << "simp-sim: wrote " << out_dir << ": " << g.layout.bounds.width() << " m x " << g.layout.bounds.height()
            << " m, " << counts[0] << " offices, " << counts[1] << " meeting rooms, " << counts[2] << " kitchens, "
            << counts[3] << " receptions, " << counts[4] << " corridors, " << g.world.objects.objects.size() << " objects\n";
        return;
    }
    if (duration_s) p.duration_s = *duration_s;
    if (changes) p.changes.fraction = *changes;
    if (coverage) p.trajectory.coverage = true;
    if (lidar) p.lidar.enabled = true;
    if (kidnap_at_s) p.kidnap_at_s = *kidnap_at_s;
    p.validateKidnap(kidnap_at_s ? "option --kidnap-at" : "[sequence] kidnap_at_s");  // against the final duration
    if (!mrpt::system::directoryExists(world_dir)) throw std::runtime_error("world directory '" + world_dir + "' does not exist");
    const world::World w = world::loadWorld(world_dir);
    const auto s = simulateSequence(w, p, seed, out_dir, world_dir);
    out << "simp-sim: wrote " << out_dir << ": " << s.steps << " steps, " << s.camera_frames << " camera frames, "
        << s.true_detections << " object detections, " << s.person_detections << " person detections, "
        << s.phantom_detections << " phantoms, path " << s.path_length_m << " m; changes: " << s.changes.removed
        << " removed, " << s.changes.moved << " moved, " << s.changes.added << " added, " << s.changes.doors_closed
        << " doors closed" << (p.lidar.enabled ? "; " + std::to_string(s.scans) + " laser scans" : std::string()) << "\n";
    if (s.coverage && s.coverage->all_reached_s >= 0)
        out << "simp-sim: coverage: all " << s.coverage->goals << " goals reached by t = " << s.coverage->all_reached_s << " s\n";
    else if (s.coverage)
        out << "simp-sim: warning: coverage: " << s.coverage->reached << " of " << s.coverage->goals << " goals reached in "
            << p.duration_s << " s: parts of the map were not seen (a longer --duration covers them)\n";
    if (s.kidnap) {
        const auto& k = *s.kidnap;
        out << "simp-sim: kidnapped at t = " << k.t_from_start_s << " s (step " << k.step << ") from (" << k.from.x
            << ", " << k.from.y << ", " << k.from.phi << ") to (" << k.to.x << ", " << k.to.y << ", " << k.to.phi
            << ") (x m, y m, phi rad), " << std::hypot(k.to.x - k.from.x, k.to.y - k.from.y) << " m; see "
            << out_dir << "/kidnap.json\n";
    }
}

}  // namespace simp::sim
