#include <simp/camera/FloorPlanThresholds.h>
#include <simp/lidar/ScanPoints.h>

#include <mrpt/poses/CPose2D.h>

#include <cmath>

namespace simp::lidar {

mrpt::maps::CSimplePointsMap scanToPoints(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t decimation,
                                          double min_range_m, double max_range_m) {
    mrpt::maps::CSimplePointsMap pts;
    const std::size_t n = scan.getScanSize();
    if (n < 2) return pts;
    const mrpt::poses::CPose2D sensor(scan.sensorPose.x(), scan.sensorPose.y(), scan.sensorPose.yaw());
    const double step = scan.aperture / static_cast<double>(n - 1);
    for (std::size_t i = 0; i < n; i += std::max<std::size_t>(1, decimation)) {
        if (!scan.getScanRangeValidity(i)) continue;
        const double r = scan.getScanRange(i);
        if (!(r > 0) || r < min_range_m || r > max_range_m) continue;
        const double a = (scan.rightToLeft ? 1.0 : -1.0) * (-0.5 * scan.aperture + step * static_cast<double>(i));
        double gx = 0, gy = 0;
        sensor.composePoint(r * std::cos(a), r * std::sin(a), gx, gy);
        pts.insertPoint(static_cast<float>(gx), static_cast<float>(gy), 0.0f);
    }
    return pts;
}

mrpt::maps::CSimplePointsMap wallSurfacePoints(const mrpt::maps::COccupancyGridMap2D& grid) {
    mrpt::maps::CSimplePointsMap pts;
    const int nx = static_cast<int>(grid.getSizeX()), ny = static_cast<int>(grid.getSizeY());
    const auto is_free = [&](int cx, int cy) {
        return cx >= 0 && cy >= 0 && cx < nx && cy < ny && grid.getCell(cx, cy) > camera::floorplan::kUnknownFree;
    };
    for (int cy = 0; cy < ny; ++cy)
        for (int cx = 0; cx < nx; ++cx) {
            if (!(grid.getCell(cx, cy) < camera::floorplan::kUnknownFree)) continue;
            if (is_free(cx - 1, cy) || is_free(cx + 1, cy) || is_free(cx, cy - 1) || is_free(cx, cy + 1))
                pts.insertPoint(grid.idx2x(static_cast<std::size_t>(cx)), grid.idx2y(static_cast<std::size_t>(cy)), 0.0f);
        }
    return pts;
}

}  // namespace simp::lidar
