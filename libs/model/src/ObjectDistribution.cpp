#include <simp/model/ObjectDistribution.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace simp::model {

ObjectDistribution makeObjectDistribution(const geometry::Box3D& box_world, const NoiseModel& noise,
                                          NoiseSource source) {
    if (!noise.mean_m.allFinite() || !noise.cov_m2.allFinite() || !std::isfinite(noise.exponent_b) ||
        noise.exponent_b <= 0.0)
        throw std::invalid_argument("noise model: mean, covariance and exponent b must be finite, b > 0");
    const Eigen::Matrix2d sym = 0.5 * (noise.cov_m2 + noise.cov_m2.transpose());
    if (sym.determinant() <= 0.0 || sym(0, 0) <= 0.0)
        throw std::invalid_argument("noise model: covariance is not positive definite");

    // Eq. shiftdist: R_o = rotation into the object's noise frame, c_o = box centre on the ground.
    const double yaw = noiseFrameYaw(box_world, source);
    Eigen::Matrix2d R_o;
    R_o << std::cos(yaw), -std::sin(yaw), std::sin(yaw), std::cos(yaw);
    const Eigen::Matrix2d cov_world = R_o * sym * R_o.transpose();
    const Eigen::Matrix2d inv = cov_world.inverse();

    ObjectDistribution d;
    d.mean_world_m = R_o * noise.mean_m + box_world.center.head<2>();
    d.inv_xx = inv(0, 0);
    d.inv_xy = 0.5 * (inv(0, 1) + inv(1, 0));
    d.inv_yy = inv(1, 1);
    d.half_b = 0.5 * noise.exponent_b;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov_world);
    d.sigma_min_m = std::sqrt(std::max(eig.eigenvalues()(0), 0.0));
    d.sigma_max_m = std::sqrt(std::max(eig.eigenvalues()(1), 0.0));
    d.sigma_x_m = std::sqrt(cov_world(0, 0));
    d.sigma_y_m = std::sqrt(cov_world(1, 1));
    return d;
}

double supportMahalanobisRadius(double exponent_b, double p_min) {
    if (!(p_min > 0.0 && p_min < 1.0)) throw std::invalid_argument("support probability must be in (0, 1)");
    return std::pow(2.0 * std::log(1.0 / p_min), 1.0 / exponent_b);
}

double maxSlopeMahalanobis(double exponent_b) {
    // f(m) = exp(-0.5 m^b), f'(m) = -0.5 b m^(b-1) exp(-0.5 m^b); |f'| peaks at m^b = 2 (b-1) / b.
    if (exponent_b < 1.0) return std::numeric_limits<double>::infinity();  // cusp at m = 0
    if (exponent_b == 1.0) return 0.5;                                     // slope largest at m -> 0
    const double mb = 2.0 * (exponent_b - 1.0) / exponent_b;
    const double m = std::pow(mb, 1.0 / exponent_b);
    return 0.5 * exponent_b * std::pow(m, exponent_b - 1.0) * std::exp(-0.5 * mb);
}

}  // namespace simp::model
