#pragma once
/// \file BatchTables.h
/// Aggregation of batch runs into the paper's Tables II/III layout (methods as rows, each
/// method's localization configs side by side, e.g. "Ours (paper)" then "Ours (robust)";
/// sequences as columns, AVG last).
///
/// Per (method, sequence) cell:
///  - success rate = successful runs / runs (%);
///  - ATE "rad/m" = mean over the successful runs of ate_rot_rad / ate_trans_m ("-/-" when
///    no run succeeded), as the paper reports ATE only where a method localizes;
///  - convergence time = mean over the successful runs (s).
/// AVG column: mean of the cells that have a value (success rate: of every sequence).

#include <simp/eval/BatchConfig.h>
#include <simp/eval/BatchRunner.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::eval {

struct BatchCell {
    int runs = 0, successes = 0;
    double success_rate = 0;                         ///< successes / runs, in [0, 1]
    std::optional<double> ate_rot_rad, ate_trans_m;  ///< means over successful runs
    std::optional<double> convergence_time_s;        ///< mean over successful runs (s)
};

/// One row of the tables: a method run with one localization config.
struct BatchRow {
    std::string method;   ///< simp-localize --method
    std::string variant;  ///< BatchVariant::name ("" = the single config)
    std::string label() const { return rowLabel(method, variant); }
};

struct BatchSummary {
    std::vector<BatchRow> rows;          ///< methods x variants, in the order of cfg.methods, cfg.variants()
    std::vector<std::string> sequences;  ///< columns
    std::vector<std::vector<BatchCell>> cells;  ///< [row][sequence]
    std::vector<BatchCell> avg;                 ///< [row]: the AVG column
};

BatchSummary summarize(const BatchConfig& cfg, const std::vector<RunRecord>& records);

/// Markdown: success-rate table, ATE table, convergence-time table (paper layout).
std::string batchMarkdown(const BatchConfig& cfg, const BatchSummary& s);

/// CSV of every run: sequence,method,seed,status,success,converged,convergence_time_s,
/// ate_trans_m,ate_rot_rad,duration_s,error,variant (empty field = null; variant last so the
/// columns of batches before localize_configs keep their positions).
std::string runsCsv(const std::vector<RunRecord>& records);

/// CSV of the cells: method,map,sequence,runs,successes,success_rate,ate_rot_rad,ate_trans_m,
/// convergence_time_s,variant (sequence "AVG" for the average column).
std::string summaryCsv(const BatchConfig& cfg, const BatchSummary& s);

}  // namespace simp::eval
