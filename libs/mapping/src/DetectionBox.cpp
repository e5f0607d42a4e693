#include <simp/mapping/DetectionBox.h>

namespace simp::mapping {

geometry::Box3D objectBoxFromDetection(const geometry::Box3D& b) {
    geometry::Box3D out;
    out.center = b.center;
    // (x, z, -y) of a right-handed frame is right-handed: x cross z = -y
    out.R.col(0) = b.R.col(0);
    out.R.col(1) = b.R.col(2);
    out.R.col(2) = -b.R.col(1);
    out.size = Eigen::Vector3d(b.size.x(), b.size.z(), b.size.y());
    return geometry::canonicalizeUpright(out);
}

}  // namespace simp::mapping
