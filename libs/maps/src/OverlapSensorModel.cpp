#include <simp/maps/LogLikelihoodBatch.h>
#include <simp/maps/OverlapSensorModel.h>
#include <simp/maps/SensorModelChecks.h>

#include <algorithm>
#include <cmath>

namespace simp::maps {

void OverlapSensorModelParams::check() const { checkEta(eta); }

OverlapSensorModel::OverlapSensorModel(const world::ObjectMapData& data, const Params& params)
    : m_params(params), m_footprints(computeMapFootprints(data)) {
    params.check();
    m_log_eta = std::log(params.eta);
}

bool OverlapSensorModel::scoresClass(int map_class) const {
    return map_class >= 0 && static_cast<std::size_t>(map_class) < m_footprints.class_objects.size() &&
           !m_footprints.class_objects[static_cast<std::size_t>(map_class)].empty();
}

std::optional<PreparedDetection> OverlapSensorModel::prepare(int map_class, const geometry::Box3D& box_in_robot,
                                                             const geometry::ConvexPolygon& footprint_in_robot,
                                                             double weight) const {
    if (!scoresClass(map_class)) return std::nullopt;
    return prepareDetection(map_class, box_in_robot, footprint_in_robot, 0.0, weight);  // no noise model to widen
}

double OverlapSensorModel::logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const {
    return logLikelihoodAt(*this, det, pose);
}

void OverlapSensorModel::accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                                  const mrpt::math::TPose2D* poses, std::size_t n,
                                                  double* sum_log) const {
    accumulateLogLikelihoodBatch(*this, dets, num_dets, poses, n, sum_log);
}

}  // namespace simp::maps
