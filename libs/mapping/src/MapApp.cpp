#include <simp/io/CommandLine.h>
#include <simp/io/StrictIni.h>
#include <mrpt/poses/CPose2D.h>
#include <simp/io/Tum.h>
#include <simp/mapping/MapApp.h>
#include <simp/eval/Plots.h>
#include <simp/eval/PngFile.h>
#include <simp/eval/Scene3D.h>
#include <simp/obs/RawlogReader.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>

namespace simp::mapping {
namespace fs = std::filesystem;

MapApp::MapApp() : log(&std::cout) {}

io::CommandLine MapApp::commandLine() {
    io::CommandLine c("simp-map", "Builds a 3D object map over the floor plan of a world from posed detections (doc/mapping.md).");
    c.required("world", "W", "world directory W (its floor plan and rooms are used, not its objects)")
        .required("rawlog", "FILE", "rawlog of CObservationObjects3D (Q/sequence.rawlog)")
        .required("poses", "FILE", "robot poses, TUM file (Q/groundtruth.tum)")
        .required("out", "M", "output world directory M")
        .option("config", "INI", ".ini with a [mapping] section (config_ini/mapping.ini)")
        .flag("odometry-only", "use the rawlog's integrated odometry (from the first TUM pose) instead of the TUM poses")
        .option("3dscene", "F", "also write an MRPT .3Dscene (SceneViewer3D): floor plan, built objects, poses")
        .option("update", "M0", "update the map M0 of an earlier session: writes the updated map, M/changes.json and\n"
                                "M/changes.png (doc/mapping.md)")
        .version("1.0");
    return c;
}

bool MapApp::initialize(int argc, const char* const* argv) {
    io::CommandLine c = commandLine();
    if (!c.parse(argc, argv, std::cout)) return false;  // --help / --version printed
    MapAppArgs a;
    a.world_dir = c.value("world");
    a.rawlog_path = c.value("rawlog");
    a.poses_path = c.value("poses");
    a.out_dir = c.value("out");
    a.config_path = c.value("config");
    a.odometry_only = c.has("odometry-only");
    a.scene_path = c.value("3dscene");
    a.update_dir = c.value("update");
    initialize(a);
    return true;
}

void MapApp::initialize(const MapAppArgs& args) {
    m_args = args;
    if (!fs::is_directory(args.world_dir)) throw std::runtime_error("world directory '" + args.world_dir + "' does not exist");
    if (!fs::exists(args.rawlog_path)) throw std::runtime_error("rawlog '" + args.rawlog_path + "' does not exist");
    if (!fs::exists(args.poses_path)) throw std::runtime_error("poses file '" + args.poses_path + "' does not exist");
    if (args.out_dir.empty()) throw std::invalid_argument("--out must not be empty");
    if (!args.update_dir.empty() && !fs::is_directory(args.update_dir))
        throw std::runtime_error("--update map '" + args.update_dir + "' " +
                                 (fs::exists(args.update_dir) ? "is not a directory" : "does not exist") +
                                 " (expected a world directory written by simp-map)");
    MappingOptions opts;
    if (!args.config_path.empty()) {
        const io::StrictIni ini(args.config_path);  // exists, is a file, is an .ini
        try {
            opts.loadFromConfigFile(ini, "mapping");
        } catch (const std::exception& e) {
            throw std::invalid_argument(args.config_path + ": " + e.what());
        }
        ini.checkUnknown();
    }
    m_builder = ObjectMapBuilder(opts);
}

world::World MapApp::loadFloorPlanWorld() const {
    const fs::path dir(m_args.world_dir);
    if (fs::exists(dir / "objects.json")) return world::loadWorld(m_args.world_dir);
    // A floor plan without objects: floorplan.yaml (+ rooms.png).
    world::World w;
    const std::string yaml = (dir / "floorplan.yaml").string();
    if (!fs::exists(yaml)) throw std::runtime_error(yaml + ": missing (a world directory needs floorplan.yaml)");
    world::loadRosMap(yaml, w.floorplan);
    if (fs::exists(dir / "rooms.png")) {
        const world::RosMapYaml meta = world::readRosMapYaml(yaml);
        w.rooms = world::loadRoomMap((dir / "rooms.png").string(), meta.resolution_m, meta.origin_x_m, meta.origin_y_m);
    }
    return w;
}

world::World MapApp::loadEarlierMap() const {
    try {
        return world::loadWorld(m_args.update_dir);
    } catch (const std::exception& e) {
        throw std::runtime_error("--update map '" + m_args.update_dir + "': " + e.what());
    }
}

void MapApp::run() {
    std::ostream& out = *log;
    world::World w = loadFloorPlanWorld();
    out << "simp-map: world '" << m_args.world_dir << "': floor plan " << w.floorplan.getSizeX() << "x"
        << w.floorplan.getSizeY() << " cells, " << (w.rooms.empty() ? "no rooms.png (segmenting rooms)" : "rooms.png")
        << ", " << w.objects.class_names.size() << " classes (its " << w.objects.objects.size()
        << " objects are not used" << (m_args.update_dir.empty() ? "" : "; the map to update is --update's") << ")\n";

    // Start from an empty map with W's class list and class noise models, or from M0 (--update).
    world::ObjectMapData start;
    start.class_names = w.objects.class_names;
    start.class_noise = w.objects.class_noise;
    start.rooms = w.objects.rooms;
    start.room_categories = w.objects.room_categories;
    world::ObjectMapData m0;
    const bool updating = !m_args.update_dir.empty();
    if (updating) {
        m0 = loadEarlierMap().objects;
        start = m0;
        // Class noise M0 lacks (a map from elsewhere) is taken from W.
        start.class_noise.resize(start.class_names.size());
        for (std::size_t c = 0; c < start.class_names.size(); ++c)
            if (!start.class_noise[c])
                if (const int k = w.objects.classId(start.class_names[c]); k >= 0)
                    start.class_noise[c] = w.objects.class_noise.at(static_cast<std::size_t>(k));
        out << "simp-map: updating the map '" << m_args.update_dir << "' of an earlier session (" << m0.objects.size()
            << " objects)\n";
    }
    try {
        m_builder.setMap(start, updating);
    } catch (const std::exception& e) {
        if (!updating) throw;
        throw std::runtime_error("--update map '" + m_args.update_dir + "/objects.json': " + e.what());
    }
    m_builder.setFloorPlan(w.floorplan, w.rooms);
    if (m_builder.options().wall_align == WallAlignMode::Auto && !m_builder.wallAlignmentActive())
        out << "simp-map: note: the floor plan of '" << m_args.world_dir
            << "' draws furniture (unknown areas enclosed by walls): wall alignment is off (wall_align = auto)\n";

    const std::vector<io::StampedPose2D> traj = io::readTum(m_args.poses_path);
    if (traj.empty()) throw std::runtime_error(m_args.poses_path + ": no poses");
    const std::vector<obs::RawlogFrame> frames = obs::readRawlog(m_args.rawlog_path);
    out << "simp-map: " << frames.size() << " frames in '" << m_args.rawlog_path << "', " << traj.size()
        << " poses in '" << m_args.poses_path << "'" << (m_args.odometry_only ? " (odometry only)" : "") << "\n";

    mrpt::poses::CPose2D odom_pose(traj.front().pose);
    std::vector<io::StampedPose2D> odometry_path;  // the poses used with --odometry-only
    m_frames_mapped = m_frames_without_pose = 0;
    std::size_t next_report = 0;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const obs::RawlogFrame& fr = frames[f];
        if (fr.odometry_increment) odom_pose = odom_pose + mrpt::poses::CPose2D(*fr.odometry_increment);
        if (fr.observations.empty()) continue;  // an odometry-only entry (actions at a higher rate)
        mrpt::math::TPose2D pose2d;
        if (m_args.odometry_only) {
            pose2d = odom_pose.asTPose();
            odometry_path.push_back({mrpt::Clock::toDouble(fr.timestamp), pose2d});
        } else if (!io::interpolatePose(traj, mrpt::Clock::toDouble(fr.timestamp), pose2d)) {
            ++m_frames_without_pose;
            continue;
        }
        const mrpt::poses::CPose3D robot_pose{mrpt::poses::CPose2D(pose2d)};
        for (const auto& o : fr.observations)
            if (o) m_builder.insert(*o, robot_pose);
        ++m_frames_mapped;
        if (f >= next_report) {
            out << "simp-map: frame " << f + 1 << "/" << frames.size() << " (" << (100 * (f + 1) / frames.size())
                << " %), " << m_builder.map().objects.size() << " objects\n";
            next_report += std::max<std::size_t>(1, frames.size() / 10);
        }
    }
    m_builder.flush();
    if (m_frames_without_pose > 0)
        out << "simp-map: warning: " << m_frames_without_pose
            << " frames outside the time span of the poses file were skipped\n";
    if (m_frames_mapped == 0)
        throw std::runtime_error("no frame of '" + m_args.rawlog_path + "' has a pose in '" + m_args.poses_path +
                                 "' (timestamps do not overlap)");

    // Output world M: floor plan and rooms used + the built objects.
    world::World result;
    result.floorplan = w.floorplan;
    result.rooms = m_builder.rooms();
    m_update = {};
    if (updating) {
        m_update = detectChanges(m0, m_builder);
        result.objects = m_update.map;
    } else {
        result.objects = m_builder.confirmedMap();
    }
    world::saveWorld(result, m_args.out_dir);
    eval::writePng((fs::path(m_args.out_dir) / "map.png").string(), eval::drawObjectMap(result.floorplan, result.objects));
    if (updating) {
        const fs::path dir(m_args.out_dir);
        world::saveChangesFile(m_update.changes, (dir / "changes.json").string(), m_args.update_dir);
        saveUpdateEvidence(m_update.evidence, (dir / "update_evidence.tsv").string());
        std::set<std::int64_t> unseen_ids;
        for (const auto& e : m_update.evidence)
            if (e.origin == "earlier" && e.decision == "unseen") unseen_ids.insert(e.id);
        eval::writePng((dir / "changes.png").string(),
                       eval::drawChangeMap(result.floorplan, result.objects, m_update.changes, unseen_ids));
        std::map<std::string, int> per_kind;
        for (const auto& c : m_update.changes) ++per_kind[c.kind];
        out << "simp-map: changes against '" << m_args.update_dir << "': " << per_kind["removed"] << " removed, "
            << per_kind["moved"] << " moved, " << per_kind["added"] << " added, " << per_kind["door_closed"]
            << " doors closed; " << m_update.unseen
            << " objects of the earlier map not in view this session (kept); " << (dir / "changes.json").string()
            << ", " << (dir / "changes.png").string() << ", " << (dir / "update_evidence.tsv").string() << "\n";
    }
    if (!m_args.scene_path.empty()) {
        eval::MapLayers layers;
        layers.floorplan = &result.floorplan;
        layers.objects = &result.objects;
        layers.ground_truth = traj;
        layers.estimate = odometry_path;
        eval::saveScene(*eval::buildScene(layers), m_args.scene_path);
        out << "simp-map: wrote the 3D scene '" << m_args.scene_path << "' (SceneViewer3D)\n";
    }

    const BuilderStats& s = m_builder.stats();
    out << "simp-map: " << s.frames << " camera frames, " << s.detections << " detections (rejected: " << s.rejected_class
        << " class disabled, " << s.rejected_confidence << " confidence, " << s.rejected_range << " range, "
        << s.rejected_room << " other room, " << s.rejected_outside << " outside the floor, " << s.rejected_invalid
        << " invalid), " << s.integrations << " integrations, " << s.merged << " merges, " << s.added << " added, " << s.purged << " purged, "
        << s.duplicates_merged << " duplicates merged\n";
    std::map<std::string, int> per_class;
    for (const auto& o : result.objects.objects) ++per_class[result.objects.class_names[o.class_id]];
    out << "simp-map: " << result.objects.objects.size() << " objects written to '" << m_args.out_dir << "'\n";
    for (const auto& [name, n] : per_class) out << "  " << std::left << std::setw(20) << name << n << "\n";
}

}  // namespace simp::mapping
