#pragma once
/// \file CentreSensorModel.h
/// The D-MCL baseline (paper Sec. "Baseline Comparisons"): the detection centre scored by the
/// object probability map m_p alone (Eq. globaldist), no shape. `sensor_model = d`.

#include <mrpt/math/TPose2D.h>
#include <simp/geometry/Box3D.h>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/maps/ObjectProbabilityMap.h>
#include <simp/maps/PreparedDetection.h>
#include <simp/world/ObjectMapData.h>

#include <cmath>
#include <cstddef>
#include <optional>

namespace simp::maps {

/// Parameters of CentreSensorModel ([<prefix>_likelihoodOpts] keys of the same names).
struct CentreSensorModelParams {
    double eta = 0.1;                  ///< likelihood of a false association, in (0, 1)
    ObjectProbabilityMap::Options mp;  ///< m_p raster
    double noise_reference_range_m = 0.0;  ///< range growth of the noise (m), as SimpSensorModelParams; 0 = off

    /// Throws std::invalid_argument naming the parameter.
    void check() const;
};

/** log p(z_k | m, x) = log(p_o + (1 - p_o) eta): Eq. combined with p_g = 1, p_o of Eq. globaldist
 * at the detection centre. Immutable once built; safe to share between threads. */
class CentreSensorModel {
   public:
    using Params = CentreSensorModelParams;
    struct Scratch {};  ///< nothing is moved per pair but the centre

    /// Throws std::invalid_argument for bad parameters, an object whose class id is outside the
    /// class list, or a class without noise model (see ObjectProbabilityMap::Options).
    CentreSensorModel(const world::ObjectMapData& data, const Params& params);

    const Params& params() const { return m_params; }
    /// True when no object of the map has a distribution.
    bool empty() const { return m_num_usable_objects == 0; }
    /// True when the class has an object with a distribution (m_p).
    bool scoresClass(int map_class) const { return m_mp.hasClass(map_class); }
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

   private:
    Params m_params;
    ObjectProbabilityMap m_mp;
    std::size_t m_num_usable_objects = 0;
    double m_log_eta = 0;
};

// The kernel (see pairLogLikelihood()).
inline double CentreSensorModel::pairLogLikelihood(const PreparedDetection& det, double c, double s, double tx, double ty,
                                                   Scratch& /*scratch*/) const {
    const double wx = c * det.center_robot_m.x() - s * det.center_robot_m.y() + tx;
    const double wy = s * det.center_robot_m.x() + c * det.center_robot_m.y() + ty;
    const auto hit = m_mp.lookup(det.map_class, wx, wy, det.noise_inv_scale2);  // Eq. globaldist
    if (hit.object < 0) return m_log_eta;                                        // p_o = 0
    return std::log(hit.p + (1.0 - hit.p) * m_params.eta);  // Eq. combined with p_g = 1
}

}  // namespace simp::maps
