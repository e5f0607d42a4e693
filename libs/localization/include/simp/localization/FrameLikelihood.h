#pragma once
/// \file FrameLikelihood.h
/// Eq. singw over a whole sensory frame: the weight of a particle is the geometric mean of
/// the likelihoods of ALL K detections of the frame (every camera of the rig).

#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/CObservationObjects3D.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace simp::localization {

/// One camera observation of an update, its camera pose in the update's robot frame, with the
/// exponent of each detection's likelihood (DetectionNovelty; empty = all 1, the paper's).
struct WeightedObservation {
    WeightedObservation() = default;
    WeightedObservation(simp::obs::CObservationObjects3D::Ptr observation, std::vector<double> detection_weights = {},
                        std::vector<double> detection_heading_weights = {})
        : obs(std::move(observation)),
          weights(std::move(detection_weights)),
          heading_weights(std::move(detection_heading_weights)) {}

    simp::obs::CObservationObjects3D::Ptr obs;
    std::vector<double> weights;  ///< one per detection of obs, or empty
    /// ManhattanHeading's exponent per detection (YawConsensus), or empty: `weights` then.
    std::vector<double> heading_weights;
};

/// Eq. singw's grouping of an update's observations: per_frame = true, one group per time stamp (in
/// order of first appearance); otherwise, or with a single time stamp, one group of all.
std::vector<std::vector<const WeightedObservation*>> frameGroups(const std::vector<WeightedObservation>& observations,
                                                                 bool per_frame);

/// The CObservationObjects3D of a sensory frame with weight 1 (other observation types skipped).
std::vector<WeightedObservation> objectObservations(const mrpt::obs::CSensoryFrame& sf);

/** Eq. singw for n robot poses over the observations of one update:
 *  - per_frame = false: log p = (1/K) sum_k w_k log p(z^k | m, x_i) over all K used detections;
 *  - per_frame = true: the observations are grouped by timestamp (one group = the detections of
 *    all cameras at one time, e.g. a frame skipped by the motion trigger and kept for this update,
 *    see SkippedDetections), Eq. singw per group, and the groups' logs added (independent frames
 *    multiply). With one timestamp both are the same.
 * w_k = 1 gives the paper's equation. Used detections: above their class confidence threshold,
 * class in the map. Writes out_log[0..n) (zeros when K = 0).
 * \return K. \throw std::runtime_error when a log-likelihood is not finite.
 */
std::size_t updateLogLikelihoods(const maps::CObjectMap& map, const std::vector<WeightedObservation>& observations,
                                 bool per_frame, const mrpt::math::TPose2D* poses, std::size_t n, double* out_log);

/// updateLogLikelihoods(map, objectObservations(sf), false, ...): one geometric mean over `sf`.
std::size_t frameLogLikelihoods(const maps::CObjectMap& map, const mrpt::obs::CSensoryFrame& sf,
                                const mrpt::math::TPose2D* poses, std::size_t n, double* out_log);

/// updateLogLikelihoods(map, objectObservations(sf), true, ...): Eq. singw per timestamp of `sf`.
std::size_t perFrameLogLikelihoods(const maps::CObjectMap& map, const mrpt::obs::CSensoryFrame& sf,
                                   const mrpt::math::TPose2D* poses, std::size_t n, double* out_log);

}  // namespace simp::localization
