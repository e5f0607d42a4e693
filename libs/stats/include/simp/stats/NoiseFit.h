#pragma once
/// \file NoiseFit.h
/// Fit of the per-class Gaussian p(c | l) = N(mu, Sigma) (Eq. perclassdist) to the object-frame
/// offsets of matched predictions, with standard errors, and the 5 cm occurrence histogram.

#include <simp/model/NoiseModel.h>

#include <Eigen/Core>
#include <vector>

namespace simp::stats {

/// Occurrence histogram on the ground plane, object frame (m). Cell (ix, iy) covers
/// [x_min + ix*cell, x_min + (ix+1)*cell) x [y_min + iy*cell, ...).
struct Histogram2D {
    double cell_m = 0.05;        ///< cell size (m); the paper's 5 cm
    double x_min_m = 0, y_min_m = 0;  ///< lower-left corner of cell (0, 0) (m)
    Eigen::MatrixXd counts;      ///< rows = ix (x), cols = iy (y)
    std::size_t outside = 0;     ///< samples that fell outside the grid

    Eigen::Vector2d cellCenter(int ix, int iy) const {
        return {x_min_m + (ix + 0.5) * cell_m, y_min_m + (iy + 0.5) * cell_m};
    }
};

/// Histogram of `samples` on a grid of `cell_m` cells covering [-half_extent, half_extent]^2
/// around `center` (the grid is aligned so that a cell corner lies on the object origin).
/// \throw std::invalid_argument for cell_m <= 0 or half_extent_m < cell_m.
Histogram2D makeHistogram(const std::vector<Eigen::Vector2d>& samples, double cell_m, const Eigen::Vector2d& center,
                          double half_extent_m);

/// A fitted noise model with its sample size and standard errors.
struct NoiseFit {
    model::NoiseModel model;             ///< mu (m), Sigma (m^2), b = 2 (Gaussian)
    std::size_t n = 0;                   ///< samples used (after outlier rejection)
    std::size_t rejected = 0;            ///< samples rejected as outliers
    Eigen::Vector2d se_mean_m{Eigen::Vector2d::Zero()};   ///< SE(mu_i) = sqrt(Sigma_ii / n)
    Eigen::Matrix2d se_cov_m2{Eigen::Matrix2d::Zero()};   ///< SE(Sigma_ij) = sqrt((S_ii S_jj + S_ij^2) / (n - 1))
};

/// Maximum-likelihood mean and unbiased sample covariance of `samples` (m).
/// With `outlier_mahalanobis` > 0 the fit is robust: samples whose Mahalanobis distance to the
/// current fit exceeds it are dropped and the fit repeated (up to 10 times); Sigma is then
/// divided by the variance factor of a 2D Gaussian truncated at that radius r,
/// c(r) = 1 - (r^2 / 2) e^{-r^2/2} / (1 - e^{-r^2/2}), so an outlier-free Gaussian is unbiased.
/// \throw std::invalid_argument with fewer than 3 samples, a non-finite sample, or a singular fit.
NoiseFit fitGaussian(const std::vector<Eigen::Vector2d>& samples, double outlier_mahalanobis = 0.0);

/// The same fit from the histogram only: cell centres weighted by counts, Sheppard's correction
/// (cell^2 / 12 subtracted from each variance). Used with `fit_source = histogram`.
/// \throw std::invalid_argument with fewer than 3 counts or a singular fit.
NoiseFit fitGaussianFromHistogram(const Histogram2D& histogram);

}  // namespace simp::stats
