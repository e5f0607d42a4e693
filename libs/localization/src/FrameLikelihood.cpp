#include <simp/localization/FrameLikelihood.h>

#include <simp/obs/CObservationObjects3D.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace simp::localization {

std::size_t frameLogLikelihoods(const maps::CObjectMap& map, const mrpt::obs::CSensoryFrame& sf,
                                const mrpt::math::TPose2D* poses, std::size_t n, double* out_log) {
    std::fill(out_log, out_log + n, 0.0);
    std::size_t K = 0;
    for (const auto& o : sf) {
        const auto* det = dynamic_cast<const simp::obs::CObservationObjects3D*>(o.get());
        if (det == nullptr || det->empty()) continue;
        map.accumulateLogLikelihoods(*det, poses, n, out_log, K);
    }
    if (K == 0) return 0;
    // Eq. singw: prod_k p_k^(1/K)  ->  (1/K) sum_k log p_k
    const double inv_k = 1.0 / static_cast<double>(K);
    for (std::size_t i = 0; i < n; ++i) {
        out_log[i] *= inv_k;
        if (!std::isfinite(out_log[i]))
            throw std::runtime_error("Eq. singw: non-finite log-likelihood for pose " + std::to_string(i) + " (" +
                                     std::to_string(poses[i].x) + ", " + std::to_string(poses[i].y) + ", " +
                                     std::to_string(poses[i].phi) + ")");
    }
    return K;
}

std::size_t perFrameLogLikelihoods(const maps::CObjectMap& map, const mrpt::obs::CSensoryFrame& sf,
                                   const mrpt::math::TPose2D* poses, std::size_t n, double* out_log) {
    std::vector<mrpt::Clock::time_point> stamps;
    for (const auto& o : sf)
        if (std::find(stamps.begin(), stamps.end(), o->timestamp) == stamps.end()) stamps.push_back(o->timestamp);
    if (stamps.size() <= 1) return frameLogLikelihoods(map, sf, poses, n, out_log);
    std::fill(out_log, out_log + n, 0.0);
    std::vector<double> group(n);
    std::size_t K_total = 0;
    for (const auto& t : stamps) {
        mrpt::obs::CSensoryFrame g;
        for (const auto& o : sf)
            if (o->timestamp == t) g.insert(o);
        const std::size_t K = frameLogLikelihoods(map, g, poses, n, group.data());
        if (K == 0) continue;
        K_total += K;
        for (std::size_t i = 0; i < n; ++i) out_log[i] += group[i];  // product over frames
    }
    return K_total;
}

}  // namespace simp::localization
