#pragma once
/// \file EdtSensorModel.h
/// The EDT-MCL baseline (paper Sec. "Baseline Comparisons"): the beam-end point model applied to
/// the detection centre, its distance to the nearest footprint of its class from a per-class
/// Euclidean distance transform (EdtMap). `sensor_model = edt`.

#include <mrpt/math/TPose2D.h>
#include <simp/geometry/Box3D.h>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/maps/EdtMap.h>
#include <simp/maps/PreparedDetection.h>
#include <simp/world/ObjectMapData.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace simp::maps {

/// Parameters of EdtSensorModel ([<prefix>_likelihoodOpts] keys edt_sigma_m, edt_max_distance_m,
/// edt_resolution_m, eta, noise_reference_range_m).
struct EdtSensorModelParams {
    double eta = 0.1;             ///< likelihood of a false association, in (0, 1)
    double sigma_m = 0.3;         ///< std. dev. of the centre distance (m), > 0
    double max_distance_m = 2.0;  ///< distances are clamped to this (m), > 0
    double resolution_m = 0.05;   ///< distance transform cell (m), > 0
    double noise_reference_range_m = 0.0;  ///< range growth (m): sigma -> s sigma, s = r / this; 0 = off

    /// Throws std::invalid_argument naming the parameter (by its .ini key).
    void check() const;
};

/** log p(z_k | m, x) = log(p_hit + (1 - p_hit) eta), p_hit = exp(-d^2 / (2 sigma^2)), d the distance
 * of the detection centre to the nearest map footprint of its class (clamped to max_distance_m).
 * Immutable once built; safe to share between threads. */
class EdtSensorModel {
   public:
    using Params = EdtSensorModelParams;
    struct Scratch {};  ///< nothing is moved per pair but the centre

    /// Throws std::invalid_argument for bad parameters or an object whose class id is outside
    /// the class list.
    EdtSensorModel(const world::ObjectMapData& data, const Params& params);

    const Params& params() const { return m_params; }
    /// True when the map has no object.
    bool empty() const { return m_num_objects == 0; }
    /// True when the map has an object of the class.
    bool scoresClass(int map_class) const {
        return map_class >= 0 && static_cast<std::size_t>(map_class) < m_class_has_objects.size() &&
               m_class_has_objects[static_cast<std::size_t>(map_class)];
    }
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

    const EdtMap& edt() const { return m_edt; }

   private:
    Params m_params;
    EdtMap m_edt;
    std::vector<bool> m_class_has_objects;  ///< per class id
    std::size_t m_num_objects = 0;
    double m_inv_two_sigma2 = 0;  ///< 1 / (2 sigma^2) (1/m^2)
};

// The kernel (see pairLogLikelihood()).
inline double EdtSensorModel::pairLogLikelihood(const PreparedDetection& det, double c, double s, double tx, double ty,
                                                Scratch& /*scratch*/) const {
    const double wx = c * det.center_robot_m.x() - s * det.center_robot_m.y() + tx;
    const double wy = s * det.center_robot_m.x() + c * det.center_robot_m.y() + ty;
    // The beam-end model of the centre, mixed with the same floor eta.
    const double d = m_edt.distance(det.map_class, wx, wy);
    const double p_hit = std::exp(-d * d * m_inv_two_sigma2 * det.noise_inv_scale2);
    return std::log(p_hit + (1.0 - p_hit) * m_params.eta);
}

}  // namespace simp::maps
