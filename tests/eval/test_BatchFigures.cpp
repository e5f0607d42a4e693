// The summary figures of simp-eval batch: sizes from BatchFigureLayout, bars and lines in the
// palette colours where the numbers put them, legends right of the plot.
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <simp/eval/BatchFigures.h>
#include <simp/eval/FigureColors.h>
#include <simp/eval/PngFile.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace simp::eval;
using L = BatchFigureLayout;

namespace {

/// Two rows (Ours paper / robust) over two sequences: paper succeeds in 1 of 2 runs on R1 and
/// never on R2, robust always.
BatchSummary twoRowSummary() {
    const fs::path ini = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_batch_figures.ini";
    std::ofstream(ini) << "[batch]\nworld = w\nsequences = R1 R2\nmethods = simp\n"
                          "localize_configs = p.ini r.ini\nlocalize_config_names = paper robust\n";
    const auto cfg = loadBatchConfig(ini.string());
    std::vector<RunRecord> records;
    const auto add = [&](const std::string& q, const std::string& v, bool ok) {
        RunRecord r;
        r.sequence = q, r.method = "simp", r.variant = v, r.success = ok;
        records.push_back(r);
    };
    add("R1", "paper", true), add("R1", "paper", false), add("R2", "paper", false);
    add("R1", "robust", true), add("R2", "robust", true);
    return summarize(cfg, records);
}

bool hasColour(const cv::Mat3b& img, const cv::Rect& area, const cv::Scalar& bgr) {
    const cv::Vec3b c(static_cast<uchar>(bgr[0]), static_cast<uchar>(bgr[1]), static_cast<uchar>(bgr[2]));
    for (int y = area.y; y < area.y + area.height; ++y)
        for (int x = area.x; x < area.x + area.width; ++x)
            if (img(y, x) == c) return true;
    return false;
}

}  // namespace

TEST(BatchFigures, SuccessBarsHaveTheRatesHeight) {
    const auto s = twoRowSummary();
    const cv::Mat3b img = drawSuccessFigure(s);
    EXPECT_EQ(img.cols, L::kFigureWidth);
    EXPECT_EQ(img.cols, 1190);
    EXPECT_EQ(img.rows, L::kTop + L::kSuccessHeight + L::kBottom);
    // Group R1 spans the first third of the plot; paper's bar (colour 0) is its first bar and 50 % high:
    // coloured just under half height, white just above.
    const double group_w = L::kPlotWidth / 3.0, bar_w = 0.8 * group_w / 2;
    const int x_paper = static_cast<int>(L::kLeft + 0.1 * group_w + bar_w / 2);
    const int y_zero = L::kTop + L::kSuccessHeight;
    const cv::Scalar paper = seriesColor(0), robust = seriesColor(1);
    EXPECT_TRUE(hasColour(img, {x_paper, y_zero - L::kSuccessHeight / 2 + 3, 1, 1}, paper));
    EXPECT_FALSE(hasColour(img, {x_paper, y_zero - L::kSuccessHeight / 2 - 5, 1, 1}, paper));
    // robust's bar on R2 (second group, second bar) is full height.
    const int x_robust = static_cast<int>(L::kLeft + group_w + 0.1 * group_w + 1.5 * bar_w);
    EXPECT_TRUE(hasColour(img, {x_robust, L::kTop + 3, 1, 1}, robust));
    // The legend names both rows right of the plot, nothing of it over the plot.
    const int legend_x = L::kLeft + L::kPlotWidth + L::kRight;
    EXPECT_TRUE(hasColour(img, {legend_x, 0, L::kLegendWidth, 60}, paper));
    EXPECT_TRUE(hasColour(img, {legend_x, 0, L::kLegendWidth, 60}, robust));

    const fs::path png = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_batch_figures" / "success.png";
    writePng(png.string(), img);
    const cv::Mat back = cv::imread(png.string());
    EXPECT_EQ(back.cols, 1190);
    EXPECT_EQ(back.rows, 390);
    EXPECT_GT(fs::file_size(png), 1000u);
}

TEST(BatchFigures, ErrorOverTimeHasOnePanelPerRowAndLinesPerSequence) {
    const auto s = twoRowSummary();
    // A robust run on R2: 1 m error falling linearly to 0 over 10 s; nothing for paper.
    RunErrorSeries run;
    run.row = 1, run.sequence = 1, run.seed = 1;
    for (int k = 0; k <= 100; ++k) {
        run.t_s.push_back(0.1 * k);
        run.trans_m.push_back(1.0 - 0.01 * k);
    }
    const cv::Mat3b img = drawErrorOverTimeFigure(s, {run}, 0.3);
    const int panel = L::kTop + L::kPanelHeight + L::kBottom;
    EXPECT_EQ(img.cols, L::kFigureWidth);
    EXPECT_EQ(img.rows, 2 * panel);
    const cv::Scalar r2 = seriesColor(1);
    // y axis spans 6 x 0.3 = 1.8 m: at t = 5 s the error is 0.5 m, 0.5 / 1.8 of the height up, in
    // the second panel; the first panel (paper) has no line of that colour.
    const int x = L::kLeft + L::kPlotWidth / 2;
    const int y = panel + L::kTop + L::kPanelHeight - static_cast<int>(0.5 / 1.8 * L::kPanelHeight);
    EXPECT_TRUE(hasColour(img, {x - 2, y - 3, 5, 7}, r2));
    EXPECT_FALSE(hasColour(img, {L::kLeft + 1, L::kTop + 1, L::kPlotWidth - 2, L::kPanelHeight - 2}, r2));
}
