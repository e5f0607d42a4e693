#pragma once
/// \file StatsOptions.h
/// Settings of simp-stats, read from section [simp-stats] of an MRPT-style .ini (key = field name).

#include <mrpt/config/CConfigFileBase.h>

#include <ostream>
#include <string>

namespace simp::stats {

struct StatsOptions {
    double delta_m = 1.0;               ///< matching gate delta: centre distance (m)
    double min_confidence = 0.0;        ///< skip predictions with a lower score
    double cell_size_m = 0.05;          ///< histogram cell (m), the paper's 5 cm
    std::string fit_source = "samples"; ///< "samples" (exact ML fit) or "histogram" (cells + Sheppard)
    double outlier_mahalanobis = 0.0;   ///< > 0: robust fit, reject beyond this Mahalanobis radius
    int min_samples = 10;               ///< classes with fewer matched samples are not modelled
    double plot_half_extent_m = 0.0;    ///< PNG half width (m); 0 = 4 sigma around mu, at least 0.5 m
    int plot_pixels_per_cell = 8;       ///< PNG scale

    /// Reads [section]; missing keys keep their defaults.
    /// \throw std::invalid_argument naming the key for an out-of-range value.
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
    /// Checks ranges; throws std::invalid_argument naming the key.
    void validate() const;
    void dumpToTextStream(std::ostream& out) const;
};

}  // namespace simp::stats
