#include <simp/sim/CoverageGoals.h>
#include <simp/sim/PathPlanner.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace simp::sim {

int goalAreaAt(const Raster& cspace, const world::RoomMap& rooms, int cx, int cy) {
    if (!rooms.empty()) return rooms.roomAt(cspace.centreX(cx), cspace.centreY(cy));
    const int block = std::max(1, static_cast<int>(5.0 / cspace.resolution_m));
    return 1 + (cy / block) * (cspace.nx / block + 1) + cx / block;
}

std::vector<Eigen::Vector2d> addReachGoals(const Raster& cspace, const world::RoomMap& rooms,
                                           std::vector<Eigen::Vector2d> goals, double reach_m,
                                           double min_gain_m2, double sample_m) {
    if (!(reach_m > 0) || !(sample_m > 0) || !(min_gain_m2 > 0))
        throw std::invalid_argument("addReachGoals: reach, sample and minimum gain must be > 0");
    const auto dist = clearance(cspace);
    const auto reachable = largestFreeArea(cspace, dist);
    const int step = std::max(1, static_cast<int>(std::lround(sample_m / cspace.resolution_m)));
    const double cell_area_m2 = std::pow(step * cspace.resolution_m, 2);

    struct Area {
        std::vector<Eigen::Vector2i> targets;     // sampled cells of the room (free or not)
        std::vector<Eigen::Vector2i> candidates;  // sampled cells a goal can be put on
        std::vector<Eigen::Vector2d> goals;       // goals already there
    };
    std::map<int, Area> areas;
    for (int cy = step / 2; cy < cspace.ny; cy += step)
        for (int cx = step / 2; cx < cspace.nx; cx += step) {
            const int id = goalAreaAt(cspace, rooms, cx, cy);
            if (id <= 0) continue;
            Area& a = areas[id];
            a.targets.emplace_back(cx, cy);
            const std::size_t i = static_cast<std::size_t>(cy) * cspace.nx + cx;
            if (dist[i] > 0 && reachable[i]) a.candidates.emplace_back(cx, cy);
        }
    for (const auto& g : goals) {
        const int cx = cspace.cellX(g.x()), cy = cspace.cellY(g.y());
        if (cspace.inside(cx, cy))
            if (auto it = areas.find(goalAreaAt(cspace, rooms, cx, cy)); it != areas.end()) it->second.goals.push_back(g);
    }
    const double reach2 = reach_m * reach_m;
    // Within reach: close enough, on a straight line that never leaves the room (walls, other rooms).
    const auto inReach = [&](int id, const Eigen::Vector2i& from, const Eigen::Vector2i& to) {
        const Eigen::Vector2d d = (to - from).cast<double>() * cspace.resolution_m;
        if (d.squaredNorm() > reach2) return false;
        const int n = std::max(std::abs(to.x() - from.x()), std::abs(to.y() - from.y()));
        for (int k = 1; k < n; ++k) {
            const int cx = from.x() + static_cast<int>(std::lround(static_cast<double>(to.x() - from.x()) * k / n));
            const int cy = from.y() + static_cast<int>(std::lround(static_cast<double>(to.y() - from.y()) * k / n));
            if (goalAreaAt(cspace, rooms, cx, cy) != id) return false;
        }
        return true;
    };
    for (auto& [id, a] : areas) {
        // which targets each candidate reaches, once
        std::vector<std::vector<std::uint32_t>> reaches(a.candidates.size());
        for (std::size_t c = 0; c < a.candidates.size(); ++c)
            for (std::uint32_t t = 0; t < a.targets.size(); ++t)
                if (inReach(id, a.candidates[c], a.targets[t])) reaches[c].push_back(t);
        std::vector<std::uint8_t> covered(a.targets.size(), 0);
        for (const auto& g : a.goals) {
            const Eigen::Vector2i gc(cspace.cellX(g.x()), cspace.cellY(g.y()));
            for (std::size_t t = 0; t < a.targets.size(); ++t)
                if (!covered[t] && inReach(id, gc, a.targets[t])) covered[t] = 1;
        }
        for (;;) {
            std::size_t best = 0, best_gain = 0;
            for (std::size_t c = 0; c < a.candidates.size(); ++c) {
                std::size_t gain = 0;
                for (const auto t : reaches[c]) gain += covered[t] == 0;
                if (gain > best_gain) best = c, best_gain = gain;  // ties: the first in raster order
            }
            if (best_gain == 0 || static_cast<double>(best_gain) * cell_area_m2 < min_gain_m2) break;
            for (const auto t : reaches[best]) covered[t] = 1;
            goals.emplace_back(cspace.centreX(a.candidates[best].x()), cspace.centreY(a.candidates[best].y()));
        }
    }
    return goals;
}

std::vector<std::size_t> coverageTour(const Raster& cspace, const std::vector<Eigen::Vector2d>& goals,
                                      std::size_t start) {
    const std::size_t n = goals.size();
    if (start >= n) throw std::invalid_argument("coverageTour: start index beyond the goals");
    // driving distances between all goals
    std::vector<std::vector<double>> d(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) {
        const auto field = drivingDistances(cspace, goals[i]);
        for (std::size_t j = 0; j < n; ++j) {
            const int cx = cspace.cellX(goals[j].x()), cy = cspace.cellY(goals[j].y());
            d[i][j] = cspace.inside(cx, cy) ? field[static_cast<std::size_t>(cy) * cspace.nx + cx]
                                            : std::numeric_limits<double>::infinity();
        }
    }
    std::vector<std::size_t> tour{start}, unconnected;
    std::vector<std::uint8_t> used(n, 0);
    used[start] = 1;
    for (std::size_t j = 0; j < n; ++j)
        if (!used[j] && !std::isfinite(d[start][j])) used[j] = 1, unconnected.push_back(j);
    while (tour.size() + unconnected.size() < n) {  // nearest neighbour; ties: the lowest index
        std::size_t best = n;
        for (std::size_t j = 0; j < n; ++j)
            if (!used[j] && (best == n || d[tour.back()][j] < d[tour.back()][best])) best = j;
        used[best] = 1;
        tour.push_back(best);
    }
    // 2-opt on the closed tour: reverse tour[i..k] while that shortens it (the start stays first);
    // distances are symmetric up to rounding, so the reversed stretch keeps its length
    const std::size_t m = tour.size();
    const auto at = [&](std::size_t i) { return tour[i % m]; };
    for (bool improved = m > 3; improved;) {
        improved = false;
        for (std::size_t i = 1; i + 1 < m; ++i)
            for (std::size_t k = i + 1; k < m; ++k) {
                const double before = d[at(i - 1)][at(i)] + d[at(k)][at(k + 1)];
                const double after = d[at(i - 1)][at(k)] + d[at(i)][at(k + 1)];
                if (after < before - 1e-6) {
                    std::reverse(tour.begin() + static_cast<std::ptrdiff_t>(i), tour.begin() + static_cast<std::ptrdiff_t>(k) + 1);
                    improved = true;
                }
            }
    }
    tour.insert(tour.end(), unconnected.begin(), unconnected.end());
    return tour;
}

}  // namespace simp::sim
