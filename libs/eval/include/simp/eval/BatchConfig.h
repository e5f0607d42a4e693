#pragma once
/// \file BatchConfig.h
/// The batch experiment description (config_ini/batch.ini, sections [batch], [metrics] and
/// [map_metrics]; keys documented in doc/evaluation.md): sequences x localization configs x
/// methods x seeds runs of simp-localize, and the built maps evaluated against their ground truth.
/// Each field is read from the .ini key of the same name; the keys of the three sections are declared
/// once (io::OptionTable: BatchConfig::table(), trajMetricsTable(), mapMetricsTable()), and loading, range
/// checks, the unknown-key check, dump() and doc/evaluation.md's key tables derive from them.

#include <simp/eval/MapMetrics.h>
#include <simp/eval/TrajectoryMetrics.h>
#include <simp/io/OptionTable.h>
#include <simp/model/LocalizationMethods.h>

#include <string>
#include <vector>

namespace simp::io {
class StrictIni;
}

namespace simp::eval {

/// One recorded/simulated sequence directory Q (Q/sequence.rawlog, Q/groundtruth.tum).
struct BatchSequence {
    std::string name;  ///< column label (R1, ...), default: the directory's name
    std::string dir;   ///< the directory Q
};

/// One simp-localize configuration, run with every method: a group of rows in the tables.
struct BatchVariant {
    std::string name;    ///< row suffix "Ours (name)" and run folder; empty = the single-config layout
    std::string config;  ///< passed as --config when not empty
};

/// A built map evaluated against its ground-truth world (Table I).
struct BatchMap {
    std::string name;          ///< table label, default: the directory's name
    std::string dir;           ///< the map's world directory
    std::string ground_truth;  ///< the ground-truth world directory
};

struct BatchConfig {
    std::string world;                       ///< localization map (world directory), required
    std::string map_name = "GT";             ///< label of the map in the tables ("Map" column)
    std::vector<BatchSequence> sequences;    ///< required, at least one
    /// Column labels as given (`sequence_names`), one per sequence; empty: the directories' names.
    std::vector<std::string> sequence_names;
    /// simp-localize --method values (model::localizationMethodNames()); default: the object models
    /// alone, the paper's comparison, which needs no scans.
    std::vector<std::string> methods = model::sensorModelTypeNames();
    int repetitions = 5;                     ///< runs per sequence, config and method
    int first_seed = 1;                      ///< seeds first_seed, first_seed + 1, ...
    int cores = 2;                           ///< runs executed in parallel
    std::string localize_bin;                ///< simp-localize path; empty = next to simp-eval
    /// One config for every run (the layout before localize_configs existed; excludes localize_configs).
    std::string localize_config;
    /// Several configs, each run with every method as its own rows (e.g. paper and robust).
    std::vector<std::string> localize_configs;
    /// Row labels of localize_configs, one each (default: each file's stem); unique, no '/'.
    std::vector<std::string> localize_config_names;
    int particles = 0;                       ///< passed as --particles when > 0
    std::vector<std::string> extra_args;     ///< appended to every simp-localize command line
    std::vector<std::string> maps;           ///< built maps (world directories) for Table I; may be empty
    std::vector<std::string> map_names;      ///< their labels, one each (default: directory names)
    /// Ground-truth world of each map: one for all, or one per map; empty = `world`.
    std::vector<std::string> map_ground_truths;
    TrajMetricsParams metrics;               ///< [metrics] section
    MapMatchParams map_metrics;              ///< [map_metrics] section

    /// The localization configs as rows: localize_configs with their names, else one unnamed
    /// variant holding localize_config.
    std::vector<BatchVariant> variants() const;
    /// The maps with their labels and ground truths resolved (defaults as documented above).
    std::vector<BatchMap> batchMaps() const;

    /// The three sections, "key = value  // meaning" per key: readable back as a batch .ini.
    std::string dump() const;

    /// [batch] keys, declared once.
    static const io::OptionTable<BatchConfig>& table();
};

/// [metrics] keys (simp-eval batch and `traj --config`), declared once.
const io::OptionTable<TrajMetricsParams>& trajMetricsTable();
/// [map_metrics] keys (simp-eval batch and `map --config`), declared once.
const io::OptionTable<MapMatchParams>& mapMetricsTable();

/// Reads an .ini file. Lists (sequences, sequence_names, methods, localize_configs, maps, ...)
/// are separated by spaces or commas. \throw std::runtime_error naming the file and key on a
/// missing required key, an unknown method, a non-positive count or mismatched list lengths.
BatchConfig loadBatchConfig(const std::string& ini_path);

/// Reads [map_metrics] (max_center_dist_m, classes) of `ini` into `p` (simp-eval map --config too).
void loadMapMetricsParams(const io::StrictIni& ini, MapMatchParams& p);
/// Reads [metrics] of `ini` into `p` (simp-eval traj --config too).
void loadTrajMetricsParams(const io::StrictIni& ini, TrajMetricsParams& p);

/// Table label of a method (model::LocalizationMethod::label: simp -> Ours, ...); an unknown name as is.
std::string methodLabel(const std::string& method);

/// Table row label: the method's paper label, with " (variant)" when the variant is named.
std::string rowLabel(const std::string& method, const std::string& variant);

}  // namespace simp::eval
