#pragma once
/// \file StatsOptions.h
/// Settings of simp-stats, read from section [simp-stats] of an MRPT-style .ini (key = field name).
/// Each key is declared once, in table(): unit, allowed values and meaning; the default is the
/// field's initializer below. Loading, range checks, the dump and doc/statistics.md's key table
/// (checked by tests/stats) derive from that declaration.

#include <mrpt/config/CConfigFileBase.h>
#include <simp/io/OptionTable.h>

#include <ostream>
#include <string>

namespace simp::stats {

struct StatsOptions {
    double delta_m = 1.0;
    double min_confidence = 0.0;
    double cell_size_m = 0.05;
    std::string fit_source = "samples";
    double outlier_mahalanobis = 0.0;
    int min_samples = 10;
    double plot_half_extent_m = 0.0;
    int plot_pixels_per_cell = 8;

    /// The declaration of every key (section "simp-stats").
    static const io::OptionTable<StatsOptions>& table();

    /// Reads [section]; missing keys keep their values. \throw std::invalid_argument naming the key.
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
    /// Checks the allowed values; throws std::invalid_argument naming the key.
    void validate() const;
    /// What is used, as an .ini section with each key's meaning and unit.
    void dumpToTextStream(std::ostream& out) const;
};

}  // namespace simp::stats
