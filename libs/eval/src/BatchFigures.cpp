#include <opencv2/imgproc.hpp>
#include <simp/eval/BatchFigures.h>
#include <simp/eval/Canvas.h>
#include <simp/eval/FigureColors.h>
#include <simp/eval/Legend.h>
#include <simp/eval/Report.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace fs = std::filesystem;

namespace simp::eval {
namespace {

using L = BatchFigureLayout;

void text(cv::Mat3b& img, const std::string& s, cv::Point at, double scale = 0.45) {
    cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, kTextBgr, 1, cv::LINE_AA);
}

/// Frame, horizontal grid lines with their values (y in [0, y_max]) and the axis labels: the y
/// label above the axis (OpenCV draws no rotated text), the x label under the area.
void drawAxes(cv::Mat3b& img, const cv::Rect& area, double y_max, int y_decimals, const std::string& y_label,
              const std::string& x_label) {
    for (int k = 0; k <= 4; ++k) {
        const int y = area.y + area.height - area.height * k / 4;
        if (k > 0 && k < 4) cv::line(img, {area.x, y}, {area.x + area.width, y}, kGridBgr, 1);
        text(img, fmt(y_max * k / 4, y_decimals), {area.x - 50, y + 4}, 0.4);
    }
    cv::rectangle(img, area, kTextBgr, 1);
    text(img, y_label, {area.x - 50, area.y - 10}, 0.5);
    text(img, x_label, {area.x + area.width / 2 - 60, area.y + area.height + 40}, 0.5);
}

/// The figure's legend right of the plot (Canvas's rule: beside, never over, growing downwards).
cv::Mat3b withLegend(cv::Mat3b img, const std::vector<LegendItem>& items) {
    Canvas c;
    c.image = img;
    c.map_width_px = L::kLeft + L::kPlotWidth + L::kRight;
    c.map_height_px = img.rows;
    drawLegend(c, items);
    return c.image;
}

}  // namespace

std::vector<RunErrorSeries> loadRunErrors(const BatchConfig& cfg, const BatchSummary& summary,
                                          const std::vector<RunRecord>& records, const std::string& out_dir) {
    std::vector<RunErrorSeries> out;
    for (const auto& r : records) {
        if (r.status != "ok") continue;
        const auto row = std::find_if(summary.rows.begin(), summary.rows.end(), [&](const BatchRow& b) {
            return b.method == r.method && b.variant == r.variant;
        });
        const auto seq = std::find(summary.sequences.begin(), summary.sequences.end(), r.sequence);
        if (row == summary.rows.end() || seq == summary.sequences.end()) continue;
        const auto& dir = cfg.sequences[static_cast<std::size_t>(seq - summary.sequences.begin())].dir;
        RunErrorSeries s;
        s.row = static_cast<std::size_t>(row - summary.rows.begin());
        s.sequence = static_cast<std::size_t>(seq - summary.sequences.begin());
        s.seed = r.seed;
        try {
            const auto m = evaluateTrajectoryFiles((fs::path(dir) / "groundtruth.tum").string(),
                                                   (fs::path(runDir(out_dir, r.sequence, r.method, r.seed, r.variant)) /
                                                    "estimate.tum")
                                                       .string(),
                                                   cfg.metrics);
            for (const auto& e : m.errors) {
                s.t_s.push_back(e.t_s - m.start_s);
                s.trans_m.push_back(e.trans_m);
            }
        } catch (const std::exception&) {
            continue;  // the run's record already says whether it evaluated; the figure shows what reads
        }
        out.push_back(std::move(s));
    }
    return out;
}

cv::Mat3b drawSuccessFigure(const BatchSummary& s) {
    cv::Mat3b img(L::kTop + L::kSuccessHeight + L::kBottom, L::kFigureWidth, cv::Vec3b(255, 255, 255));
    const cv::Rect area(L::kLeft, L::kTop, L::kPlotWidth, L::kSuccessHeight);
    drawAxes(img, area, 100.0, 0, "success rate (%)", "sequence (AVG: mean over sequences)");
    const std::size_t groups = s.sequences.size() + 1, bars = std::max<std::size_t>(1, s.rows.size());
    const double group_w = static_cast<double>(area.width) / static_cast<double>(groups);
    const double bar_w = 0.8 * group_w / static_cast<double>(bars);
    for (std::size_t g = 0; g < groups; ++g) {
        const double gx = area.x + g * group_w;
        const std::string name = g < s.sequences.size() ? s.sequences[g] : "AVG";
        text(img, name, {static_cast<int>(gx + group_w / 2) - 4 * static_cast<int>(name.size()), area.y + area.height + 18});
        for (std::size_t r = 0; r < s.rows.size(); ++r) {
            const double rate = g < s.sequences.size() ? s.cells[r][g].success_rate : s.avg[r].success_rate;
            const int x0 = static_cast<int>(gx + 0.1 * group_w + r * bar_w);
            const int h = static_cast<int>(std::lround(rate * area.height));
            // a 0 % bar is a line on the axis, so a method that never succeeds is still visible
            cv::rectangle(img, cv::Rect(x0, area.y + area.height - std::max(h, 2), std::max(1, static_cast<int>(bar_w) - 1),
                                        std::max(h, 2)),
                          seriesColor(r), cv::FILLED);
        }
    }
    std::vector<LegendItem> legend;
    for (std::size_t r = 0; r < s.rows.size(); ++r) legend.emplace_back(s.rows[r].label(), seriesColor(r));
    return withLegend(img, legend);
}

cv::Mat3b drawErrorOverTimeFigure(const BatchSummary& s, const std::vector<RunErrorSeries>& runs, double max_trans_m) {
    const int panel_h = L::kTop + L::kPanelHeight + L::kBottom;
    cv::Mat3b img(std::max<int>(1, static_cast<int>(s.rows.size())) * panel_h, L::kFigureWidth, cv::Vec3b(255, 255, 255));
    const double y_max = 6.0 * max_trans_m;
    double t_max = 1e-9;
    for (const auto& r : runs)
        if (!r.t_s.empty()) t_max = std::max(t_max, r.t_s.back());
    for (std::size_t row = 0; row < s.rows.size(); ++row) {
        const cv::Rect area(L::kLeft, static_cast<int>(row) * panel_h + L::kTop, L::kPlotWidth, L::kPanelHeight);
        drawAxes(img, area, y_max, 2, s.rows[row].label() + ": translation error (m; above " + fmt(y_max, 2) + " m drawn at the top)",
                 "time since start (s)");
        for (double f = 0; f <= 1.0001; f += 0.25)
            text(img, fmt(f * t_max, t_max < 20 ? 1 : 0),
                 {area.x + static_cast<int>(f * area.width) - 8, area.y + area.height + 16}, 0.4);
        const auto px = [&](double t, double v) {
            return cv::Point(area.x + static_cast<int>(std::clamp(t / t_max, 0.0, 1.0) * area.width),
                             area.y + area.height - static_cast<int>(std::clamp(v / y_max, 0.0, 1.0) * area.height));
        };
        for (int x = area.x; x < area.x + area.width; x += 12)  // the convergence bound, dashed
            cv::line(img, {x, px(0, max_trans_m).y}, {std::min(x + 6, area.x + area.width), px(0, max_trans_m).y},
                     kTextBgr, 1);
        for (const auto& r : runs) {
            if (r.row != row) continue;
            std::vector<cv::Point> pts;
            for (std::size_t k = 0; k < r.t_s.size(); ++k) pts.push_back(px(r.t_s[k], r.trans_m[k]));
            // crisp lines: dozens of runs overlap, anti-aliasing would blend their colours
            if (pts.size() > 1) cv::polylines(img, pts, false, seriesColor(r.sequence), 1, cv::LINE_8);
        }
    }
    std::vector<LegendItem> legend;
    for (std::size_t q = 0; q < s.sequences.size(); ++q)
        legend.emplace_back("sequence " + s.sequences[q], seriesColor(q));
    legend.emplace_back("bound " + fmt(max_trans_m, 2) + " m (dashed)", kTextBgr);
    return withLegend(img, legend);
}

}  // namespace simp::eval
