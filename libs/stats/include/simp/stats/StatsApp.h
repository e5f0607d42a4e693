#pragma once
/// \file StatsApp.h
/// simp-stats: learns the per-class detection noise model from a detector's rawlog, the
/// ground-truth trajectory and the ground-truth world (paper Sec. "Statistical Analysis").
///   simp-stats --rawlog Q/sequence.rawlog --poses Q/groundtruth.tum --world W --out DIR
///              [--delta M] [--config INI]
/// Writes DIR/class_noise.json, DIR/class_noise.csv, DIR/class_noise_stats.csv and
/// DIR/noise_<class>.png (doc/statistics.md).

#include <simp/io/CommandLine.h>
#include <simp/stats/NoiseFit.h>
#include <simp/stats/OffsetSamples.h>
#include <simp/stats/StatsOptions.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace simp::stats {

class StatsApp {
   public:
    /// Parses the command line; throws std::invalid_argument on a bad or missing argument.
    /// Returns false when only --help was asked (printed to `out`).
    bool initialize(int argc, const char* const* argv, std::ostream& out);
    /// Runs the analysis and writes the outputs; returns the process exit code.
    int run(std::ostream& out);

    static std::string usage();
    /// The declared options (the --help text and the checks derive from them).
    static io::CommandLine commandLine();

    /// @name Results of run()
    /// @{
    std::vector<std::string> class_names;          ///< of the world
    std::vector<std::optional<NoiseFit>> fits;     ///< per class id
    OffsetSamples samples;
    /// @}

    std::string rawlog_path, poses_path, world_path, out_dir, config_path;
    StatsOptions options;
};

}  // namespace simp::stats
