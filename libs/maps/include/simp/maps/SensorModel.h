#pragma once
/// \file SensorModel.h
/// The 3D-object sensor model selected by `sensor_model` (simp | edt | d | o): one of the four
/// value types, chosen once when it is built; every call then dispatches once (std::visit) into
/// that model's batch loop, whose per-pair kernel is inlined (no per-pair call or branch on the
/// model).

#include <mrpt/math/TPose2D.h>
#include <simp/geometry/Box3D.h>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/maps/CentreSensorModel.h>
#include <simp/maps/EdtSensorModel.h>
#include <simp/maps/ObjectProbabilityMap.h>
#include <simp/maps/OverlapSensorModel.h>
#include <simp/maps/PreparedDetection.h>
#include <simp/maps/SensorModelTypes.h>
#include <simp/maps/SimpSensorModel.h>
#include <simp/world/ObjectMapData.h>

#include <cstddef>
#include <optional>
#include <variant>

namespace simp::maps {

/// One of the models, by value.
using AnySensorModel = std::variant<SimpSensorModel, EdtSensorModel, CentreSensorModel, OverlapSensorModel>;

/// The selected model's own parameters, taken from the .ini's set of all of them.
SimpSensorModelParams simpParams(const SensorModelParams& p);
CentreSensorModelParams centreParams(const SensorModelParams& p);
OverlapSensorModelParams overlapParams(const SensorModelParams& p);
EdtSensorModelParams edtParams(const SensorModelParams& p);

/// The model `params.type` built for a map. Immutable once built; safe to share between threads.
class SensorModel {
   public:
    /// Builds the model `params.type` with its own parameters (simpParams(), ...). Throws
    /// std::invalid_argument (naming the parameter, class or object) as the model does, and for
    /// any parameter of the set out of its range, used by this model or not (eta outside (0, 1),
    /// non-positive EDT parameters, ...).
    SensorModel(const world::ObjectMapData& data, const SensorModelParams& params);

    const SensorModelParams& params() const { return m_params; }
    /// The model itself, e.g. std::get_if<SimpSensorModel>(&model()).
    const AnySensorModel& model() const { return m_model; }

    /// True when the map has no object usable by the selected model.
    bool empty() const;
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
    /// Eq. combined for simp, the baseline's likelihood otherwise (the detection's weight not applied).
    double logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const;
    /// sum_log[i] += weight_k log p(z_k | m, poses[i]) for every detection k (no allocation, no
    /// virtual call, one dispatch per call).
    void accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                  const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log) const;

    /// Several groups at once (LogLikelihoodBatch.h: accumulateLogLikelihoodGroups): the same
    /// result, bit for bit, as one accumulateLogLikelihoods() call per group, cos/sin once per pose.
    void accumulateLogLikelihoodGroups(const PreparedDetection* dets, const std::size_t* group_ends,
                                       std::size_t num_groups, const mrpt::math::TPose2D* poses, std::size_t n,
                                       double* sum_log) const;

    /// The m_p raster of simp and d; an empty one (no class) for edt and o.
    const ObjectProbabilityMap& probabilityMap() const;

   private:
    SensorModelParams m_params;
    AnySensorModel m_model;
};

}  // namespace simp::maps
