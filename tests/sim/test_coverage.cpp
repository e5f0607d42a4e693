// Coverage trajectories (a mapping run): room goals along a tour, a turn at each, every room
// cut into parts; and the built-in office furnished with the authors' classes.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <simp/sim/Office.h>
#include <simp/sim/Random.h>
#include <simp/sim/Raster.h>
#include <simp/sim/Trajectory.h>
#include <mrpt/math/wrap2pi.h>

#include <map>
#include <set>

namespace {

using namespace simp::sim;

struct Scene {
    GeneratedOffice office;
    Raster obstacles;
};

Scene officeScene(int rooms, std::uint64_t seed) {
    OfficeParams p;
    p.rooms = rooms;
    p.size_m2 = 0;
    Scene s{generateOfficeWithLayout(p, seed), {}};
    s.obstacles = drivingObstacles(s.office.world);
    return s;
}

/// Room ids (rooms.png) the trajectory passes through.
std::set<int> roomsVisited(const Scene& s, const std::vector<simp::io::StampedPose2D>& traj) {
    std::set<int> ids;
    for (const auto& p : traj) ids.insert(s.office.world.rooms.roomAt(p.pose.x, p.pose.y));
    ids.erase(0);
    return ids;
}

TEST(SimCoverage, RoomsAreCutIntoAtMostFourParts) {
    const Scene s = officeScene(4, 7);
    const auto cspace = inflate(s.obstacles, 0.4);
    const auto one = roomGoals(cspace, s.office.world.rooms);
    const auto parts = roomGoals(cspace, s.office.world.rooms, 3.0);
    EXPECT_EQ(one.size(), s.office.layout.rooms.size());
    // rooms are 3.5-6 m wide and 4-6 m deep: 1-2 parts of ~3 m per side, at most 2 x 2
    EXPECT_GT(parts.size(), one.size());
    EXPECT_LE(parts.size(), 4 * one.size());
    std::map<int, int> parts_per_room;
    for (const auto& g : parts) ++parts_per_room[s.office.world.rooms.roomAt(g.x(), g.y())];
    for (const auto& g : one) {
        const int id = s.office.world.rooms.roomAt(g.x(), g.y());
        EXPECT_GE(parts_per_room[id], 1) << "room " << id;
        EXPECT_LE(parts_per_room[id], 4) << "room " << id;
    }
}

TEST(SimCoverage, GoalsLieWhereTheRobotCanDrive) {
    // One room 10 m x 3 m: a pocket x < 3 m closed off by a wall (the most open spot, 1.45 m
    // from any obstacle), and the drivable rest, 7 m long but only 1.45 m wide.
    Raster r;
    r.nx = 200;
    r.ny = 60;
    r.resolution_m = 0.05;
    r.blocked.assign(static_cast<std::size_t>(r.nx * r.ny), 0);
    for (int cy = 0; cy < r.ny; ++cy)
        for (int cx = 0; cx < r.nx; ++cx) {
            const bool border = cx == 0 || cy == 0 || cx == r.nx - 1 || cy == r.ny - 1;
            const bool closing_wall = cx == 60;
            const bool narrow = cx > 60 && cy > 30;
            r.set(cx, cy, border || closing_wall || narrow);
        }
    simp::world::RoomMap rooms;
    rooms.ids = cv::Mat1w(r.ny, r.nx, static_cast<std::uint16_t>(1));
    rooms.resolution_m = r.resolution_m;
    const auto goals = roomGoals(r, rooms);
    ASSERT_EQ(goals.size(), 1u);
    EXPECT_GT(goals[0].x(), 3.05);  // in the drivable part, not in the pocket
    EXPECT_LT(goals[0].y(), 1.55);
}

TEST(SimCoverage, CoverageEntersEveryRoomAndTurnsAtEachGoal) {
    const Scene s = officeScene(6, 3);
    TrajectoryParams p;
    p.coverage = true;
    Rng rng_a(5);
    CoverageProgress progress;
    const auto cover = generateTrajectory(s.obstacles, s.office.world.rooms, p, 0.0, 0.1, 900.0, rng_a, {}, nullptr,
                                          nullptr, &progress);
    std::set<int> all;
    for (const auto& r : s.office.layout.rooms) all.insert(r.id);
    EXPECT_EQ(roomsVisited(s, cover), all);
    EXPECT_GT(progress.goals, all.size());  // the parts' goals and those that bring corners within reach
    EXPECT_EQ(progress.reached, progress.goals);
    EXPECT_GT(progress.all_reached_s, 0.0);
    EXPECT_LE(progress.all_reached_s, 900.0);
    // The same run cut short has not reached them all, and says so.
    Rng rng_b(5);
    CoverageProgress short_run;
    const auto part = generateTrajectory(s.obstacles, s.office.world.rooms, p, 0.0, 0.1, progress.all_reached_s / 2, rng_b,
                                         {}, nullptr, nullptr, &short_run);
    EXPECT_EQ(short_run.goals, progress.goals);
    EXPECT_LT(short_run.reached, progress.goals);
    EXPECT_LT(short_run.all_reached_s, 0.0);

    // A full turn at every goal: the heading sweeps 2 pi many times (once per goal reached).
    double turned = 0;
    for (std::size_t k = 1; k < cover.size(); ++k)
        turned += std::abs(mrpt::math::wrapToPi(cover[k].pose.phi - cover[k - 1].pose.phi));
    EXPECT_GT(turned, 2 * M_PI * static_cast<double>(all.size()));
}

TEST(SimCoverage, VisitOrderKeyIsChecked) {
    TrajectoryParams p;
    mrpt::config::CConfigFileMemory ok("[trajectory]\nvisit_order = coverage\ncoverage_part_m = 2.5\n");
    p.loadFromConfig(ok, "trajectory");
    EXPECT_TRUE(p.coverage);
    EXPECT_DOUBLE_EQ(p.coverage_part_m, 2.5);
    mrpt::config::CConfigFileMemory bad("[trajectory]\nvisit_order = spiral\n");
    try {
        p.loadFromConfig(bad, "trajectory");
        FAIL() << "no error for visit_order = spiral";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("visit_order"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("spiral"), std::string::npos) << e.what();
    }
    mrpt::config::CConfigFileMemory zero("[trajectory]\ncoverage_part_m = 0\n");
    EXPECT_THROW(p.loadFromConfig(zero, "trajectory"), std::invalid_argument);
}

TEST(SimOfficeClasses, WorkplacesAreTablesAndTheReceptionHasTheOnlyDesk) {
    const Scene s = officeScene(10, 1);
    const auto& data = s.office.world.objects;
    std::map<std::string, int> count;
    for (const auto& o : data.objects) ++count[data.class_names[static_cast<std::size_t>(o.class_id)]];
    int receptions = 0, offices = 0;
    for (const auto& r : s.office.layout.rooms) {
        receptions += r.type == RoomType::Reception;
        offices += r.type == RoomType::Office;
    }
    ASSERT_EQ(receptions, 1);
    EXPECT_EQ(count["desk"], 1);                 // the reception counter
    EXPECT_GE(count["table"], offices);          // at least one work table per office
    EXPECT_GE(count["board"], offices);          // 1-3 boards per office
    EXPECT_GE(count["sink"], 2);                 // kitchen + most offices
    EXPECT_LE(count["potted plant"], 1 + offices / 3);  // plants are rare (the authors' office: one)
}

}  // namespace
