#pragma once
/// \file SingleFrameWeight.h
/// Eq. singw: the likelihood of the K detections of one frame is the geometric mean of their
/// per-detection likelihoods, p(Z | m, x) = prod_k p(z^k | m, x)^(1/K). The one implementation
/// of CObjectMap's MRPT likelihood and of the filter's batch frame likelihood.

#include <cstddef>

namespace simp::model {

/// Eq. singw in logs: (1/K) sum_k log p(z^k | m, x), from `sum_log` = sum_k log p(z^k | m, x) over
/// K > 0 used detections (K = 0: no factor; callers return the neutral 0 themselves).
/// Written as a product with 1/K so that a loop over poses (the same K) gives the same numbers.
inline double singwLog(double sum_log, std::size_t K) { return sum_log * (1.0 / static_cast<double>(K)); }

}  // namespace simp::model
