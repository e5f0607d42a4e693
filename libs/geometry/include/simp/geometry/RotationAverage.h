#pragma once
/// \file RotationAverage.h
/// Weighted average of rotations: the arithmetic mean of the matrices projected back
/// onto SO(3) by SVD (Moakher 2002, "Means and averaging in the group of rotations"),
/// as the map update of a merged object's orientation.

#include <Eigen/Core>
#include <vector>

namespace simp::geometry {

/// Weighted mean rotation: U V^T of the SVD U S V^T = sum_i w_i R_i / sum_i w_i, with the
/// sign of the last singular direction flipped when needed so that det = +1 (the
/// closest rotation in the Frobenius norm). Map update: R_o2 = U V^T of
/// SVD((n_match^o2 R_o2 + n_match^o1 R_o1) / (n_match^o1 + n_match^o2)).
/// \throw std::invalid_argument when Rs is empty, sizes differ, a weight is negative or
///        not finite, the weights sum to 0, or a matrix is not finite.
Eigen::Matrix3d averageRotations(const std::vector<Eigen::Matrix3d>& Rs, const std::vector<double>& weights);

}  // namespace simp::geometry
