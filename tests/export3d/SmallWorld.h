#pragma once
// A 4 m x 3 m world for the export tests: free floor, a wall along the bottom row of cells
// (y in [0, 0.1) m), a table, a door closed in the wall and a door standing in an open gap.
#include <simp/geometry/Box3D.h>
#include <simp/world/World.h>

#include <filesystem>
#include <string>

namespace simp_test {

inline simp::world::World smallWorld() {
    simp::world::World w;
    simp::world::setGridExactly(w.floorplan, 0.0, 0.0, 80, 60, 0.05, 1.0f);  // 4 x 3 m, all free
    for (unsigned cx = 0; cx < 80; ++cx)
        for (unsigned cy = 0; cy < 2; ++cy) w.floorplan.setCell(cx, cy, 0.0f);  // wall: y in [0, 0.1)
    for (unsigned cx = 60; cx < 80; ++cx)
        for (unsigned cy = 40; cy < 60; ++cy) w.floorplan.setCell(cx, cy, 0.5f);  // unknown corner
    w.objects.class_names = {"table", "door"};
    w.objects.class_noise.resize(2);
    simp::world::MapObject table;
    table.id = 1;
    table.class_id = 0;
    table.box = simp::geometry::makeUprightBox({2.0, 1.5, 0.4}, {1.0, 0.6, 0.8}, 0.3);
    simp::world::MapObject closed_door;
    closed_door.id = 2;
    closed_door.class_id = 1;
    closed_door.box = simp::geometry::makeUprightBox({1.0, 0.05, 1.0}, {0.8, 0.04, 2.0}, 0.0);
    simp::world::MapObject open_door = closed_door;  // in free space: a door standing open in its gap
    open_door.id = 3;
    open_door.box = simp::geometry::makeUprightBox({0.5, 2.5, 1.0}, {0.8, 0.04, 2.0}, 0.0);
    w.objects.objects = {table, closed_door, open_door};
    return w;
}

/// SIMP_TEST_OUTPUT_DIR/export3d/<suite>.<test>, emptied.
inline std::string freshDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto p = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "export3d" /
                   (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p.string();
}

}  // namespace simp_test
