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

double OverlapSensorModel::pairLogLikelihood(const PreparedDetection& det, double c, double s, double tx, double ty,
                                             Scratch& scratch) const {
    const double wx = c * det.center_robot_m.x() - s * det.center_robot_m.y() + tx;
    const double wy = s * det.center_robot_m.x() + c * det.center_robot_m.y() + ty;
    // Best overlap with any object of the class; IoU plays the association probability.
    const Eigen::Vector2d wc(wx, wy);
    double best_iou = 0.0;
    scratch.world_valid = false;
    for (const std::int32_t o : m_footprints.class_objects[static_cast<std::size_t>(det.map_class)]) {
        const ObjectFootprint& of = m_footprints.objects[static_cast<std::size_t>(o)];
        if (!circlesOverlap(wc, det.radius_m, of.circle_center_m, of.circle_radius_m)) continue;
        best_iou = std::max(best_iou, footprintIou(det, c, s, tx, ty, wc, of, scratch));
    }
    if (best_iou <= 0.0) return m_log_eta;
    const double p_g = m_iou_score(best_iou);  // Eq. iouscore
    return std::log(best_iou * p_g + (1.0 - best_iou) * m_params.eta);
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
