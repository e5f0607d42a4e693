#include <simp/localization/FrameLikelihood.h>
#include <simp/model/SingleFrameWeight.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace simp::localization {
namespace {

/// Eq. singw of one group of observations: out_log[i] = (1/K) sum_k w_k log p_k(x_i).
std::size_t groupLogLikelihoods(const maps::CObjectMap& map, const std::vector<const WeightedObservation*>& group,
                                const mrpt::math::TPose2D* poses, std::size_t n, double* out_log) {
    std::fill(out_log, out_log + n, 0.0);
    std::size_t K = 0;
    std::vector<maps::CObjectMap::WeightedDetections> cameras;  // weighed together: cos/sin once per pose
    for (const auto* o : group) {
        if (o->obs->empty()) continue;
        if (!o->weights.empty() && o->weights.size() != o->obs->size())
            throw std::invalid_argument("Eq. singw: " + std::to_string(o->weights.size()) + " weights for " +
                                        std::to_string(o->obs->size()) + " detections");
        cameras.push_back({o->obs.get(), o->weights.empty() ? nullptr : o->weights.data()});
    }
    if (!cameras.empty()) map.accumulateLogLikelihoods(cameras.data(), cameras.size(), poses, n, out_log, K);
    if (K == 0) return 0;
    for (std::size_t i = 0; i < n; ++i) {
        out_log[i] = model::singwLog(out_log[i], K);
        if (!std::isfinite(out_log[i]))
            throw std::runtime_error("Eq. singw: non-finite log-likelihood for pose " + std::to_string(i) + " (" +
                                     std::to_string(poses[i].x) + ", " + std::to_string(poses[i].y) + ", " +
                                     std::to_string(poses[i].phi) + ")");
    }
    return K;
}

}  // namespace

std::vector<WeightedObservation> objectObservations(const mrpt::obs::CSensoryFrame& sf) {
    std::vector<WeightedObservation> out;
    for (const auto& o : sf)
        if (auto det = std::dynamic_pointer_cast<simp::obs::CObservationObjects3D>(o)) out.push_back({det, {}});
    return out;
}

std::vector<std::vector<const WeightedObservation*>> frameGroups(const std::vector<WeightedObservation>& observations,
                                                                 bool per_frame) {
    std::vector<mrpt::Clock::time_point> stamps;
    if (per_frame)
        for (const auto& o : observations)
            if (std::find(stamps.begin(), stamps.end(), o.obs->timestamp) == stamps.end())
                stamps.push_back(o.obs->timestamp);
    std::vector<std::vector<const WeightedObservation*>> groups;
    if (stamps.size() <= 1) {
        groups.emplace_back();
        for (const auto& o : observations) groups.back().push_back(&o);
        return groups;
    }
    for (const auto& t : stamps) {
        groups.emplace_back();
        for (const auto& o : observations)
            if (o.obs->timestamp == t) groups.back().push_back(&o);
    }
    return groups;
}

std::size_t updateLogLikelihoods(const maps::CObjectMap& map, const std::vector<WeightedObservation>& observations,
                                 bool per_frame, const mrpt::math::TPose2D* poses, std::size_t n, double* out_log) {
    const auto groups = frameGroups(observations, per_frame);
    if (groups.size() == 1) return groupLogLikelihoods(map, groups.front(), poses, n, out_log);
    std::fill(out_log, out_log + n, 0.0);
    std::vector<double> group_log(n);
    std::size_t K_total = 0;
    for (const auto& group : groups) {
        const std::size_t K = groupLogLikelihoods(map, group, poses, n, group_log.data());
        if (K == 0) continue;
        K_total += K;
        for (std::size_t i = 0; i < n; ++i) out_log[i] += group_log[i];  // product over frames
    }
    return K_total;
}

std::size_t frameLogLikelihoods(const maps::CObjectMap& map, const mrpt::obs::CSensoryFrame& sf,
                                const mrpt::math::TPose2D* poses, std::size_t n, double* out_log) {
    return updateLogLikelihoods(map, objectObservations(sf), false, poses, n, out_log);
}

std::size_t perFrameLogLikelihoods(const maps::CObjectMap& map, const mrpt::obs::CSensoryFrame& sf,
                                   const mrpt::math::TPose2D* poses, std::size_t n, double* out_log) {
    return updateLogLikelihoods(map, objectObservations(sf), true, poses, n, out_log);
}

}  // namespace simp::localization
