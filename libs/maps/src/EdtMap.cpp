#include <simp/maps/EdtMap.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace simp::maps {

EdtMap::EdtMap(const MapFootprints& footprints, double resolution_m, double max_distance_m)
    : m_max_distance_m(max_distance_m) {
    if (!(resolution_m > 0.0) || !(max_distance_m > 0.0))
        throw std::invalid_argument("EDT map: resolution and max distance must be > 0 m");
    m_classes.resize(footprints.class_objects.size());
    for (std::size_t c = 0; c < m_classes.size(); ++c) {
        const auto& objects = footprints.class_objects[c];
        if (objects.empty()) continue;
        Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
        for (const auto o : objects) {
            Eigen::Vector2d a, b;
            footprints.objects[static_cast<std::size_t>(o)].polygon.bounds(a, b);
            lo = lo.cwiseMin(a);
            hi = hi.cwiseMax(b);
        }
        ClassEdt& e = m_classes[c];
        e.grid = GridGeometry::covering(lo.x() - max_distance_m, lo.y() - max_distance_m, hi.x() + max_distance_m,
                                        hi.y() + max_distance_m, resolution_m);
        // 255 = free, 0 = object; row = iy, column = ix; OpenCV pixel centres are integer.
        cv::Mat1b free(e.grid.ny, e.grid.nx, static_cast<unsigned char>(255));
        constexpr int kShift = 8;  // sub-pixel precision of the polygon vertices
        for (const auto o : objects) {
            const auto& poly = footprints.objects[static_cast<std::size_t>(o)].polygon;
            std::vector<cv::Point> pts;
            for (std::size_t v = 0; v < poly.n; ++v) {
                const double u = (poly.v[v].x() - e.grid.x0_m) * e.grid.inv_resolution - 0.5;
                const double w = (poly.v[v].y() - e.grid.y0_m) * e.grid.inv_resolution - 0.5;
                pts.emplace_back(static_cast<int>(std::lround(u * (1 << kShift))),
                                 static_cast<int>(std::lround(w * (1 << kShift))));
            }
            if (pts.size() >= 3) cv::fillConvexPoly(free, pts, cv::Scalar(0), cv::LINE_8, kShift);
            // A footprint smaller than a cell still marks the cell holding its centre.
            const auto cell = e.grid.cellIndex(footprints.objects[static_cast<std::size_t>(o)].circle_center_m.x(),
                                               footprints.objects[static_cast<std::size_t>(o)].circle_center_m.y());
            if (cell >= 0) free(static_cast<int>(cell / e.grid.nx), static_cast<int>(cell % e.grid.nx)) = 0;
        }
        cv::Mat1f dist;
        cv::distanceTransform(free, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
        e.distance_m.resize(e.grid.cellCount());
        for (int iy = 0; iy < e.grid.ny; ++iy)
            for (int ix = 0; ix < e.grid.nx; ++ix)
                e.distance_m[static_cast<std::size_t>(iy) * static_cast<std::size_t>(e.grid.nx) + static_cast<std::size_t>(ix)] =
                    std::min(static_cast<float>(max_distance_m),
                             static_cast<float>(dist(iy, ix) * resolution_m));
    }
}

}  // namespace simp::maps
