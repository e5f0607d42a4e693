/// \file Omni3DBox.cpp
#include <simp/detector_io/Omni3DBox.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <stdexcept>

namespace simp::detector_io {

geometry::Box3D boxFromOmni3D(const Eigen::Vector3d& center_cam, const Eigen::Vector3d& d, const Eigen::Matrix3d& R) {
    geometry::Box3D b;
    b.center = center_cam;
    b.size = Eigen::Vector3d(d.z(), d.y(), d.x());
    b.R = R;
    return b;
}

Eigen::Vector3d omni3DDimensions(const geometry::Box3D& box) { return {box.size.z(), box.size.y(), box.size.x()}; }

std::array<Eigen::Vector3d, 8> omni3DCorners(const geometry::Box3D& box) {
    const auto c = box.corners();
    std::array<Eigen::Vector3d, 8> out;
    for (std::size_t i = 0; i < 8; ++i) out[i] = c[static_cast<std::size_t>(kOmni3DCornerToBox3D[i])];
    return out;
}

geometry::Box3D boxFromOmni3DCorners(const std::array<Eigen::Vector3d, 8>& v) {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    for (const auto& p : v) center += p / 8.0;
    const Eigen::Vector3d ax = (v[1] - v[0] + v[2] - v[3] + v[5] - v[4] + v[6] - v[7]) / 4.0;
    const Eigen::Vector3d ay = (v[3] - v[0] + v[2] - v[1] + v[7] - v[4] + v[6] - v[5]) / 4.0;
    const Eigen::Vector3d az = (v[4] - v[0] + v[5] - v[1] + v[6] - v[2] + v[7] - v[3]) / 4.0;
    Eigen::Matrix3d A;
    A << ax, ay, az;
    if (!A.allFinite() || ax.norm() <= 0 || ay.norm() <= 0 || az.norm() <= 0 || A.determinant() <= 0)
        throw std::invalid_argument("box from 8 corners: degenerate or mirrored corners (expected Omni3D order v0..v7)");
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
    geometry::Box3D b;
    b.R = svd.matrixU() * svd.matrixV().transpose();  // closest rotation to the column directions
    b.center = center;
    for (int k = 0; k < 3; ++k) {
        double lo = 0, hi = 0;
        for (const auto& p : v) {
            const double s = b.R.col(k).dot(p - center);
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
        b.size(k) = hi - lo;
    }
    return b;
}

}  // namespace simp::detector_io
