#include <simp/world/Gridmap.h>
#include <simp/world/MapConvertApps.h>

#include <set>
#include <sstream>
#include <stdexcept>

namespace simp::world {

std::string describeObjectCounts(const ObjectMapData& data) {
    std::vector<int> counts(data.class_names.size(), 0);
    for (const auto& o : data.objects) ++counts[static_cast<std::size_t>(o.class_id)];
    std::string s;
    for (std::size_t c = 0; c < counts.size(); ++c)
        if (counts[c] > 0) s += "  " + data.class_names[c] + ": " + std::to_string(counts[c]) + "\n";
    return s;
}

io::CommandLine ImportMapApp::commandLine() {
    io::CommandLine c("simp-import-map",
                      "Reads the authors' map format in D (floor.config, global_variance.json, Map.yaml + image,\n"
                      "roomseg.png, class_noise.csv) and writes the world directory W (floorplan.yaml/.png,\n"
                      "rooms.png, objects.json). See doc/import-export.md.");
    c.required("simp-dir", "D", "the authors' map directory")
        .required("out", "W", "the world directory to write")
        .option("heights", "INI", "section [class_heights]: <class, '_' for ' '> = height (m)");
    return c;
}

std::string ImportMapApp::usage() { return commandLine().help(); }

void ImportMapApp::initialize(int argc, const char* const* argv) {
    io::CommandLine c = commandLine();
    std::ostringstream help;
    help_ = !c.parse(argc, argv, help);
    if (help_) return;
    simp_dir = c.value("simp-dir"), out_dir = c.value("out"), heights_ini = c.value("heights");
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

io::CommandLine ExportMapApp::commandLine() {
    io::CommandLine c("simp-export-map", "A world directory W -> the authors' map format, MRPT's .gridmap, an OctoMap.");
    c.required("world", "W", "the world directory to read")
        .option("out", "D", "the world directory W in the authors' map format (floor.config,\n"
                            "global_variance.json/.csv, Map.yaml + Map.png, roomseg.png, class_noise.csv,\n"
                            "category_meta.json). See doc/import-export.md.")
        .option("gridmap", "F.gridmap", "the floor plan as MRPT's .gridmap (gzip-compressed COccupancyGridMap2D), the\n"
                                        "map_file of MRPT's pf-localization. See doc/plugin.md.")
        .option("octomap", "F.bt|F.ot", "the 3D metric-semantic map through OctoMap: .bt (OcTree, binary) or .ot\n"
                                        "(ColorOcTree with class colours): walls extruded to the ceiling, closed doors,\n"
                                        "object boxes, free space. See doc/import-export.md.")
        .option("resolution", "M", "voxel edge (m, default 0.05) of --octomap, overrides [octomap] resolution_m of --config")
        .option("config", "INI", ".ini with an [octomap] section, for --octomap")
        .notes("At least one of --out, --gridmap, --octomap.");
    return c;
}

std::string ExportMapApp::usage() { return commandLine().help(); }

void ExportMapApp::initialize(int argc, const char* const* argv) {
    io::CommandLine c = commandLine();
    std::ostringstream help;
    help_ = !c.parse(argc, argv, help);
    if (help_) return;
    world_dir = c.value("world"), out_dir = c.value("out"), gridmap_path = c.value("gridmap");
    octomap_path = c.value("octomap"), config_ini = c.value("config"), resolution = c.value("resolution");
    if (out_dir.empty() && gridmap_path.empty() && octomap_path.empty())
        throw std::invalid_argument("nothing to write: give --out D, --gridmap F or --octomap F (see --help)");
    if (octomap_path.empty() && (!config_ini.empty() || !resolution.empty()))
        throw std::invalid_argument("--config and --resolution are options of --octomap (see --help)");
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
