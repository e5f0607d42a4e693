#pragma once
/// \file BatchRunner.h
/// Runs simp-localize for every (sequence, method, seed) of a BatchConfig, `cores` at a time,
/// evaluates each estimate with evaluateTrajectory and stores it next to it. Resumable.
///
/// Layout of OUT (doc/evaluation.md; <variant>/ only when the batch names several localize_configs):
///   OUT/runs/<sequence>/[<variant>/]<method>/seed<S>/estimate.tum, steps.csv   written by simp-localize
///   OUT/runs/<sequence>/<method>/seed<S>/localize.log              its standard output and error
///   OUT/runs/<sequence>/<method>/seed<S>/result.json               the evaluation (RunRecord)
/// A run whose estimate.tum and result.json both exist is not run again.

#include <simp/eval/BatchConfig.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace simp::eval {

/// Outcome of one run, as stored in result.json.
struct RunRecord {
    std::string sequence, method;
    std::string variant;         ///< BatchVariant::name ("" = the single-config layout)
    int seed = 0;
    std::string status = "ok";   ///< ok | localize_failed | eval_failed
    std::string error;           ///< message when status != ok
    bool success = false, converged = false;
    std::optional<double> convergence_time_s, ate_trans_m, ate_rot_rad;
    double duration_s = 0;
    bool resumed = false;        ///< read back from a previous batch, not run now (not stored)
};

nlohmann::json toJson(const RunRecord& r);
/// \throw std::runtime_error naming `where` when a key is missing or has the wrong type
///        ("variant" may be absent: results of batches before localize_configs existed).
RunRecord runRecordFromJson(const nlohmann::json& j, const std::string& where);

/// Directory of one run below `out_dir` (the variant's folder only when it is named).
std::string runDir(const std::string& out_dir, const std::string& sequence, const std::string& method, int seed,
                   const std::string& variant = "");

/// The simp-localize command line of one run (`--config variant.config` when not empty).
std::vector<std::string> localizeCommand(const BatchConfig& cfg, const std::string& localize_bin,
                                         const BatchSequence& seq, const BatchVariant& variant,
                                         const std::string& method, int seed, const std::string& run_dir);

/// Executes (or resumes) every run (sequences x variants x methods x seeds); on `progress` a bar redrawn in place when `terminal`, else one
/// line per finished run ("[3/8 runs] R1 simp seed 2: ok, success"). Returns the records
/// in the order sequences x methods x variants x seeds. A failing run is recorded, never thrown.
/// \throw std::runtime_error when the simp-localize binary does not exist, or the world or a
///        sequence's groundtruth.tum / sequence.rawlog is missing (before anything runs).
std::vector<RunRecord> runBatch(const BatchConfig& cfg, const std::string& out_dir, std::ostream& progress,
                                bool terminal = true);

}  // namespace simp::eval
