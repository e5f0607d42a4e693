#include <simp/localization/ObjectMcl.h>

#include <simp/localization/FrameLikelihood.h>

#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace simp::localization {

ObjectMcl::ObjectMcl(std::shared_ptr<const maps::CObjectMap> map, std::size_t num_particles)
    : mrpt::slam::CMonteCarloLocalization2D(num_particles), m_map(std::move(map)) {
    if (!m_map) throw std::invalid_argument("ObjectMcl: null object map");
    options.metricMap = m_map;  // MRPT asserts a map is set before an update
    setLoggerName("simp::localization::ObjectMcl");
}

void ObjectMcl::prediction_and_update_pfStandardProposal(
    const mrpt::obs::CActionCollection* actions, const mrpt::obs::CSensoryFrame* sf,
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions& PF_options) {
    // 1) Prediction only: MRPT draws from the action's motion model (and does KLD sampling).
    mrpt::slam::CMonteCarloLocalization2D::prediction_and_update_pfStandardProposal(actions, nullptr, PF_options);
    m_last_pruned = 0;
    if (prune_outside_free_space && m_free_space) pruneOutsideFreeSpace(PF_options.max_loglikelihood_dyn_range);
    m_last_injected = 0;
    if (recovery_alpha_fast > 0.0 && m_free_space) injectRandomParticles();

    // 2) Update: all particles in one batch (Eq. singw over all cameras of the frame).
    m_last_K = 0;
    if (sf == nullptr) return;
    const std::size_t n = m_particles.size();
    m_poses.resize(n);
    m_log_lik.resize(n);
    for (std::size_t i = 0; i < n; ++i) m_poses[i] = m_particles[i].d;
    m_last_K = singw_per_frame ? perFrameLogLikelihoods(*m_map, *sf, m_poses.data(), n, m_log_lik.data())
                               : frameLogLikelihoods(*m_map, *sf, m_poses.data(), n, m_log_lik.data());
    if (m_last_K == 0) return;
    if (recovery_alpha_fast > 0.0) updateRecoveryAverages(m_log_lik.data(), n);
    for (std::size_t i = 0; i < n; ++i) m_particles[i].log_w += m_log_lik[i] * PF_options.powFactor;
}

double ObjectMcl::PF_SLAM_computeObservationLikelihoodForParticle(
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions& /*PF_options*/, const size_t /*particleIndexForMap*/,
    const mrpt::obs::CSensoryFrame& observation, const mrpt::poses::CPose3D& x) const {
    const mrpt::math::TPose2D pose(x.x(), x.y(), x.yaw());
    double log_lik = 0;
    if (singw_per_frame)
        perFrameLogLikelihoods(*m_map, observation, &pose, 1, &log_lik);
    else
        frameLogLikelihoods(*m_map, observation, &pose, 1, &log_lik);
    return log_lik;
}

void ObjectMcl::pruneOutsideFreeSpace(double dyn_range) {
    double floor_lw = 0.0;
    if (!prune_keeps_weight) {
        double max_lw = -std::numeric_limits<double>::infinity();
        for (const auto& p : m_particles)
            if (m_free_space->isFree(p.d.x, p.d.y)) max_lw = std::max(max_lw, p.log_w);
        if (!std::isfinite(max_lw)) max_lw = 0.0;  // every particle left: all get the same weight
        floor_lw = max_lw - dyn_range;
    }
    for (auto& p : m_particles) {
        if (m_free_space->isFree(p.d.x, p.d.y)) continue;
        p.d = m_free_space->drawUniform();
        if (!prune_keeps_weight) p.log_w = floor_lw;
        ++m_last_pruned;
    }
}

void ObjectMcl::updateRecoveryAverages(const double* log_lik, std::size_t n) {
    // w_avg = sum_i w_i p(z | x_i) / sum_i w_i with the weights before this update: the filter's
    // estimate of p(z_t | z_1:t-1), the quantity augmented MCL tracks.
    double max_lw = -std::numeric_limits<double>::infinity();
    for (const auto& p : m_particles) max_lw = std::max(max_lw, p.log_w);
    double sum_w = 0.0, sum_wl = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double w = std::exp(m_particles[i].log_w - max_lw);
        sum_w += w;
        sum_wl += w * std::exp(log_lik[i]);
    }
    if (!(sum_w > 0.0)) return;
    const double w_avg = sum_wl / sum_w;
    if (m_w_slow < 0.0) m_w_slow = m_w_fast = w_avg;
    m_w_slow += recovery_alpha_slow * (w_avg - m_w_slow);
    m_w_fast += recovery_alpha_fast * (w_avg - m_w_fast);
}

void ObjectMcl::injectRandomParticles() {
    if (!(m_w_slow > 0.0) || m_particles.empty()) return;
    const double p_inject = std::max(0.0, 1.0 - m_w_fast / m_w_slow);
    if (p_inject <= 0.0) return;
    // The new particles get the mean weight: log(sum_i w_i / N), computed with log-sum-exp.
    double max_lw = -std::numeric_limits<double>::infinity();
    for (const auto& p : m_particles) max_lw = std::max(max_lw, p.log_w);
    double sum_w = 0.0;
    for (const auto& p : m_particles) sum_w += std::exp(p.log_w - max_lw);
    const double mean_log_w = max_lw + std::log(sum_w / static_cast<double>(m_particles.size()));
    auto& rng = mrpt::random::getRandomGenerator();
    for (auto& p : m_particles) {
        if (rng.drawUniform(0.0, 1.0) >= p_inject) continue;
        p.d = m_free_space->drawUniform();
        p.log_w = mean_log_w;
        ++m_last_injected;
    }
}

}  // namespace simp::localization
