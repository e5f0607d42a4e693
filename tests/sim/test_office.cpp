// The built-in office: deterministic per seed, connected, objects clear of walls and each other.
#include <gtest/gtest.h>
#include <simp/geometry/Footprint.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/Office.h>
#include <simp/sim/PathPlanner.h>
#include <simp/sim/Raster.h>
#include <simp/sim/Trajectory.h>

#include "SimTestUtil.h"

#include <filesystem>
#include <fstream>
#include <queue>
#include <set>
#include <sstream>

namespace {

std::string tmpDir(const std::string& name) { return simp::sim::test::emptyDir(name); }
using simp::sim::test::slurp;

/// Free cells reachable from (sx, sy) by 4-connected flood fill.
std::vector<std::uint8_t> floodFill(const simp::sim::Raster& r, int sx, int sy) {
    std::vector<std::uint8_t> seen(r.blocked.size(), 0);
    std::queue<std::pair<int, int>> q;
    q.push({sx, sy});
    seen[static_cast<std::size_t>(sy) * r.nx + sx] = 1;
    while (!q.empty()) {
        const auto [x, y] = q.front();
        q.pop();
        const int d[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        for (const auto& s : d) {
            const int nx = x + s[0], ny = y + s[1];
            if (r.isBlocked(nx, ny) || seen[static_cast<std::size_t>(ny) * r.nx + nx]) continue;
            seen[static_cast<std::size_t>(ny) * r.nx + nx] = 1;
            q.push({nx, ny});
        }
    }
    return seen;
}

void checkOffice(const simp::sim::GeneratedOffice& g) {
    const auto& w = g.world;
    const auto walls = simp::sim::wallRaster(w.floorplan);
    // connected: a flood fill from the first corridor reaches every room (and corridor)
    const simp::sim::Room* corridor = nullptr;
    for (const auto& r : g.layout.rooms)
        if (r.type == simp::sim::RoomType::Corridor) corridor = &r;
    ASSERT_NE(corridor, nullptr);
    const double cx = 0.5 * (corridor->interior.x0 + corridor->interior.x1), cy = 0.5 * (corridor->interior.y0 + corridor->interior.y1);
    const auto seen = floodFill(walls, walls.cellX(cx), walls.cellY(cy));
    std::set<int> reached;
    for (int y = 0; y < walls.ny; ++y)
        for (int x = 0; x < walls.nx; ++x)
            if (seen[static_cast<std::size_t>(y) * walls.nx + x]) reached.insert(w.rooms.roomAt(walls.centreX(x), walls.centreY(y)));
    for (const auto& r : g.layout.rooms) EXPECT_TRUE(reached.count(r.id)) << "room " << r.id << " is not connected";

    // the robot (radius 0.3 m) can reach every room's goal from the corridor around the furniture
    const auto cspace = simp::sim::inflate(simp::sim::drivingObstacles(w), 0.3);
    const auto goals = simp::sim::roomGoals(cspace, w.rooms);
    EXPECT_EQ(goals.size(), g.layout.rooms.size());
    ASSERT_FALSE(goals.empty());
    const auto reach = floodFill(cspace, cspace.cellX(goals[0].x()), cspace.cellY(goals[0].y()));
    for (std::size_t i = 1; i < goals.size(); ++i)
        EXPECT_TRUE(reach[static_cast<std::size_t>(cspace.cellY(goals[i].y())) * cspace.nx + cspace.cellX(goals[i].x())])
            << "goal " << i << " unreachable";
    if (goals.size() > 1) {
        EXPECT_TRUE(simp::sim::planPath(cspace, goals[0], goals[1]).has_value());
    }

    // objects: every point of a footprint on free floor, no two footprints overlapping
    std::set<int> classes;
    for (std::size_t i = 0; i < w.objects.objects.size(); ++i) {
        const auto& o = w.objects.objects[i];
        classes.insert(o.class_id);
        EXPECT_TRUE(o.box.isValid());
        const auto fp = simp::geometry::footprint(o.box);
        const Eigen::Vector2d c = fp.centroid();
        for (std::size_t k = 0; k < fp.n; ++k)
            for (double f : {0.0, 0.5, 0.98}) {
                const Eigen::Vector2d p = c + f * (fp.v[k] - c);
                EXPECT_FALSE(walls.isBlockedAt(p.x(), p.y())) << "object " << o.id << " overlaps a wall";
            }
        for (std::size_t j = i + 1; j < w.objects.objects.size(); ++j) {
            if ((w.objects.objects[j].box.center - o.box.center).head<2>().norm() > 3.0) continue;  // cannot touch
            EXPECT_LE(simp::geometry::intersectionArea(fp, simp::geometry::footprint(w.objects.objects[j].box)), 1e-9)
                << "objects " << o.id << " and " << w.objects.objects[j].id << " overlap";
        }
    }
    // the furniture classes of the paper appear (person never)
    const auto& names = w.objects.class_names;
    for (const char* n : {"door", "desk", "chair", "cabinet", "table", "sink", "oven", "sofa"})
        EXPECT_TRUE(classes.count(simp::obs::classIndexOf(names, n))) << n;
    EXPECT_FALSE(classes.count(simp::obs::classIndexOf(names, "person")));
}

}  // namespace

TEST(SimOffice, DefaultOfficeIsConnectedAndClean) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE(seed);
        const auto g = simp::sim::generateOfficeWithLayout({}, seed);
        int rooms = 0;
        for (const auto& r : g.layout.rooms) rooms += r.type != simp::sim::RoomType::Corridor;
        EXPECT_EQ(rooms, 10);
        checkOffice(g);
    }
}

TEST(SimOffice, LargeOfficeReachesRequestedArea) {
    simp::sim::OfficeParams p;
    p.size_m2 = 5000;
    const auto g = simp::sim::generateOfficeWithLayout(p, 9);
    double free_area = 0;
    for (const auto& r : g.layout.rooms) free_area += r.interior.area();
    EXPECT_GT(g.layout.bounds.area(), 5000 * 0.85);
    EXPECT_GT(free_area, 4000);
    checkOffice(g);
}

TEST(SimOffice, DeterministicPerSeed) {
    const std::string a = tmpDir("office_a"), b = tmpDir("office_b"), c = tmpDir("office_c");
    simp::world::saveWorld(simp::sim::generateOffice({}, 5), a);
    simp::world::saveWorld(simp::sim::generateOffice({}, 5), b);
    simp::world::saveWorld(simp::sim::generateOffice({}, 6), c);
    for (const char* f : {"objects.json", "floorplan.png", "floorplan.yaml", "rooms.png"})
        EXPECT_EQ(slurp(a + "/" + f), slurp(b + "/" + f)) << f;
    EXPECT_NE(slurp(a + "/objects.json"), slurp(c + "/objects.json"));
    // and it loads back with rooms and class noise models
    const auto w = simp::world::loadWorld(a);
    EXPECT_FALSE(w.rooms.empty());
    EXPECT_TRUE(w.objects.class_noise.at(static_cast<std::size_t>(w.objects.classId("desk"))).has_value());
}

TEST(SimOffice, ClassNoiseHasTheAuthorsMagnitudes) {
    const auto noise = simp::sim::officeClassNoise(simp::obs::defaultClassNames());
    const auto& desk = noise.at(13);
    ASSERT_TRUE(desk.has_value());
    EXPECT_NEAR(desk->mean_m.x(), 5.288 * 0.05, 1e-9);
    EXPECT_NEAR(std::sqrt(desk->cov_m2(1, 1)), 20.390 * 0.05, 1e-9);
    EXPECT_EQ(noise.at(2)->exponent_b, 4.0);   // oven
    EXPECT_FALSE(noise.at(1).has_value());     // door: not modelled by the authors
}

TEST(SimOffice, RejectsBadParameters) {
    simp::sim::OfficeParams p;
    p.rooms = 0;
    EXPECT_THROW(simp::sim::generateOffice(p, 1), std::invalid_argument);
    p = {};
    p.wall_thickness_m = std::nan("");
    EXPECT_THROW(simp::sim::generateOffice(p, 1), std::invalid_argument);
}
