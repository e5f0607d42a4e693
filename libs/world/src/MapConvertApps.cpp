#include <simp/world/Gridmap.h>
#include <simp/world/MapConvertApps.h>

#include <map>
#include <set>
#include <stdexcept>

namespace simp::world {

namespace {

/// Parses "--key value" pairs into the given targets; "--help"/"-h" sets help.
void parseArgs(int argc, const char* const* argv, const std::map<std::string, std::string*>& opts, bool& help,
               const std::string& usage) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            help = true;
            return;
        }
        const auto it = opts.find(a);
        if (it == opts.end()) throw std::invalid_argument("unknown option '" + a + "'\n" + usage);
        if (i + 1 >= argc) throw std::invalid_argument("option " + a + " needs a value\n" + usage);
        *it->second = argv[++i];
    }
}

}  // namespace

std::string describeObjectCounts(const ObjectMapData& data) {
    std::vector<int> counts(data.class_names.size(), 0);
    for (const auto& o : data.objects) ++counts[static_cast<std::size_t>(o.class_id)];
    std::string s;
    for (std::size_t c = 0; c < counts.size(); ++c)
        if (counts[c] > 0) s += "  " + data.class_names[c] + ": " + std::to_string(counts[c]) + "\n";
    return s;
}

std::string ImportMapApp::usage() {
    return "usage: simp-import-map --simp-dir D --out W [--heights INI]\n"
           "  Reads the authors' map format in D (floor.config, global_variance.json, Map.yaml + image,\n"
           "  roomseg.png, class_noise.csv) and writes the world directory W (floorplan.yaml/.png,\n"
           "  rooms.png, objects.json). INI section [class_heights]: <class, '_' for ' '> = height (m).\n"
           "  See doc/import-export.md.\n";
}

void ImportMapApp::initialize(int argc, const char* const* argv) {
    parseArgs(argc, argv, {{"--simp-dir", &simp_dir}, {"--out", &out_dir}, {"--heights", &heights_ini}}, help_, usage());
    if (help_) return;
    if (simp_dir.empty()) throw std::invalid_argument("missing --simp-dir D\n" + usage());
    if (out_dir.empty()) throw std::invalid_argument("missing --out W\n" + usage());
}

int ImportMapApp::run(std::ostream& out) {
    if (help_) {
        out << usage();
        return 0;
    }
    SimpImportOptions opt;
    if (!heights_ini.empty()) opt = loadSimpImportOptions(heights_ini);
    out << "Importing the authors' map from " << simp_dir << " ...\n";
    result = importSimpMap(simp_dir, opt);
    saveWorld(result, out_dir);
    const auto& g = result.floorplan;
    out << "Floor plan: " << g.getSizeX() << " x " << g.getSizeY() << " cells at " << g.getResolution()
        << " m, origin (" << g.getXMin() << ", " << g.getYMin() << ") m\n";
    if (result.rooms.empty()) {
        out << "Rooms: none (no room raster)\n";
    } else {
        std::set<int> ids;
        for (auto it = result.rooms.ids.begin(); it != result.rooms.ids.end(); ++it)
            if (*it != 0) ids.insert(*it);
        out << "Rooms: " << ids.size() << " in the room raster, " << result.objects.rooms.size() << " named\n";
    }
    out << "Objects: " << result.objects.objects.size() << " in " << result.objects.class_names.size()
        << " classes\n" << describeObjectCounts(result.objects);
    out << "Wrote world directory " << out_dir << "\n";
    return 0;
}

std::string ExportMapApp::usage() {
    return "usage: simp-export-map --world W [--out D] [--gridmap F.gridmap] [--octomap F.bt|F.ot]\n"
           "                       [--resolution M] [--config INI]\n"
           "  --out D      the world directory W in the authors' map format (floor.config,\n"
           "               global_variance.json/.csv, Map.yaml + Map.png, roomseg.png, class_noise.csv,\n"
           "               category_meta.json). See doc/import-export.md.\n"
           "  --gridmap F  the floor plan as MRPT's .gridmap (gzip-compressed COccupancyGridMap2D), the\n"
           "               map_file of MRPT's pf-localization. See doc/plugin.md.\n"
           "  --octomap F  the 3D metric-semantic map through OctoMap: .bt (OcTree, binary) or .ot\n"
           "               (ColorOcTree with class colours): walls extruded to the ceiling, closed doors,\n"
           "               object boxes, free space. --resolution M: voxel edge (m, default 0.05, overrides\n"
           "               [octomap] resolution_m of --config INI). See doc/import-export.md.\n"
           "  At least one of --out, --gridmap, --octomap.\n";
}

void ExportMapApp::initialize(int argc, const char* const* argv) {
    parseArgs(argc, argv,
              {{"--world", &world_dir}, {"--out", &out_dir}, {"--gridmap", &gridmap_path}, {"--octomap", &octomap_path},
               {"--config", &config_ini}, {"--resolution", &resolution}},
              help_, usage());
    if (help_) return;
    if (world_dir.empty()) throw std::invalid_argument("missing --world W\n" + usage());
    if (out_dir.empty() && gridmap_path.empty() && octomap_path.empty())
        throw std::invalid_argument("nothing to write: give --out D, --gridmap F or --octomap F\n" + usage());
    if (octomap_path.empty() && (!config_ini.empty() || !resolution.empty()))
        throw std::invalid_argument("--config and --resolution are options of --octomap\n" + usage());
}

int ExportMapApp::run(std::ostream& out) {
    if (help_) {
        out << usage();
        return 0;
    }
    if (!octomap_path.empty() && !octomap_writer)
        throw std::logic_error("simp-export-map: this program was built without the OctoMap exporter");
    const World w = loadWorld(world_dir);
    if (!out_dir.empty()) {
        exportSimpMap(w, out_dir);
        out << "Exported " << w.objects.objects.size() << " objects\n"
            << describeObjectCounts(w.objects) << "to the authors' format in " << out_dir << "\n";
    }
    if (!gridmap_path.empty()) {
        saveGridmap(w.floorplan, gridmap_path);
        const auto& g = w.floorplan;
        out << "Wrote the floor plan (" << g.getSizeX() << " x " << g.getSizeY() << " cells at " << g.getResolution()
            << " m, x " << g.getXMin() << " .. " << g.getXMax() << " m, y " << g.getYMin() << " .. " << g.getYMax()
            << " m) as MRPT .gridmap " << gridmap_path << "\n";
        if (const double shift = gridmapOriginShift(g); shift > 1e-6)
            out << "Note: MRPT reads this grid with its origin rounded to a multiple of " << g.getResolution()
                << " m: the floor plan moves by " << shift << " m (COccupancyGridMap2D::setSize, doc/plugin.md)\n";
    }
    if (!octomap_path.empty()) out << octomap_writer(w, config_ini, resolution, octomap_path);
    return 0;
}

}  // namespace simp::world
