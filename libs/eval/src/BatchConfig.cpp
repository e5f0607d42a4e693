#include <simp/io/StrictIni.h>
#include <simp/eval/BatchConfig.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace simp::eval {
namespace {

std::vector<std::string> splitList(const std::string& s) {
    std::string t = s;
    std::replace(t.begin(), t.end(), ',', ' ');
    std::istringstream in(t);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

/// Comma-separated list whose entries may hold spaces (class names such as "potted plant").
std::vector<std::string> splitListKeepingSpaces(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string w; std::getline(in, w, ',');) {
        const auto b = w.find_first_not_of(" \t"), e = w.find_last_not_of(" \t");
        if (b != std::string::npos) out.push_back(w.substr(b, e - b + 1));
    }
    return out;
}

const std::vector<std::string> kMethods{"simp", "edt", "d", "o", "lidar", "simp+lidar"};

}  // namespace

std::string methodLabel(const std::string& method) {
    if (method == "simp") return "Ours";
    if (method == "edt") return "EDT-MCL";
    if (method == "d") return "D-MCL";
    if (method == "o") return "O-MCL";
    if (method == "lidar") return "LiDAR-MCL";
    if (method == "simp+lidar") return "Ours+LiDAR";
    return method;
}

std::string rowLabel(const std::string& method, const std::string& variant) {
    return variant.empty() ? methodLabel(method) : methodLabel(method) + " (" + variant + ")";
}

void loadMapMetricsParams(const io::StrictIni& ini, MapMatchParams& p) {
    p.max_center_dist_m = ini.readNumber("map_metrics", "max_center_dist_m", p.max_center_dist_m, 1e-6, 100);
    const auto classes = splitListKeepingSpaces(ini.read_string("map_metrics", "classes", ""));
    if (!classes.empty()) p.classes = classes;
}

namespace {

/// Labels of `items`: `names` when given (one each), else `fallback(item)`; unique, usable as a folder.
std::vector<std::string> labelsOf(const std::vector<std::string>& items, const std::vector<std::string>& names,
                                  const std::string& names_key, const std::string& items_key,
                                  std::string (*fallback)(const std::string&),
                                  const std::function<void(const std::string&, const std::string&)>& fail) {
    if (!names.empty() && items.empty()) fail(names_key, "given without " + items_key);
    if (!names.empty() && names.size() != items.size())
        fail(names_key, std::to_string(names.size()) + " names for " + std::to_string(items.size()) + " entries of " +
                            items_key);
    std::vector<std::string> out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string name = names.empty() ? fallback(items[i]) : names[i];
        // a label names a run folder and a table row: a path or a repeated label would mix runs up
        if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos)
            fail(names.empty() ? items_key : names_key, "'" + name + "' cannot label '" + items[i] + "' (set " +
                                                            names_key + ")");
        if (std::find(out.begin(), out.end(), name) != out.end())
            fail(names.empty() ? items_key : names_key, "two entries are named '" + name + "' (set " + names_key + ")");
        out.push_back(name);
    }
    return out;
}

/// Last component of a directory path, also when written with a trailing '/' ("demo_out/map/" -> "map").
std::string dirName(const std::string& dir) {
    std::filesystem::path p = std::filesystem::path(dir).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
    return p.filename().string();
}
std::string fileStem(const std::string& file) { return std::filesystem::path(file).stem().string(); }

BatchConfig loadBatchConfigStrict(const std::string& ini_path) {
    const io::StrictIni ini(ini_path);  // exists, is a file, is an .ini
    const std::function<void(const std::string&, const std::string&)> fail = [&](const std::string& key,
                                                                                 const std::string& why) {
        throw std::runtime_error("batch config '" + ini_path + "', key '" + key + "': " + why);
    };
    BatchConfig c;
    const std::string S = "batch";
    c.world = ini.read_string(S, "world", "");
    if (c.world.empty()) fail("[batch] world", "required (the localization map's world directory)");
    c.map_name = ini.read_string(S, "map_name", c.map_name);
    const auto dirs = splitList(ini.read_string(S, "sequences", ""));
    if (dirs.empty()) fail("[batch] sequences", "required (list of sequence directories)");
    const auto names = splitList(ini.read_string(S, "sequence_names", ""));
    if (!names.empty() && names.size() != dirs.size())
        fail("[batch] sequence_names", std::to_string(names.size()) + " names for " + std::to_string(dirs.size()) +
                                           " sequences");
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        std::string name = names.empty() ? std::filesystem::path(dirs[i]).lexically_normal().filename().string()
                                         : names[i];
        if (name.empty()) name = "S" + std::to_string(i + 1);
        for (const auto& s : c.sequences)
            if (s.name == name) fail("[batch] sequences", "two sequences are named '" + name + "' (set sequence_names)");
        c.sequences.push_back({name, dirs[i]});
    }
    const auto methods = splitList(ini.read_string(S, "methods", ""));
    if (!methods.empty()) c.methods = methods;
    for (const auto& m : c.methods)
        if (std::find(kMethods.begin(), kMethods.end(), m) == kMethods.end())
            fail("[batch] methods", "unknown method '" + m + "' (known: simp edt d o lidar simp+lidar)");
    c.repetitions = static_cast<int>(ini.readInteger(S, "repetitions", c.repetitions, 1, 1000));
    c.first_seed = static_cast<int>(ini.readInteger(S, "first_seed", c.first_seed, 0, 2147483647));
    c.cores = static_cast<int>(ini.readInteger(S, "cores", c.cores, 1, 256));
    c.localize_bin = ini.read_string(S, "localize_bin", "");
    c.localize_config = ini.read_string(S, "localize_config", "");
    c.localize_configs = splitList(ini.read_string(S, "localize_configs", ""));
    if (!c.localize_config.empty() && !c.localize_configs.empty())
        fail("[batch] localize_configs", "excludes [batch] localize_config (one config: localize_config; several: "
                                         "localize_configs)");
    c.localize_config_names = labelsOf(c.localize_configs, splitList(ini.read_string(S, "localize_config_names", "")),
                                       "[batch] localize_config_names", "[batch] localize_configs", fileStem, fail);
    c.particles = static_cast<int>(ini.readInteger(S, "particles", 0, 0, 500000));
    c.extra_args = splitList(ini.read_string(S, "extra_args", ""));
    c.maps = splitList(ini.read_string(S, "maps", ""));
    c.map_names = labelsOf(c.maps, splitList(ini.read_string(S, "map_names", "")), "[batch] map_names",
                           "[batch] maps", dirName, fail);
    c.map_ground_truths = splitList(ini.read_string(S, "map_ground_truths", ""));
    if (!c.map_ground_truths.empty() && c.maps.empty()) fail("[batch] map_ground_truths", "given without [batch] maps");
    if (c.map_ground_truths.size() > 1 && c.map_ground_truths.size() != c.maps.size())
        fail("[batch] map_ground_truths", std::to_string(c.map_ground_truths.size()) + " ground truths for " +
                                              std::to_string(c.maps.size()) + " maps (give one for all, or one each)");

    const std::string M = "metrics";
    c.metrics.max_trans_m = ini.readNumber(M, "max_trans_m", c.metrics.max_trans_m, 1e-6, 1e3);
    c.metrics.max_rot_rad = ini.readNumber(M, "max_rot_rad", c.metrics.max_rot_rad, 1e-6, 2 * M_PI);
    c.metrics.max_outside_s = ini.readNumber(M, "max_outside_s", c.metrics.max_outside_s, 0, 1e6);
    c.metrics.convergence_fraction = ini.readNumber(M, "convergence_fraction", c.metrics.convergence_fraction, 1e-6, 1);
    if (!(c.metrics.max_trans_m > 0)) fail("[metrics] max_trans_m", "must be > 0");
    if (!(c.metrics.max_rot_rad > 0)) fail("[metrics] max_rot_rad", "must be > 0");
    if (!(c.metrics.max_outside_s >= 0)) fail("[metrics] max_outside_s", "must be >= 0");
    if (!(c.metrics.convergence_fraction > 0 && c.metrics.convergence_fraction <= 1))
        fail("[metrics] convergence_fraction", "must be in (0, 1]");
    loadMapMetricsParams(ini, c.map_metrics);
    ini.checkUnknown();
    return c;
}
}  // namespace

std::vector<BatchVariant> BatchConfig::variants() const {
    if (localize_configs.empty()) return {{"", localize_config}};
    std::vector<BatchVariant> v;
    for (std::size_t i = 0; i < localize_configs.size(); ++i)
        v.push_back({i < localize_config_names.size() ? localize_config_names[i] : fileStem(localize_configs[i]),
                     localize_configs[i]});
    return v;
}

std::vector<BatchMap> BatchConfig::batchMaps() const {
    std::vector<BatchMap> v;
    for (std::size_t i = 0; i < maps.size(); ++i) {
        const std::string gt = map_ground_truths.empty()       ? world
                               : map_ground_truths.size() == 1 ? map_ground_truths[0]
                                                               : map_ground_truths[i];
        v.push_back({i < map_names.size() ? map_names[i] : dirName(maps[i]), maps[i], gt});
    }
    return v;
}

BatchConfig loadBatchConfig(const std::string& ini_path) {
    try {
        return loadBatchConfigStrict(ini_path);
    } catch (const std::invalid_argument& e) {  // io::StrictIni's errors: this function throws runtime_error
        throw std::runtime_error(e.what());
    }
}

std::string BatchConfig::dump() const {
    std::ostringstream s;
    s << "world = " << world << "\nmap_name = " << map_name << "\nsequences =";
    for (const auto& q : sequences) s << " " << q.name << ":" << q.dir;
    s << "\nmethods =";
    for (const auto& m : methods) s << " " << m;
    s << "\nrepetitions = " << repetitions << "\nfirst_seed = " << first_seed << "\ncores = " << cores
      << "\nlocalize_bin = " << localize_bin << "\nlocalize configs =";
    for (const auto& v : variants()) s << " " << (v.name.empty() ? "" : v.name + ":") << (v.config.empty() ? "(none)" : v.config);
    s << "\nparticles = " << particles << "\nextra_args =";
    for (const auto& a : extra_args) s << " " << a;
    s << "\nmaps =";
    for (const auto& m : batchMaps()) s << " " << m.name << ":" << m.dir << " vs " << m.ground_truth;
    s << "\n[metrics] max_trans_m = " << metrics.max_trans_m << ", max_rot_rad = " << metrics.max_rot_rad
      << ", max_outside_s = " << metrics.max_outside_s << ", convergence_fraction = " << metrics.convergence_fraction
      << "\n[map_metrics] max_center_dist_m = " << map_metrics.max_center_dist_m << ", classes =";
    for (const auto& k : map_metrics.classes) s << " '" << k << "'";
    s << "\n";
    return s.str();
}

}  // namespace simp::eval
