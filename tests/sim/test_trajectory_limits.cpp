// simp-sim sequence --duration 1e300 once cast an overflowing double to an integer (UB) and
// reported "0 steps": the duration is bounded (kMaxDuration_s) before any cast.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <simp/sim/Trajectory.h>

using ::testing::HasSubstr;

TEST(TrajectoryLimits, AbsurdDurationIsRejected) {
    simp::sim::Raster obstacles;
    simp::world::RoomMap rooms;
    simp::sim::TrajectoryParams p;
    simp::sim::Rng rng(1);
    for (double d : {1e300, simp::sim::kMaxDuration_s * 2, std::numeric_limits<double>::infinity()}) {
        try {
            simp::sim::generateTrajectory(obstacles, rooms, p, 0.0, 0.1, d, rng);
            FAIL() << d;
        } catch (const std::invalid_argument& e) {
            EXPECT_THAT(e.what(), HasSubstr("duration"));
        }
    }
    EXPECT_THROW(simp::sim::checkDuration(-1, "--duration"), std::invalid_argument);
    EXPECT_NO_THROW(simp::sim::checkDuration(120, "--duration"));
    // Within the duration bound but too many poses at a tiny step.
    EXPECT_THROW(simp::sim::generateTrajectory(obstacles, rooms, p, 0.0, 1e-6, 1e5, rng), std::invalid_argument);
}
