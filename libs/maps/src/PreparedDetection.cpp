#include <simp/maps/PreparedDetection.h>

#include <algorithm>

namespace simp::maps {

PreparedDetection prepareDetection(int map_class, const geometry::Box3D& box_in_robot,
                                   const geometry::ConvexPolygon& footprint_in_robot, double noise_reference_range_m,
                                   double weight) {
    PreparedDetection d;
    d.map_class = map_class;
    d.center_robot_m = box_in_robot.center.head<2>();
    d.footprint_robot = footprint_in_robot;
    d.area_m2 = footprint_in_robot.area();
    d.offsets_robot.n = footprint_in_robot.n;
    for (std::size_t v = 0; v < footprint_in_robot.n; ++v) {
        d.offsets_robot.v[v] = footprint_in_robot.v[v] - d.center_robot_m;
        d.radius_m = std::max(d.radius_m, d.offsets_robot.v[v].norm());
    }
    if (const auto r = geometry::asRectangle(footprint_in_robot)) {
        d.is_rect = true;
        d.rect_robot = *r;
    }
    if (noise_reference_range_m > 0.0) {
        const double s = std::max(1.0, d.center_robot_m.norm() / noise_reference_range_m);
        d.noise_inv_scale2 = 1.0 / (s * s);
    }
    d.weight = weight;
    return d;
}

}  // namespace simp::maps
