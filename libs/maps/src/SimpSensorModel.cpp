#include <simp/maps/LogLikelihoodBatch.h>
#include <simp/maps/SensorModelChecks.h>
#include <simp/maps/SimpSensorModel.h>

#include <cmath>

namespace simp::maps {

void SimpSensorModelParams::check() const {
    checkEta(eta);
    checkProbabilityMapOptions(mp);
    checkNoiseReferenceRange(noise_reference_range_m);
}

SimpSensorModel::SimpSensorModel(const world::ObjectMapData& data, const Params& params)
    : m_params(params), m_footprints(computeMapFootprints(data)) {
    params.check();
    m_mp = ObjectProbabilityMap(data, params.mp);
    for (std::size_t c = 0; c < m_mp.numClasses(); ++c) m_num_usable_objects += m_mp.objectsOf(static_cast<int>(c)).size();
    m_log_eta = std::log(params.eta);
    m_exp_minus_1 = std::exp(-1.0);
}

bool SimpSensorModel::scoresClass(int map_class) const { return m_mp.hasClass(map_class); }

std::optional<PreparedDetection> SimpSensorModel::prepare(int map_class, const geometry::Box3D& box_in_robot,
                                                          const geometry::ConvexPolygon& footprint_in_robot,
                                                          double weight) const {
    if (!scoresClass(map_class)) return std::nullopt;
    return prepareDetection(map_class, box_in_robot, footprint_in_robot, m_params.noise_reference_range_m, weight);
}

double SimpSensorModel::pairLogLikelihood(const PreparedDetection& det, double c, double s, double tx, double ty,
                                          Scratch& scratch) const {
    // Detection centre in the world for this pose.
    const double wx = c * det.center_robot_m.x() - s * det.center_robot_m.y() + tx;
    const double wy = s * det.center_robot_m.x() + c * det.center_robot_m.y() + ty;
    // Eq. globaldist: p_o = max over the class's objects of p_o(c), o_max its argmax (raster).
    const auto hit = m_mp.lookup(det.map_class, wx, wy, det.noise_inv_scale2);
    if (hit.object < 0) return m_log_eta;  // p_o = 0: Eq. combined gives eta
    // Eq. iouscore: p_g = exp(-(1 - IoU)) between the detection footprint and o_max's.
    const ObjectFootprint& of = m_footprints.objects[static_cast<std::size_t>(hit.object)];
    double p_g = m_exp_minus_1;  // IoU = 0
    const Eigen::Vector2d wc(wx, wy);
    if (circlesOverlap(wc, det.radius_m, of.circle_center_m, of.circle_radius_m)) {
        scratch.world_valid = false;
        p_g = m_iou_score(footprintIou(det, c, s, tx, ty, wc, of, scratch));
    }
    return std::log(hit.p * p_g + (1.0 - hit.p) * m_params.eta);  // Eq. combined
}

double SimpSensorModel::logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const {
    return logLikelihoodAt(*this, det, pose);
}

void SimpSensorModel::accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                               const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log) const {
    accumulateLogLikelihoodBatch(*this, dets, num_dets, poses, n, sum_log);
}

}  // namespace simp::maps
