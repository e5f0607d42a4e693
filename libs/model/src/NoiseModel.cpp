#include <simp/model/NoiseModel.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace simp::model {

bool NoiseModel::isValid() const {
    if (!mean_m.allFinite() || !cov_m2.allFinite() || !std::isfinite(exponent_b)) return false;
    if (exponent_b <= 0.0) return false;
    // Symmetric up to rounding of the numbers that were written out.
    const double scale = cov_m2.cwiseAbs().maxCoeff();
    if (std::abs(cov_m2(0, 1) - cov_m2(1, 0)) > 1e-12 * (1.0 + scale)) return false;
    // Positive definite (Sylvester): both leading minors > 0.
    return cov_m2(0, 0) > 0.0 && cov_m2(0, 0) * cov_m2(1, 1) - cov_m2(0, 1) * cov_m2(1, 0) > 0.0;
}

Eigen::Matrix2d offsetCovariance(const NoiseModel& model) {
    const double b = model.exponent_b;
    const double e_r2 = std::pow(2.0, 2.0 / b) * std::tgamma(4.0 / b) / std::tgamma(2.0 / b);
    return model.cov_m2 * (e_r2 / 2.0);
}

NoiseModel withoutFootprint(const NoiseModel& model, const geometry::Box3D& box, NoiseSource source,
                            double min_std_fraction) {
    // The footprint's covariance (uniform box, box frame) expressed in the model's frame.
    const Eigen::Rotation2Dd R(geometry::yawOf(box) - noiseFrameYaw(box, source));
    const Eigen::Vector2d side = box.size.head<2>();
    const Eigen::Matrix2d extent =
        R.toRotationMatrix() * (side.cwiseProduct(side) / 12.0).asDiagonal() * R.toRotationMatrix().transpose();
    const Eigen::Matrix2d spread = offsetCovariance(model);
    Eigen::Vector2d scale;
    for (int i = 0; i < 2; ++i) {
        const double floor2 = min_std_fraction * min_std_fraction * spread(i, i);
        scale[i] = std::sqrt(std::max(spread(i, i) - extent(i, i), floor2) / spread(i, i));
    }
    NoiseModel out = model;
    out.cov_m2 = scale.asDiagonal() * model.cov_m2 * scale.asDiagonal();
    return out;
}

}  // namespace simp::model
