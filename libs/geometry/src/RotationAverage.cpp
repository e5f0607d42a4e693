#include <simp/geometry/RotationAverage.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <stdexcept>
#include <string>

namespace simp::geometry {

Eigen::Matrix3d averageRotations(const std::vector<Eigen::Matrix3d>& Rs, const std::vector<double>& weights) {
    const std::string where = "simp::geometry::averageRotations: ";
    if (Rs.empty()) throw std::invalid_argument(where + "no rotations to average");
    if (Rs.size() != weights.size())
        throw std::invalid_argument(where + std::to_string(Rs.size()) + " rotations but " +
                                    std::to_string(weights.size()) + " weights");
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    double total = 0.0;
    for (std::size_t i = 0; i < Rs.size(); ++i) {
        if (!std::isfinite(weights[i]) || weights[i] < 0.0)
            throw std::invalid_argument(where + "weight " + std::to_string(i) + " = " + std::to_string(weights[i]) +
                                        " is not a finite number >= 0");
        if (!Rs[i].allFinite()) throw std::invalid_argument(where + "rotation " + std::to_string(i) + " is not finite");
        sum += weights[i] * Rs[i];
        total += weights[i];
    }
    if (!(total > 0.0)) throw std::invalid_argument(where + "the weights sum to 0");
    // Moakher 2002: the projection of the arithmetic mean onto SO(3).
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum / total, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Matrix3d& U = svd.matrixU();
    const Eigen::Matrix3d& V = svd.matrixV();
    Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
    D(2, 2) = (U * V.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    return U * D * V.transpose();
}

}  // namespace simp::geometry
