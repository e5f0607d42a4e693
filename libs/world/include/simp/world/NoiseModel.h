#pragma once
/// \file NoiseModel.h
/// Per-class detection noise of box centres on the ground (paper Sec. "Statistical Analysis").

#include <Eigen/Core>

namespace simp::world {

/// Distribution of a detected box centre around the true object centre, in the object
/// frame on the ground (x = the object's local x axis projected on the floor, y = left of it).
/// Density shape: exp(-0.5 * m^(b)) with m the Mahalanobis distance for Sigma; b = 2 is a
/// Gaussian, b = 4 a flatter generalized Gaussian (the authors' `b` column).
struct NoiseModel {
    Eigen::Vector2d mean_m{Eigen::Vector2d::Zero()};                  ///< mu (m), object frame
    Eigen::Matrix2d cov_m2{Eigen::Matrix2d::Identity() * 0.04};       ///< Sigma (m^2), object frame
    double exponent_b = 2.0;                                          ///< shape exponent, > 0

    /// True when all numbers are finite, Sigma is symmetric positive definite and b > 0.
    bool isValid() const;
};

}  // namespace simp::world
