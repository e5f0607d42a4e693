#pragma once
/// \file LocalizeOptions.h
/// The project's own .ini keys of simp-localize: [LocalizationExperiment], [MotionModel] and the
/// sections of the localizer's parameter structs. Each key is declared once, in an io::OptionTable
/// (LocalizeOptions.cpp, LocalizeOptions_params.cpp): loading, range checks and the dump derive from it.
/// MRPT's own sections ([PF_options], [KLD_options], [MetricMap]) are read by MRPT's loaders.

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <simp/localization/ObjectMclParams.h>
#include <simp/camera/FloorPlanThresholds.h>
#include <simp/io/OptionTable.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace simp::localization {

/// How the pose written to estimate.tum is computed from the particle set.
enum class EstimateMode {
    Cluster,  ///< weighted mean of the highest-weight cluster (default; see ParticleSummary.h)
    Mean      ///< weighted mean of all particles
};

/// Where estimate.tum starts.
enum class ReportFrom {
    Localized,  ///< at the first step in state localized (a robot must not act on a search-phase guess)
    Start       ///< at the first frame (the paper's evaluation)
};

/// [LocalizationExperiment]: the run itself. Every default here and in the other option structs of
/// simp-localize is config_ini/simp.ini's value, so the app without --config runs as with simp.ini
/// (tests/localization/test_defaults.cpp compares them field by field).
struct ExperimentOptions : public mrpt::config::CLoadableOptions {
    std::size_t particles_count = 5000;   ///< initial particles (paper: 5000)
    std::uint32_t seed = 0;               ///< seed of mrpt::random::getRandomGenerator()
    std::string sensor_model;             ///< "" = the [MetricMap] object map's own; else a model::localizationMethods() name
    double free_cells_threshold = camera::floorplan::kParticleMinFree;  ///< a floor-plan cell is free when p_free >= this
    double update_min_d_xy = 0.10;        ///< filter update after this translation (m); paper d_xy
    double update_min_d_phi = 0.03;       ///< ... or this rotation (rad); paper d_theta
    bool keep_skipped_detections = true;  ///< use the detections of skipped frames at the next update
    /// The filter's own parameters, handed to ObjectMcl as they are. The project's default differs from
    /// the paper's in one: a pruned particle gets the smallest weight (prune_keeps_weight = false).
    ObjectMclParams filter{/*prune_outside_free_space=*/true, /*prune_keeps_weight=*/false,
                           /*singw_per_frame=*/true, /*resample_resets_weights=*/true,
                           /*recovery_alpha_slow=*/0.0, /*recovery_alpha_fast=*/0.0};
    EstimateMode estimate_mode = EstimateMode::Cluster;
    double cluster_radius_m = 0.5;        ///< cluster: particles within this distance of the peak (m)
    double cluster_max_dphi = 0.785398;   ///< cluster: and within this heading difference (rad; pi/4 as the .ini files write it)
    double cluster_cell_m = 0.5;          ///< cluster: xy bin size used to find the peak (m)
    int cluster_phi_bins = 8;             ///< cluster: heading bins used to find the peak
    /// While localized, the particle count follows a KLD bound ([KLD_options] bins) between this and
    /// particles_count (Fox, IJRR 2003); 0 = always particles_count (the paper).
    std::size_t tracking_min_particles = 1000;
    /// Floor on the reported cluster's spread, per axis (m) and in heading (rad): after an update whose
    /// cluster is tighter, every particle is moved by zero-mean Gaussian noise that brings the spread
    /// up to it. Persistent detection errors let the set collapse onto a biased pose that it can then
    /// never leave (doc/localization.md "Spread floor"). 0 = off (the paper, simp-paper.ini).
    double min_spread_xy_m = 0.13;
    double min_spread_phi_rad = 0.06;
    /// While `lost`, the filter's own set weighs the detections with this exponent (times
    /// [PF_options] powFactor); the challenger's set (the search) weighs them fully. A `lost` is
    /// mostly false (changed furniture fills the window) and its detections pull a right set away;
    /// after a true one the challenger, not the set, finds the place. 1 = as always (the paper).
    double lost_detection_power = 0.5;
    ReportFrom report_from = ReportFrom::Localized;  ///< first line of estimate.tum
    bool write_particles = true;          ///< write O/final_particles.txt
    bool write_png = true;                ///< write O/trajectory.png

    /// The declaration of every key (section [LocalizationExperiment]).
    static const io::OptionTable<ExperimentOptions>& table();
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section) override;
    void dumpToTextStream(std::ostream& out) const override;
};

/// [MotionModel]: the odometry noise, mapped onto MRPT's CActionRobotMovement2D::TMotionModelOptions.
/// Defaults: the paper's sigma_odom = (0.15 m, 0.15 m, 0.15 rad) as the authors' code applies it,
/// i.e. proportional to the motion (doc/localization.md, "Motion model").
struct MotionModelOptions : public mrpt::config::CLoadableOptions {
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions mrpt_options = defaults();

    /// The paper's sigma_odom = 0.15 per m / per rad (config_ini/simp-paper.ini).
    static mrpt::obs::CActionRobotMovement2D::TMotionModelOptions paperDefaults();
    /// config_ini/simp.ini's: 0.05 per m / per rad (doc/localization.md "Robust tracking").
    static mrpt::obs::CActionRobotMovement2D::TMotionModelOptions defaults();
    /// The declaration of every key (section [MotionModel]; keys = MRPT's field names).
    static const io::OptionTable<MotionModelOptions>& table();
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section) override;
    void dumpToTextStream(std::ostream& out) const override;
};

struct StateParams;
struct DetectionNoveltyParams;
struct SensorResettingParams;
struct HypothesisSearchParams;
struct ChallengerParams;
/// [State], [DetectionNovelty], [SensorResetting], [HypothesisSearch], [Challenger] (missing keys keep their defaults).
void loadStateParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section, StateParams& p);
void loadNoveltyParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section, DetectionNoveltyParams& p);
void loadResettingParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section, SensorResettingParams& p);
void loadSearchParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section, HypothesisSearchParams& p);
void loadChallengerParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section, ChallengerParams& p);
/// The declarations behind the loaders above.
const io::OptionTable<StateParams>& stateParamsTable();
const io::OptionTable<DetectionNoveltyParams>& noveltyParamsTable();
const io::OptionTable<SensorResettingParams>& resettingParamsTable();
const io::OptionTable<HypothesisSearchParams>& searchParamsTable();
const io::OptionTable<ChallengerParams>& challengerParamsTable();

/// [PF_options] settings that MRPT needs together: KLD sampling (adaptiveSampleSize = true) in MRPT
/// 2.5's 2D MCL draws with multinomial resampling only, so it sets resamplingMethod = prMultinomial.
/// Returns one note per change for the log (empty: nothing changed).
std::vector<std::string> reconcilePfOptions(mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf);

struct LocalizerOptions;
/// Every section simp-localize's options read ([LocalizationExperiment], [MotionModel], [PF_options],
/// [KLD_options], [State], [DetectionNovelty], [SensorResetting]); read through io::StrictIni, whose
/// checkUnknown() afterwards names every key none of them asked for.
void loadLocalizerOptions(const mrpt::config::CConfigFileBase& cfg, LocalizerOptions& options);

}  // namespace simp::localization
