#pragma once
/// \file BatchFigures.h
/// Summary figures of a batch (drawn with the project's figure module, doc/figures.md: the legend
/// right of the plot by drawLegend, series colours simp::obs::seriesColorRgb, not class colours):
///  - success.png: success rate (%) per sequence (groups on the x axis, AVG last), one bar per
///    table row (method, localization config);
///  - error_over_time.png: one panel per table row (run group), the translation error (m) of every
///    run over the time since the sequence start, coloured by sequence, the bound dashed.

#include <simp/eval/BatchConfig.h>
#include <simp/eval/BatchRunner.h>
#include <simp/eval/BatchTables.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace simp::eval {

/// Pixel layout of the batch figures: a plot area kPlotWidth wide between margins, a legend
/// panel on the right. success.png is kFigureWidth x (kTop + kSuccessHeight + kBottom);
/// error_over_time.png is kFigureWidth x rows * (kTop + kPanelHeight + kBottom) (both grow
/// downwards when the legend is taller, to the right when a label is wider than kLegendWidth).
struct BatchFigureLayout {
    static constexpr int kLeft = 70, kPlotWidth = 800, kRight = 20, kLegendWidth = 300;
    static constexpr int kTop = 40, kBottom = 50, kSuccessHeight = 300, kPanelHeight = 200;
    static constexpr int kFigureWidth = kLeft + kPlotWidth + kRight + kLegendWidth;
};

/// The translation error over time of one run (a line of error_over_time.png).
struct RunErrorSeries {
    std::size_t row = 0;        ///< index into BatchSummary::rows
    std::size_t sequence = 0;   ///< index into BatchSummary::sequences (the line's colour)
    int seed = 0;
    std::vector<double> t_s;      ///< time since the sequence start (s)
    std::vector<double> trans_m;  ///< translation error (m)
};

/// Reads back every run with status ok (its estimate.tum under `out_dir` against its sequence's
/// groundtruth.tum) and evaluates it with cfg.metrics. Runs that cannot be read are left out.
std::vector<RunErrorSeries> loadRunErrors(const BatchConfig& cfg, const BatchSummary& summary,
                                          const std::vector<RunRecord>& records, const std::string& out_dir);

cv::Mat3b drawSuccessFigure(const BatchSummary& summary);

/// `max_trans_m`: the convergence bound, dashed; the y axis spans 6 x the bound (errors clipped
/// at the top, as in simp-eval traj's figure).
cv::Mat3b drawErrorOverTimeFigure(const BatchSummary& summary, const std::vector<RunErrorSeries>& runs,
                                  double max_trans_m);

}  // namespace simp::eval
