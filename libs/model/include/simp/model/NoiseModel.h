#pragma once
/// \file NoiseModel.h
/// Per-class (or per-object) detection noise of box centres on the ground (paper Sec.
/// "Statistical Analysis", Eq. perclassdist). Its frame is NoiseFrame.h's.

#include <Eigen/Core>
#include <simp/geometry/Box3D.h>
#include <simp/model/NoiseFrame.h>

namespace simp::model {

/// Distribution of a detected box centre around the true object centre, in the object's noise
/// frame on the ground (NoiseFrame.h): for a class model, y along the object's longer horizontal
/// side; for an object's own model (MapObject::noise), the box's own frame (x = its local x axis).
/// Density shape: exp(-0.5 * m^(b)) with m the Mahalanobis distance for Sigma; b = 2 is a
/// Gaussian, b = 4 a flatter generalized Gaussian (the authors' `b` column).
struct NoiseModel {
    Eigen::Vector2d mean_m{Eigen::Vector2d::Zero()};                  ///< mu (m), noise frame
    Eigen::Matrix2d cov_m2{Eigen::Matrix2d::Identity() * 0.04};       ///< Sigma (m^2), noise frame
    double exponent_b = 2.0;                                          ///< shape exponent, > 0

    /// True when all numbers are finite, Sigma is symmetric positive definite and b > 0.
    bool isValid() const;
};

/// Covariance of the offsets the model describes: Sigma * E[r^2] / 2 with
/// E[r^2] = 2^(2/b) Gamma(4/b) / Gamma(2/b) (equals Sigma for b = 2).
Eigen::Matrix2d offsetCovariance(const NoiseModel& model);

/// The centre noise hidden in a model fitted to rasterized detected *footprints* (the authors'
/// heatmaps, doc/simulator.md "Which noise model"): per axis i of the model's frame, the model's
/// variance (offsetCovariance()) minus that of a uniform footprint of `box` along the axis
/// (side^2 / 12), floored at (min_std_fraction * the model's std)^2; applied by scaling Sigma
/// (b and mu kept). `source` says which frame the model is in (noiseFrameYaw()).
NoiseModel withoutFootprint(const NoiseModel& model, const geometry::Box3D& box, NoiseSource source,
                            double min_std_fraction);

}  // namespace simp::model
