#pragma once
/// \file ObjectMcl.h
/// Monte Carlo localization on the object map (paper Sec. "3D Semantic Localization") as an
/// MRPT CMonteCarloLocalization2D: MRPT's prediction, KLD sampling and resampling; the
/// particle weights of Eq. singw over all cameras' detections of a frame.

#include <mrpt/slam/CMonteCarloLocalization2D.h>
#include <simp/localization/FrameLikelihood.h>
#include <simp/localization/FreeSpace.h>
#include <simp/localization/ManhattanHeading.h>
#include <simp/localization/ObjectMclParams.h>
#include <simp/localization/ScanLikelihood.h>
#include <simp/maps/CObjectMap.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace simp::localization {

/** The filter. Drive it with mrpt::bayes::CParticleFilter::executeOn(mcl, actions, sf).
 *
 * Weights: for PF_algorithm = pfStandardProposal (the default) the prediction runs first
 * (MRPT's own, including KLD-adaptive sample size), then all particles are weighed in one
 * batch per frame with frameLogLikelihoods(). The other MRPT algorithms (auxiliary PF)
 * evaluate single poses through PF_SLAM_computeObservationLikelihoodForParticle(), which
 * computes the same Eq. singw for that pose: same numbers, slower.
 *
 * Pruning (the authors' code does it too): after the prediction, particles that left the
 * floor plan's free space are redrawn uniformly over it, keeping their weight.
 */
class ObjectMcl : public mrpt::slam::CMonteCarloLocalization2D {
   public:
    /// `map` must stay alive as long as the filter (it is shared with options.metricMap).
    explicit ObjectMcl(std::shared_ptr<const maps::CObjectMap> map, std::size_t num_particles = 1);

    /// The free space used for pruning (nullptr, the default, or prune_outside_free_space = false: no pruning).
    void setFreeSpace(std::shared_ptr<const FreeSpace> free_space) { m_free_space = std::move(free_space); }
    ObjectMclParams params;  ///< pruning, singw grouping, recovery ([LocalizationExperiment] keys of the same names)

    /// Detections K used by the last update (0: no update or no usable detection).
    std::size_t lastDetectionCount() const { return m_last_K; }
    /// Particles redrawn by the last prediction.
    std::size_t lastPrunedCount() const { return m_last_pruned; }
    /// Particles replaced by random ones at the last step (recovery).
    std::size_t lastInjectedCount() const { return m_last_injected; }

    /// @name The steps of one update, for a driver that runs them itself (Localizer)
    /// prediction_and_update_pfStandardProposal() = predict, prune, recovery, weigh.
    /// @{
    /// Prediction from `actions` (nullptr: none; MRPT's motion-model sampler, composed in 2D), then pruning and augmented-MCL recovery
    /// as configured above.
    void predict(const mrpt::obs::CActionCollection* actions,
                 const mrpt::bayes::CParticleFilter::TParticleFilterOptions& PF_options);
    /// Adds pow_factor x Eq. singw of the update's observations to every particle's log-weight.
    /// \return K, the detections used (0: weights unchanged).
    std::size_t weigh(const std::vector<WeightedObservation>& observations, double pow_factor);
    /// Adds pow_factor x the scan model's log-likelihood of `scan` (LidarModelOptions::weight applied)
    /// to every particle's log-weight (`simp-localize --method lidar|simp+lidar`).
    void weighScan(const ScanLikelihood& model, const mrpt::obs::CObservation2DRangeScan& scan, double pow_factor);
    /// Adds pow_factor x the box-yaw heading log-likelihood of the update's observations
    /// (ManhattanHeadingOptions::weight applied; grouped as params.singw_per_frame) to every particle.
    void weighHeading(const ManhattanHeading& model, const std::vector<WeightedObservation>& observations,
                      double pow_factor);
    /// Replaces min(poses.size(), N) particles, spread evenly over the set, by `poses`, each with the
    /// mean weight of the set (sensor resetting). \return how many were replaced.
    std::size_t inject(const std::vector<mrpt::math::TPose2D>& poses);
    /// Systematic resampling to `n` particles (equal weights). MRPT 2.5's computeResampling cannot
    /// change the count: it draws the first n teeth of an N-tooth comb (n < N, biased to the first
    /// particles) or runs past its arrays (n > N); doc/mrpt-issues.md.
    void resampleTo(std::size_t n);
    /// MRPT's resampling (PF_options.resamplingMethod, same particle count), then equal weights
    /// when params.resample_resets_weights (ObjectMclParams.h).
    void resample(const mrpt::bayes::CParticleFilter::TParticleFilterOptions& PF_options);
    /// Draws `n` particles around `pose`: Gaussian with std sigma_xy_m in x and y and sigma_phi_rad
    /// in heading (zero spread allowed), equal weights.
    /// Moves every particle by zero-mean Gaussian noise (weights kept); the set's seeded generator.
    void jitter(double sigma_xy_m, double sigma_phi_rad);
    void resetAround(const mrpt::math::TPose2D& pose, double sigma_xy_m, double sigma_phi_rad, std::size_t n);
    /// @}

    /// @name mrpt::slam::CMonteCarloLocalization2D overrides
    /// @{
    void prediction_and_update_pfStandardProposal(
        const mrpt::obs::CActionCollection* actions, const mrpt::obs::CSensoryFrame* sf,
        const mrpt::bayes::CParticleFilter::TParticleFilterOptions& PF_options) override;

    /// Eq. singw for one pose (log).
    double PF_SLAM_computeObservationLikelihoodForParticle(
        const mrpt::bayes::CParticleFilter::TParticleFilterOptions& PF_options, const size_t particleIndexForMap,
        const mrpt::obs::CSensoryFrame& observation, const mrpt::poses::CPose3D& x) const override;
    /// @}

    /// @name MRPT's weight accessors, with MRPT's arithmetic, on m_particles directly: MRPT's own
    /// reach the particles through a dynamic_cast per call (per particle in its loops, resampling
    /// included), a tenth of a run's time.
    /// @{
    double getW(size_t i) const override;
    void setW(size_t i, double w) override;
    size_t particlesCount() const override { return m_particles.size(); }
    double normalizeWeights(double* out_max_log_w = nullptr) override;
    double ESS() const override;
    /// MRPT's substitution (particle k = old particle sorted(indx)[k]) in place.
    void performSubstitution(const std::vector<size_t>& indx) override;
    /// @}

   private:
    void pruneOutsideFreeSpace(double dyn_range);
    void injectRandomParticles();
    void updateRecoveryAverages(const double* log_lik, std::size_t n);
    double meanLogWeight() const;

    std::shared_ptr<const maps::CObjectMap> m_map;
    std::shared_ptr<const FreeSpace> m_free_space;
    std::vector<mrpt::math::TPose2D> m_poses;  ///< scratch: particle poses of the batch
    std::vector<double> m_log_lik;             ///< scratch: their log-likelihoods
    std::vector<std::uint8_t> m_free;          ///< scratch: particle in the free space (pruning)
    std::vector<CParticleList::value_type> m_old_particles;  ///< scratch: the set before a substitution
    std::size_t m_last_K = 0, m_last_pruned = 0, m_last_injected = 0;
    double m_w_slow = -1.0, m_w_fast = -1.0;  ///< recovery averages; < 0 = not started
};

}  // namespace simp::localization
