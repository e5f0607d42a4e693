#include <mrpt/math/wrap2pi.h>
#include <simp/sim/CoverageGoals.h>
#include <simp/sim/PathPlanner.h>
#include <simp/sim/Trajectory.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace simp::sim {
namespace {

/// Nearest free cell centre of `cspace` within `radius_m` of p (p itself when free).
std::optional<Eigen::Vector2d> nearestFree(const Raster& cspace, const Eigen::Vector2d& p, double radius_m) {
    const int cx = cspace.cellX(p.x()), cy = cspace.cellY(p.y());
    if (!cspace.isBlocked(cx, cy)) return p;
    const int r = static_cast<int>(radius_m / cspace.resolution_m);
    std::optional<Eigen::Vector2d> best;
    double best_d = 1e18;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            if (cspace.isBlocked(cx + dx, cy + dy)) continue;
            const double d = dx * dx + dy * dy;
            if (d < best_d) {
                best_d = d;
                best = Eigen::Vector2d(cspace.centreX(cx + dx), cspace.centreY(cy + dy));
            }
        }
    return best;
}

/// Unicycle state and the current plan.
struct Driver {
    mrpt::math::TPose2D pose;
    std::vector<Eigen::Vector2d> waypoints;
    std::size_t next = 0;
    double speed = 0.3;
    double spin_left_rad = 0;  ///< remaining on-the-spot turn
};

}  // namespace

std::vector<Eigen::Vector2d> roomGoals(const Raster& cspace, const world::RoomMap& rooms, double part_m) {
    const auto dist = clearance(cspace);
    // Goals only where the robot can drive: the max-clearance cell of a part may lie in a pocket
    // closed off by furniture, and an unreachable goal leaves its room unvisited.
    const auto reachable = largestFreeArea(cspace, dist);
    const auto idAt = [&](int cx, int cy) { return goalAreaAt(cspace, rooms, cx, cy); };
    // Cell bounds of every room, to cut it into parts of about part_m x part_m.
    struct Bounds { int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1; };
    std::map<int, Bounds> bounds;
    if (part_m > 0)
        for (int cy = 0; cy < cspace.ny; ++cy)
            for (int cx = 0; cx < cspace.nx; ++cx)
                if (const int id = idAt(cx, cy); id > 0) {
                    Bounds& b = bounds[id];
                    b.x0 = std::min(b.x0, cx), b.x1 = std::max(b.x1, cx), b.y0 = std::min(b.y0, cy), b.y1 = std::max(b.y1, cy);
                }
    const auto partOf = [&](int id, int cx, int cy) {
        if (part_m <= 0) return 0;
        const Bounds& b = bounds.at(id);
        const auto cut = [&](int c, int c0, int c1) {
            const double len_m = (c1 - c0 + 1) * cspace.resolution_m;
            // at most 2 parts per side: a corridor is driven along anyway
            const int n = std::clamp(static_cast<int>(std::lround(len_m / part_m)), 1, 2);
            return std::min(n - 1, (c - c0) * n / (c1 - c0 + 1));
        };
        return cut(cx, b.x0, b.x1) * 1000 + cut(cy, b.y0, b.y1);
    };
    std::map<std::pair<int, int>, std::pair<float, std::size_t>> best;  // (room, part) -> (clearance, cell)
    for (int cy = 0; cy < cspace.ny; ++cy)
        for (int cx = 0; cx < cspace.nx; ++cx) {
            const std::size_t i = static_cast<std::size_t>(cy) * cspace.nx + cx;
            if (dist[i] <= 0 || !reachable[i]) continue;
            const int id = idAt(cx, cy);
            if (id <= 0) continue;
            const std::pair<int, int> key{id, partOf(id, cx, cy)};
            auto it = best.find(key);
            if (it == best.end() || dist[i] > it->second.first) best[key] = {dist[i], i};
        }
    std::vector<Eigen::Vector2d> goals;
    for (const auto& [id, b] : best) {
        const int cx = static_cast<int>(b.second % cspace.nx), cy = static_cast<int>(b.second / cspace.nx);
        goals.emplace_back(cspace.centreX(cx), cspace.centreY(cy));
    }
    return goals;
}

std::optional<mrpt::math::TPose2D> drawKidnapPose(const Raster& cspace, const Eigen::Vector2d& from_m,
                                                  double min_distance_m, double margin_m, Rng& rng) {
    const auto dist = clearance(cspace);
    // the goals' free area: from anywhere else the robot could not plan on
    const auto reachable = largestFreeArea(cspace, dist);
    std::vector<std::size_t> cells;
    for (int cy = 0; cy < cspace.ny; ++cy)
        for (int cx = 0; cx < cspace.nx; ++cx) {
            const std::size_t i = static_cast<std::size_t>(cy) * cspace.nx + cx;
            if (!reachable[i] || dist[i] <= 0 || dist[i] < margin_m) continue;
            if ((Eigen::Vector2d(cspace.centreX(cx), cspace.centreY(cy)) - from_m).norm() < min_distance_m) continue;
            cells.push_back(i);
        }
    if (cells.empty()) return std::nullopt;
    const std::size_t i = cells[rng.index(cells.size())];
    const int cx = static_cast<int>(i % static_cast<std::size_t>(cspace.nx)), cy = static_cast<int>(i / static_cast<std::size_t>(cspace.nx));
    return mrpt::math::TPose2D(cspace.centreX(cx), cspace.centreY(cy), rng.uniform(-M_PI, M_PI));
}

void checkDuration(double duration_s, const std::string& what) {
    if (!(duration_s > 0 && duration_s <= kMaxDuration_s))
        throw std::invalid_argument(what + " = " + std::to_string(duration_s) + " s must be in (0, " +
                                    std::to_string(kMaxDuration_s) + "] s");
}

std::vector<io::StampedPose2D> generateTrajectory(const Raster& obstacles, const world::RoomMap& rooms,
                                                  const TrajectoryParams& p, double t0_s, double dt_s,
                                                  double duration_s, Rng& rng, const KidnapParams& kidnap,
                                                  Rng* kidnap_rng, KidnapEvent* kidnap_event,
                                                  CoverageProgress* coverage) {
    if (!(dt_s > 0) || !(duration_s >= 0)) throw std::invalid_argument("generateTrajectory: dt must be > 0, duration >= 0");
    const bool kidnapped = kidnap.at_s >= 0;
    if (kidnapped && (!kidnap_rng || !kidnap_event))
        throw std::invalid_argument("generateTrajectory: a kidnap needs kidnap_rng and kidnap_event");
    // Checked before the cast to an integer below (a double beyond size_t is UB).
    if (duration_s > 0) checkDuration(duration_s, "generateTrajectory: duration");
    if (duration_s / dt_s >= static_cast<double>(kMaxTrajectorySteps))
        throw std::invalid_argument("generateTrajectory: duration " + std::to_string(duration_s) + " s at a step of " +
                                    std::to_string(dt_s) + " s gives more than " +
                                    std::to_string(kMaxTrajectorySteps) + " poses");
    const Raster cspace = inflate(obstacles, p.robot_radius_m + p.clearance_m);
    std::vector<Eigen::Vector2d> goals = roomGoals(cspace, rooms, p.coverage ? p.coverage_part_m : 0.0);
    if (p.coverage && p.coverage_reach_m > 0)
        goals = addReachGoals(cspace, rooms, std::move(goals), p.coverage_reach_m, p.coverage_min_gain_m2);
    if (goals.empty())
        throw std::runtime_error("generateTrajectory: no free space for a robot of radius " +
                                 std::to_string(p.robot_radius_m) + " m in the map");

    Driver d;
    const std::size_t start_goal = rng.index(goals.size());
    const Eigen::Vector2d start = goals[start_goal];
    const std::vector<std::size_t> tour =
        p.coverage && p.coverage_tour ? coverageTour(cspace, goals, start_goal) : std::vector<std::size_t>{};
    d.pose = {start.x(), start.y(), rng.uniform(-M_PI, M_PI)};
    std::vector<std::size_t> order;
    std::size_t order_pos = 0;
    std::size_t leg_goal = start_goal;  // the goal the current leg drives to
    std::vector<std::uint8_t> reached(goals.size(), 0);
    reached[start_goal] = 1;
    std::size_t n_reached = 1, step = 0;
    if (coverage) *coverage = {goals.size(), 1, goals.size() == 1 ? 0.0 : -1.0};
    const auto markReached = [&](std::size_t goal) {
        if (reached[goal]) return;
        reached[goal] = 1;
        ++n_reached;
        if (!coverage) return;
        coverage->reached = n_reached;
        if (n_reached == goals.size()) coverage->all_reached_s = static_cast<double>(step) * dt_s;
    };
    int failures = 0;

    const auto newLeg = [&]() {
        // next room goal from a shuffled visiting order; unreachable goals are skipped
        for (int attempt = 0; attempt < static_cast<int>(goals.size()) + 1; ++attempt) {
            if (order_pos >= order.size() && !tour.empty()) {
                order = tour;  // the same tour every round
                order_pos = 0;
            }
            if (order_pos >= order.size()) {
                order.resize(goals.size());
                for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
                for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.index(i)]);
                order_pos = 0;
            }
            if (p.coverage && tour.empty()) {  // the nearest goal of this round next (straight-line distance)
                const Eigen::Vector2d here(d.pose.x, d.pose.y);
                const auto nearest = std::min_element(
                    order.begin() + static_cast<std::ptrdiff_t>(order_pos), order.end(),
                    [&](std::size_t a, std::size_t b) { return (goals[a] - here).norm() < (goals[b] - here).norm(); });
                std::iter_swap(order.begin() + static_cast<std::ptrdiff_t>(order_pos), nearest);
            }
            leg_goal = order[order_pos++];
            const Eigen::Vector2d goal = goals[leg_goal];
            const auto from = nearestFree(cspace, {d.pose.x, d.pose.y}, 0.6);
            if (from && (goal - *from).norm() < 0.5) markReached(leg_goal);  // there already
            if (!from || (goal - *from).norm() < 0.5) continue;
            if (auto path = planPath(cspace, *from, goal)) {
                d.waypoints = shortcutPath(cspace, *path);
                d.next = 1;
                d.speed = rng.uniform(p.speed_min_mps, p.speed_max_mps);
                return true;
            }
        }
        return false;
    };

    std::vector<io::StampedPose2D> out;
    const auto n = static_cast<std::size_t>(std::floor(duration_s / dt_s + 1e-9)) + 1;
    std::size_t kidnap_step = 0;  // 0 = none (pose 0 is the start)
    if (kidnapped) {
        if (n < 2) throw std::runtime_error("generateTrajectory: a kidnap needs at least one step (duration >= dt)");
        // the first pose at or after t0 + at_s; the 1e-9 absorbs rounding (at 15 Hz, 16.6 / (1 / 15.0) is
        // 249.00000000000003, which would move the teleport one pose later)
        const double k = std::ceil(kidnap.at_s / dt_s - 1e-9);
        kidnap_step = static_cast<std::size_t>(std::clamp(k, 1.0, static_cast<double>(n - 1)));
    }
    out.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        step = k;
        if (k == kidnap_step && kidnapped) {
            // lifted during step k: the motion integrated for it is discarded (the wheels did not turn)
            const mrpt::math::TPose2D from = out.back().pose;
            const auto to = drawKidnapPose(cspace, {from.x, from.y}, kidnap.min_distance_m, kidnap.margin_m, *kidnap_rng);
            if (!to) {
                std::ostringstream msg;
                msg << "kidnap at " << kidnap.at_s << " s: no free cell of the robot's area is " << kidnap.min_distance_m
                    << " m or more from (" << from.x << ", " << from.y << ") (see [sequence] kidnap_min_distance_m)";
                throw std::runtime_error(msg.str());
            }
            d.pose = *to;
            d.waypoints.clear();  // plan from the new pose
            d.next = 0;
            d.spin_left_rad = 0;
            failures = 0;
            *kidnap_event = {k, t0_s + static_cast<double>(k) * dt_s, static_cast<double>(k) * dt_s, from, *to};
        }
        out.push_back({t0_s + static_cast<double>(k) * dt_s, d.pose});
        double v = 0, w = 0;
        if (d.spin_left_rad > 0) {
            w = std::min(p.turn_rate_radps, d.spin_left_rad / dt_s);
            d.spin_left_rad -= w * dt_s;
        } else {
            while (d.next < d.waypoints.size() &&
                   (d.waypoints[d.next] - Eigen::Vector2d(d.pose.x, d.pose.y)).norm() < p.waypoint_tolerance_m) {
                ++d.next;
                if (d.next == d.waypoints.size()) markReached(leg_goal);
                if (d.next == d.waypoints.size() && (rng.bernoulli(p.spin_probability) || p.coverage))
                    d.spin_left_rad = p.coverage && p.coverage_turn_deg > 0 ? p.coverage_turn_deg / 180.0 * M_PI : 2 * M_PI;
            }
            if (d.next >= d.waypoints.size() && d.spin_left_rad <= 0 && failures < 3) {
                if (!newLeg()) ++failures;  // nowhere to go: stand still
            }
            if (d.next < d.waypoints.size() && d.spin_left_rad <= 0) {
                const Eigen::Vector2d target = d.waypoints[d.next];
                const double dist = (target - Eigen::Vector2d(d.pose.x, d.pose.y)).norm();
                const double err = mrpt::math::wrapToPi(std::atan2(target.y() - d.pose.y, target.x() - d.pose.x) - d.pose.phi);
                if (std::abs(err) > p.turn_in_place_rad) {
                    w = std::copysign(std::min(p.turn_rate_radps, std::abs(err) / dt_s), err);  // turn in place
                } else {
                    w = std::clamp(2.0 * err, -p.turn_rate_radps, p.turn_rate_radps);
                    const bool last = d.next + 1 == d.waypoints.size();
                    v = std::min(d.speed, last ? std::max(0.1, dist) : d.speed);
                    v = std::min(v, dist / dt_s);
                }
            }
        }
        // exact unicycle integration over dt
        if (std::abs(w) < 1e-9) {
            d.pose.x += v * dt_s * std::cos(d.pose.phi);
            d.pose.y += v * dt_s * std::sin(d.pose.phi);
        } else {
            const double phi1 = d.pose.phi + w * dt_s;
            d.pose.x += v / w * (std::sin(phi1) - std::sin(d.pose.phi));
            d.pose.y -= v / w * (std::cos(phi1) - std::cos(d.pose.phi));
            d.pose.phi = phi1;
        }
        d.pose.phi = mrpt::math::wrapToPi(d.pose.phi);
    }
    return out;
}

}  // namespace simp::sim
