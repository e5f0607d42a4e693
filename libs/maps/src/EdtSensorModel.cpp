#include <simp/maps/EdtSensorModel.h>
#include <simp/maps/LogLikelihoodBatch.h>
#include <simp/maps/MapFootprints.h>
#include <simp/maps/SensorModelChecks.h>

#include <cmath>
#include <stdexcept>

namespace simp::maps {

void EdtSensorModelParams::check() const {
    checkEta(eta);
    if (!(sigma_m > 0.0)) throw std::invalid_argument("edt_sigma_m must be > 0");
    if (!(max_distance_m > 0.0)) throw std::invalid_argument("edt_max_distance_m must be > 0");
    if (!(resolution_m > 0.0)) throw std::invalid_argument("edt_resolution_m must be > 0");
    checkNoiseReferenceRange(noise_reference_range_m);
}

EdtSensorModel::EdtSensorModel(const world::ObjectMapData& data, const Params& params) : m_params(params) {
    const MapFootprints footprints = computeMapFootprints(data);
    params.check();
    m_edt = EdtMap(footprints, params.resolution_m, params.max_distance_m);
    m_class_has_objects.resize(footprints.class_objects.size());
    for (std::size_t c = 0; c < footprints.class_objects.size(); ++c)
        m_class_has_objects[c] = !footprints.class_objects[c].empty();
    m_num_objects = data.objects.size();
    m_inv_two_sigma2 = 1.0 / (2.0 * params.sigma_m * params.sigma_m);
}

std::optional<PreparedDetection> EdtSensorModel::prepare(int map_class, const geometry::Box3D& box_in_robot,
                                                         const geometry::ConvexPolygon& footprint_in_robot,
                                                         double weight) const {
    if (!scoresClass(map_class)) return std::nullopt;
    return prepareDetection(map_class, box_in_robot, footprint_in_robot, m_params.noise_reference_range_m, weight);
}

double EdtSensorModel::logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const {
    return logLikelihoodAt(*this, det, pose);
}

void EdtSensorModel::accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                              const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log) const {
    accumulateLogLikelihoodBatch(*this, dets, num_dets, poses, n, sum_log);
}

}  // namespace simp::maps
