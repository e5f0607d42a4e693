#pragma once
/// \file LocalizeApp.h
/// simp-localize: global localization of a rawlog on a world directory. The program's main()
/// is a try/catch around initialize() + run(); tests drive the same class in-process
/// (as mrpt::apps::MonteCarloLocalization_App).

#include <mrpt/bayes/CParticleFilter.h>
#include <simp/io/StrictIni.h>
#include <simp/io/Tum.h>
#include <simp/maps/CObjectMap.h>
#include <simp/localization/LocalizeOptions.h>
#include <simp/localization/Localizer.h>
#include <simp/localization/ParticleSummary.h>
#include <simp/localization/StepRecord.h>

#include <array>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace simp::localization {

class LocalizeApp {
   public:
    /// Command line (doc/localization.md):
    ///   simp-localize --world W --rawlog Q/sequence.rawlog --out O [--config INI]
    ///                 [--method simp|edt|d|o] [--particles N] [--seed S]
    ///                 [--initial-pose x,y,phi[,sigma_xy,sigma_phi]] [--quiet]
    /// Reads and validates the .ini. \throw std::invalid_argument on bad arguments or .ini keys.
    void initialize(int argc, const char* const* argv);
    void initialize(const std::vector<std::string>& args);

    /// Runs the filter over the whole rawlog and writes O/estimate.tum, O/steps.csv,
    /// O/final_particles.txt and O/trajectory.png. \throw std::runtime_error naming the file
    /// on a missing/corrupt input. Does nothing after --help.
    void run();

    /// @name Parameters (filled by initialize(); may be changed before run())
    /// @{
    std::string world_dir, rawlog_path, out_dir, config_path;
    std::unique_ptr<io::StrictIni> params;   ///< the .ini (empty without --config)
    LocalizerOptions options;                ///< everything the .ini sets
    /// --initial-pose: x, y (m), phi (rad), sigma_xy (m), sigma_phi (rad); tracking from it
    std::optional<std::array<double, 5>> initial_pose;
    bool show_progress = true;               ///< progress lines on stderr
    std::ostream* log = nullptr;             ///< informative messages (nullptr: std::cerr unless quiet)
    /// @}

    /// @name Results of run()
    /// @{
    bool help_requested = false;             ///< --help was given: nothing to run
    std::vector<StepRecord> steps;           ///< one per frame
    std::vector<io::StampedPose2D> estimate; ///< the estimate.tum lines (from the first localized step by default)
    std::size_t truncated_at_entry = 0;      ///< > 0: the rawlog's tail from this entry on was incomplete
    std::vector<mrpt::math::TPose2D> final_particles;
    std::string sensor_model_used;           ///< simp | edt | d | o
    /// @}

   private:
    void loadConfig();
    std::shared_ptr<maps::CObjectMap> m_object_map;  ///< made from the .ini by initialize()
};

/// --initial-pose "x,y,phi[,sigma_xy,sigma_phi]" -> {x, y, phi, sigma_xy, sigma_phi} (defaults 0.2 m,
/// 0.1 rad). \throw std::invalid_argument naming the text when malformed.
std::array<double, 5> parseInitialPose(const std::string& text);

/// The message of an exception for a user: MRPT's nested exceptions reduced to their
/// "Message:" lines (no locations, no call stacks).
std::string describeError(const std::exception& e);

}  // namespace simp::localization
