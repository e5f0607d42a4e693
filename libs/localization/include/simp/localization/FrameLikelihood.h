#pragma once
/// \file FrameLikelihood.h
/// Eq. singw over a whole sensory frame: the weight of a particle is the geometric mean of
/// the likelihoods of ALL K detections of the frame (every camera of the rig).

#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <simp/maps/CObjectMap.h>

#include <cstddef>

namespace simp::localization {

/** log p(z_t | m, x_i) = (1/K) sum_k log p(z_t^k | m, x_i) for n robot poses (Eq. singw),
 * K = detections used over all simp::obs::CObservationObjects3D of `sf` (those above their
 * class confidence threshold whose class is in the map). Writes out_log[0..n); all zeros
 * (no information) when K = 0. Other observation types are ignored.
 * \return K. \throw std::runtime_error when a log-likelihood is not finite.
 */
std::size_t frameLogLikelihoods(const maps::CObjectMap& map, const mrpt::obs::CSensoryFrame& sf,
                                const mrpt::math::TPose2D* poses, std::size_t n, double* out_log);

/** Eq. singw per camera frame, multiplied over the frames of `sf`: the observations are grouped
 * by timestamp (one group = the detections of all cameras at one time, e.g. a frame skipped by
 * the motion trigger and kept for this update, see SkippedDetections) and
 * log p = sum_groups (1/K_g) sum_{k in g} log p(z^k | m, x_i). With one timestamp this equals
 * frameLogLikelihoods(). Groups with K_g = 0 contribute nothing.
 * eturn the total K. 	hrow std::runtime_error when a log-likelihood is not finite.
 */
std::size_t perFrameLogLikelihoods(const maps::CObjectMap& map, const mrpt::obs::CSensoryFrame& sf,
                                   const mrpt::math::TPose2D* poses, std::size_t n, double* out_log);

}  // namespace simp::localization
