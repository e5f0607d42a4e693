#include <simp/geometry/Footprint.h>
#include <simp/maps/MapFootprints.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace simp::maps {

MapFootprints computeMapFootprints(const world::ObjectMapData& data) {
    MapFootprints out;
    out.objects.resize(data.objects.size());
    out.class_objects.resize(data.class_names.size());
    for (std::size_t i = 0; i < data.objects.size(); ++i) {
        const auto& obj = data.objects[i];
        if (obj.class_id < 0 || static_cast<std::size_t>(obj.class_id) >= data.class_names.size())
            throw std::invalid_argument("object map: object #" + std::to_string(i) + " (id " + std::to_string(obj.id) +
                                        ") has class id " + std::to_string(obj.class_id) + " outside the class list");
        ObjectFootprint& f = out.objects[i];
        f.polygon = geometry::footprint(obj.box);
        f.circle_center_m = obj.box.center.head<2>();
        for (std::size_t v = 0; v < f.polygon.n; ++v)
            f.circle_radius_m = std::max(f.circle_radius_m, (f.polygon.v[v] - f.circle_center_m).norm());
        f.area_m2 = f.polygon.area();
        if (const auto r = geometry::asRectangle(f.polygon)) {
            f.is_rect = true;
            f.rect = *r;
        }
        out.class_objects[static_cast<std::size_t>(obj.class_id)].push_back(static_cast<std::int32_t>(i));
    }
    return out;
}

double iouWithAreas(const geometry::ConvexPolygon& a, double area_a, const geometry::ConvexPolygon& b, double area_b) {
    if (area_a <= 0.0 || area_b <= 0.0) return 0.0;
    return iouFromIntersection(geometry::intersectionArea(a, b), area_a, area_b);
}

}  // namespace simp::maps
