#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/filesystem.h>
#include <simp/sim/Office.h>
#include <simp/sim/Sequence.h>
#include <simp/sim/SimApp.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace simp::sim {
namespace {

double parseNumber(const std::string& opt, const std::string& v) {
    std::size_t used = 0;
    double d = 0;
    try {
        d = std::stod(v, &used);
    } catch (const std::logic_error&) {
        used = 0;
    }
    if (used != v.size() || !std::isfinite(d))
        throw std::invalid_argument("option " + opt + ": '" + v + "' is not a finite number");
    return d;
}

std::uint64_t parseSeed(const std::string& v) {
    if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos)
        throw std::invalid_argument("option --seed: '" + v + "' is not a non-negative integer");
    try {
        return std::stoull(v);
    } catch (const std::out_of_range&) {
        throw std::invalid_argument("option --seed: '" + v + "' is out of range");
    }
}

std::unique_ptr<mrpt::config::CConfigFileBase> openConfig(const std::string& path) {
    if (path.empty()) return std::make_unique<mrpt::config::CConfigFileMemory>(std::string());
    if (!mrpt::system::fileExists(path)) throw std::runtime_error("config file '" + path + "' does not exist");
    return std::make_unique<mrpt::config::CConfigFile>(path);
}

}  // namespace

std::string SimApp::usage() {
    return "simp-sim: the SIMP simulator (built-in office world, sequences with odometry and 3D object detections)\n"
           "\n"
           "  simp-sim world --builtin office --seed S --out W [--size-m2 A | --rooms N] [--config INI]\n"
           "      writes the world directory W (floorplan.yaml/.png, rooms.png, objects.json)\n"
           "  simp-sim sequence --world W --seed S --out Q [--config INI] [--duration SEC] [--changes F] [--coverage]\n"
           "                    [--kidnap-at SEC]\n"
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
        if (i + 1 >= args.size()) throw std::invalid_argument("option " + opt + " needs a value");
        const std::string& v = args[++i];
        if (opt == "--seed") {
            seed = parseSeed(v);
            seed_given = true;
        } else if (opt == "--out") out_dir = v;
        else if (opt == "--config") config_path = v;
        else if (command == "world" && opt == "--builtin") builtin = v;
        else if (command == "world" && opt == "--size-m2") size_m2 = parseNumber(opt, v);
        else if (command == "world" && opt == "--rooms") {
            const double r = parseNumber(opt, v);
            if (r != std::floor(r) || r < 1) throw std::invalid_argument("option --rooms: '" + v + "' is not a positive integer");
            rooms = static_cast<int>(r);
        } else if (command == "sequence" && (opt == "--world" || opt == "--world-in")) world_dir = v;
        else if (command == "sequence" && opt == "--duration") duration_s = parseNumber(opt, v);
        else if (command == "sequence" && opt == "--changes") changes = parseNumber(opt, v);
        else if (command == "sequence" && opt == "--kidnap-at") kidnap_at_s = parseNumber(opt, v);
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
    const auto cfg = openConfig(config_path);
    if (command == "world") {
        OfficeParams p;
        p.loadFromConfig(*cfg, "office");
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
    SimParams p;
    p.loadFromConfig(*cfg);
    if (duration_s) p.duration_s = *duration_s;
    if (changes) p.changes.fraction = *changes;
    if (coverage) p.trajectory.coverage = true;
    if (kidnap_at_s) p.kidnap_at_s = *kidnap_at_s;
    p.validateKidnap(kidnap_at_s ? "option --kidnap-at" : "[sequence] kidnap_at_s");  // against the final duration
    if (!mrpt::system::directoryExists(world_dir)) throw std::runtime_error("world directory '" + world_dir + "' does not exist");
    const world::World w = world::loadWorld(world_dir);
    const auto s = simulateSequence(w, p, seed, out_dir);
    out << "simp-sim: wrote " << out_dir << ": " << s.steps << " steps, " << s.camera_frames << " camera frames, "
        << s.true_detections << " object detections, " << s.person_detections << " person detections, "
        << s.phantom_detections << " phantoms, path " << s.path_length_m << " m; changes: " << s.changes.removed
        << " removed, " << s.changes.moved << " moved, " << s.changes.added << " added, " << s.changes.doors_closed
        << " doors closed\n";
    if (s.kidnap) {
        const auto& k = *s.kidnap;
        out << "simp-sim: kidnapped at t = " << k.t_from_start_s << " s (step " << k.step << ") from (" << k.from.x
            << ", " << k.from.y << ", " << k.from.phi << ") to (" << k.to.x << ", " << k.to.y << ", " << k.to.phi
            << ") (x m, y m, phi rad), " << std::hypot(k.to.x - k.from.x, k.to.y - k.from.y) << " m; see "
            << out_dir << "/kidnap.json\n";
    }
}

}  // namespace simp::sim
