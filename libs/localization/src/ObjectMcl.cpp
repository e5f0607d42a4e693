#include <simp/localization/ObjectMcl.h>

#include <simp/localization/FrameLikelihood.h>

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
    if (prune_outside_free_space && m_free_space) pruneOutsideFreeSpace();

    // 2) Update: all particles in one batch (Eq. singw over all cameras of the frame).
    m_last_K = 0;
    if (sf == nullptr) return;
    const std::size_t n = m_particles.size();
    m_poses.resize(n);
    m_log_lik.resize(n);
    for (std::size_t i = 0; i < n; ++i) m_poses[i] = m_particles[i].d;
    m_last_K = frameLogLikelihoods(*m_map, *sf, m_poses.data(), n, m_log_lik.data());
    if (m_last_K == 0) return;
    for (std::size_t i = 0; i < n; ++i) m_particles[i].log_w += m_log_lik[i] * PF_options.powFactor;
}

double ObjectMcl::PF_SLAM_computeObservationLikelihoodForParticle(
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions& /*PF_options*/, const size_t /*particleIndexForMap*/,
    const mrpt::obs::CSensoryFrame& observation, const mrpt::poses::CPose3D& x) const {
    const mrpt::math::TPose2D pose(x.x(), x.y(), x.yaw());
    double log_lik = 0;
    frameLogLikelihoods(*m_map, observation, &pose, 1, &log_lik);
    return log_lik;
}

void ObjectMcl::pruneOutsideFreeSpace() {
    for (auto& p : m_particles) {
        if (m_free_space->isFree(p.d.x, p.d.y)) continue;
        p.d = m_free_space->drawUniform();  // keeps p.log_w
        ++m_last_pruned;
    }
}

}  // namespace simp::localization
