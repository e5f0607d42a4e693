/// \file NoiseFit.cpp
#include <simp/stats/NoiseFit.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

namespace simp::stats {

namespace {

void setStandardErrors(NoiseFit& f) {
    const Eigen::Matrix2d& S = f.model.cov_m2;
    const double n = static_cast<double>(f.n);
    f.se_mean_m = (S.diagonal() / n).cwiseSqrt();
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) f.se_cov_m2(i, j) = std::sqrt((S(i, i) * S(j, j) + S(i, j) * S(i, j)) / (n - 1.0));
}

/// Weighted mean and covariance (weights = 1 for samples, counts for cells); denominators
/// sum(w) and sum(w) - 1 (unbiased for unit weights).
void weightedMoments(const std::vector<Eigen::Vector2d>& x, const std::vector<double>& w, const std::vector<char>& keep,
                     Eigen::Vector2d& mean, Eigen::Matrix2d& cov, double& total) {
    total = 0;
    mean.setZero();
    for (std::size_t i = 0; i < x.size(); ++i)
        if (keep[i]) {
            mean += w[i] * x[i];
            total += w[i];
        }
    mean /= total;
    cov.setZero();
    for (std::size_t i = 0; i < x.size(); ++i)
        if (keep[i]) cov += w[i] * (x[i] - mean) * (x[i] - mean).transpose();
    cov /= (total - 1.0);
}

void requireSpd(const Eigen::Matrix2d& cov, const char* what) {
    if (!cov.allFinite() || cov(0, 0) <= 0 || cov.determinant() <= 1e-18)
        throw std::invalid_argument(std::string(what) + ": singular covariance (all samples on a line or a point)");
}

}  // namespace

Histogram2D makeHistogram(const std::vector<Eigen::Vector2d>& samples, double cell_m, const Eigen::Vector2d& center,
                          double half_extent_m) {
    if (!(cell_m > 0.0)) throw std::invalid_argument("makeHistogram: cell size must be > 0 m");
    if (!(half_extent_m >= cell_m)) throw std::invalid_argument("makeHistogram: half extent must be >= one cell");
    Histogram2D h;
    h.cell_m = cell_m;
    h.x_min_m = std::floor((center.x() - half_extent_m) / cell_m) * cell_m;
    h.y_min_m = std::floor((center.y() - half_extent_m) / cell_m) * cell_m;
    const int nx = static_cast<int>(std::ceil((center.x() + half_extent_m - h.x_min_m) / cell_m));
    const int ny = static_cast<int>(std::ceil((center.y() + half_extent_m - h.y_min_m) / cell_m));
    h.counts = Eigen::MatrixXd::Zero(nx, ny);
    for (const Eigen::Vector2d& s : samples) {
        const int ix = static_cast<int>(std::floor((s.x() - h.x_min_m) / cell_m));
        const int iy = static_cast<int>(std::floor((s.y() - h.y_min_m) / cell_m));
        if (ix < 0 || iy < 0 || ix >= nx || iy >= ny)
            ++h.outside;
        else
            h.counts(ix, iy) += 1.0;
    }
    return h;
}

NoiseFit fitGaussian(const std::vector<Eigen::Vector2d>& samples, double outlier_mahalanobis) {
    if (samples.size() < 3)
        throw std::invalid_argument("fitGaussian: need at least 3 samples, got " + std::to_string(samples.size()));
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (!samples[i].allFinite()) throw std::invalid_argument("fitGaussian: sample " + std::to_string(i) + " is not finite");
    const std::vector<double> w(samples.size(), 1.0);
    std::vector<char> keep(samples.size(), 1);
    Eigen::Vector2d mean;
    Eigen::Matrix2d cov;
    double total = 0;
    weightedMoments(samples, w, keep, mean, cov, total);
    requireSpd(cov, "fitGaussian");
    if (outlier_mahalanobis > 0.0) {
        const double r2 = outlier_mahalanobis * outlier_mahalanobis;
        const double e = std::exp(-0.5 * r2);
        const double shrink = 1.0 - 0.5 * r2 * e / (1.0 - e);  // per-axis variance factor of the truncation
        for (int it = 0; it < 10; ++it) {
            const Eigen::Matrix2d info = cov.inverse();
            bool changed = false;
            for (std::size_t i = 0; i < samples.size(); ++i) {
                const Eigen::Vector2d d = samples[i] - mean;
                const char k = d.dot(info * d) <= r2 ? 1 : 0;
                changed |= (k != keep[i]);
                keep[i] = k;
            }
            weightedMoments(samples, w, keep, mean, cov, total);
            if (total < 3) throw std::invalid_argument("fitGaussian: fewer than 3 samples left after outlier rejection");
            cov /= shrink;
            requireSpd(cov, "fitGaussian");
            if (!changed) break;
        }
    }
    NoiseFit f;
    f.model.mean_m = mean;
    f.model.cov_m2 = 0.5 * (cov + cov.transpose());
    f.model.exponent_b = 2.0;
    f.n = static_cast<std::size_t>(total);
    f.rejected = samples.size() - f.n;
    setStandardErrors(f);
    return f;
}

NoiseFit fitGaussianFromHistogram(const Histogram2D& h) {
    std::vector<Eigen::Vector2d> x;
    std::vector<double> w;
    for (int ix = 0; ix < h.counts.rows(); ++ix)
        for (int iy = 0; iy < h.counts.cols(); ++iy)
            if (h.counts(ix, iy) > 0) {
                x.push_back(h.cellCenter(ix, iy));
                w.push_back(h.counts(ix, iy));
            }
    const std::vector<char> keep(x.size(), 1);
    double total = 0;
    for (double v : w) total += v;
    if (total < 3) throw std::invalid_argument("fitGaussianFromHistogram: need at least 3 counts");
    Eigen::Vector2d mean;
    Eigen::Matrix2d cov;
    weightedMoments(x, w, keep, mean, cov, total);
    cov.diagonal().array() -= h.cell_m * h.cell_m / 12.0;  // Sheppard's correction
    requireSpd(cov, "fitGaussianFromHistogram");
    NoiseFit f;
    f.model.mean_m = mean;
    f.model.cov_m2 = cov;
    f.n = static_cast<std::size_t>(total);
    setStandardErrors(f);
    return f;
}

}  // namespace simp::stats
