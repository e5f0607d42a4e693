#include <opencv2/imgproc.hpp>
#include <simp/eval/FigureColors.h>
#include <simp/eval/ScaleBar.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace simp::eval {
namespace {

constexpr int kMinStripWidth = 140;  ///< px: room for a bar and its label
constexpr int kHeight = 44;          ///< px of the strip the bar and its label take

}  // namespace

double roundLengthAtMost(double max_m) {
    double best = 0.1;
    for (double decade = 0.1; decade <= 1000.0; decade *= 10.0)
        for (double step : {1.0, 2.0, 5.0})
            if (step * decade <= max_m * (1.0 + 1e-9)) best = step * decade;
    return best;
}

double scaleBarLength(double map_width_m) { return roundLengthAtMost(std::max(map_width_m, 1e-6) / 5.0); }

ScaleBar drawScaleBar(Canvas& canvas) {
    const int top = canvas.strip_used_px;
    ensureStrip(canvas, kMinStripWidth, top + kHeight);
    const int strip_w = canvas.image.cols - canvas.map_width_px;
    const double fit_m = (strip_w - 2 * Canvas::kStripMargin) / canvas.px_per_m;
    ScaleBar bar;
    bar.length_m = std::min(scaleBarLength(canvas.map_width_px / canvas.px_per_m), roundLengthAtMost(fit_m));
    bar.length_px = static_cast<int>(std::lround(bar.length_m * canvas.px_per_m));
    const int x0 = canvas.map_width_px + Canvas::kStripMargin, y = top + 30;
    bar.from = {x0, y};
    bar.to = {x0 + bar.length_px, y};
    const cv::Scalar ink = toBgr(obs::figure_colors::kText);
    std::ostringstream label;
    label << "scale: " << bar.length_m << " m";
    cv::putText(canvas.image, label.str(), {x0, top + 16}, cv::FONT_HERSHEY_SIMPLEX, 0.5, ink, 1, cv::LINE_AA);
    // Rectangles, not thick lines (whose caps overshoot): the ink spans columns [from.x, to.x] exactly.
    cv::rectangle(canvas.image, cv::Rect(bar.from.x, y - 1, bar.length_px + 1, 3), ink, cv::FILLED);
    cv::rectangle(canvas.image, cv::Rect(bar.from.x, y - 5, 2, 10), ink, cv::FILLED);
    cv::rectangle(canvas.image, cv::Rect(bar.to.x - 1, y - 5, 2, 10), ink, cv::FILLED);
    canvas.strip_used_px = top + kHeight;
    return bar;
}

}  // namespace simp::eval
