#pragma once
/// \file ObjectMcl.h
/// Monte Carlo localization on the object map (paper Sec. "3D Semantic Localization") as an
/// MRPT CMonteCarloLocalization2D: MRPT's prediction, KLD sampling and resampling; the
/// particle weights of Eq. singw over all cameras' detections of a frame.

#include <mrpt/slam/CMonteCarloLocalization2D.h>
#include <simp/localization/FreeSpace.h>
#include <simp/maps/CObjectMap.h>

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
    bool prune_outside_free_space = true;
    /// true: a pruned particle keeps its weight (authors' code); false: it gets the smallest weight
    /// MRPT keeps (max log-weight - PF_options.max_loglikelihood_dyn_range), i.e. p(x off free space) ~ 0.
    bool prune_keeps_weight = true;

    /// Recovery by random particles (augmented MCL, Thrun et al., "Probabilistic Robotics", Table 8.3;
    /// not in the paper; 0 = off). After each update with K > 0 detections, w_avg = the weighted mean
    /// over the particles of the frame likelihood (Eq. singw) is smoothed into w_slow (rate alpha_slow)
    /// and w_fast (rate alpha_fast); at the next step each particle is replaced, with probability
    /// max(0, 1 - w_fast / w_slow), by a pose drawn uniformly over the free space, with the mean weight.
    /// Requires alpha_slow < alpha_fast, both in [0, 1], and a free space (setFreeSpace).
    /// true: Eq. singw per camera frame (timestamp), multiplied over the frames of the update
    /// (perFrameLogLikelihoods); false: one geometric mean over all detections of the update.
    bool singw_per_frame = true;
    double recovery_alpha_slow = 0.0;
    double recovery_alpha_fast = 0.0;

    const maps::CObjectMap& objectMap() const { return *m_map; }
    /// Detections K used by the last update (0: no update or no usable detection).
    std::size_t lastDetectionCount() const { return m_last_K; }
    /// Particles redrawn by the last prediction.
    std::size_t lastPrunedCount() const { return m_last_pruned; }
    /// Particles replaced by random ones at the last step (recovery).
    std::size_t lastInjectedCount() const { return m_last_injected; }

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

   private:
    void pruneOutsideFreeSpace(double dyn_range);
    void injectRandomParticles();
    void updateRecoveryAverages(const double* log_lik, std::size_t n);

    std::shared_ptr<const maps::CObjectMap> m_map;
    std::shared_ptr<const FreeSpace> m_free_space;
    std::vector<mrpt::math::TPose2D> m_poses;  ///< scratch: particle poses of the batch
    std::vector<double> m_log_lik;             ///< scratch: their log-likelihoods
    std::size_t m_last_K = 0, m_last_pruned = 0, m_last_injected = 0;
    double m_w_slow = -1.0, m_w_fast = -1.0;  ///< recovery averages; < 0 = not started
};

}  // namespace simp::localization
