#pragma once
/// \file BatchTables.h
/// Aggregation of batch runs into the paper's Tables II/III layout (methods as rows,
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

struct BatchSummary {
    std::vector<std::string> methods;    ///< rows
    std::vector<std::string> sequences;  ///< columns
    std::vector<std::vector<BatchCell>> cells;  ///< [method][sequence]
    std::vector<BatchCell> avg;                 ///< [method]: the AVG column
};

BatchSummary summarize(const BatchConfig& cfg, const std::vector<RunRecord>& records);

/// Markdown: success-rate table, ATE table, convergence-time table (paper layout).
std::string batchMarkdown(const BatchConfig& cfg, const BatchSummary& s);

/// CSV of every run: sequence,method,seed,status,success,converged,convergence_time_s,
/// ate_trans_m,ate_rot_rad,duration_s,error (empty field = null).
std::string runsCsv(const std::vector<RunRecord>& records);

/// CSV of the cells: method,map,sequence,runs,successes,success_rate,ate_rot_rad,ate_trans_m,
/// convergence_time_s (sequence "AVG" for the average column).
std::string summaryCsv(const BatchConfig& cfg, const BatchSummary& s);

}  // namespace simp::eval
