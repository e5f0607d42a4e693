#pragma once
/// \file GridGeometry.h
/// Geometry of a 2D raster in the world frame: origin, resolution, size, cell lookup.

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace simp::maps {

/// A regular grid over the world xy plane. Cell (ix, iy) covers
/// [x0 + ix*res, x0 + (ix+1)*res) x [y0 + iy*res, y0 + (iy+1)*res); row-major, iy outer.
struct GridGeometry {
    double x0_m = 0, y0_m = 0;     ///< world coordinates of the lower-left corner of cell (0, 0) (m)
    double resolution_m = 0.05;    ///< cell side (m)
    double inv_resolution = 20.0;  ///< 1 / resolution_m (1/m), cached for lookups
    std::int32_t nx = 0, ny = 0;   ///< cells along x and y

    /// Grid covering [x_min, x_max] x [y_min, y_max] (m) at `resolution_m`.
    static GridGeometry covering(double x_min, double y_min, double x_max, double y_max, double resolution_m) {
        GridGeometry g;
        g.resolution_m = resolution_m;
        g.inv_resolution = 1.0 / resolution_m;
        g.x0_m = x_min;
        g.y0_m = y_min;
        g.nx = static_cast<std::int32_t>(std::ceil((x_max - x_min) * g.inv_resolution)) + 1;
        g.ny = static_cast<std::int32_t>(std::ceil((y_max - y_min) * g.inv_resolution)) + 1;
        return g;
    }

    std::size_t cellCount() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
    bool empty() const { return nx <= 0 || ny <= 0; }

    /// Linear index of the cell holding world point (x, y) (m), or -1 outside the grid.
    /// NaN coordinates fall outside.
    std::int64_t cellIndex(double x_m, double y_m) const {
        const double fx = (x_m - x0_m) * inv_resolution;
        const double fy = (y_m - y0_m) * inv_resolution;
        if (!(fx >= 0.0 && fy >= 0.0 && fx < nx && fy < ny)) return -1;
        return static_cast<std::int64_t>(static_cast<std::int32_t>(fy)) * nx + static_cast<std::int32_t>(fx);
    }

    /// World coordinates (m) of the centre of cell (ix, iy).
    double cellCenterX(std::int32_t ix) const { return x0_m + (ix + 0.5) * resolution_m; }
    double cellCenterY(std::int32_t iy) const { return y0_m + (iy + 0.5) * resolution_m; }
};

}  // namespace simp::maps
