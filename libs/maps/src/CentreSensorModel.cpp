#include <simp/maps/CentreSensorModel.h>
#include <simp/maps/LogLikelihoodBatch.h>
#include <simp/maps/SensorModelChecks.h>

#include <cmath>

namespace simp::maps {

void CentreSensorModelParams::check() const {
    checkEta(eta);
    checkProbabilityMapOptions(mp);
    checkNoiseReferenceRange(noise_reference_range_m);
}

CentreSensorModel::CentreSensorModel(const world::ObjectMapData& data, const Params& params) : m_params(params) {
    params.check();
    m_mp = ObjectProbabilityMap(data, params.mp);
    for (std::size_t c = 0; c < m_mp.numClasses(); ++c) m_num_usable_objects += m_mp.objectsOf(static_cast<int>(c)).size();
    m_log_eta = std::log(params.eta);
}

std::optional<PreparedDetection> CentreSensorModel::prepare(int map_class, const geometry::Box3D& box_in_robot,
                                                            const geometry::ConvexPolygon& footprint_in_robot,
                                                            double weight) const {
    if (!scoresClass(map_class)) return std::nullopt;
    return prepareDetection(map_class, box_in_robot, footprint_in_robot, m_params.noise_reference_range_m, weight);
}

double CentreSensorModel::logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const {
    return logLikelihoodAt(*this, det, pose);
}

void CentreSensorModel::accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                                 const mrpt::math::TPose2D* poses, std::size_t n,
                                                 double* sum_log) const {
    accumulateLogLikelihoodBatch(*this, dets, num_dets, poses, n, sum_log);
}

}  // namespace simp::maps
