#include <opencv2/imgproc.hpp>
#include <simp/eval/FigureColors.h>
#include <simp/eval/Legend.h>

#include <algorithm>

namespace simp::eval {
namespace {

constexpr int kRow = 24;       ///< px per legend line
constexpr int kSwatchW = 22;   ///< swatch width (px)
constexpr int kSwatchH = 14;   ///< swatch height (px)
constexpr int kTextGap = 8;    ///< px between swatch and label
constexpr double kFontScale = 0.5;

}  // namespace

cv::Rect drawLegend(Canvas& canvas, const std::vector<LegendItem>& items) {
    int text_w = 0;
    for (const auto& item : items) {
        int baseline = 0;
        text_w = std::max(text_w, cv::getTextSize(item.first, cv::FONT_HERSHEY_SIMPLEX, kFontScale, 1, &baseline).width);
    }
    const int x0 = canvas.map_width_px + Canvas::kStripMargin;
    const int top = canvas.strip_used_px;
    const int width = kSwatchW + kTextGap + text_w;
    const int height = kRow * static_cast<int>(items.size()) + Canvas::kStripMargin;
    ensureStrip(canvas, width + 2 * Canvas::kStripMargin, top + height);
    int y = top + kRow;  // baseline of the first label
    for (const auto& [label, color] : items) {
        cv::rectangle(canvas.image, cv::Rect(x0, y - 12, kSwatchW, kSwatchH), color, cv::FILLED);
        cv::putText(canvas.image, label, {x0 + kSwatchW + kTextGap, y}, cv::FONT_HERSHEY_SIMPLEX, kFontScale,
                    toBgr(obs::figure_colors::kText), 1, cv::LINE_AA);
        y += kRow;
    }
    canvas.strip_used_px = top + height;
    return {x0, top, width, height};
}

std::vector<LegendItem> classLegend(const world::ObjectMapData& objects, const std::set<int>& present) {
    std::vector<LegendItem> legend;
    for (int id : present) {
        const bool named = id >= 0 && id < static_cast<int>(objects.class_names.size());
        legend.emplace_back(named ? objects.class_names[static_cast<std::size_t>(id)] : "class " + std::to_string(id),
                            classColor(id, objects.class_names));
    }
    return legend;
}

}  // namespace simp::eval
