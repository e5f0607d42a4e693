#include <simp/localization/StepRecord.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace simp::localization {

std::string stepsCsvHeader() {
    return "time_s,est_x_m,est_y_m,est_phi_rad,mean_x_m,mean_y_m,mean_phi_rad,cov_xx,cov_xy,cov_yy,cov_xphi,"
           "cov_yphi,cov_phiphi,cluster_weight,particles,ess,detections,updated,pruned,seconds,state,fit,"
           "fit_detections,est_std_xy_m,est_std_phi_rad,injected,rival_nats,challenger_particles,local_gain_nats,local_offset_m,"
           "challenger_x_m,challenger_y_m,challenger_phi_rad,challenger_state,challenger_fit,challenger_lead_nats,unmapped_objects,"
           "challenger_views_expected,challenger_views_seen";
}

std::string stepsCsvLine(const StepRecord& s) {
    char line[640];
    const double std_xy = std::sqrt(std::max(0.0, s.cluster_cov(0, 0) + s.cluster_cov(1, 1)));
    const double std_phi = std::sqrt(std::max(0.0, s.cluster_cov(2, 2)));
    std::snprintf(line, sizeof(line),
                  "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g,%.6f,%zu,%.3f,%zu,%d,%zu,%.6f,%s,"
                  "%.4f,%zu,%.6f,%.6f,%zu\n",
                  s.t_s, s.estimate.x, s.estimate.y, s.estimate.phi, s.mean.x, s.mean.y, s.mean.phi, s.cov(0, 0),
                  s.cov(0, 1), s.cov(1, 1), s.cov(0, 2), s.cov(1, 2), s.cov(2, 2), s.cluster_weight, s.particles, s.ess,
                  s.detections, s.updated ? 1 : 0, s.pruned, s.seconds, toString(s.state).c_str(), s.fit,
                  s.fit_detections, std_xy, std_phi, s.injected);
    std::string out(line);
    out.pop_back();  // the newline, after the rival column
    // An optional number: empty when not computed (NaN).
    const auto number = [&](double v, const char* fmt) {
        if (!std::isfinite(v)) return std::string(",");
        std::snprintf(line, sizeof(line), fmt, v);
        return std::string(line);
    };
    out += number(s.rival_advantage, ",%.3f");
    out += "," + std::to_string(s.challenger_particles);
    out += number(s.local_gain, ",%.3f") + number(s.local_offset_m, ",%.3f");
    if (s.challenger_particles > 0) {
        out += number(s.challenger_estimate.x, ",%.6f") + number(s.challenger_estimate.y, ",%.6f") +
               number(s.challenger_estimate.phi, ",%.6f") + "," + toString(s.challenger_state) +
               number(s.challenger_fit, ",%.4f") + number(s.challenger_lead, ",%.3f");
    } else {
        out += ",,,,,,";
    }
    out += "," + std::to_string(s.unmapped_objects);
    const auto count = [](long v) { return v < 0 ? std::string(",") : "," + std::to_string(v); };
    out += count(s.challenger_views_expected) + count(s.challenger_views_seen) + "\n";
    return out;
}

void writeStepsCsv(const std::string& path, const std::vector<StepRecord>& steps) {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    std::ofstream f(path);
    if (!f) throw std::runtime_error("cannot write '" + path + "'");
    f << stepsCsvHeader() << "\n";
    for (const auto& s : steps) f << stepsCsvLine(s);
    if (!f) throw std::runtime_error("error while writing '" + path + "'");
}

}  // namespace simp::localization
