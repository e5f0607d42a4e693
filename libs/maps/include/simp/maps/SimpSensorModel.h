#pragma once
/// \file SimpSensorModel.h
/// The paper's 3D-object sensor model (Sec. "3D Semantic Localization"): Eq. globaldist (m_p),
/// Eq. iouscore and Eq. combined, per detection and particle pose. `sensor_model = simp`.

#include <mrpt/math/TPose2D.h>
#include <simp/geometry/Box3D.h>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/maps/FootprintOverlap.h>
#include <simp/maps/IouScore.h>
#include <simp/maps/MapFootprints.h>
#include <simp/maps/ObjectProbabilityMap.h>
#include <simp/maps/PreparedDetection.h>
#include <simp/maps/TableLog.h>
#include <simp/world/ObjectMapData.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

namespace simp::maps {

/// Parameters of SimpSensorModel ([<prefix>_likelihoodOpts] keys of the same names).
struct SimpSensorModelParams {
    double eta = 0.1;                  ///< Eq. combined: likelihood of a false association, in (0, 1)
    ObjectProbabilityMap::Options mp;  ///< m_p raster (mp_resolution_m, mp_min_probability, ...)
    /// Range growth of the detection noise: a detection whose centre is r > this (m) from the robot
    /// is scored with Sigma -> s^2 Sigma, s = r / this (monocular depth error grows with distance).
    /// 0 = off (the paper's model).
    double noise_reference_range_m = 0.0;
    /// > 0: the detected box's yaw is scored against o_max's (project addition): p_g is multiplied
    /// by exp(-min(1, 0.5 d^2 / sigma^2)) / m, d = sin(2 dyaw) / 2 (about dyaw for small angles; a
    /// box turned by 90 deg is the same solid, so d repeats every 90 deg), sigma = this (rad), m the
    /// mean of the exp for dyaw ~ N(0, sigma^2) (0.734 at 0.1): a correct association's yaw error
    /// costs nothing on average, so eta and the thresholds weighed against it keep their meaning.
    /// Bounded like Eq. iouscore: a wrong yaw costs at most 1 nat more than a right one. 0 = off
    /// (the paper's model).
    double yaw_sigma_rad = 0.0;

    /// Throws std::invalid_argument naming the parameter.
    void check() const;
};

/** log p(z_k | m, x) = log(p_o p_g + (1 - p_o) eta) (Eq. combined) with p_o of the class's most
 * likely object o_max at the detection centre (Eq. globaldist, from the m_p raster) and
 * p_g = exp(-(1 - IoU)) of the detection's footprint with o_max's (Eq. iouscore).
 * Everything that depends only on the map is precomputed; immutable, safe to share between threads. */
class SimpSensorModel {
   public:
    using Params = SimpSensorModelParams;
    using Scratch = OverlapScratch;

    /// Throws std::invalid_argument for bad parameters, an object whose class id is outside the
    /// class list, or a class without noise model (unless mp.skip_classes_without_noise or
    /// mp.unmodelled_noise_std_m).
    SimpSensorModel(const world::ObjectMapData& data, const Params& params);

    const Params& params() const { return m_params; }
    /// True when no object of the map has a distribution (every detection would be ignored).
    bool empty() const { return m_num_usable_objects == 0; }
    /// True when the class has an object with a distribution (m_p).
    bool scoresClass(int map_class) const;
    /// The detection made ready for many poses; std::nullopt when !scoresClass(map_class).
    std::optional<PreparedDetection> prepare(int map_class, const geometry::Box3D& box_in_robot,
                                             const geometry::ConvexPolygon& footprint_in_robot,
                                             double weight = 1.0) const;

    /// log p(z_k | m, x) of one detection for the robot at `pose` (weight not applied).
    double logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const;
    /// sum_log[i] += weight_k log p(z_k | m, poses[i]) for every detection k (LogLikelihoodBatch.h).
    void accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                  const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log) const;
    /// The per-pair kernel, robot at (x, y) = (tx, ty) with (c, s) = (cos phi, sin phi). Inline
    /// (below): a non-inline member of a shared library may be interposed, so GCC would not inline
    /// it into the batch loop.
    double pairLogLikelihood(const PreparedDetection& det, double c, double s, double tx, double ty,
                             Scratch& scratch) const;

    const ObjectProbabilityMap& probabilityMap() const { return m_mp; }
    const MapFootprints& footprints() const { return m_footprints; }

   private:
    Params m_params;
    MapFootprints m_footprints;  ///< IoU with o_max
    ObjectProbabilityMap m_mp;
    std::size_t m_num_usable_objects = 0;
    double m_log_eta = 0;
    double m_exp_minus_1 = 0;  ///< p_g at IoU = 0
    double m_yaw_gain = 0;     ///< 0.5 / yaw_sigma_rad^2 (0: no yaw term)
    double m_yaw_scale = 1;    ///< 1 / the mean yaw factor of a correct association (see yaw_sigma_rad)
    IouScore m_iou_score;      ///< Eq. iouscore
    TableLog m_log;            ///< Eq. combined's log
};

// The kernel (see pairLogLikelihood()).
inline double SimpSensorModel::pairLogLikelihood(const PreparedDetection& det, double c, double s, double tx, double ty,
                                                 Scratch& scratch) const {
    // Detection centre in the world for this pose.
    const double wx = c * det.center_robot_m.x() - s * det.center_robot_m.y() + tx;
    const double wy = s * det.center_robot_m.x() + c * det.center_robot_m.y() + ty;
    // Eq. globaldist: p_o = max over the class's objects of p_o(c), o_max its argmax (raster).
    const auto hit = m_mp.lookup(det.map_class, wx, wy, det.noise_inv_scale2);
    if (hit.object < 0) return m_log_eta;  // p_o = 0: Eq. combined gives eta
    // Eq. iouscore: p_g = exp(-(1 - IoU)) between the detection footprint and o_max's.
    const ObjectFootprint& of = m_footprints.objects[static_cast<std::size_t>(hit.object)];
    double iou = 0.0;
    const Eigen::Vector2d wc(wx, wy);
    if (circlesOverlap(wc, det.radius_m, of.circle_center_m, of.circle_radius_m)) {
        scratch.world_valid = false;
        iou = footprintIou(det, c, s, tx, ty, wc, of, scratch);
    }
    double p_g;
    if (m_yaw_gain > 0 && det.is_rect && of.is_rect) {
        // The detected box's axis in the world against the object's: d = sin(dyaw) cos(dyaw).
        const double ax = c * det.rect_robot.c - s * det.rect_robot.s, ay = s * det.rect_robot.c + c * det.rect_robot.s;
        const double d = (of.rect.c * ay - of.rect.s * ax) * (of.rect.c * ax + of.rect.s * ay);
        p_g = m_yaw_scale * m_iou_score(iou, m_yaw_gain * d * d);  // p_g exp(-min(1, ...)) in one evaluation
    } else {
        p_g = iou > 0.0 ? m_iou_score(iou) : m_exp_minus_1;
    }
    return m_log(hit.p * p_g + (1.0 - hit.p) * m_params.eta);  // Eq. combined
}

}  // namespace simp::maps
