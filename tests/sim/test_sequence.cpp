// simulateSequence end to end on a small office: byte-identical per seed, a valid rawlog in the
// actions + sensory-frames format, odometry consistent with the ground truth.
#include <gtest/gtest.h>
#include <mrpt/io/CFileInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/io/Tum.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/registerAllClasses.h>
#include <simp/sim/Office.h>
#include <simp/sim/Raster.h>
#include <simp/sim/Sequence.h>
#include <simp/sim/WorldChanges.h>
#include <simp/world/SimpFormat.h>

#include "SimTestUtil.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace {

std::string tmpDir(const std::string& name) { return simp::sim::test::clearedDir(name); }
using simp::sim::test::slurp;

simp::world::World smallOffice() {
    simp::sim::OfficeParams p;
    p.rooms = 4;
    return simp::sim::generateOffice(p, 21);
}

simp::sim::SimParams shortRun() {
    simp::sim::SimParams p;
    p.duration_s = 20;
    p.progress = false;
    return p;
}

}  // namespace

TEST(SimSequence, SameSeedGivesByteIdenticalFiles) {
    const auto w = smallOffice();
    auto p = shortRun();
    p.changes.fraction = 0.3;
    const std::string a = tmpDir("seq_a"), b = tmpDir("seq_b"), c = tmpDir("seq_c");
    simp::sim::simulateSequence(w, p, 77, a);
    simp::sim::simulateSequence(w, p, 77, b);
    simp::sim::simulateSequence(w, p, 78, c);
    for (const char* f : {"sequence.rawlog", "groundtruth.tum", "world/objects.json", "world/floorplan.png", "overview.png",
                          "changes.json"}) {
        const std::string fa = slurp(a + "/" + f);
        EXPECT_FALSE(fa.empty()) << f;
        EXPECT_EQ(fa, slurp(b + "/" + f)) << f;
    }
    EXPECT_NE(slurp(a + "/sequence.rawlog"), slurp(c + "/sequence.rawlog"));
    EXPECT_NE(slurp(a + "/groundtruth.tum"), slurp(c + "/groundtruth.tum"));
}

TEST(SimSequence, RawlogHasOdometryAndCameraFrames) {
    simp::obs::registerAllClasses();
    const auto w = smallOffice();
    auto p = shortRun();
    p.odometry.noise_scale = 0;  // perfect odometry: increments compose to the ground truth
    const std::string dir = tmpDir("seq_content");
    const auto summary = simp::sim::simulateSequence(w, p, 5, dir);
    const auto gt = simp::io::readTum(dir + "/groundtruth.tum");
    ASSERT_EQ(gt.size(), 201u);  // 20 s at 10 Hz, both ends
    EXPECT_NEAR(gt.front().t_s, p.epoch_s, 1e-6);
    EXPECT_GT(summary.path_length_m, 2.0);

    mrpt::io::CFileInputStream f(dir + "/sequence.rawlog");
    auto arch = mrpt::serialization::archiveFrom(f);
    mrpt::poses::CPose2D pose(gt.front().pose);
    std::size_t steps = 0, frames = 0, detections = 0;
    for (;;) {
        mrpt::serialization::CSerializable::Ptr o1, o2;
        try {
            o1 = arch.ReadObject();
        } catch (const std::exception&) {
            break;  // end of file
        }
        o2 = arch.ReadObject();
        auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(o1);
        auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(o2);
        ASSERT_TRUE(acts && sf) << "step " << steps << " is not an action collection + sensory frame";
        ++steps;
        auto odo = acts->getBestMovementEstimation();
        ASSERT_TRUE(odo);
        pose = pose + odo->rawOdometryIncrementReading;
        const double t = mrpt::Clock::toDouble(odo->timestamp);
        EXPECT_NEAR(t, gt[steps].t_s, 1e-6);
        EXPECT_NEAR(pose.x(), gt[steps].pose.x, 1e-5);
        EXPECT_NEAR(pose.y(), gt[steps].pose.y, 1e-5);
        if (sf->size() == 0) continue;
        ASSERT_EQ(sf->size(), 4u);
        for (std::size_t c = 0; c < 4; ++c) {
            auto ob = sf->getObservationByClass<simp::obs::CObservationObjects3D>(c);
            ASSERT_TRUE(ob);
            EXPECT_EQ(ob->sensorLabel, "CAMERA_" + std::to_string(c));
            EXPECT_NEAR(mrpt::Clock::toDouble(ob->timestamp), t, 1e-6);
            ASSERT_TRUE(ob->intrinsics().has_value());
            EXPECT_NEAR(ob->intrinsics()->fx(), 380.07, 1e-9);
            EXPECT_NEAR(ob->cameraPose().z(), 0.63, 1e-9);
            for (const auto& d : ob->detections()) EXPECT_GT(d.box_in_camera.center.z(), 0.0);  // in front
            detections += ob->size();
            ++frames;
        }
    }
    EXPECT_EQ(steps, 200u);
    EXPECT_EQ(frames, 400u);  // 5 Hz x 20 s x 4 cameras
    EXPECT_EQ(frames, summary.camera_frames);
    EXPECT_GT(detections, 50u);
    for (const char* f : {"world/floorplan.yaml", "world/objects.json", "world/rooms.png", "overview.png"})
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
}

TEST(SimChanges, FractionOfObjectsChangesAndDoorsClose) {
    const auto map = smallOffice();
    simp::sim::ChangeParams p;
    p.fraction = 0.3;
    simp::sim::Rng rng(8);
    simp::sim::ChangeSummary s;
    const auto changed = simp::sim::applyChanges(map, p, rng, &s);
    const int door = map.objects.classId("door");
    std::size_t n = 0, doors = 0;
    for (const auto& o : map.objects.objects) (o.class_id == door ? doors : n)++;
    const auto expected = static_cast<int>(std::lround(0.3 * n));
    EXPECT_EQ(s.removed + s.moved + s.added, expected);  // moves that fail become removals
    EXPECT_EQ(s.doors_closed, static_cast<int>(std::lround(0.3 * doors)));
    EXPECT_EQ(changed.objects.objects.size(), map.objects.objects.size() - s.removed + s.added);
    // closed doors: fewer free cells in the floor plan, door objects still there
    const auto free_cells = [](const simp::world::World& w) {
        int k = 0;
        for (unsigned y = 0; y < w.floorplan.getSizeY(); ++y)
            for (unsigned x = 0; x < w.floorplan.getSizeX(); ++x) k += w.floorplan.getCell(x, y) > 0.5f;
        return k;
    };
    EXPECT_LT(free_cells(changed), free_cells(map));
    std::size_t doors_after = 0;
    for (const auto& o : changed.objects.objects) doors_after += o.class_id == door;
    EXPECT_EQ(doors_after, doors);
    // nothing changes at fraction 0
    p.fraction = 0;
    const auto same = simp::sim::applyChanges(map, p, rng, &s);
    EXPECT_EQ(same.objects.objects.size(), map.objects.objects.size());
    EXPECT_EQ(free_cells(same), free_cells(map));
}

TEST(SimChanges, AMovedObjectStaysInItsRoom) {
    // Furniture is carried within its room: a cabinet against a wall does not reappear on the
    // wall's far side. The built-in office (a room map), every object changed, several draws.
    simp::sim::OfficeParams office;
    const auto map = simp::sim::generateOffice(office, 3);
    ASSERT_FALSE(map.rooms.empty());
    simp::sim::ChangeParams p;
    p.fraction = 1.0;
    int moves = 0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        simp::sim::Rng rng(seed);
        simp::sim::ChangeSummary s;
        simp::sim::applyChanges(map, p, rng, &s);
        for (const auto& c : s.changes) {
            if (c.kind != simp::sim::ObjectChange::Kind::Moved) continue;
            ASSERT_TRUE(c.before && c.after);
            const auto& a = c.before->box.center;
            const auto& b = c.after->box.center;
            const int room = map.rooms.roomAt(a.x(), a.y());
            if (room <= 0) continue;
            ++moves;
            EXPECT_EQ(map.rooms.roomAt(b.x(), b.y()), room) << "seed " << seed << ": object " << c.before->id << " moved from ("
                                                           << a.x() << ", " << a.y() << ") to (" << b.x() << ", " << b.y() << ")";
        }
    }
    EXPECT_GT(moves, 50);  // a third of the non-door objects per draw
}

namespace {

/// Rooms (ids of rooms.png) with a cell in the largest area a disc of radius r can drive in.
std::set<int> drivableRooms(const simp::world::World& w, double r) {
    const auto cspace = simp::sim::inflate(simp::sim::drivingObstacles(w), r);
    const auto area = simp::sim::largestFreeArea(cspace, simp::sim::clearance(cspace));
    std::set<int> rooms;
    for (int cy = 0; cy < cspace.ny; ++cy)
        for (int cx = 0; cx < cspace.nx; ++cx)
            if (area[static_cast<std::size_t>(cy) * cspace.nx + cx])
                rooms.insert(w.rooms.roomAt(cspace.centreX(cx), cspace.centreY(cy)));
    rooms.erase(0);
    return rooms;
}

/// Over `seeds` draws of every object changed (no door closed): the draws after which a room
/// the robot could drive to before is out of its reach.
int drawsThatCutOffARoom(const simp::world::World& map, double passage_radius_m, int seeds) {
    simp::sim::ChangeParams p;
    p.fraction = 1.0;
    p.door_close_fraction = 0.0;
    p.passage_radius_m = passage_radius_m;
    const double r = 0.4;  // the trajectory's robot radius + clearance
    const auto before = drivableRooms(map, r);
    int cut = 0;
    for (int seed = 1; seed <= seeds; ++seed) {
        simp::sim::Rng rng(static_cast<std::uint64_t>(seed));
        const auto after = drivableRooms(simp::sim::applyChanges(map, p, rng), r);
        cut += std::any_of(before.begin(), before.end(), [&](int room) { return !after.count(room); });
    }
    return cut;
}

}  // namespace

TEST(SimChanges, AddedOrMovedFurnitureKeepsEveryRoomReachable) {
    // A facility keeps its corridors and doorways passable: an added table across a corridor
    // cut off the rooms beyond it, and a coverage run after the change never saw them.
    simp::sim::OfficeParams office;
    const auto map = simp::sim::generateOffice(office, 2);
    ASSERT_GT(drawsThatCutOffARoom(map, 0.0, 8), 0) << "without the rule some draw closes a passage";
    EXPECT_EQ(drawsThatCutOffARoom(map, 0.4, 8), 0);
}

TEST(SimSequence, RunsInTheImportedAuthorsOffice) {
    const std::string simp_dir = std::string(SIMP_SHARED_DATA_DIR) + "/simp-office";
    if (!std::filesystem::exists(simp_dir + "/floor.config"))
        GTEST_SKIP() << "the authors' data is absent (" << simp_dir << "); skipping the real-world sequence";
    const auto w = simp::world::importSimpMap(simp_dir);
    // Map.png is mostly free (white): with MRPT's convention (getCell = free probability) most
    // cells read > 0.5. A loader that stores occupancy probability instead makes the office solid.
    std::size_t free_cells = 0;
    for (unsigned y = 0; y < w.floorplan.getSizeY(); ++y)
        for (unsigned x = 0; x < w.floorplan.getSizeX(); ++x) free_cells += w.floorplan.getCell(x, y) > 0.5f;
    ASSERT_GE(free_cells, w.floorplan.getSizeX() * w.floorplan.getSizeY() / 4)
        << "the floor plan reads mostly occupied: getCell() must be the free probability (MRPT's convention)";
    auto p = shortRun();
    p.duration_s = 15;
    const std::string dir = tmpDir("seq_simp_office");
    const auto s = simp::sim::simulateSequence(w, p, 3, dir);
    EXPECT_EQ(s.steps, 150u);
    EXPECT_GT(s.path_length_m, 1.0);
    EXPECT_GT(s.true_detections, 20u);
    EXPECT_TRUE(std::filesystem::exists(dir + "/world/objects.json"));
}
