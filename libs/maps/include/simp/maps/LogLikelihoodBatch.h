#pragma once
/// \file LogLikelihoodBatch.h
/// The batch loop every 3D-object sensor model shares: weigh K prepared detections at N particle
/// poses. Instantiated by each model's .cpp with its pair kernel, so the kernel is inlined: no
/// call, virtual or not, and no branch on the model per (particle x detection) pair.

#include <mrpt/math/TPose2D.h>
#include <simp/geometry/SinCos.h>
#include <simp/maps/PreparedDetection.h>

#include <cmath>
#include <cstddef>

namespace simp::maps {

/// Several groups of prepared detections at once (e.g. the cameras of one frame): group g is
/// dets[group_ends[g - 1] .. group_ends[g]) (group_ends[-1] = 0). For every pose i and every group g
/// in order, sum_log[i] += sum_{k in g} weight_k log p(z_k | m, poses[i]) (k in order): the same
/// additions in the same order as one accumulateLogLikelihoodBatch() call per group, so the same
/// bits, with cos/sin of a particle's heading once for all groups (particle-major). `Model`
/// provides a `Scratch` type and `double pairLogLikelihood(const PreparedDetection&, double c,
/// double s, double tx, double ty, Scratch&) const` for the robot at (tx, ty, atan2(s, c)), inline.
template <typename Model>
void accumulateLogLikelihoodGroups(const Model& model, const PreparedDetection* dets, const std::size_t* group_ends,
                                   std::size_t num_groups, const mrpt::math::TPose2D* poses, std::size_t n,
                                   double* sum_log) {
    if (num_groups == 0 || n == 0) return;
    typename Model::Scratch scratch;  // reused for every pair
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = poses[i];
        double s, c;
        geometry::sinCos(p.phi, s, c);
        std::size_t k = 0;
        for (std::size_t g = 0; g < num_groups; ++g) {
            double acc = 0.0;
            for (; k < group_ends[g]; ++k) acc += dets[k].weight * model.pairLogLikelihood(dets[k], c, s, p.x, p.y, scratch);
            sum_log[i] += acc;
        }
    }
}

/// sum_log[i] += sum_k weight_k log p(z_k | m, poses[i]), k in order: one group of num_dets.
template <typename Model>
void accumulateLogLikelihoodBatch(const Model& model, const PreparedDetection* dets, std::size_t num_dets,
                                  const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log) {
    if (num_dets == 0) return;
    accumulateLogLikelihoodGroups(model, dets, &num_dets, 1, poses, n, sum_log);
}

/// log p(z | m, pose) of one prepared detection through the same kernel (weight not applied).
template <typename Model>
double logLikelihoodAt(const Model& model, const PreparedDetection& det, const mrpt::math::TPose2D& pose) {
    typename Model::Scratch scratch;
    double s, c;
    geometry::sinCos(pose.phi, s, c);
    return model.pairLogLikelihood(det, c, s, pose.x, pose.y, scratch);
}

}  // namespace simp::maps
