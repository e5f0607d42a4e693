#include <simp/geometry/Footprint.h>

namespace simp::geometry {

ConvexPolygon footprint(const Box3D& box_in_frame) {
    const auto corners = box_in_frame.corners();
    std::array<Eigen::Vector2d, 8> xy;
    for (int i = 0; i < 8; ++i) xy[i] = corners[i].head<2>();
    return convexHull(xy.data(), xy.size());
}

}  // namespace simp::geometry
