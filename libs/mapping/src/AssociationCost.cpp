#include <simp/geometry/Box3DIoU.h>
#include <simp/geometry/RotationAverage.h>
#include <simp/mapping/AssociationCost.h>

#include <algorithm>
#include <cmath>

namespace simp::mapping {

double associationCost(const geometry::Box3D& o1, const model::ObjectDistribution& p_o1, const geometry::Box3D& o2) {
    // Eq. costfunc
    const double c_iou = 1.0 - geometry::iou3D(o1, o2);
    const double c_cen = 1.0 - p_o1.probability(o2.center.x(), o2.center.y());
    return 0.5 * (c_iou + c_cen);
}

geometry::Box3D closestEquivalent(const geometry::Box3D& box, const Eigen::Matrix3d& reference) {
    geometry::Box3D best = box;
    double best_dist = (box.R - reference).squaredNorm();
    Eigen::Matrix3d Rz90;  // rotation by +90 deg about local z
    Rz90 << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    Eigen::Matrix3d R = box.R;
    for (int k = 1; k < 4; ++k) {
        R = R * Rz90;
        const double dist = (R - reference).squaredNorm();
        if (dist < best_dist) {
            best_dist = dist;
            best.R = R;
            best.size = box.size;
            if (k % 2 == 1) std::swap(best.size.x(), best.size.y());
        }
    }
    return best;
}

geometry::Box3D mergeBoxes(const geometry::Box3D& object, double n_o2, const geometry::Box3D& prediction, double n_o1) {
    const geometry::Box3D aligned = closestEquivalent(prediction, object.R);
    const double n = n_o1 + n_o2;
    geometry::Box3D out;
    out.center = (n_o2 * object.center + n_o1 * aligned.center) / n;  // weighted centre
    out.size = (n_o2 * object.size + n_o1 * aligned.size) / n;        // weighted dimensions
    out.R = geometry::averageRotations({object.R, aligned.R}, {n_o2, n_o1});  // U V^T of the SVD
    return out;
}

}  // namespace simp::mapping
