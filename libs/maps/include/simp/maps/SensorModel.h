#pragma once
/// \file SensorModel.h
/// The 3D-object sensor models evaluated at many robot poses (paper Sec. "3D Semantic
/// Localization"): everything that depends only on the map is precomputed here once.

#include <mrpt/math/TPose2D.h>
#include <simp/geometry/Box3D.h>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/geometry/OrientedRect.h>
#include <simp/maps/EdtMap.h>
#include <simp/maps/IouScore.h>
#include <simp/maps/MapFootprints.h>
#include <simp/maps/ObjectProbabilityMap.h>
#include <simp/maps/SensorModelTypes.h>
#include <simp/world/ObjectMapData.h>

#include <optional>

namespace simp::maps {

/// A detection, in the robot frame, ready to be moved to many particle poses.
struct PreparedDetection {
    int map_class = -1;                                     ///< class id in the object map
    Eigen::Vector2d center_robot_m{Eigen::Vector2d::Zero()};  ///< box centre on the ground (robot frame, m)
    geometry::ConvexPolygon footprint_robot;                ///< ground footprint (robot frame, m)
    double area_m2 = 0;                                     ///< footprint area (m^2)
    double radius_m = 0;                                    ///< bounding circle about center_robot_m (m)
    geometry::ConvexPolygon offsets_robot;  ///< footprint_robot - center_robot_m: moved into a map object's frame
    bool is_rect = false;                   ///< footprint_robot is a rectangle: rect_robot (separating-axis test)
    geometry::OrientedRect rect_robot;
    double noise_inv_scale2 = 1;  ///< 1 / s^2 of the range growth (SensorModelParams::noise_reference_range_m)
    double weight = 1;            ///< exponent on p(z_k | m, x): 1 = an independent detection, < 1 a repeated one
};

/// Precomputed map side of the sensor models. Immutable once built; safe to share between threads.
class SensorModel {
   public:
    /// Throws std::invalid_argument (naming the parameter, class or object) for eta outside
    /// (0, 1), non-positive EDT parameters, a class without noise model (simp, d), ...
    SensorModel(const world::ObjectMapData& data, const SensorModelParams& params);

    const SensorModelParams& params() const { return m_params; }
    /// True when the map has no object usable by the selected model.
    bool empty() const { return m_num_usable_objects == 0; }
    /// True when the map has an object of class `map_class` this model can score a detection
    /// against (simp and d skip a class without noise model; see ObjectProbabilityMap).
    bool scoresClass(int map_class) const;

    /// Prepares a detection of map class `map_class` (box and footprint in the robot frame) whose
    /// log-likelihood is taken `weight` times (1 = the paper's). std::nullopt when the class has no
    /// usable object in the map (the detection is ignored).
    std::optional<PreparedDetection> prepare(int map_class, const geometry::Box3D& box_in_robot,
                                             const geometry::ConvexPolygon& footprint_in_robot,
                                             double weight = 1.0) const;

    /// log p(z_k | m, x) of one prepared detection for the robot at `pose` (x, y in m, phi in rad):
    /// Eq. combined for Simp, the baseline's likelihood otherwise (the detection's weight not applied).
    double logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const;

    /// sum_log[i] += weight_k log p(z_k | m, poses[i]) for every detection k (no allocation, no virtual calls).
    void accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                  const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log) const;

    const ObjectProbabilityMap& probabilityMap() const { return m_mp; }
    const MapFootprints& footprints() const { return m_footprints; }
    const EdtMap& edt() const { return m_edt; }

   private:
    /// Footprints moved per pair, reused for every pair of a call (no construction per pair).
    struct Scratch {
        geometry::ConvexPolygon world;  ///< the detection in the world (generic clipping)
        bool world_valid = false;       ///< `world` holds the current pair's pose
        geometry::ConvexPolygon local;  ///< the detection in a rectangular map object's frame
    };
    template <SensorModelType T>
    double kernel(const PreparedDetection& det, double c, double s, double tx, double ty, Scratch& scratch) const;
    template <SensorModelType T>
    void accumulate(const PreparedDetection* dets, std::size_t num_dets, const mrpt::math::TPose2D* poses,
                    std::size_t n, double* sum_log) const;

    SensorModelParams m_params;
    ObjectProbabilityMap m_mp;   ///< simp, d
    MapFootprints m_footprints;  ///< all models (simp, o: IoU; edt: raster source)
    EdtMap m_edt;                ///< edt
    std::size_t m_num_usable_objects = 0;
    double m_log_eta = 0;
    double m_exp_minus_1 = 0;
    IouScore m_iou_score;  ///< Eq. iouscore
    double m_inv_two_sigma2 = 0;
};

}  // namespace simp::maps
