#include <opencv2/imgproc.hpp>
#include <simp/eval/Canvas.h>
#include <simp/eval/FigureColors.h>
#include <simp/eval/Legend.h>
#include <simp/eval/Plots.h>
#include <simp/eval/ScaleBar.h>
#include <simp/eval/Report.h>
#include <simp/geometry/Footprint.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace simp::eval {
namespace {

namespace fc = obs::figure_colors;
const cv::Scalar kLifted = toBgr(fc::kKidnapLifted), kPutDown = toBgr(fc::kKidnapPutDown), kParticles = toBgr(fc::kParticles),
                 kGt = toBgr(fc::kGroundTruth), kEstBefore = toBgr(fc::kEstimateBefore), kEstAfter = toBgr(fc::kEstimate),
                 kConv = toBgr(fc::kConvergence), kDiv = toBgr(fc::kDivergence);

/// One error panel: values over time, a dashed bound, vertical event lines.
void drawPanel(cv::Mat3b& img, const cv::Rect& area, const TrajMetrics& m, double bound, double y_max,
               const std::string& label, bool translation) {
    const double t_max = std::max(m.duration_s, 1e-9);
    const auto px = [&](double t, double v) {
        const double u = std::clamp(t / t_max, 0.0, 1.0), w = std::clamp(v / y_max, 0.0, 1.0);
        return cv::Point(area.x + static_cast<int>(u * area.width), area.y + area.height - static_cast<int>(w * area.height));
    };
    cv::rectangle(img, area, kTextBgr, 1);
    for (int k = 1; k < 4; ++k) {  // y grid
        const double v = y_max * k / 4;
        cv::line(img, px(0, v), px(t_max, v), kGridBgr, 1);
        cv::putText(img, fmt(v, 2), {area.x - 44, px(0, v).y + 4}, cv::FONT_HERSHEY_SIMPLEX, 0.38, kTextBgr, 1, cv::LINE_AA);
    }
    for (double f = 0; f <= 1.0001; f += 0.25)  // time ticks
        cv::putText(img, fmt(f * m.duration_s, m.duration_s < 20 ? 1 : 0), {px(f * t_max, 0).x - 8, area.y + area.height + 14},
                    cv::FONT_HERSHEY_SIMPLEX, 0.38, kTextBgr, 1, cv::LINE_AA);
    for (int x = area.x; x < area.x + area.width; x += 12)  // dashed bound
        cv::line(img, {x, px(0, bound).y}, {std::min(x + 6, area.x + area.width), px(0, bound).y}, kTextBgr, 1);
    std::vector<cv::Point> pts;
    for (const auto& s : m.errors) pts.push_back(px(s.t_s - m.start_s, translation ? s.trans_m : s.rot_rad));
    if (pts.size() > 1) cv::polylines(img, pts, false, kEstAfter, 1, cv::LINE_AA);
    if (m.convergence_time_s) cv::line(img, px(*m.convergence_time_s, 0), px(*m.convergence_time_s, y_max), kConv, 2);
    if (m.divergence_time_s)
        cv::line(img, px(*m.divergence_time_s, 0), px(*m.divergence_time_s, y_max), kDiv, 2);
    cv::putText(img, label, {area.x, area.y - 5}, cv::FONT_HERSHEY_SIMPLEX, 0.5, kTextBgr, 1, cv::LINE_AA);
}

}  // namespace

cv::Mat3b drawErrorPlot(const TrajMetrics& m, const TrajMetricsParams& p, int width, int height) {
    cv::Mat3b img(height, width, cv::Vec3b(255, 255, 255));
    const int left = 56, right = 16, top = 22, gap = 40, bottom = 34;
    const int panel_h = (height - top - gap - bottom) / 2;
    const cv::Rect a(left, top, width - left - right, panel_h), b(left, top + panel_h + gap, width - left - right, panel_h);
    const auto yMax = [&](bool trans, double bound) {
        double mx = 0;
        for (const auto& s : m.errors) mx = std::max(mx, trans ? s.trans_m : s.rot_rad);
        return std::max(2.0 * bound, std::min(mx * 1.05, 6.0 * bound));  // errors above are clipped at the top
    };
    drawPanel(img, a, m, p.max_trans_m, yMax(true, p.max_trans_m), "translation error (m)", true);
    drawPanel(img, b, m, p.max_rot_rad, yMax(false, p.max_rot_rad), "rotation error (rad)", false);
    std::string status = "time since start (s)";
    if (m.convergence_time_s) status += "   converged at " + fmt(*m.convergence_time_s, 1) + " s (blue)";
    if (m.divergence_time_s) status += "   diverged at " + fmt(*m.divergence_time_s, 1) + " s (red)";
    status += m.success ? "   success" : "   failure";
    cv::putText(img, status, {left, height - 6}, cv::FONT_HERSHEY_SIMPLEX, 0.45, kTextBgr, 1, cv::LINE_AA);
    return img;
}

cv::Mat3b drawTrajectoryMap(const MapLayers& l) {
    WorldBounds bounds;
    for (const auto* traj : {&l.ground_truth, &l.estimate})
        for (const auto& s : *traj) bounds.add(s.pose.x, s.pose.y);
    for (const auto& p : l.particles) bounds.add(p.x, p.y);
    if (l.objects)
        for (const auto& o : l.objects->objects) bounds.add(o.box);
    Canvas c = makeCanvasFor(l.floorplan, bounds);

    std::set<int> present;
    if (l.objects)
        for (const auto& o : l.objects->objects) {
            drawPolygon(c, geometry::footprint(o.box), classColor(o.class_id, l.objects->class_names), 1, 0.25);
            present.insert(o.class_id);
        }
    cv::Mat3b on_map = c.map();
    for (const auto& p : l.particles) cv::circle(on_map, c.toPixel(p.x, p.y), 1, kParticles, cv::FILLED);
    const auto polyline = [&](const std::vector<io::StampedPose2D>& traj, const cv::Scalar& colour, std::size_t jump) {
        std::vector<cv::Point> pts;
        for (const auto& s : traj) pts.push_back(c.toPixel(s.pose.x, s.pose.y));
        for (std::size_t k = 1; k < pts.size(); ++k)
            if (k != jump) cv::line(on_map, pts[k - 1], pts[k], colour, 2, cv::LINE_AA);
        if (!pts.empty()) cv::circle(on_map, pts.front(), 6, colour, 2, cv::LINE_AA);
    };
    polyline(l.ground_truth, kGt, l.ground_truth_jump);
    polyline(l.estimate, kEstAfter, 0);
    const bool kidnap = l.ground_truth_jump > 0 && l.ground_truth_jump < l.ground_truth.size();
    if (kidnap) {
        const auto& from = l.ground_truth[l.ground_truth_jump - 1].pose;
        const auto& to = l.ground_truth[l.ground_truth_jump].pose;
        cv::circle(on_map, c.toPixel(from.x, from.y), 8, kLifted, 2, cv::LINE_AA);
        cv::circle(on_map, c.toPixel(to.x, to.y), 7, kPutDown, cv::FILLED, cv::LINE_AA);
    }
    if (!l.estimate.empty()) {  // the final estimate with its heading
        const auto& b = l.estimate.back().pose;
        cv::circle(on_map, c.toPixel(b.x, b.y), 4, kEstAfter, cv::FILLED, cv::LINE_AA);
        cv::line(on_map, c.toPixel(b.x, b.y), c.toPixel(b.x + 0.5 * std::cos(b.phi), b.y + 0.5 * std::sin(b.phi)),
                 kEstAfter, 2, cv::LINE_AA);
    }
    drawScaleBar(c);
    std::vector<LegendItem> legend;
    if (!l.ground_truth.empty()) legend.emplace_back("ground truth (o = start)", kGt);
    if (kidnap) {
        legend.emplace_back("kidnap: lifted here", kLifted);
        legend.emplace_back("kidnap: put down here", kPutDown);
    }
    if (!l.estimate.empty()) legend.emplace_back("estimate (o = start)", kEstAfter);
    if (!l.particles.empty()) legend.emplace_back("final particles", kParticles);
    if (l.objects)
        for (auto& item : classLegend(*l.objects, present)) legend.push_back(std::move(item));
    drawLegend(c, legend);
    return c.image;
}

cv::Mat3b drawTrajectoryFigure(const std::vector<io::StampedPose2D>& gt, const std::vector<io::StampedPose2D>& est,
                               const TrajMetrics& m, const TrajMetricsParams& p, const world::World* world) {
    WorldBounds bounds;
    for (const auto* traj : {&gt, &est})
        for (const auto& s : *traj) bounds.add(s.pose.x, s.pose.y);
    Canvas c = makeCanvasFor(world ? &world->floorplan : nullptr, bounds);
    cv::Mat3b on_map = c.map();

    std::vector<cv::Point> gt_px;
    for (const auto& s : gt) gt_px.push_back(c.toPixel(s.pose.x, s.pose.y));
    cv::polylines(on_map, gt_px, false, kGt, 2, cv::LINE_AA);
    const double t_conv = m.convergence_time_s ? m.start_s + *m.convergence_time_s : std::numeric_limits<double>::max();
    std::vector<cv::Point> after;
    for (const auto& s : est) {
        if (s.t_s < m.start_s || s.t_s > m.start_s + m.duration_s) continue;
        if (s.t_s < t_conv) cv::circle(on_map, c.toPixel(s.pose.x, s.pose.y), 2, kEstBefore, cv::FILLED, cv::LINE_AA);
        else after.push_back(c.toPixel(s.pose.x, s.pose.y));
    }
    if (after.size() > 1) cv::polylines(on_map, after, false, kEstAfter, 2, cv::LINE_AA);
    if (!gt_px.empty()) cv::circle(on_map, gt_px.front(), 6, kGt, 2, cv::LINE_AA);
    if (!after.empty()) cv::drawMarker(on_map, after.front(), kConv, cv::MARKER_CROSS, 16, 3);
    drawScaleBar(c);
    drawLegend(c, {{"ground truth (o = start)", kGt},
                   {"estimate before convergence", kEstBefore},
                   {"estimate after convergence", kEstAfter},
                   {"convergence", kConv}});

    const cv::Mat3b errors = drawErrorPlot(m, p, c.image.cols, 320);
    cv::Mat3b figure;
    cv::vconcat(c.image, errors, figure);
    return figure;
}

}  // namespace simp::eval
