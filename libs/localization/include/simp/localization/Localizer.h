#pragma once
/// \file Localizer.h
/// Online global localization: one odometry increment and one sensory frame at a time in, pose,
/// covariance and state out (doc/localization.md). Holds MRPT's particle filter (ObjectMcl), the
/// motion trigger of the paper (d_xy, d_theta) with the reuse of the skipped frames' detections,
/// and what makes the filter hold over long runs (not in the paper; each off in
/// config_ini/simp-paper.ini): tempering of repeated detections, sensor resetting, the
/// localization state and fewer particles while tracking.

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/slam/TKLDParams.h>
#include <simp/localization/DetectionNovelty.h>
#include <simp/localization/DetectionPoseSampler.h>
#include <simp/localization/HypothesisSearch.h>
#include <simp/localization/KldSampleCount.h>
#include <simp/localization/LocalizationState.h>
#include <simp/localization/LocalizeOptions.h>
#include <simp/localization/ObjectMcl.h>
#include <simp/localization/ParticleSummary.h>
#include <simp/localization/ScanWindow.h>
#include <simp/localization/SkippedDetections.h>
#include <simp/localization/StepRecord.h>
#include <simp/localization/ViewWindow.h>
#include <simp/localization/YawConsensus.h>

#include <limits>
#include <memory>
#include <optional>

namespace simp::localization {

/// [SensorResetting]: fraction of the particles replaced at an update with detections, by state,
/// by poses drawn from the detections (DetectionPoseSampler), `uniform_share` of them uniformly.
struct SensorResettingParams {
    double global_fraction = 0.02;    ///< while searching
    double lost_fraction = 0.0;       ///< while lost (0: the challenger searches, the set keeps its track)
    double localized_fraction = 0.0;  ///< while localized
    double local_fraction = 0.1;      ///< drawn about a better pose near the estimate ([State] local_margin) ...
    double local_position_std_m = 0.1;     ///< ... with this spread (m): the climb's resolution, not a fit's noise
    double local_heading_std_rad = 0.05;   ///< ... and this (rad)
    double uniform_share = 0.2;       ///< of the injected particles, this share uniform over free space
    DetectionPoseSamplerParams sampler;
};

/// [Challenger]: recovery from a kidnap without giving up the current hypothesis. When the state
/// turns `lost`, a second particle set starts a global search (uniform over the free space, as at
/// the start, `reset_fraction` of it reset from the detections at each update) beside the current
/// one. Both are updated with the same odometry and detections. The challenger replaces the current
/// set when its own state is `localized`, it explains the detections seen since `lost` (the fit
/// window) better than the current estimate by `win_margin` nats, and it is either within
/// `agree_distance_m` of the current estimate and turned by at most the search's
/// `distinct_heading_rad` (samePlace: the same place, better told) or passes the tests of a distinct
/// place (`replace_max_fit`, `min_objects`, the LiDAR veto). It is dropped when the current set
/// is `localized` again (the `lost` was false). A false `lost` thus costs CPU, never the track (a
/// restart on `lost` lost 9 of 16 tracking runs, doc/results-localization.md).
struct ChallengerParams {
    bool enabled = true;
    double win_margin = 3.0;        ///< nats (log-likelihood of the fit window)
    double agree_distance_m = 1.0;  ///< closer to the current estimate than this: the same place
    double reset_fraction = 0.3;    ///< of its particles reset from the detections per update ([SensorResetting] draws)
    /// true: the share reset is reset_fraction x the share of the fit window its estimate leaves
    /// unexplained (reset_fraction until the window is scored): once it holds the right place the
    /// resetting no longer takes the cluster weight that `localized` asks for
    bool reset_by_fit = true;
    /// true: until it is `localized`, a search of the places that explain the detections since
    /// `lost` ([HypothesisSearch] scoring, whatever its `enabled`) runs at each update: its resetting
    /// draws about the best of them instead of from the current frame alone, and it is `localized`
    /// only when its estimate beats every other place by [State] rival_margin
    bool hypothesis_search = true;
    std::size_t particles = 0;      ///< particles of the challenger (0: [LocalizationExperiment] particles_count)
    /// The detections since `lost` it is judged on (its search, its fit and rival test, its lead
    /// over the current estimate): the last `window` of them, not older than window_max_age_s (s).
    /// Longer than [State] fit_window: look-alike places that explain a dozen detections do not
    /// explain the robot's whole way since `lost`.
    std::size_t window = 24;
    double window_max_age_s = 30;
    /// It replaces the current set at a distinct place only when the current estimate explains at
    /// most this share of the window: a kidnapped estimate explains next to nothing, an estimate
    /// made `lost` by moved furniture still explains part (1: no such condition).
    double replace_max_fit = 0.1;
    /// ... and only when its estimate explains detections of at least min_objects distinct objects of
    /// the window (detections of one class within object_radius_m (m) of each other, in the odometry
    /// frame, are one object): a look-alike place explains the few objects of a detection-poor
    /// stretch, the robot's true place after a kidnap the several it passes. 0: no such condition.
    std::size_t min_objects = 4;
    double object_radius_m = 0.75;
    /// With a LiDAR (simp+lidar): the scans since `lost` (the last scan_window of them) are scored at
    /// both estimates too, and a challenger elsewhere takes over only when they do not prefer the current
    /// estimate by more than scan_veto_nats (the scan model's weighted log-likelihood). One scan does not
    /// tell look-alike places apart; the way since `lost` mostly does. scan_window = 0: no veto.
    std::size_t scan_window = 20;
    double scan_veto_nats = 1.0;
    /// ... and only when the camera frames since `lost` (ViewWindow), placed at its estimate, showed
    /// at least min_view_recall of the views of map objects they should have shown, once they should
    /// have shown view_min_expected (fewer: no such condition). A look-alike place explains the few
    /// objects the robot saw; it also holds objects in view that the robot never saw. 0: off.
    double min_view_recall = 0.1;
    std::size_t view_min_expected = 30;
    ViewWindowParams views;  ///< which views are expected, and when one is shown
};

/// Whether a `localized` challenger replaces the current set. `lead`: its log-likelihood of the
/// detections since `lost` minus the current estimate's. It must lead by win_margin at the same place
/// too (a few nats there are the window's noise; the current set carries the longer track).
/// Elsewhere the current estimate must explain at most replace_max_fit of the window, the
/// challenger's at least min_objects objects, and the scans since `lost` (std::nullopt: none) must
/// not prefer the current estimate by more than scan_veto_nats, and the frames since `lost` must have
/// shown min_view_recall of the map objects they should have shown at its estimate. The rest is asked
/// only when needed (each scores the window): current_fit() -> double, explained_objects() ->
/// std::size_t, scan_lead() -> std::optional<double>, view_recall() -> ViewWindow::Recall.
template <class CurrentFit, class ExplainedObjects, class ScanLead, class ViewRecall>
bool challengerTakesOver(const ChallengerParams& c, bool same_place, double lead, CurrentFit current_fit,
                         ExplainedObjects explained_objects, ScanLead scan_lead, ViewRecall view_recall) {
    if (!(lead >= c.win_margin)) return false;
    if (same_place) return true;
    if (c.replace_max_fit < 1.0 && current_fit() > c.replace_max_fit) return false;
    if (c.min_objects > 0 && explained_objects() < c.min_objects) return false;
    const std::optional<double> scans = scan_lead();
    if (scans && *scans < -c.scan_veto_nats) return false;
    if (!(c.min_view_recall > 0)) return true;
    const ViewWindow::Recall views = view_recall();
    return views.expected < c.view_min_expected ||
           static_cast<double>(views.seen) >= c.min_view_recall * static_cast<double>(views.expected);
}

/// Everything the localizer reads from the .ini.
struct LocalizerOptions {
    ExperimentOptions experiment;
    MotionModelOptions motion;
    mrpt::bayes::CParticleFilter::TParticleFilterOptions pf = defaultPfOptions();
    mrpt::slam::TKLDParams kld = defaultKldParams();
    StateParams state;
    DetectionNoveltyParams novelty;
    SensorResettingParams resetting;
    HypothesisSearchParams search;
    ChallengerParams challenger;
    LidarModelOptions lidar;  ///< [LidarModel]: used by sensor_model lidar / simp+lidar only
    ManhattanHeadingOptions heading;  ///< [ManhattanHeading]: box yaws against the map's axes (weight 0: off)

    /// pfStandardProposal, prSystematic, no adaptive size, BETA 0.5 (MRPT's section defaults).
    static mrpt::bayes::CParticleFilter::TParticleFilterOptions defaultPfOptions();
    /// config_ini/simp.ini's [KLD_options]: bins 0.2 m x 5 deg, delta 0.01, epsilon 0.02, 1000 to
    /// 20000 particles (MRPT's own defaults differ).
    static mrpt::slam::TKLDParams defaultKldParams();
};

class Localizer {
   public:
    /// `map` and `floorplan` must outlive the localizer. \throw std::invalid_argument when the
    /// floor plan has no free cell.
    Localizer(std::shared_ptr<const maps::CObjectMap> map, const mrpt::maps::COccupancyGridMap2D& floorplan,
              const LocalizerOptions& options);

    /// Global localization: particles_count particles uniform over the free space, state global.
    void startGlobal();
    /// Tracking from a known pose: particles Gaussian about `pose` (std sigma_xy_m, sigma_phi_rad),
    /// state localized. \throw std::invalid_argument when the pose is not in free space.
    void startAt(const mrpt::math::TPose2D& pose, double sigma_xy_m, double sigma_phi_rad);

    /// One frame: the odometry increment since the previous frame (robot frame of the previous
    /// frame) and the frame's observations (may be empty). Runs a filter update when the motion
    /// trigger fires; returns the state after the frame (`seconds` left 0: the caller times it).
    StepRecord step(double t_s, const mrpt::poses::CPose2D& odometry_increment, const mrpt::obs::CSensoryFrame& frame);

    /// The LiDAR (doc/lidar.md): each update also weighs the latest scan since the previous update with
    /// `model` (nullptr: none, the default). use_objects = false drops the object detections entirely
    /// (`--method lidar`: no object weights, sensor resetting or hypothesis search from detections).
    void setScanModel(std::shared_ptr<const ScanLikelihood> model, bool use_objects) {
        m_scan_model = std::move(model);
        m_use_objects = use_objects;
    }
    /// Challengers started and challengers that replaced the current set, so far ([Challenger]).
    std::size_t challengersStarted() const { return m_challengers_started; }
    std::size_t challengersWon() const { return m_challengers_won; }

    const ObjectMcl& filter() const { return *m_mcl; }
    LocalizationState state() const { return m_monitor.state(); }
    const LocalizerOptions& options() const { return m_opts; }

   private:
    /// One filter update of `mcl` (the current set or the challenger) whose state is `state`.
    void update(ObjectMcl& mcl, LocalizationState state, const mrpt::poses::CPose2D* motion,
                const std::vector<WeightedObservation>& observations, StepRecord& rec);
    std::size_t injectFromDetections(ObjectMcl& mcl, LocalizationState state,
                                     const std::vector<WeightedObservation>& observations);
    std::unique_ptr<ObjectMcl> makeFilter() const;
    /// `n` particles uniform over the floor plan's free space (the start of a global search).
    void resetUniform(ObjectMcl& mcl, std::size_t n) const;
    /// [LocalizationExperiment] min_spread_*: widens a set whose cluster is tighter than the floor and
    /// returns its new summary (the same summary when nothing was done).
    ParticleSummary keepSpread(ObjectMcl& mcl, const ParticleSummary& summary) const;
    /// After the state update ([Challenger]): starts the challenger when the state turns `lost`,
    /// judges it after its updates, drops it when the state is `localized` again. True when the
    /// challenger replaced the current set (m_mcl, m_summary, m_monitor are then its own).
    bool challenge(double t_s, const mrpt::poses::CPose2D& now, bool had_detections, LocalizationState before);
    /// [Challenger] hypothesis_search: the places its resetting draws about at this update.
    void seedChallenger(const std::vector<WeightedObservation>& observations);
    /// Runs the hypothesis search when due (m_hypotheses is empty otherwise).
    void injectAboutLocalTarget(ObjectMcl& mcl, const mrpt::poses::CPose2D* motion);
    void searchHypotheses(double t_s, const std::vector<WeightedObservation>& observations);
    std::size_t particleTarget(const ObjectMcl& mcl, LocalizationState state) const;

    std::shared_ptr<const maps::CObjectMap> m_map;
    const mrpt::maps::COccupancyGridMap2D& m_floorplan;
    LocalizerOptions m_opts;
    std::shared_ptr<FreeSpace> m_free;
    std::unique_ptr<ObjectMcl> m_mcl;
    /// The challenger while `lost` ([Challenger]); null otherwise.
    struct Challenger {
        std::unique_ptr<ObjectMcl> mcl;
        StateMonitor monitor;
        std::optional<ParticleSummary> summary;
        double unexplained = 1.0;  ///< share of the fit window its estimate does not explain
        std::vector<Hypothesis> places;   ///< hypothesis_search: the distinct places found at this update
        std::vector<Hypothesis> targets;  ///< those its resetting draws about (about as good as the best)
        /// for steps.csv: its estimate now, the fit of it and its lead on the window (NaN: not yet)
        static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
        mrpt::math::TPose2D now{kNone, kNone, kNone};
        double fit = kNone;
        double lead = kNone;
    };
    std::optional<Challenger> m_challenger;
    std::size_t m_challengers_started = 0, m_challengers_won = 0;
    mrpt::bayes::CParticleFilter m_pf;
    DetectionNovelty m_novelty;
    DetectionPoseSampler m_sampler;
    HypothesisSearch m_search;
    HypothesisSearch m_challenger_search;  ///< [HypothesisSearch] parameters, always enabled
    std::vector<Hypothesis> m_hypotheses;  ///< of the current update (empty: not searched)
    std::vector<Hypothesis> m_reset_targets;  ///< those worth particles (about as good as the estimate or better)
    double m_last_search_s = -std::numeric_limits<double>::infinity();
    /// A pose near the estimate that explains the fit window better by [State] local_margin, as of
    /// the last update (the next one draws [SensorResetting] local_fraction of the set about it).
    std::optional<mrpt::math::TPose2D> m_local_target;
    /// The state has entered `localized` by its own test since the start (not by startAt): from then
    /// on a better pose nearby ends `localized` but draws no particles (doc/localization.md).
    bool m_entered_localized = false;
    FitWindow m_fit;
    FitWindow m_since_lost;  ///< [Challenger] window: what the challenger is judged on
    StateMonitor m_monitor;
    SkippedDetections m_skipped;
    mrpt::poses::CPose2D m_pending;   ///< odometry not yet applied to the particles
    mrpt::poses::CPose2D m_odometry;  ///< integrated odometry (odometry frame)
    /// Summary of the particle set as of the last update: the set changes only at updates, and
    /// summarizing 5000 particles at every 10 Hz frame was a quarter of a run's time.
    std::optional<ParticleSummary> m_summary;
    bool m_first = true;
    std::shared_ptr<const ScanLikelihood> m_scan_model;
    std::optional<ManhattanHeading> m_heading;  ///< set when [ManhattanHeading] is on and the map has axes
    YawConsensus m_yaw_consensus;               ///< used with m_heading when consensus_tolerance_rad > 0
    bool m_use_objects = true;
    mrpt::obs::CObservation2DRangeScan::Ptr m_pending_scan;  ///< the latest scan not yet weighed
    ScanWindow m_scans_since_lost;  ///< [Challenger] scan_window: the scans weighed since `lost`
    ViewWindow m_views_since_lost;  ///< [Challenger] views: the camera frames since `lost`
    std::optional<ViewWindow::Recall> m_views_asked;  ///< what the take-over asked of them at this step
};

}  // namespace simp::localization
