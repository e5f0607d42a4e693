#include <simp/maps/LogLikelihoodBatch.h>
#include <simp/maps/SensorModel.h>

#include <stdexcept>

namespace simp::maps {
namespace {

/// Every parameter of the set is checked, used by the selected model or not: a bad value is an error
/// whichever model is selected (the .ini loader names the key; this covers options set in code).
const SensorModelParams& checked(const SensorModelParams& p) {
    simpParams(p).check();
    edtParams(p).check();
    return p;
}

AnySensorModel makeModel(const world::ObjectMapData& data, const SensorModelParams& p) {
    switch (p.type) {
        case SensorModelType::Simp: return SimpSensorModel(data, simpParams(p));
        case SensorModelType::Edt: return EdtSensorModel(data, edtParams(p));
        case SensorModelType::D: return CentreSensorModel(data, centreParams(p));
        case SensorModelType::O: return OverlapSensorModel(data, overlapParams(p));
    }
    throw std::invalid_argument("unknown sensor model type");
}

}  // namespace

SimpSensorModelParams simpParams(const SensorModelParams& p) {
    return {p.eta, p.mp, p.noise_reference_range_m, p.yaw_sigma_rad};
}
CentreSensorModelParams centreParams(const SensorModelParams& p) { return {p.eta, p.mp, p.noise_reference_range_m}; }
OverlapSensorModelParams overlapParams(const SensorModelParams& p) { return {p.eta}; }
EdtSensorModelParams edtParams(const SensorModelParams& p) {
    return {p.eta, p.edt_sigma_m, p.edt_max_distance_m, p.edt_resolution_m, p.noise_reference_range_m};
}

SensorModel::SensorModel(const world::ObjectMapData& data, const SensorModelParams& params)
    : m_params(checked(params)), m_model(makeModel(data, params)) {}

bool SensorModel::empty() const {
    return std::visit([](const auto& m) { return m.empty(); }, m_model);
}

bool SensorModel::scoresClass(int map_class) const {
    return std::visit([&](const auto& m) { return m.scoresClass(map_class); }, m_model);
}

std::optional<PreparedDetection> SensorModel::prepare(int map_class, const geometry::Box3D& box_in_robot,
                                                      const geometry::ConvexPolygon& footprint_in_robot,
                                                      double weight) const {
    return std::visit([&](const auto& m) { return m.prepare(map_class, box_in_robot, footprint_in_robot, weight); },
                      m_model);
}

double SensorModel::logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const {
    return std::visit([&](const auto& m) { return m.logLikelihood(det, pose); }, m_model);
}

void SensorModel::accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                           const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log) const {
    std::visit([&](const auto& m) { m.accumulateLogLikelihoods(dets, num_dets, poses, n, sum_log); }, m_model);
}

void SensorModel::accumulateLogLikelihoodGroups(const PreparedDetection* dets, const std::size_t* group_ends,
                                                std::size_t num_groups, const mrpt::math::TPose2D* poses,
                                                std::size_t n, double* sum_log) const {
    std::visit(
        [&](const auto& m) {
            simp::maps::accumulateLogLikelihoodGroups(m, dets, group_ends, num_groups, poses, n, sum_log);
        },
        m_model);
}

const ObjectProbabilityMap& SensorModel::probabilityMap() const {
    static const ObjectProbabilityMap kNone;
    if (const auto* m = std::get_if<SimpSensorModel>(&m_model)) return m->probabilityMap();
    if (const auto* m = std::get_if<CentreSensorModel>(&m_model)) return m->probabilityMap();
    return kNone;
}

}  // namespace simp::maps
