#include <simp/geometry/Box3D.h>

#include <cmath>

namespace simp::geometry {

std::array<Eigen::Vector3d, 8> Box3D::corners() const {
    std::array<Eigen::Vector3d, 8> out;
    const Eigen::Vector3d half = 0.5 * size;
    for (int i = 0; i < 8; ++i) {
        const Eigen::Vector3d signs((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
        out[i] = center + R * signs.cwiseProduct(half);
    }
    return out;
}

Box3D Box3D::transformed(const Eigen::Isometry3d& T) const {
    Box3D b;
    b.center = T * center;
    b.size = size;
    b.R = T.linear() * R;
    return b;
}

bool Box3D::isValid(double rotation_tolerance) const {
    if (!center.allFinite() || !size.allFinite() || !R.allFinite()) return false;
    if ((size.array() <= 0.0).any()) return false;
    const double orthogonality = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    return orthogonality <= rotation_tolerance && std::abs(R.determinant() - 1.0) <= rotation_tolerance;
}

Box3D makeUprightBox(const Eigen::Vector3d& center, const Eigen::Vector3d& size_xyz, double yaw_rad) {
    Box3D b;
    b.center = center;
    b.size = size_xyz;
    b.R = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return b;
}

Box3D canonicalizeUpright(const Box3D& box) {
    // Pick the local axis most aligned with the frame's vertical as the new z.
    int up_axis = 0;
    double best = -1.0;
    for (int k = 0; k < 3; ++k) {
        const double a = std::abs(box.R(2, k));
        if (a > best) { best = a; up_axis = k; }
    }
    const int x_axis = (up_axis + 1) % 3;
    const int y_axis = (up_axis + 2) % 3;  // cyclic order keeps right-handedness
    Box3D out;
    out.center = box.center;
    Eigen::Vector3d ez = box.R.col(up_axis);
    Eigen::Vector3d ex = box.R.col(x_axis);
    Eigen::Vector3d ey = box.R.col(y_axis);
    if (ez.z() < 0) {  // flip z and y together: still a rotation
        ez = -ez;
        ey = -ey;
    }
    out.R.col(0) = ex;
    out.R.col(1) = ey;
    out.R.col(2) = ez;
    out.size = Eigen::Vector3d(box.size[x_axis], box.size[y_axis], box.size[up_axis]);
    return out;
}

bool containsPoint(const Box3D& box, const Eigen::Vector3d& p) {
    const Eigen::Vector3d local = box.R.transpose() * (p - box.center);
    return (local.cwiseAbs().array() <= 0.5 * box.size.array()).all();
}

double yawOf(const Box3D& box) { return std::atan2(box.R(1, 0), box.R(0, 0)); }

}  // namespace simp::geometry
