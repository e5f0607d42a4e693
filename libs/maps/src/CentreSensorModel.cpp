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

double CentreSensorModel::pairLogLikelihood(const PreparedDetection& det, double c, double s, double tx, double ty,
                                            Scratch& /*scratch*/) const {
    const double wx = c * det.center_robot_m.x() - s * det.center_robot_m.y() + tx;
    const double wy = s * det.center_robot_m.x() + c * det.center_robot_m.y() + ty;
    const auto hit = m_mp.lookup(det.map_class, wx, wy, det.noise_inv_scale2);  // Eq. globaldist
    if (hit.object < 0) return m_log_eta;                                        // p_o = 0
    return std::log(hit.p + (1.0 - hit.p) * m_params.eta);  // Eq. combined with p_g = 1
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
