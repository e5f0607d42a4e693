#pragma once
/// \file BatchConfig.h
/// The batch experiment description (config_ini/batch.ini, section [batch] and [metrics];
/// keys documented in doc/evaluation.md): sequences x methods x seeds runs of simp-localize.

#include <simp/eval/TrajectoryMetrics.h>

#include <string>
#include <vector>

namespace simp::eval {

/// One recorded/simulated sequence directory Q (Q/sequence.rawlog, Q/groundtruth.tum).
struct BatchSequence {
    std::string name;  ///< column label (R1, ...), default: the directory's name
    std::string dir;   ///< the directory Q
};

struct BatchConfig {
    std::string world;                       ///< localization map (world directory), required
    std::string map_name = "GT";             ///< label of the map in the tables ("Map" column)
    std::vector<BatchSequence> sequences;    ///< required, at least one
    std::vector<std::string> methods{"simp", "edt", "d", "o"};  ///< simp-localize --method values
    int repetitions = 5;                     ///< runs per sequence and method
    int first_seed = 1;                      ///< seeds first_seed, first_seed + 1, ...
    int cores = 2;                           ///< runs executed in parallel
    std::string localize_bin;                ///< simp-localize path; empty = next to simp-eval
    std::string localize_config;             ///< passed as --config when not empty
    int particles = 0;                       ///< passed as --particles when > 0
    std::vector<std::string> extra_args;     ///< appended to every simp-localize command line
    TrajMetricsParams metrics;               ///< [metrics] section

    /// Multi-line "key = value" dump of what is used.
    std::string dump() const;
};

/// Reads an .ini file. Lists (sequences, sequence_names, methods, extra_args) are separated
/// by spaces or commas. \throw std::runtime_error naming the file and key on a missing
/// required key, an unknown method, a non-positive count or mismatched list lengths.
BatchConfig loadBatchConfig(const std::string& ini_path);

/// Paper label of a method: simp -> Ours, edt -> EDT-MCL, d -> D-MCL, o -> O-MCL.
std::string methodLabel(const std::string& method);

}  // namespace simp::eval
