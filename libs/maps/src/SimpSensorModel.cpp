#include <simp/maps/LogLikelihoodBatch.h>
#include <simp/maps/SensorModelChecks.h>
#include <simp/maps/SimpSensorModel.h>

#include <cmath>
#include <stdexcept>

namespace simp::maps {

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
