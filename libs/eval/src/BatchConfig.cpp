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

using io::ValueRange;

std::string joined(const std::vector<std::string>& v, const char* sep = " ") {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
    return s;
}

/// A free-text key (a path or a label) of T.
template <class T, class Field>
void textKey(io::OptionTable<T>& t, const std::string& key, Field field, const std::string& allowed, const std::string& meaning) {
    t.custom(
        key, "", allowed, meaning, [field](T& o, const std::string& text, const std::string&) { o.*field = text; },
        [field](const T& o, int) { return o.*field; });
}

/// A list key of T (entries separated by spaces or commas); an empty value keeps the default.
template <class T, class Field>
void listKey(io::OptionTable<T>& t, const std::string& key, Field field, const std::string& meaning) {
    t.custom(
        key, "", "a list", meaning,
        [field](T& o, const std::string& text, const std::string&) {
            if (const auto v = splitList(text); !v.empty()) o.*field = v;
        },
        [field](const T& o, int) { return joined(o.*field); });
}

}  // namespace

std::string methodLabel(const std::string& method) {
    const model::LocalizationMethod* m = model::findLocalizationMethod(method);
    return m ? m->label : method;
}

std::string rowLabel(const std::string& method, const std::string& variant) {
    return variant.empty() ? methodLabel(method) : methodLabel(method) + " (" + variant + ")";
}

const io::OptionTable<BatchConfig>& BatchConfig::table() {
    using O = BatchConfig;
    static const io::OptionTable<O> t = [] {
        io::OptionTable<O> t("batch");
        textKey(t, "world", &O::world, "required", "localization map, a world directory");
        textKey(t, "map_name", &O::map_name, "a label", "label in the tables' `Map` column");
        t.custom(
            "sequences", "", "required, a list", "sequence directories (each with `sequence.rawlog`, `groundtruth.tum`)",
            [](O& o, const std::string& text, const std::string&) {
                o.sequences.clear();
                for (const auto& dir : splitList(text)) o.sequences.push_back({"", dir});
            },
            [](const O& o, int) {
                std::vector<std::string> dirs;
                for (const auto& q : o.sequences) dirs.push_back(q.dir);
                return joined(dirs);
            });
        listKey(t, "sequence_names", &O::sequence_names, "column labels, one per sequence (must be unique); default: directory names");
        t.custom(
            "methods", "", "a list of " + io::option_text::choices(model::localizationMethodNames()),
            "`simp-localize --method` values (`lidar`, `simp+lidar` need sequences with scans, doc/lidar.md)",
            [](O& o, const std::string& text, const std::string& at) {
                if (const auto v = splitList(text); !v.empty()) o.methods = v;
                for (const auto& m : o.methods)
                    if (!model::findLocalizationMethod(m))
                        throw std::invalid_argument(at + ": unknown method '" + m + "' (known: " + joined(model::localizationMethodNames()) + ")");
            },
            [](const O& o, int) { return joined(o.methods); });
        t.integer("repetitions", &O::repetitions, ValueRange::between(1, 1000), "runs per sequence, config and method")
            .integer("first_seed", &O::first_seed, ValueRange::between(0, 2147483647), "seeds `first_seed ... first_seed + repetitions - 1`")
            .integer("cores", &O::cores, ValueRange::between(1, 256), "parallel runs; `--cores` overrides");
        textKey(t, "localize_bin", &O::localize_bin, "a path", "simp-localize path; empty = the `simp-localize` next to the simp-eval binary");
        textKey(t, "localize_config", &O::localize_config, "a path",
                "one config for every run, passed as `--config` (`--method` overrides its sensor model); excludes `localize_configs`");
        listKey(t, "localize_configs", &O::localize_configs, "several configs, each run with every method as its own rows; each file must exist");
        listKey(t, "localize_config_names", &O::localize_config_names, "row labels and run folders, one per config, unique, no `/`; default: file stems");
        t.integer("particles", &O::particles, ValueRange::between(0, 500000), "passed as `--particles` when > 0");
        listKey(t, "extra_args", &O::extra_args, "appended to each simp-localize command line");
        listKey(t, "maps", &O::maps, "built maps (world directories) for the map tables");
        listKey(t, "map_names", &O::map_names, "labels, one per map, unique, no `/`; default: directory names");
        listKey(t, "map_ground_truths", &O::map_ground_truths, "ground-truth world: one for every map, or one per map; empty = `world`");
        t.rule("world", [](const O& o) { return !o.world.empty(); }, "be set (the localization map's world directory)")
            .rule("sequences", [](const O& o) { return !o.sequences.empty(); }, "be set (a list of sequence directories)")
            .rule("localize_configs", [](const O& o) { return o.localize_config.empty() || o.localize_configs.empty(); },
                  "not be given with [batch] localize_config (one config: localize_config; several: localize_configs)")
            .rule("map_ground_truths", [](const O& o) { return o.map_ground_truths.empty() || !o.maps.empty(); }, "not be given without [batch] maps")
            .rule("map_ground_truths",
                  [](const O& o) { return o.map_ground_truths.size() <= 1 || o.map_ground_truths.size() == o.maps.size(); },
                  "hold one ground truth for all maps, or one per map");
        return t;
    }();
    return t;
}

const io::OptionTable<TrajMetricsParams>& trajMetricsTable() {
    using O = TrajMetricsParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("metrics")
            .number("max_trans_m", &O::max_trans_m, "m", ValueRange::between(1e-6, 1e3), "convergence radius")
            .number("max_rot_rad", &O::max_rot_rad, "rad", ValueRange::between(1e-6, 2 * M_PI), "orientation bound (pi/4)")
            .number("max_outside_s", &O::max_outside_s, "s", ValueRange::between(0, 1e6), "accumulated time outside the bounds that is a divergence")
            .number("convergence_fraction", &O::convergence_fraction, "", ValueRange::between(1e-6, 1),
                    "convergence must happen within this fraction of the duration");
    return t;
}

const io::OptionTable<MapMatchParams>& mapMetricsTable() {
    using O = MapMatchParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("map_metrics")
            .number("max_center_dist_m", &O::max_center_dist_m, "m", ValueRange::between(1e-6, 100),
                    "centre gate of the map tables and `simp-eval map --config`")
            .custom(
                "classes", "", "a comma-separated list",
                "classes evaluated (names may hold spaces); empty = every class of either map; `map --classes` overrides",
                [](O& o, const std::string& text, const std::string&) {
                    if (const auto v = splitListKeepingSpaces(text); !v.empty()) o.classes = v;
                },
                [](const O& o, int) { return joined(o.classes, ", "); });
    return t;
}

void loadMapMetricsParams(const io::StrictIni& ini, MapMatchParams& p) { mapMetricsTable().load(ini, "map_metrics", p); }
void loadTrajMetricsParams(const io::StrictIni& ini, TrajMetricsParams& p) { trajMetricsTable().load(ini, "metrics", p); }

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

/// What the table cannot check key by key: labels of sequences, configs and maps (unique, usable as folders).
void resolveLabels(BatchConfig& c) {
    const std::function<void(const std::string&, const std::string&)> fail = [](const std::string& key, const std::string& why) {
        throw std::invalid_argument(key + ": " + why);
    };
    const auto& names = c.sequence_names;
    if (!names.empty() && names.size() != c.sequences.size())
        fail("[batch] sequence_names", std::to_string(names.size()) + " names for " + std::to_string(c.sequences.size()) + " sequences");
    for (std::size_t i = 0; i < c.sequences.size(); ++i) {
        std::string name = names.empty() ? std::filesystem::path(c.sequences[i].dir).lexically_normal().filename().string() : names[i];
        if (name.empty()) name = "S" + std::to_string(i + 1);
        for (std::size_t k = 0; k < i; ++k)
            if (c.sequences[k].name == name) fail("[batch] sequences", "two sequences are named '" + name + "' (set sequence_names)");
        c.sequences[i].name = name;
    }
    c.localize_config_names = labelsOf(c.localize_configs, c.localize_config_names, "[batch] localize_config_names",
                                       "[batch] localize_configs", fileStem, fail);
    c.map_names = labelsOf(c.maps, c.map_names, "[batch] map_names", "[batch] maps", dirName, fail);
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
        const io::StrictIni ini(ini_path);  // exists, is a file, is an .ini
        BatchConfig c;
        ini.loadChecked([&](const io::StrictIni& i) {
            BatchConfig::table().load(i, "batch", c);
            trajMetricsTable().load(i, "metrics", c.metrics);
            mapMetricsTable().load(i, "map_metrics", c.map_metrics);
            resolveLabels(c);
        });
        return c;
    } catch (const std::invalid_argument& e) {  // "FILE: [section] key: ..."; this function throws runtime_error
        throw std::runtime_error(e.what());
    }
}

std::string BatchConfig::dump() const {
    std::ostringstream s;
    table().dump(*this, s);
    trajMetricsTable().dump(metrics, s);
    mapMetricsTable().dump(map_metrics, s);
    return s.str();
}

}  // namespace simp::eval
