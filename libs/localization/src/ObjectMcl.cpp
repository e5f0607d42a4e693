#include <simp/localization/ObjectMcl.h>

#include <simp/localization/FrameLikelihood.h>
#include <simp/localization/GaussianMotionSampler.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace simp::localization {

ObjectMcl::ObjectMcl(std::shared_ptr<const maps::CObjectMap> map, std::size_t num_particles)
    : mrpt::slam::CMonteCarloLocalization2D(num_particles), m_map(std::move(map)) {
    if (!m_map) throw std::invalid_argument("ObjectMcl: null object map");
    options.metricMap = m_map;  // MRPT asserts a map is set before an update
    setLoggerName("simp::localization::ObjectMcl");
}

void ObjectMcl::predict(const mrpt::obs::CActionCollection* actions,
                        const mrpt::bayes::CParticleFilter::TParticleFilterOptions& PF_options) {
    if (actions && !PF_options.adaptiveSampleSize) {
        // MRPT's fixed-size prediction (one sample of the action's motion model per particle, in
        // particle order, from the same sampler and random numbers), composed in 2D: MRPT's generic
        // code composes 3D poses (a rotation matrix per particle and back), which was a quarter of a
        // run's time for the same poses up to rounding.
        const auto movement = actions->getBestMovementEstimation();
        if (!movement || !movement->poseChange)
            throw std::invalid_argument("ObjectMcl::predict: the action collection holds no 2D robot movement");
        if (const auto* gaussian = dynamic_cast<const mrpt::poses::CPosePDFGaussian*>(movement->poseChange.get())) {
            const GaussianMotionSampler sampler(*gaussian);
            for (auto& p : m_particles) p.d = sampler.move(p.d);
        } else {
            m_movementDrawer.setPosePDF(*movement->poseChange);
            mrpt::poses::CPose2D increment;
            for (auto& p : m_particles) {
                m_movementDrawer.drawSample(increment);
                p.d = (mrpt::poses::CPose2D(p.d) + increment).asTPose();
            }
        }
    } else {
        // MRPT draws from the action's motion model and does KLD sampling when enabled.
        mrpt::slam::CMonteCarloLocalization2D::prediction_and_update_pfStandardProposal(actions, nullptr, PF_options);
    }
    m_last_pruned = 0;
    if (params.prune_outside_free_space && m_free_space) pruneOutsideFreeSpace(PF_options.max_loglikelihood_dyn_range);
    m_last_injected = 0;
    if (params.recovery_alpha_fast > 0.0 && m_free_space) injectRandomParticles();
}

std::size_t ObjectMcl::weigh(const std::vector<WeightedObservation>& observations, double pow_factor) {
    m_last_K = 0;
    const std::size_t n = m_particles.size();
    m_poses.resize(n);
    m_log_lik.resize(n);
    for (std::size_t i = 0; i < n; ++i) m_poses[i] = m_particles[i].d;
    m_last_K = updateLogLikelihoods(*m_map, observations, params.singw_per_frame, m_poses.data(), n, m_log_lik.data());
    if (m_last_K == 0) return 0;
    if (params.recovery_alpha_fast > 0.0) updateRecoveryAverages(m_log_lik.data(), n);
    for (std::size_t i = 0; i < n; ++i) m_particles[i].log_w += m_log_lik[i] * pow_factor;
    return m_last_K;
}

void ObjectMcl::weighScan(const ScanLikelihood& model, const mrpt::obs::CObservation2DRangeScan& scan,
                          double pow_factor) {
    const std::size_t n = m_particles.size();
    m_poses.resize(n);
    m_log_lik.resize(n);
    for (std::size_t i = 0; i < n; ++i) m_poses[i] = m_particles[i].d;
    model.logLikelihoods(scan, m_poses.data(), n, m_log_lik.data());
    for (std::size_t i = 0; i < n; ++i) m_particles[i].log_w += m_log_lik[i] * pow_factor;
}

void ObjectMcl::weighHeading(const ManhattanHeading& model, const std::vector<WeightedObservation>& observations,
                             double pow_factor) {
    const std::size_t n = m_particles.size();
    m_poses.resize(n);
    m_log_lik.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) m_poses[i] = m_particles[i].d;
    if (model.addLogLikelihoods(observations, params.singw_per_frame, m_poses.data(), n, m_log_lik.data()) == 0) return;
    for (std::size_t i = 0; i < n; ++i) m_particles[i].log_w += m_log_lik[i] * pow_factor;
}

void ObjectMcl::prediction_and_update_pfStandardProposal(
    const mrpt::obs::CActionCollection* actions, const mrpt::obs::CSensoryFrame* sf,
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions& PF_options) {
    predict(actions, PF_options);
    m_last_K = 0;
    if (sf == nullptr) return;
    weigh(objectObservations(*sf), PF_options.powFactor);
}

double ObjectMcl::getW(size_t i) const {
    if (i >= m_particles.size()) throw std::out_of_range("ObjectMcl::getW: particle " + std::to_string(i) + " of " + std::to_string(m_particles.size()));
    return m_particles[i].log_w;
}

void ObjectMcl::setW(size_t i, double w) {
    if (i >= m_particles.size()) throw std::out_of_range("ObjectMcl::setW: particle " + std::to_string(i) + " of " + std::to_string(m_particles.size()));
    m_particles[i].log_w = w;
}

double ObjectMcl::normalizeWeights(double* out_max_log_w) {
    if (m_particles.empty()) return 0;
    double min_w = m_particles[0].log_w, max_w = min_w;
    for (const auto& p : m_particles) {
        max_w = std::max<double>(max_w, p.log_w);
        min_w = std::min<double>(min_w, p.log_w);
    }
    for (auto& p : m_particles) p.log_w -= max_w;
    if (out_max_log_w) *out_max_log_w = max_w;
    return std::exp(max_w - min_w);
}

double ObjectMcl::ESS() const {
    // MRPT's arithmetic, each exp taken once instead of once per pass.
    std::vector<double> linear(m_particles.size());
    double sum_linear = 0;
    std::size_t i = 0;
    for (const auto& p : m_particles) sum_linear += (linear[i++] = std::exp(p.log_w));
    double cum = 0;
    for (const double w : linear) cum += mrpt::square(w / sum_linear);
    return cum == 0 ? 0 : 1.0 / (static_cast<double>(m_particles.size()) * cum);
}

void ObjectMcl::performSubstitution(const std::vector<size_t>& indx) {
    // MRPT's result (new particle k = old particle sorted(indx)[k], weight included) without its
    // new deque and its sort of an index list that resampling already gives sorted.
    std::vector<size_t> sorted_copy;
    const std::vector<size_t>* sorted = &indx;
    if (!std::is_sorted(indx.begin(), indx.end())) {
        sorted_copy = indx;
        std::sort(sorted_copy.begin(), sorted_copy.end());
        sorted = &sorted_copy;
    }
    m_old_particles.assign(m_particles.begin(), m_particles.end());
    m_particles.resize(sorted->size());
    auto it = m_particles.begin();
    for (const size_t k : *sorted) *it++ = m_old_particles[k];
}

double ObjectMcl::meanLogWeight() const {
    double max_lw = -std::numeric_limits<double>::infinity();
    for (const auto& p : m_particles) max_lw = std::max(max_lw, p.log_w);
    double sum_w = 0.0;
    for (const auto& p : m_particles) sum_w += std::exp(p.log_w - max_lw);
    return max_lw + std::log(sum_w / static_cast<double>(m_particles.size()));
}

std::size_t ObjectMcl::inject(const std::vector<mrpt::math::TPose2D>& poses) {
    const std::size_t n = m_particles.size();
    const std::size_t m = std::min(poses.size(), n);
    if (m == 0) return 0;
    const double mean_log_w = meanLogWeight();
    // Every (n / m)-th particle: the replaced ones are an even sample of the set, so each
    // hypothesis gives up the same share of its weight.
    for (std::size_t j = 0; j < m; ++j) {
        auto& p = m_particles[(j * n) / m];
        p.d = poses[j];
        p.log_w = mean_log_w;
    }
    m_last_injected += m;
    return m;
}

void ObjectMcl::resampleTo(std::size_t n) {
    if (n == 0) throw std::invalid_argument("ObjectMcl::resampleTo: zero particles");
    const std::size_t m = m_particles.size();
    double max_lw = -std::numeric_limits<double>::infinity();
    for (const auto& p : m_particles) max_lw = std::max(max_lw, p.log_w);
    std::vector<double> cdf(m);
    double sum = 0.0;
    for (std::size_t i = 0; i < m; ++i) cdf[i] = (sum += std::exp(m_particles[i].log_w - max_lw));
    const double step = sum / static_cast<double>(n);
    double u = mrpt::random::getRandomGenerator().drawUniform(0.0, step);
    std::vector<std::size_t> idx(n);
    std::size_t j = 0;
    for (std::size_t k = 0; k < n; ++k, u += step) {
        while (j + 1 < m && cdf[j] < u) ++j;
        idx[k] = j;
    }
    performSubstitution(idx);
    for (auto& p : m_particles) p.log_w = 0.0;
}

void ObjectMcl::resample(const mrpt::bayes::CParticleFilter::TParticleFilterOptions& PF_options) {
    performResampling(PF_options);
    if (params.resample_resets_weights)
        for (auto& p : m_particles) p.log_w = 0.0;
}

void ObjectMcl::resetAround(const mrpt::math::TPose2D& pose, double sigma_xy_m, double sigma_phi_rad, std::size_t n) {
    if (n == 0) throw std::invalid_argument("ObjectMcl::resetAround: zero particles");
    auto& rng = mrpt::random::getRandomGenerator();
    m_particles.resize(n);
    for (auto& p : m_particles) {
        p.d = mrpt::math::TPose2D(pose.x + rng.drawGaussian1D(0.0, sigma_xy_m), pose.y + rng.drawGaussian1D(0.0, sigma_xy_m),
                                  mrpt::math::wrapToPi(pose.phi + rng.drawGaussian1D(0.0, sigma_phi_rad)));
        p.log_w = 0.0;
    }
}

void ObjectMcl::jitter(double sigma_xy_m, double sigma_phi_rad) {
    auto& rng = mrpt::random::getRandomGenerator();
    for (auto& p : m_particles) {
        if (sigma_xy_m > 0) {
            p.d.x += rng.drawGaussian1D(0.0, sigma_xy_m);
            p.d.y += rng.drawGaussian1D(0.0, sigma_xy_m);
        }
        if (sigma_phi_rad > 0) p.d.phi = mrpt::math::wrapToPi(p.d.phi + rng.drawGaussian1D(0.0, sigma_phi_rad));
    }
}

double ObjectMcl::PF_SLAM_computeObservationLikelihoodForParticle(
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions& /*PF_options*/, const size_t /*particleIndexForMap*/,
    const mrpt::obs::CSensoryFrame& observation, const mrpt::poses::CPose3D& x) const {
    const mrpt::math::TPose2D pose(x.x(), x.y(), x.yaw());
    double log_lik = 0;
    if (params.singw_per_frame)
        perFrameLogLikelihoods(*m_map, observation, &pose, 1, &log_lik);
    else
        frameLogLikelihoods(*m_map, observation, &pose, 1, &log_lik);
    return log_lik;
}

void ObjectMcl::pruneOutsideFreeSpace(double dyn_range) {
    m_free.resize(m_particles.size());  // looked up once for both passes
    std::size_t n = 0;
    for (const auto& p : m_particles) m_free[n++] = m_free_space->isFree(p.d.x, p.d.y);
    double floor_lw = 0.0;
    if (!params.prune_keeps_weight) {
        double max_lw = -std::numeric_limits<double>::infinity();
        std::size_t i = 0;
        for (const auto& p : m_particles)
            if (m_free[i++]) max_lw = std::max(max_lw, p.log_w);
        if (!std::isfinite(max_lw)) max_lw = 0.0;  // every particle left: all get the same weight
        floor_lw = max_lw - dyn_range;
    }
    std::size_t i = 0;
    for (auto& p : m_particles) {
        if (m_free[i++]) continue;
        p.d = m_free_space->drawUniform();
        if (!params.prune_keeps_weight) p.log_w = floor_lw;
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
    m_w_slow += params.recovery_alpha_slow * (w_avg - m_w_slow);
    m_w_fast += params.recovery_alpha_fast * (w_avg - m_w_fast);
}

void ObjectMcl::injectRandomParticles() {
    if (!(m_w_slow > 0.0) || m_particles.empty()) return;
    const double p_inject = std::max(0.0, 1.0 - m_w_fast / m_w_slow);
    if (p_inject <= 0.0) return;
    const double mean_log_w = meanLogWeight();  // the new particles get the mean weight
    auto& rng = mrpt::random::getRandomGenerator();
    for (auto& p : m_particles) {
        if (rng.drawUniform(0.0, 1.0) >= p_inject) continue;
        p.d = m_free_space->drawUniform();
        p.log_w = mean_log_w;
        ++m_last_injected;
    }
}

}  // namespace simp::localization
