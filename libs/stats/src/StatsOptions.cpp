/// \file StatsOptions.cpp
#include <mrpt/config/CConfigFileBase.h>
#include <simp/stats/StatsOptions.h>

#include <cmath>
#include <stdexcept>

namespace simp::stats {

void StatsOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section) {
    MRPT_LOAD_CONFIG_VAR(delta_m, double, cfg, section);
    MRPT_LOAD_CONFIG_VAR(min_confidence, double, cfg, section);
    MRPT_LOAD_CONFIG_VAR(cell_size_m, double, cfg, section);
    fit_source = cfg.read_string(section, "fit_source", fit_source);
    MRPT_LOAD_CONFIG_VAR(outlier_mahalanobis, double, cfg, section);
    MRPT_LOAD_CONFIG_VAR(min_samples, int, cfg, section);
    MRPT_LOAD_CONFIG_VAR(plot_half_extent_m, double, cfg, section);
    MRPT_LOAD_CONFIG_VAR(plot_pixels_per_cell, int, cfg, section);
    validate();
}

void StatsOptions::validate() const {
    const auto bad = [](const std::string& key, const std::string& what) {
        throw std::invalid_argument("[simp-stats] " + key + ": " + what);
    };
    if (!(delta_m > 0) || !std::isfinite(delta_m)) bad("delta_m", "must be > 0 (m)");
    if (!(min_confidence >= 0 && min_confidence <= 1)) bad("min_confidence", "must be in [0, 1]");
    if (!(cell_size_m > 0) || !std::isfinite(cell_size_m)) bad("cell_size_m", "must be > 0 (m)");
    if (fit_source != "samples" && fit_source != "histogram")
        bad("fit_source", "must be 'samples' or 'histogram', got '" + fit_source + "'");
    if (!(outlier_mahalanobis >= 0) || !std::isfinite(outlier_mahalanobis))
        bad("outlier_mahalanobis", "must be >= 0 (0 = off)");
    if (min_samples < 3) bad("min_samples", "must be >= 3");
    if (!(plot_half_extent_m >= 0)) bad("plot_half_extent_m", "must be >= 0 (0 = automatic)");
    if (plot_pixels_per_cell < 1) bad("plot_pixels_per_cell", "must be >= 1");
}

void StatsOptions::dumpToTextStream(std::ostream& out) const {
    out << "[simp-stats]\n"
        << "delta_m             = " << delta_m << "  // matching gate (m)\n"
        << "min_confidence      = " << min_confidence << "\n"
        << "cell_size_m         = " << cell_size_m << "  // histogram cell (m)\n"
        << "fit_source          = " << fit_source << "\n"
        << "outlier_mahalanobis = " << outlier_mahalanobis << "  // 0 = plain ML fit\n"
        << "min_samples         = " << min_samples << "\n"
        << "plot_half_extent_m  = " << plot_half_extent_m << "  // 0 = automatic\n"
        << "plot_pixels_per_cell= " << plot_pixels_per_cell << "\n";
}

}  // namespace simp::stats
