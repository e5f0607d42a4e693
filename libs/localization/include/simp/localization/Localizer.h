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
#include <simp/localization/LocalizationState.h>
#include <simp/localization/LocalizeOptions.h>
#include <simp/localization/ObjectMcl.h>
#include <simp/localization/ParticleSummary.h>
#include <simp/localization/SkippedDetections.h>
#include <simp/localization/StepRecord.h>

#include <limits>
#include <memory>
#include <optional>

namespace simp::localization {

/// [SensorResetting]: fraction of the particles replaced at an update with detections, by state,
/// by poses drawn from the detections (DetectionPoseSampler), `uniform_share` of them uniformly.
struct SensorResettingParams {
    double global_fraction = 0.02;    ///< while searching
    double lost_fraction = 0.3;       ///< while lost
    double localized_fraction = 0.0;  ///< while localized
    double uniform_share = 0.2;       ///< of the injected particles, this share uniform over free space
    DetectionPoseSamplerParams sampler;
};

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
    LidarModelOptions lidar;  ///< [LidarModel]: used by sensor_model lidar / simp+lidar only

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
    /// Scans weighed so far.
    std::size_t scansUsed() const { return m_scans_used; }

    const ObjectMcl& filter() const { return *m_mcl; }
    LocalizationState state() const { return m_monitor.state(); }
    const LocalizerOptions& options() const { return m_opts; }

   private:
    void update(const mrpt::poses::CPose2D* motion, const std::vector<WeightedObservation>& observations,
                StepRecord& rec);
    std::size_t injectFromDetections(const std::vector<WeightedObservation>& observations);
    /// Runs the hypothesis search when due (m_hypotheses is empty otherwise).
    void searchHypotheses(double t_s, const std::vector<WeightedObservation>& observations);
    std::size_t particleTarget() const;

    std::shared_ptr<const maps::CObjectMap> m_map;
    const mrpt::maps::COccupancyGridMap2D& m_floorplan;
    LocalizerOptions m_opts;
    std::shared_ptr<FreeSpace> m_free;
    std::unique_ptr<ObjectMcl> m_mcl;
    mrpt::bayes::CParticleFilter m_pf;
    DetectionNovelty m_novelty;
    DetectionPoseSampler m_sampler;
    HypothesisSearch m_search;
    std::vector<Hypothesis> m_hypotheses;  ///< of the current update (empty: not searched)
    std::vector<Hypothesis> m_reset_targets;  ///< those worth particles (about as good as the estimate or better)
    double m_last_search_s = -std::numeric_limits<double>::infinity();
    FitWindow m_fit;
    StateMonitor m_monitor;
    SkippedDetections m_skipped;
    mrpt::poses::CPose2D m_pending;   ///< odometry not yet applied to the particles
    mrpt::poses::CPose2D m_odometry;  ///< integrated odometry (odometry frame)
    /// Summary of the particle set as of the last update: the set changes only at updates, and
    /// summarizing 5000 particles at every 10 Hz frame was a quarter of a run's time.
    std::optional<ParticleSummary> m_summary;
    bool m_first = true;
    std::shared_ptr<const ScanLikelihood> m_scan_model;
    bool m_use_objects = true;
    mrpt::obs::CObservation2DRangeScan::Ptr m_pending_scan;  ///< the latest scan not yet weighed
    std::size_t m_scans_used = 0;
};

/// Bins of kld's sizes (xy in m, phi in rad) that hold at least one particle.
std::size_t occupiedBinCount(const mrpt::poses::CPosePDFParticles& pdf, const mrpt::slam::TKLDParams& kld);

/// Particles needed for a KLD bound (Fox, IJRR 2003) on the set's occupied bins of kld's bin
/// sizes (xy in m, phi in rad as MRPT's TKLDParams holds it): (k-1)/(2 eps) (1 - 2/(9(k-1)) +
/// sqrt(2/(9(k-1))) z_{1-delta})^3 with k occupied bins.
std::size_t kldParticleCount(const mrpt::poses::CPosePDFParticles& pdf, const mrpt::slam::TKLDParams& kld);

}  // namespace simp::localization
