#pragma once
/// \file OverlapSensorModel.h
/// The O-MCL baseline (paper Sec. "Baseline Comparisons"): the detection's footprint overlap
/// with the map's objects of its class (Eq. iouscore), no noise model. `sensor_model = o`.

#include <mrpt/math/TPose2D.h>
#include <simp/geometry/Box3D.h>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/maps/FootprintOverlap.h>
#include <simp/maps/IouScore.h>
#include <simp/maps/MapFootprints.h>
#include <simp/maps/PreparedDetection.h>
#include <simp/maps/TableLog.h>
#include <simp/world/ObjectMapData.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace simp::maps {

/// Parameters of OverlapSensorModel ([<prefix>_likelihoodOpts] key of the same name).
struct OverlapSensorModelParams {
    double eta = 0.1;  ///< likelihood of a false association, in (0, 1)

    /// Throws std::invalid_argument naming the parameter.
    void check() const;
};

/** log p(z_k | m, x) = log(IoU p_g + (1 - IoU) eta) with IoU the best footprint overlap with any
 * object of the detection's class (the overlap plays the association probability) and p_g of
 * Eq. iouscore; eta when nothing overlaps. Immutable once built; safe to share between threads. */
class OverlapSensorModel {
   public:
    using Params = OverlapSensorModelParams;
    using Scratch = OverlapScratch;

    /// Throws std::invalid_argument for bad parameters or an object whose class id is outside
    /// the class list.
    OverlapSensorModel(const world::ObjectMapData& data, const Params& params);

    const Params& params() const { return m_params; }
    /// True when the map has no object.
    bool empty() const { return m_footprints.objects.empty(); }
    /// True when the map has an object of the class.
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

    const MapFootprints& footprints() const { return m_footprints; }

   private:
    Params m_params;
    MapFootprints m_footprints;
    double m_log_eta = 0;
    IouScore m_iou_score;  ///< Eq. iouscore
    TableLog m_log;        ///< Eq. combined's log
};

// The kernel (see pairLogLikelihood()).
inline double OverlapSensorModel::pairLogLikelihood(const PreparedDetection& det, double c, double s, double tx, double ty,
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
    return m_log(best_iou * p_g + (1.0 - best_iou) * m_params.eta);
}

}  // namespace simp::maps
