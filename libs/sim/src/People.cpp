#include <simp/sim/PathPlanner.h>
#include <simp/sim/People.h>
#include <simp/sim/Trajectory.h>

#include <cmath>

namespace simp::sim {

std::vector<std::vector<mrpt::math::TPose2D>> simulatePeople(const Raster& obstacles, const world::RoomMap& rooms,
                                                             const PeopleParams& p, const std::vector<double>& times_s,
                                                             Rng& rng) {
    std::vector<std::vector<mrpt::math::TPose2D>> out;
    if (p.count <= 0 || times_s.empty()) return out;
    const Raster cspace = inflate(obstacles, 0.3);
    const auto goals = roomGoals(cspace, rooms);
    if (goals.size() < 2) return out;
    for (int person = 0; person < p.count; ++person) {
        std::vector<mrpt::math::TPose2D> poses;
        Eigen::Vector2d pos = goals[rng.index(goals.size())];
        double heading = rng.uniform(-M_PI, M_PI);
        std::vector<Eigen::Vector2d> path;
        std::size_t next = 0;
        double speed = 1.0;
        int failures = 0;
        for (std::size_t k = 0; k < times_s.size(); ++k) {
            poses.push_back({pos.x(), pos.y(), heading});
            if (k + 1 == times_s.size()) break;
            double budget = 0;  // distance to walk until the next time stamp
            if (next >= path.size() && failures < 5) {
                const auto leg = planPath(cspace, pos, goals[rng.index(goals.size())]);
                if (leg && leg->size() > 1) {
                    path = shortcutPath(cspace, *leg);
                    next = 1;
                    speed = rng.uniform(p.speed_min_mps, p.speed_max_mps);
                } else {
                    ++failures;
                }
            }
            budget = speed * (times_s[k + 1] - times_s[k]);
            while (budget > 0 && next < path.size()) {
                const Eigen::Vector2d d = path[next] - pos;
                const double len = d.norm();
                if (len > 1e-9) heading = std::atan2(d.y(), d.x());
                if (len <= budget) {
                    pos = path[next++];
                    budget -= len;
                } else {
                    pos += d / len * budget;
                    budget = 0;
                }
            }
        }
        out.push_back(std::move(poses));
    }
    return out;
}

}  // namespace simp::sim
