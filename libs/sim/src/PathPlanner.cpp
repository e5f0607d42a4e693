#include <simp/sim/PathPlanner.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace simp::sim {
namespace {

/// The 8-connected moves from free cell (cx, cy): f(nx, ny, length in cells) for every free
/// neighbour; a diagonal move needs both cells it cuts the corner of free.
template <typename F>
void forEachMove(const Raster& cspace, int cx, int cy, F&& f) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            const int nx = cx + dx, ny = cy + dy;
            if (cspace.isBlocked(nx, ny)) continue;
            if (dx != 0 && dy != 0 && (cspace.isBlocked(cx + dx, cy) || cspace.isBlocked(cx, cy + dy))) continue;
            f(nx, ny, static_cast<float>((dx != 0 && dy != 0) ? std::sqrt(2.0) : 1.0));
        }
}

}  // namespace

std::optional<std::vector<Eigen::Vector2d>> planPath(const Raster& cspace, const Eigen::Vector2d& from,
                                                     const Eigen::Vector2d& to) {
    const int sx = cspace.cellX(from.x()), sy = cspace.cellY(from.y());
    const int gx = cspace.cellX(to.x()), gy = cspace.cellY(to.y());
    if (cspace.isBlocked(sx, sy) || cspace.isBlocked(gx, gy)) return std::nullopt;
    const std::size_t n = static_cast<std::size_t>(cspace.nx) * cspace.ny;
    const auto idx = [&](int cx, int cy) { return static_cast<std::size_t>(cy) * cspace.nx + cx; };
    std::vector<float> g(n, std::numeric_limits<float>::infinity());
    std::vector<std::int64_t> parent(n, -1);
    std::vector<std::uint8_t> closed(n, 0);
    using Entry = std::pair<float, std::size_t>;  // (f, cell); ties broken by cell index -> deterministic
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    const auto h = [&](int cx, int cy) {
        const double dx = std::abs(cx - gx), dy = std::abs(cy - gy);
        return static_cast<float>(std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy));
    };
    g[idx(sx, sy)] = 0;
    open.push({h(sx, sy), idx(sx, sy)});
    const std::size_t goal = idx(gx, gy);
    while (!open.empty()) {
        const std::size_t c = open.top().second;
        open.pop();
        if (closed[c]) continue;
        closed[c] = 1;
        if (c == goal) break;
        forEachMove(cspace, static_cast<int>(c % cspace.nx), static_cast<int>(c / cspace.nx), [&](int nx, int ny, float step) {
            const std::size_t k = idx(nx, ny);
            const float ng = g[c] + step;
            if (ng < g[k]) {
                g[k] = ng;
                parent[k] = static_cast<std::int64_t>(c);
                open.push({ng + h(nx, ny), k});
            }
        });
    }
    if (!closed[goal]) return std::nullopt;
    std::vector<Eigen::Vector2d> path;
    for (std::int64_t c = static_cast<std::int64_t>(goal); c >= 0; c = parent[static_cast<std::size_t>(c)]) {
        const int cx = static_cast<int>(c % cspace.nx), cy = static_cast<int>(c / cspace.nx);
        path.emplace_back(cspace.centreX(cx), cspace.centreY(cy));
    }
    std::reverse(path.begin(), path.end());
    return path;
}

std::vector<float> drivingDistances(const Raster& cspace, const Eigen::Vector2d& from) {
    const std::size_t n = static_cast<std::size_t>(cspace.nx) * cspace.ny;
    std::vector<float> g(n, std::numeric_limits<float>::infinity());
    const int sx = cspace.cellX(from.x()), sy = cspace.cellY(from.y());
    if (cspace.isBlocked(sx, sy)) return g;
    const auto idx = [&](int cx, int cy) { return static_cast<std::size_t>(cy) * cspace.nx + cx; };
    using Entry = std::pair<float, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    g[idx(sx, sy)] = 0;
    open.push({0.f, idx(sx, sy)});
    while (!open.empty()) {
        const auto [d, c] = open.top();
        open.pop();
        if (d > g[c]) continue;  // a stale entry
        forEachMove(cspace, static_cast<int>(c % cspace.nx), static_cast<int>(c / cspace.nx), [&](int nx, int ny, float step) {
            const std::size_t k = idx(nx, ny);
            const float ng = d + step;
            if (ng < g[k]) {
                g[k] = ng;
                open.push({ng, k});
            }
        });
    }
    for (auto& v : g) v *= static_cast<float>(cspace.resolution_m);
    return g;
}

std::vector<Eigen::Vector2d> shortcutPath(const Raster& cspace, const std::vector<Eigen::Vector2d>& path) {
    if (path.size() <= 2) return path;
    std::vector<Eigen::Vector2d> out{path.front()};
    std::size_t i = 0;
    while (i + 1 < path.size()) {
        std::size_t j = std::min(path.size() - 1, i + 400);  // at most 20 m at 0.05 m cells
        while (j > i + 1 && !lineOfSight(cspace, path[i], path[j])) --j;
        out.push_back(path[j]);
        i = j;
    }
    return out;
}

}  // namespace simp::sim
