#pragma once
/// \file DemoApp.h
/// The main demo (`simp-demo`): the whole pipeline on the built-in office world, no external data.
///  1. generate the built-in office (ground-truth world);
///  2. simulate a mapping run with ground-truth poses and build the object map (the paper's mapping);
///  3. evaluate the built map against the ground truth (paper Table I metrics);
///  4. simulate localization runs with long-term changes and localize globally in the built map
///     with the paper's sensor model;
///  5. a kidnapped robot: one more run, teleported halfway (odometry does not see it);
///  6. print the tables (success, convergence time, ATE per sequence; the kidnap) and write PNGs.

#include <simp/io/CommandLine.h>

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace simp::localization {
class LocalizeApp;
}
namespace simp::world {
struct World;
}

namespace simp::demo {

struct DemoOptions {
    std::string out_dir = "demo_out";              ///< everything is written here
    std::uint64_t seed = 1;                        ///< world, sequences and filters derive their seeds from it
    int rooms = 10;                                ///< size of the built-in office
    double mapping_duration_s = 600;               ///< simulated time of the mapping run (s, a coverage run); 600 s covers every room of the default office
    double localization_duration_s = 90;           ///< simulated time of each localization run (s)
    std::vector<double> changes = {0.0, 0.15, 0.3};  ///< long-term change fraction of each localization run
    /// the kidnapped run K1 (15 % changes, teleported at half its duration); --no-kidnap: none
    bool kidnap_run = true;
    int particles = 5000;                          ///< MCL particles (paper: 5000)
    std::string method = "simp";                   ///< sensor model: a name of model::sensorModelTypeNames()
    /// simp-localize .ini (default: the project's config_ini/simp.ini, the paper's settings)
    std::string localization_config = defaultLocalizationConfig();
    /// simp-map .ini (default: the project's config_ini/mapping.ini when present, else built-in defaults)
    std::string mapping_config = defaultMappingConfig();

    static std::string defaultLocalizationConfig();
    static std::string defaultMappingConfig();
};

/// The kidnapped run's result (simp::eval::evaluateKidnap): lost within 5 s of the teleport, localized
/// again at the right place within 20 s, and the estimate after it a success by the paper's metrics.
struct DemoKidnapRun {
    std::string name = "K1";
    double changes = 0.15;
    double kidnap_at_s = 0;                   ///< after the start (s)
    double lost_after_s = -1;                 ///< < 0: never said lost
    double relocalized_after_s = -1;          ///< < 0: never localized again within the bounds
    double after_ate_trans_m = -1, after_ate_rot_rad = -1;  ///< after the teleport; < 0 when undefined
    bool success = false;
};

/// One localization run's result.
struct DemoRun {
    std::string name;            ///< e.g. "R1"
    double changes = 0;          ///< change fraction of its world
    bool success = false, converged = false;
    double convergence_time_s = -1;  ///< < 0 when it did not converge
    double ate_trans_m = -1, ate_rot_rad = -1;  ///< < 0 when undefined
    double duration_s = 0;
};

class DemoApp {
   public:
    /// Parses `simp-demo [--out DIR] [--seed S] [--rooms N] [--particles N] [--method M] [--runs N]
    /// [--mapping-duration SEC] [--duration SEC] [--config INI] [--mapping-config INI]`. Returns false after --help.
    /// \throw std::invalid_argument naming a bad option.
    bool initialize(const std::vector<std::string>& args, std::ostream& out);
    /// Runs the pipeline; progress and the table go to `out`.
    void run(std::ostream& out);

    static std::string usage();
    static io::CommandLine commandLine();  ///< the declared options

    DemoOptions options;
    /// @name Results
    /// @{
    std::vector<DemoRun> runs;
    std::vector<DemoKidnapRun> kidnap_runs;  ///< empty with --no-kidnap
    double map_iou = 0, map_precision = 0, map_recall = 0;
    /// @}

   private:
    /// simp-localize on `seq_dir` in the map `map_dir`, outputs in `est_dir`.
    localization::LocalizeApp localize(const std::string& map_dir, const std::string& seq_dir,
                                       const std::string& est_dir, std::uint64_t seed) const;
    /// Step 5: simulates, localizes and evaluates the kidnapped run.
    DemoKidnapRun runKidnapped(const std::filesystem::path& root, const std::string& map_dir,
                               const world::World& truth, const world::World& built, std::ostream& out) const;
};

/// The result table in Markdown (also written to DIR/results.md). A failed run shows "failed (diverged)"
/// or "failed (never converged)" and "—" for its convergence time and ATE.
std::string resultsTable(const std::vector<DemoRun>& runs);
/// The kidnapped runs' table in Markdown: the teleport time, when the filter said lost and localized
/// again, the ATE after the teleport (successful runs only) and success.
std::string kidnapTable(const std::vector<DemoKidnapRun>& runs);

}  // namespace simp::demo
