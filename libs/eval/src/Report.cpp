#include <simp/eval/Report.h>

#include <iomanip>
#include <sstream>

namespace simp::eval {
namespace {

nlohmann::json optionalNumber(const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace

std::string fmt(double value, int decimals) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s << std::fixed << std::setprecision(decimals) << value;
    return s.str();
}

nlohmann::json toJson(const TrajMetrics& m) {
    return {{"success", m.success},
            {"converged", m.converged},
            {"convergence_time_s", optionalNumber(m.convergence_time_s)},
            {"ate_trans_m", optionalNumber(m.ate_trans_m)},
            {"ate_rot_rad", optionalNumber(m.ate_rot_rad)},
            {"duration_s", m.duration_s}};
}

std::string trajSummaryText(const TrajMetrics& m, const TrajMetricsParams& p) {
    std::ostringstream s;
    s << "sequence duration (ground-truth span): " << fmt(m.duration_s, 3) << " s\n"
      << "estimates used: " << m.n_estimates_used << " (ignored outside the ground-truth span: "
      << m.n_estimates_ignored << ")\n"
      << "bounds: " << fmt(p.max_trans_m, 3) << " m, " << fmt(p.max_rot_rad, 4) << " rad; divergence after "
      << fmt(p.max_outside_s, 2) << " s accumulated outside\n";
    if (!m.converged) {
        s << "converged: no\nsuccess: no\n";
        return s.str();
    }
    s << "converged: yes, after " << fmt(*m.convergence_time_s, 3) << " s (limit "
      << fmt(p.convergence_fraction * m.duration_s, 3) << " s = " << fmt(100 * p.convergence_fraction, 0)
      << " % of the duration)\n"
      << "time outside the bounds after convergence: " << fmt(m.time_outside_s, 3) << " s\n"
      << "diverged: " << (m.diverged ? "yes, at " + fmt(*m.divergence_time_s, 3) + " s" : std::string("no")) << "\n"
      << "success: " << (m.success ? "yes" : "no") << "\n"
      << "ATE after convergence: " << fmt(*m.ate_rot_rad, 3) << " rad / " << fmt(*m.ate_trans_m, 3) << " m\n";
    return s.str();
}

nlohmann::json toJson(const MapMetrics& m) {
    nlohmann::json per_class = nlohmann::json::object();
    for (const auto& [name, c] : m.per_class)
        per_class[name] = {{"iou", c.iou}, {"precision", c.precision}, {"recall", c.recall}};
    return {{"iou", m.iou}, {"precision", m.precision}, {"recall", m.recall}, {"per_class", per_class}};
}

std::string mapMarkdownTable(const MapMetrics& m) {
    std::ostringstream s;
    s << "| |";
    for (const auto& [name, c] : m.per_class) s << " " << name << " |";
    s << " AVG |\n|---|";
    for (std::size_t i = 0; i <= m.per_class.size(); ++i) s << "---:|";
    s << "\n";
    const auto row = [&](const char* label, auto value, double avg) {
        s << "| " << label << " |";
        for (const auto& [name, c] : m.per_class) s << " " << fmt(value(c), 2) << " |";
        s << " " << fmt(avg, 2) << " |\n";
    };
    row("IoU", [](const ClassMapMetrics& c) { return c.iou; }, m.iou);
    row("Pr", [](const ClassMapMetrics& c) { return c.precision; }, m.precision);
    row("Rc", [](const ClassMapMetrics& c) { return c.recall; }, m.recall);
    row("IoU3D", [](const ClassMapMetrics& c) { return c.iou_3d; }, m.iou_3d);
    std::size_t n_gt = 0, n_pred = 0, n_match = 0;
    s << "| GT/pred/matched |";
    for (const auto& [name, c] : m.per_class) {
        s << " " << c.n_gt << "/" << c.n_pred << "/" << c.n_matched << " |";
        n_gt += c.n_gt;
        n_pred += c.n_pred;
        n_match += c.n_matched;
    }
    s << " " << n_gt << "/" << n_pred << "/" << n_match << " |\n";
    return s.str();
}

}  // namespace simp::eval
