#include <mrpt/core/exceptions.h>
#include <simp/maps/CObjectMap.h>
#include <simp/model/SingleFrameWeight.h>

#include <array>
#include <cmath>
#include <iostream>

namespace simp::maps {
namespace {

/// Detections processed per batch on the stack (no heap allocation in the batch path); small
/// enough that the per-call setup stays cheap for MRPT's one-pose-per-call interface.
constexpr std::size_t kBatch = 16;

mrpt::math::TPose2D toPose2D(const mrpt::poses::CPose3D& p) { return {p.x(), p.y(), p.yaw()}; }

}  // namespace

std::shared_ptr<const SensorModel> CObjectMap::sensorModel() const {
    const auto params = likelihoodOptions.modelParams();
    std::lock_guard<std::mutex> lock(m_cache_mutex);
    if (!m_model || m_model->params() != params) m_model = std::make_shared<const SensorModel>(m_data, params);
    return m_model;
}

void CObjectMap::warnEmptyOnce() const {
    std::lock_guard<std::mutex> lock(m_cache_mutex);
    if (m_warned_empty) return;
    m_warned_empty = true;
    std::cerr << "[simp::maps::CObjectMap] warning: the object map has no object usable by sensor model '"
              << toString(likelihoodOptions.sensor_model)
              << "': every detection is ignored and every pose gets the same (neutral) likelihood\n";
}

int CObjectMap::usableClassOf(const simp::obs::CObservationObjects3D& obs, std::size_t k) const {
    const auto& det = obs.detections().at(k);
    const std::string& name = obs.classNameOf(det);
    // Compared in the detector's single precision, so "0.7" in the .ini admits a 0.7f score.
    if (det.confidence < static_cast<float>(likelihoodOptions.thresholdOf(name))) return -1;  // under threshold
    const int cls = m_data.classId(name);
    // A class the sensor model cannot score (simp and d: no noise model) is ignored like an unknown
    // one, so that everything counting detections (the state's fit window) counts the same ones.
    return sensorModel()->scoresClass(cls) ? cls : -1;
}

std::size_t CObjectMap::prepareDetections(const SensorModel& model, const simp::obs::CObservationObjects3D& obs,
                                          std::size_t& first, PreparedDetection* out, std::size_t cap,
                                          const double* weights) const {
    std::size_t count = 0;
    for (; first < obs.size() && count < cap; ++first) {
        const int cls = usableClassOf(obs, first);
        if (cls < 0 || (weights && weights[first] == 0.0)) continue;  // weight 0: not scored, not counted
        auto prepared =
            model.prepare(cls, obs.boxInRobot(first), obs.footprintInRobot(first), weights ? weights[first] : 1.0);
        if (prepared) out[count++] = *prepared;
    }
    return count;
}

std::optional<double> CObjectMap::detectionLogLikelihood(const simp::obs::CObservationObjects3D& obs, std::size_t k,
                                                         const mrpt::math::TPose2D& robot_pose) const {
    const auto model = sensorModel();
    if (model->empty()) warnEmptyOnce();
    const int cls = usableClassOf(obs, k);
    if (cls < 0) return std::nullopt;
    const auto prepared = model->prepare(cls, obs.boxInRobot(k), obs.footprintInRobot(k));
    if (!prepared) return std::nullopt;
    const double log_p = model->logLikelihood(*prepared, robot_pose);
    MRPT_CHECK_NORMAL_NUMBER(log_p);
    return log_p;
}

namespace {

/// Prepares the usable detections of each observation in chunks of at most kBatch (a chunk is one
/// group: its log-likelihoods are summed, then added to sum_log) into a stack buffer of `Capacity`
/// detections, weighed whenever it cannot take another chunk. The chunks and their order do not
/// depend on `Capacity`: a buffer of kBatch weighs chunk by chunk, a larger one shares cos/sin.
template <std::size_t Capacity, typename Prepare>
std::size_t accumulateChunks(const SensorModel& model, const CObjectMap::WeightedDetections* observations,
                             std::size_t num_observations, const mrpt::math::TPose2D* poses, std::size_t n,
                             double* sum_log, const Prepare& prepare) {
    static_assert(Capacity >= kBatch);
    std::array<PreparedDetection, Capacity> buffer;
    std::array<std::size_t, Capacity> group_ends{};
    std::size_t filled = 0, groups = 0, used = 0;
    const auto flush = [&] {
        model.accumulateLogLikelihoodGroups(buffer.data(), group_ends.data(), groups, poses, n, sum_log);
        filled = groups = 0;
    };
    for (std::size_t o = 0; o < num_observations; ++o) {
        std::size_t next = 0;
        while (next < observations[o].obs->size()) {
            if (Capacity - filled < kBatch) flush();
            const std::size_t count = prepare(observations[o], next, buffer.data() + filled, kBatch);
            if (count == 0) continue;
            filled += count;
            group_ends[groups++] = filled;
            used += count;
        }
    }
    if (groups > 0) flush();
    return used;
}

/// Detections a frame's observations share a buffer of: cos/sin once per pose for up to this many.
constexpr std::size_t kFrameBatch = 4 * kBatch;

}  // namespace

void CObjectMap::accumulateLogLikelihoods(const simp::obs::CObservationObjects3D& obs,
                                          const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log,
                                          std::size_t& used, const double* weights) const {
    const auto model = sensorModel();
    if (model->empty()) warnEmptyOnce();
    const WeightedDetections one{&obs, weights};
    // A buffer of one chunk: MRPT calls with one pose per call, so the setup must stay small.
    used += accumulateChunks<kBatch>(
        *model, &one, 1, poses, n, sum_log,
        [&](const WeightedDetections& o, std::size_t& next, PreparedDetection* out, std::size_t cap) {
            return prepareDetections(*model, *o.obs, next, out, cap, o.weights);
        });
}

void CObjectMap::accumulateLogLikelihoods(const WeightedDetections* observations, std::size_t num_observations,
                                          const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log,
                                          std::size_t& used) const {
    const auto model = sensorModel();
    if (model->empty()) warnEmptyOnce();
    used += accumulateChunks<kFrameBatch>(
        *model, observations, num_observations, poses, n, sum_log,
        [&](const WeightedDetections& o, std::size_t& next, PreparedDetection* out, std::size_t cap) {
            return prepareDetections(*model, *o.obs, next, out, cap, o.weights);
        });
}

double CObjectMap::internal_computeObservationLikelihood(const mrpt::obs::CObservation& obs,
                                                         const mrpt::poses::CPose3D& takenFrom) const {
    const auto* objects = dynamic_cast<const simp::obs::CObservationObjects3D*>(&obs);
    if (!objects) return 0.0;  // not ours: neutral
    const auto pose = toPose2D(takenFrom);
    double sum_log = 0.0;
    std::size_t used = 0;
    accumulateLogLikelihoods(*objects, &pose, 1, &sum_log, used);
    if (used == 0) return 0.0;
    const double log_p = model::singwLog(sum_log, used);
    MRPT_CHECK_NORMAL_NUMBER(log_p);
    return log_p;
}

bool CObjectMap::internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const {
    return dynamic_cast<const simp::obs::CObservationObjects3D*>(&obs) != nullptr;
}

}  // namespace simp::maps
