/// \file StatsOptions.cpp
#include <simp/stats/StatsOptions.h>

namespace simp::stats {

const io::OptionTable<StatsOptions>& StatsOptions::table() {
    using io::ValueRange;
    using O = StatsOptions;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("simp-stats")
            .number("delta_m", &O::delta_m, "m", ValueRange::positive(),
                    "matching gate: 3D distance between the prediction's and the object's centres")
            .number("min_confidence", &O::min_confidence, "", ValueRange::between(0, 1), "predictions with a lower score are skipped")
            .number("cell_size_m", &O::cell_size_m, "m", ValueRange::positive(),
                    "histogram cell (the paper's 5 cm); also the pixel size of `class_noise.csv`")
            .choice("fit_source", &O::fit_source, {"samples", "histogram"},
                    "`samples`: fit to the exact offsets; `histogram`: fit to the 5 cm histogram")
            .number("outlier_mahalanobis", &O::outlier_mahalanobis, "", ValueRange::atLeast(0),
                    "> 0: robust fit, samples beyond this Mahalanobis radius are rejected; 0 = off")
            .integer("min_samples", &O::min_samples, ValueRange::atLeast(3),
                     "classes with fewer matched predictions are not modelled (empty CSV row, no JSON entry)")
            .number("plot_half_extent_m", &O::plot_half_extent_m, "m", ValueRange::atLeast(0),
                    "half width of the PNG; 0 = max(0.5 m, 4 sigma_max) around mu")
            .integer("plot_pixels_per_cell", &O::plot_pixels_per_cell, ValueRange::atLeast(1), "PNG scale: pixels per histogram cell");
    return t;
}

void StatsOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section) {
    table().load(cfg, section, *this);
}

void StatsOptions::validate() const { table().validate(*this); }

void StatsOptions::dumpToTextStream(std::ostream& out) const { table().dump(*this, out); }

}  // namespace simp::stats
