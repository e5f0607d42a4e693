#include <simp/maps/LogLikelihoodBatch.h>
#include <simp/maps/SensorModelChecks.h>
#include <simp/maps/SimpSensorModel.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace simp::maps {
namespace {

/// E[exp(-min(1, d^2 / (2 sigma^2)))], d = sin(2 dyaw) / 2, dyaw ~ N(0, sigma^2): the mean yaw factor
/// of a correct association at the right pose (trapezoid rule over +-8 sigma; the factor is bounded
/// and smooth, 4001 points are exact to about 1e-9).
double meanYawFactor(double sigma) {
    const double gain = 0.5 / (sigma * sigma), lo = -8 * sigma, h = 16 * sigma / 4000;
    double sum = 0, norm = 0;
    for (int i = 0; i <= 4000; ++i) {
        const double dyaw = lo + h * i, w = (i == 0 || i == 4000) ? 0.5 : 1.0;
        const double d = 0.5 * std::sin(2 * dyaw), g = w * std::exp(-0.5 * dyaw * dyaw / (sigma * sigma));
        sum += g * std::exp(-std::min(1.0, gain * d * d));
        norm += g;
    }
    return sum / norm;
}

}  // namespace

void SimpSensorModelParams::check() const {
    checkEta(eta);
    checkProbabilityMapOptions(mp);
    checkNoiseReferenceRange(noise_reference_range_m);
    if (!(yaw_sigma_rad >= 0.0 && std::isfinite(yaw_sigma_rad)))
        throw std::invalid_argument("yaw_sigma_rad must be >= 0 (0 = off)");
}

SimpSensorModel::SimpSensorModel(const world::ObjectMapData& data, const Params& params)
    : m_params(params), m_footprints(computeMapFootprints(data)) {
    params.check();
    m_mp = ObjectProbabilityMap(data, params.mp);
    for (std::size_t c = 0; c < m_mp.numClasses(); ++c) m_num_usable_objects += m_mp.objectsOf(static_cast<int>(c)).size();
    m_log_eta = std::log(params.eta);
    m_exp_minus_1 = std::exp(-1.0);
    m_yaw_gain = params.yaw_sigma_rad > 0 ? 0.5 / (params.yaw_sigma_rad * params.yaw_sigma_rad) : 0.0;
    m_yaw_scale = params.yaw_sigma_rad > 0 ? 1.0 / meanYawFactor(params.yaw_sigma_rad) : 1.0;
}

bool SimpSensorModel::scoresClass(int map_class) const { return m_mp.hasClass(map_class); }

std::optional<PreparedDetection> SimpSensorModel::prepare(int map_class, const geometry::Box3D& box_in_robot,
                                                          const geometry::ConvexPolygon& footprint_in_robot,
                                                          double weight) const {
    if (!scoresClass(map_class)) return std::nullopt;
    return prepareDetection(map_class, box_in_robot, footprint_in_robot, m_params.noise_reference_range_m, weight);
}

double SimpSensorModel::logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const {
    return logLikelihoodAt(*this, det, pose);
}

void SimpSensorModel::accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                               const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log) const {
    accumulateLogLikelihoodBatch(*this, dets, num_dets, poses, n, sum_log);
}

}  // namespace simp::maps
