#include <simp/world/SimpPixels.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace simp::world {

Eigen::Vector2d SimpPixelFrame::toPixel(const Eigen::Vector2d& xy) const {
    return {(xy.x() - origin_x_m) / resolution_m, rows - (xy.y() - origin_y_m) / resolution_m};
}

Eigen::Vector2i SimpPixelFrame::toPixelRounded(const Eigen::Vector2d& xy) const {
    // std::nearbyint in the default rounding mode rounds half to even, as numpy.round does.
    const double u = std::nearbyint((xy.x() - origin_x_m) / resolution_m);
    const double v = rows - std::nearbyint((xy.y() - origin_y_m) / resolution_m);
    return {static_cast<int>(u), static_cast<int>(v)};
}

Eigen::Vector2d SimpPixelFrame::toWorld(const Eigen::Vector2d& uv) const {
    return {origin_x_m + uv.x() * resolution_m, origin_y_m + (rows - uv.y()) * resolution_m};
}

RectangleFit fitRectangle(const std::array<Eigen::Vector2d, 4>& c) {
    for (const auto& p : c)
        if (!p.allFinite()) throw std::invalid_argument("fitRectangle: non-finite corner");
    RectangleFit f;
    f.center_m = 0.25 * (c[0] + c[1] + c[2] + c[3]);
    // Direction modulo 90 deg: edges of a rectangle have angles phi, phi + 90, ... which all
    // coincide after multiplying by 4; average those unit vectors weighted by edge length.
    double s = 0, co = 0;
    for (int k = 0; k < 4; ++k) {
        const Eigen::Vector2d e = c[static_cast<std::size_t>((k + 1) % 4)] - c[static_cast<std::size_t>(k)];
        const double len = e.norm();
        const double phi = std::atan2(e.y(), e.x());
        s += len * std::sin(4 * phi);
        co += len * std::cos(4 * phi);
    }
    f.yaw_rad = std::atan2(s, co) / 4;  // (-pi/4, pi/4]
    const Eigen::Vector2d ax(std::cos(f.yaw_rad), std::sin(f.yaw_rad));
    const Eigen::Vector2d ay(-ax.y(), ax.x());
    double hx = 0, hy = 0;
    for (const auto& p : c) {
        hx += std::abs((p - f.center_m).dot(ax));
        hy += std::abs((p - f.center_m).dot(ay));
    }
    f.length_x_m = 2 * hx / 4;
    f.length_y_m = 2 * hy / 4;
    const double longer = std::max(f.length_x_m, f.length_y_m);
    if (!std::isfinite(longer) || !(std::min(f.length_x_m, f.length_y_m) > 1e-9 * longer))
        throw std::invalid_argument("fitRectangle: degenerate rectangle (a side has zero length)");
    return f;
}

}  // namespace simp::world
