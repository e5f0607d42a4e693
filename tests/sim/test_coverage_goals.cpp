// CoverageGoals.h: the further goals of a coverage run bring every part of a room within reach,
// and the tour visits them by driving distance, not as the crow flies.
#include <gtest/gtest.h>
#include <simp/sim/CoverageGoals.h>
#include <simp/sim/Raster.h>
#include <simp/sim/Trajectory.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

namespace {

using namespace simp::sim;

Raster emptyRaster(double w_m, double h_m) {
    Raster r;
    r.resolution_m = 0.05;
    r.nx = static_cast<int>(std::lround(w_m / r.resolution_m));
    r.ny = static_cast<int>(std::lround(h_m / r.resolution_m));
    r.blocked.assign(static_cast<std::size_t>(r.nx) * r.ny, 0);
    return r;
}

simp::world::RoomMap roomsOf(const Raster& r, const std::function<int(int, int)>& id) {
    simp::world::RoomMap rooms;
    rooms.resolution_m = r.resolution_m;
    rooms.ids = cv::Mat1w(r.ny, r.nx, static_cast<std::uint16_t>(0));
    for (int cy = 0; cy < r.ny; ++cy)  // row 0 of the image = the top (max y)
        for (int cx = 0; cx < r.nx; ++cx) rooms.ids(r.ny - 1 - cy, cx) = static_cast<std::uint16_t>(id(cx, cy));
    return rooms;
}

/// True when p (m) is within reach_m of some goal on a straight line that stays in room `id`.
bool withinReach(const simp::world::RoomMap& rooms, const std::vector<Eigen::Vector2d>& goals,
                 const Eigen::Vector2d& p, double reach_m) {
    for (const auto& g : goals) {
        if ((g - p).norm() > reach_m) continue;
        bool inside = true;
        for (int k = 0; k <= 100 && inside; ++k) {
            const Eigen::Vector2d q = g + (p - g) * (k / 100.0);
            inside = rooms.roomAt(q.x(), q.y()) == 1;
        }
        if (inside) return true;
    }
    return false;
}

TEST(CoverageGoals, EveryPartOfAnLShapedRoomIsWithinReach) {
    // An L of two 10 m x 3 m arms: from the widest spot the far ends are 7-8 m away, and no
    // straight line from one arm's end reaches the other's.
    Raster r = emptyRaster(10, 10);
    const auto inL = [](int cx, int cy) { return cx < 60 || cy < 60; };
    for (int cy = 0; cy < r.ny; ++cy)
        for (int cx = 0; cx < r.nx; ++cx) {
            const bool border = cx == 0 || cy == 0 || cx == r.nx - 1 || cy == r.ny - 1;
            r.set(cx, cy, border || !inL(cx, cy));
        }
    const auto rooms = roomsOf(r, [&](int cx, int cy) { return r.isBlocked(cx, cy) ? 0 : 1; });
    const Raster cspace = inflate(r, 0.4);
    const auto first = roomGoals(cspace, rooms);
    ASSERT_EQ(first.size(), 1u);
    const double reach_m = 2.5;
    const auto goals = addReachGoals(cspace, rooms, first, reach_m, 0.25);
    ASSERT_GT(goals.size(), 2u);
    EXPECT_EQ(goals[0], first[0]);  // the given goals come first
    int out_of_reach = 0, cells = 0;
    for (int cy = 0; cy < r.ny; cy += 2)
        for (int cx = 0; cx < r.nx; cx += 2) {
            if (r.isBlocked(cx, cy)) continue;
            ++cells;
            // the room is sampled every 0.25 m: a cell is at most half a diagonal from a sample
            const Eigen::Vector2d p(r.centreX(cx), r.centreY(cy));
            out_of_reach += !withinReach(rooms, goals, p, reach_m + 0.25 * std::sqrt(0.5));
        }
    EXPECT_EQ(out_of_reach, 0) << "of " << cells << " cells";
    for (const auto& g : goals) EXPECT_FALSE(cspace.isBlockedAt(g.x(), g.y()));

    // A larger reach needs fewer goals; a larger minimum gain stops earlier.
    EXPECT_LT(addReachGoals(cspace, rooms, first, 5.0, 0.25).size(), goals.size());
    EXPECT_LE(addReachGoals(cspace, rooms, first, reach_m, 5.0).size(), goals.size());
    EXPECT_THROW(addReachGoals(cspace, rooms, first, 0.0, 1.0), std::invalid_argument);
}

TEST(CoverageGoals, TheTourCrossesADividingWallOnceEachWay) {
    // 12 m x 6 m, a wall along y = 3 m with a gap at x > 10.5 m; goals at x = 1, 3, ... 9 m on
    // both sides. As the crow flies each goal's nearest is across the wall; driven, it is not.
    Raster r = emptyRaster(12, 6);
    for (int cx = 0; cx < 210; ++cx) r.set(cx, 60, true);
    std::vector<Eigen::Vector2d> goals;
    for (int i = 0; i < 5; ++i) {
        goals.emplace_back(1.0 + 2 * i, 1.5);
        goals.emplace_back(1.0 + 2 * i, 4.5);
    }
    goals.emplace_back(11.9, 5.9);  // walled in below
    r.set(r.cellX(11.9) - 1, r.cellY(5.9), true);
    r.set(r.cellX(11.9), r.cellY(5.9) - 1, true);
    r.set(r.cellX(11.9) - 1, r.cellY(5.9) - 1, true);
    const auto tour = coverageTour(r, goals, 0);
    ASSERT_EQ(tour.size(), goals.size());
    EXPECT_EQ(std::set<std::size_t>(tour.begin(), tour.end()).size(), goals.size());  // a permutation
    EXPECT_EQ(tour.front(), 0u);
    EXPECT_EQ(tour.back(), goals.size() - 1);  // not connected: last
    int crossings = 0;
    for (std::size_t k = 1; k + 1 < tour.size(); ++k) crossings += (goals[tour[k]].y() > 3) != (goals[tour[k - 1]].y() > 3);
    EXPECT_EQ(crossings, 1);  // over once; the closed tour comes back once
    EXPECT_THROW(coverageTour(r, goals, goals.size()), std::invalid_argument);
}

}  // namespace
