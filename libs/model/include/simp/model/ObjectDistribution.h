#pragma once
/// \file ObjectDistribution.h
/// The detection-centre distribution of one map object, p_o(c | l) (paper Eqs. perclassdist,
/// shiftdist): the one implementation of the sensor model, the mapper's association cost and the
/// statistics' tests.

#include <simp/geometry/Box3D.h>
#include <simp/model/NoiseFrame.h>
#include <simp/model/NoiseModel.h>

#include <Eigen/Core>
#include <cmath>

namespace simp::model {

/// p_o(c) = exp(-0.5 * m(c)^b), m = Mahalanobis distance of the world point c to mu_o for Sigma_o.
///
/// Eq. shiftdist: the class (or per-object) noise model, given in the object frame on the
/// ground, is moved to the object: mu_o = R_o mu + c_o, Sigma_o = R_o Sigma R_o^T, with
/// c_o the box centre on the ground (world, m) and R_o the 2D rotation into the object's noise
/// frame (NoiseFrame.h).
///
/// Unnormalized on purpose: the peak is exactly 1, so p_o is in [0, 1] and can be used as
/// the association probability of Eq. combined (p_o p_g + (1 - p_o) eta). The normalized
/// density of Eq. perclassdist would scale with 1/|Sigma| and exceed 1 for small Sigma.
struct ObjectDistribution {
    Eigen::Vector2d mean_world_m{Eigen::Vector2d::Zero()};  ///< mu_o (m), world frame
    double inv_xx = 1, inv_xy = 0, inv_yy = 1;              ///< Sigma_o^-1 (1/m^2)
    double half_b = 1.0;                                    ///< b / 2 (b = shape exponent)
    double sigma_max_m = 1.0;                               ///< sqrt of Sigma_o's largest eigenvalue (m)
    double sigma_min_m = 1.0;                               ///< sqrt of Sigma_o's smallest eigenvalue (m)
    double sigma_x_m = 1.0, sigma_y_m = 1.0;                ///< sqrt(Sigma_o(0,0)), sqrt(Sigma_o(1,1)) (m)

    /// m^2 of the world point (x, y) (m).
    double mahalanobis2(double x_m, double y_m) const {
        const double dx = x_m - mean_world_m.x(), dy = y_m - mean_world_m.y();
        return inv_xx * dx * dx + 2.0 * inv_xy * dx * dy + inv_yy * dy * dy;
    }
    /// m^b from m^2 (fast paths for the Gaussian b = 2 and the authors' b = 4).
    double powerB(double m2) const {
        if (half_b == 1.0) return m2;
        if (half_b == 2.0) return m2 * m2;
        return std::pow(m2, half_b);
    }
    /// p_o at the world point (x, y) (m), in [0, 1]. `inv_scale2` = 1 / s^2 widens Sigma_o to
    /// s^2 Sigma_o (s >= 1: a detection noisier than the model, e.g. a distant one).
    double probability(double x_m, double y_m, double inv_scale2 = 1.0) const {
        return std::exp(-0.5 * powerB(mahalanobis2(x_m, y_m) * inv_scale2));
    }
};

/// Eq. shiftdist for a map object's box (world frame, canonical upright) and the noise model that
/// applies to it, from `source` (its frame: NoiseFrame.h; an object's own noise is in its box
/// frame, a class model in the class noise frame).
/// Throws std::invalid_argument when the noise model is not valid (Sigma not SPD, b <= 0).
ObjectDistribution makeObjectDistribution(const geometry::Box3D& box_world, const NoiseModel& noise,
                                          NoiseSource source);

/// Mahalanobis radius m_s beyond which p_o < p_min: exp(-0.5 m_s^b) = p_min.
double supportMahalanobisRadius(double exponent_b, double p_min);

/// Largest slope of p_o along any direction in Mahalanobis units, max_m d/dm exp(-0.5 m^b);
/// divided by sigma_min it bounds |grad p_o| in 1/m (used to bound raster errors).
double maxSlopeMahalanobis(double exponent_b);

}  // namespace simp::model
