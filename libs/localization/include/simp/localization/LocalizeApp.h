#pragma once
/// \file LocalizeApp.h
/// simp-localize: global localization of a rawlog on a world directory. The program's main()
/// is a try/catch around initialize() + run(); tests drive the same class in-process
/// (as mrpt::apps::MonteCarloLocalization_App).

#include <mrpt/bayes/CParticleFilter.h>
#include <simp/io/CommandLine.h>
#include <simp/io/StrictIni.h>
#include <simp/io/Tum.h>
#include <simp/maps/CObjectMap.h>
#include <simp/localization/LocalizeOptions.h>
#include <simp/localization/Localizer.h>
#include <simp/localization/ParticleSummary.h>
#include <simp/localization/StepRecord.h>
#include <simp/maps/CObjectMap.h>
#include <simp/world/World.h>

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
    ///                 [--initial-pose x,y,phi[,sigma_xy,sigma_phi]] [--gt Q/groundtruth.tum]
    ///                 [--3dscene F] [--quiet]
    /// Reads and validates the .ini. \throw std::invalid_argument on bad arguments or .ini keys.
    void initialize(int argc, const char* const* argv);
    void initialize(const std::vector<std::string>& args);
    /// The declared options (the --help text and the checks derive from them).
    static io::CommandLine commandLine();

    /// Runs the filter over the whole rawlog and writes O/estimate.tum, O/steps.csv,
    /// O/final_particles.txt, O/trajectory.png (with the ground truth of --gt) and the --3dscene file. \throw std::runtime_error naming the file
    /// on a missing/corrupt input. Does nothing after --help.
    void run();

    /// @name Parameters (filled by initialize(); may be changed before run())
    /// @{
    std::string world_dir, rawlog_path, out_dir, config_path;
    std::unique_ptr<io::StrictIni> params;   ///< the .ini (empty without --config)
    LocalizerOptions options;                ///< everything the .ini sets
    /// --initial-pose: x, y (m), phi (rad), sigma_xy (m), sigma_phi (rad); tracking from it
    std::optional<std::array<double, 5>> initial_pose;
    std::string gt_path;                     ///< --gt: ground truth (TUM) drawn in the figure and the 3D scene
    std::string scene_path;                  ///< --3dscene: MRPT .3Dscene to write (empty = none)
    bool show_progress = true;               ///< progress lines on stderr
    std::ostream* log = nullptr;             ///< informative messages (nullptr: std::cerr unless quiet)
    /// What the loader changed so that the .ini's settings work together (reconcilePfOptions);
    /// run() logs each line.
    std::vector<std::string> config_notes;
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
    /// trajectory.png and the --3dscene file from the results of run().
    void writePictures(const world::World& world, const std::vector<io::StampedPose2D>& ground_truth) const;
    std::shared_ptr<maps::CObjectMap> m_object_map;  ///< made from the .ini by initialize()
};

/// The object map's likelihood options of simp-localize without --config: config_ini/simp.ini's
/// (the map's own defaults except skip_classes_without_noise = true and unmodelled_noise_std_m = 0.3:
/// a class without a noise model, e.g. the built-in office's doors and chairs, is scored with a
/// 0.3 m isotropic model rather than being an error; doc/localization.md "Unmodelled classes").
maps::CObjectMap::TLikelihoodOptions defaultLikelihoodOptions();

/// The object map: from the .ini's [MetricMap] (MRPT's TSetOfMetricMapInitializers, which can create
/// "semanticObjectMap" / "simp::maps::CObjectMap"); without [MetricMap], one with
/// defaultLikelihoodOptions(). \throw std::invalid_argument naming `file` when [MetricMap] creates none.
std::shared_ptr<maps::CObjectMap> makeObjectMap(const mrpt::config::CConfigFileBase& cfg, const std::string& file);

/// --initial-pose "x,y,phi[,sigma_xy,sigma_phi]" -> {x, y, phi, sigma_xy, sigma_phi} (defaults 0.2 m,
/// 0.1 rad). \throw std::invalid_argument naming the text when malformed.
std::array<double, 5> parseInitialPose(const std::string& text);

/// The message of an exception for a user: MRPT's nested exceptions reduced to their
/// "Message:" lines (no locations, no call stacks).
std::string describeError(const std::exception& e);

}  // namespace simp::localization
