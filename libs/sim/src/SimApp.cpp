#include <simp/io/StrictIni.h>
#include <simp/io/StrictNumber.h>
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

std::string SimApp::usage() {
    return "simp-sim: the SIMP simulator (built-in office world, sequences with odometry and 3D object detections)\n"
           "\n"
           "  simp-sim world --builtin office --seed S --out W [--size-m2 A | --rooms N] [--config INI]\n"
           "      writes the world directory W (floorplan.yaml/.png, rooms.png, objects.json)\n"
           "  simp-sim sequence --world W --seed S --out Q [--config INI] [--duration SEC] [--changes F] [--coverage]\n"
           "                    [--kidnap-at SEC] [--lidar]\n"
           "      writes Q/sequence.rawlog, Q/groundtruth.tum, Q/groundtruth_mrpt.txt (for pf-localization),\n"
           "      Q/world/, Q/changes.json and Q/overview.png\n"
           "      (+ Q/kidnap.json with --kidnap-at; --world-in W is a synonym of --world)\n"
           "\n"
           "  --seed S       every random choice derives from S (same S -> byte-identical files)\n"
           "  --config INI   MRPT .ini with the simulator's knobs (config_ini/sim.ini documents all)\n"
           "  --duration SEC simulated time (s), overrides [sequence] duration_s\n"
           "  --changes F    fraction in [0, 1] of objects removed/moved/added and of doors closed\n"
           "                 (every change is listed in Q/changes.json)\n"
           "  --coverage     visit the rooms nearest-first with a full turn in each (a mapping run);\n"
           "                 same as [trajectory] visit_order = coverage\n"
           "  --kidnap-at SEC  at SEC s after the start (0 <= SEC <= duration) teleport the robot once to a random\n"
           "                 free pose >= [sequence] kidnap_min_distance_m (3 m) away; odometry does not show it,\n"
           "                 Q/groundtruth.tum does; Q/kidnap.json records it. Overrides [sequence] kidnap_at_s\n"
           "  --lidar        also write 2D laser scans (CObservation2DRangeScan, sensorLabel LIDAR) into the\n"
           "                 sensory frames; same as [lidar] enabled = true (doc/lidar.md)\n"
           "  --size-m2 A    target floor area (m^2) of the built-in office; --rooms N: number of rooms\n";
}

bool SimApp::initialize(const std::vector<std::string>& args, std::ostream& out) {
    if (args.empty()) throw std::invalid_argument("missing command ('world' or 'sequence'); see --help");
    for (const auto& a : args)
        if (a == "--help" || a == "-h") {
            out << usage();
            return false;
        }
    command = args[0];
    if (command != "world" && command != "sequence")
        throw std::invalid_argument("unknown command '" + command + "' (expected 'world' or 'sequence')");
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& opt = args[i];
        if (command == "sequence" && opt == "--coverage") {
            coverage = true;
            continue;
        }
        if (command == "sequence" && opt == "--lidar") {
            lidar = true;
            continue;
        }
        if (i + 1 >= args.size()) throw std::invalid_argument("option " + opt + " needs a value");
        const std::string& v = args[++i];
        if (opt == "--seed") {
            seed = static_cast<std::uint64_t>(io::parseInteger(v, "option --seed", 0, kMaxSeed));
            seed_given = true;
        } else if (opt == "--out") out_dir = v;
        else if (opt == "--config") config_path = v;
        else if (command == "world" && opt == "--builtin") builtin = v;
        else if (command == "world" && opt == "--size-m2") size_m2 = io::parseNumber(v, "option --size-m2", 1, 1e6);
        else if (command == "world" && opt == "--rooms") rooms = static_cast<int>(io::parseInteger(v, "option --rooms", 1, 2000)); else if (command == "sequence" && (opt == "--world" || opt == "--world-in")) world_dir = v;
        else if (command == "sequence" && opt == "--duration") duration_s = io::parseNumber(v, "option --duration", 1e-3, kMaxDuration_s);
        else if (command == "sequence" && opt == "--changes") changes = io::parseNumber(v, "option --changes", 0, 1);
        else if (command == "sequence" && opt == "--kidnap-at") kidnap_at_s = io::parseNumber(v, "option --kidnap-at", 0, kMaxDuration_s);
        else throw std::invalid_argument("unknown option '" + opt + "' for command '" + command + "'");
    }
    if (!seed_given) throw std::invalid_argument("option --seed is required");
    if (out_dir.empty()) throw std::invalid_argument("option --out is required");
    if (command == "world") {
        if (builtin != "office") throw std::invalid_argument("option --builtin: unknown world '" + builtin + "' (only 'office')");
        if (size_m2 && rooms) throw std::invalid_argument("options --size-m2 and --rooms exclude each other");
        if (size_m2 && !(*size_m2 > 0)) throw std::invalid_argument("option --size-m2 must be > 0");
    } else {
        if (world_dir.empty()) throw std::invalid_argument("option --world is required");
        if (duration_s && !(*duration_s > 0)) throw std::invalid_argument("option --duration must be > 0");
        if (changes && !(*changes >= 0 && *changes <= 1)) throw std::invalid_argument("option --changes must be in [0, 1]");
        // negative means "off" only in the .ini (its default); on the command line it is a mistake
        if (kidnap_at_s && !(*kidnap_at_s >= 0))
            throw std::invalid_argument("option --kidnap-at must be >= 0 (s after the start of the sequence)");
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
    const auto s = simulateSequence(w, p, seed, out_dir);
    out << "simp-sim: wrote " << out_dir << ": " << s.steps << " steps, " << s.camera_frames << " camera frames, "
        << s.true_detections << " object detections, " << s.person_detections << " person detections, "
        << s.phantom_detections << " phantoms, path " << s.path_length_m << " m; changes: " << s.changes.removed
        << " removed, " << s.changes.moved << " moved, " << s.changes.added << " added, " << s.changes.doors_closed
        << " doors closed" << (p.lidar.enabled ? "; " + std::to_string(s.scans) + " laser scans" : std::string()) << "\n";
    if (s.kidnap) {
        const auto& k = *s.kidnap;
        out << "simp-sim: kidnapped at t = " << k.t_from_start_s << " s (step " << k.step << ") from (" << k.from.x
            << ", " << k.from.y << ", " << k.from.phi << ") to (" << k.to.x << ", " << k.to.y << ", " << k.to.phi
            << ") (x m, y m, phi rad), " << std::hypot(k.to.x - k.from.x, k.to.y - k.from.y) << " m; see "
            << out_dir << "/kidnap.json\n";
    }
}

}  // namespace simp::sim
