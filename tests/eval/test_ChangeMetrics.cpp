// Change detection metrics (ChangeMetrics.h): per-kind precision / recall, id matching of
// removed / moved, class + centre gate of added, the translation through a built before map,
// and the changes.json round trip.
#include <gtest/gtest.h>
#include <simp/eval/ChangeMetrics.h>
#include <simp/world/ChangesFile.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using simp::geometry::makeUprightBox;
using simp::world::ChangeRecord;

namespace {

ChangeRecord removed(std::int64_t id, const std::string& cls, double x, double y) {
    ChangeRecord c;
    c.kind = "removed";
    c.id_before = id;
    c.class_name = cls;
    c.before = makeUprightBox({x, y, 0.4}, {1.0, 0.6, 0.8}, 0.0);
    return c;
}
ChangeRecord moved(std::int64_t id, const std::string& cls, double x, double y, double x2, double y2) {
    ChangeRecord c = removed(id, cls, x, y);
    c.kind = "moved";
    c.id_after = id;
    c.after = makeUprightBox({x2, y2, 0.4}, {1.0, 0.6, 0.8}, 0.5);
    return c;
}
ChangeRecord added(std::int64_t id, const std::string& cls, double x, double y) {
    ChangeRecord c;
    c.kind = "added";
    c.id_after = id;
    c.class_name = cls;
    c.after = makeUprightBox({x, y, 0.4}, {1.0, 0.6, 0.8}, 0.0);
    return c;
}

ChangeRecord doorClosed(std::int64_t id, double x, double y) {
    ChangeRecord c;
    c.kind = "door_closed";
    c.id_before = c.id_after = id;
    c.class_name = "door";
    c.before = c.after = makeUprightBox({x, y, 1.0}, {0.9, 0.05, 2.0}, 0.0);
    return c;
}

}  // namespace

TEST(ChangeMetrics, ClosedDoorsAreAKindOfTheirOwn) {
    // Three doors closed; the report finds two of them and one that was not, and reports a fourth
    // door removed: a removal, not a closed door.
    const std::vector<ChangeRecord> truth = {doorClosed(5, 1, 1), doorClosed(6, 3, 1), doorClosed(7, 5, 1),
                                             removed(1, "table", 1, 4)};
    const std::vector<ChangeRecord> report = {doorClosed(5, 1, 1), doorClosed(7, 5, 1), doorClosed(8, 7, 1),
                                              removed(1, "table", 1, 4), removed(6, "door", 3, 1)};
    const auto s = simp::eval::scoreChanges(truth, report);
    EXPECT_EQ(s.doors_closed.n_true, 3u);
    EXPECT_EQ(s.doors_closed.n_reported, 3u);
    EXPECT_EQ(s.doors_closed.n_correct, 2u);
    EXPECT_DOUBLE_EQ(s.removed.precision, 0.5);  // the door reported removed
    EXPECT_DOUBLE_EQ(s.removed.recall, 1.0);
    const auto j = simp::eval::toJson(s);
    EXPECT_DOUBLE_EQ(j["door_closed"]["precision"].get<double>(), 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(j["door_closed"]["recall"].get<double>(), 2.0 / 3.0);
    // Scoring the object classes only leaves the doors out.
    simp::eval::ChangeMatchParams p;
    p.classes = {"table"};
    const auto t = simp::eval::scoreChanges(truth, report, p);
    EXPECT_EQ(t.doors_closed.n_true, 0u);
    EXPECT_DOUBLE_EQ(t.removed.precision, 1.0);
}

TEST(ChangeMetrics, PrecisionAndRecallPerKind) {
    const std::vector<ChangeRecord> truth = {removed(1, "table", 1, 1), removed(2, "sofa", 3, 1),
                                             moved(3, "table", 5, 1, 5.8, 1), added(10, "table", 2, 4),
                                             added(11, "sink", 6, 4)};
    std::vector<ChangeRecord> report = {removed(1, "table", 1.1, 1),            // right
                                        removed(3, "table", 5, 1),              // it moved: wrong kind
                                        moved(7, "cabinet", 8, 1, 8.5, 1),      // nothing moved there
                                        added(50, "table", 2.9, 4),             // 0.9 m from the truth: within 1 m
                                        added(51, "sink", 7.2, 4)};             // 1.2 m: outside the gate
    report[0].confidence = 0.9;
    const auto s = simp::eval::scoreChanges(truth, report);
    EXPECT_EQ(s.removed.n_true, 2u);
    EXPECT_EQ(s.removed.n_reported, 2u);
    EXPECT_EQ(s.removed.n_correct, 1u);
    EXPECT_DOUBLE_EQ(s.removed.precision, 0.5);
    EXPECT_DOUBLE_EQ(s.removed.recall, 0.5);
    EXPECT_DOUBLE_EQ(s.moved.precision, 0.0);
    EXPECT_DOUBLE_EQ(s.moved.recall, 0.0);
    EXPECT_DOUBLE_EQ(s.added.precision, 0.5);
    EXPECT_DOUBLE_EQ(s.added.recall, 0.5);

    // A wider gate takes the sink; a class filter leaves only the tables.
    simp::eval::ChangeMatchParams p;
    p.max_center_dist_m = 1.5;
    EXPECT_DOUBLE_EQ(simp::eval::scoreChanges(truth, report, p).added.recall, 1.0);
    p = {};
    p.classes = {"table"};
    const auto t = simp::eval::scoreChanges(truth, report, p);
    EXPECT_EQ(t.removed.n_true, 1u);
    EXPECT_DOUBLE_EQ(t.removed.recall, 1.0);
    EXPECT_EQ(t.moved.n_reported, 0u);
    EXPECT_DOUBLE_EQ(t.moved.precision, 1.0);  // nothing claimed, nothing wrong
}

TEST(ChangeMetrics, NoChangeAndEmptyReportScoreOne) {
    const auto s = simp::eval::scoreChanges({}, {});
    EXPECT_DOUBLE_EQ(s.removed.precision, 1.0);
    EXPECT_DOUBLE_EQ(s.added.recall, 1.0);
    const auto j = simp::eval::toJson(s);
    // The contract's key order: removed, moved, added; precision, recall first.
    EXPECT_EQ(j.begin().key(), "removed");
    EXPECT_EQ(j["removed"].begin().key(), "precision");
}

TEST(ChangeMetrics, BuiltBeforeMapIdsAreTranslated) {
    // W: table 1 at (1, 1), sofa 2 at (4, 1), cabinet 3 at (7, 1). M0 (built): table 101 near
    // table 1, cabinet 103 near cabinet 3, a ghost table 104 at (4, 5); it never had the sofa.
    simp::world::ObjectMapData W, M0;
    W.class_names = M0.class_names = {"table", "sofa", "cabinet"};
    const auto obj = [](std::int64_t id, int cls, double x, double y) {
        simp::world::MapObject o;
        o.id = id;
        o.class_id = cls;
        o.box = makeUprightBox({x, y, 0.4}, {1.0, 0.6, 0.8}, 0.0);
        return o;
    };
    W.objects = {obj(1, 0, 1, 1), obj(2, 1, 4, 1), obj(3, 2, 7, 1)};
    M0.objects = {obj(101, 0, 1.1, 1), obj(103, 2, 7.1, 1), obj(104, 0, 4, 5)};
    const std::vector<ChangeRecord> truth = {removed(1, "table", 1, 1), removed(2, "sofa", 4, 1),
                                             moved(3, "cabinet", 7, 1, 7.6, 1)};
    const std::vector<ChangeRecord> report = {removed(101, "table", 1.1, 1), removed(104, "table", 4, 5),
                                              moved(103, "cabinet", 7.1, 1, 7.6, 1)};
    simp::eval::BeforeMaps before;
    before.world = &W;
    before.map = &M0;
    const auto s = simp::eval::scoreChanges(truth, report, {}, before);
    EXPECT_EQ(s.truth_not_in_map, 1u);   // the sofa M0 never had
    EXPECT_EQ(s.ignored_reports, 1u);    // the ghost's removal
    EXPECT_DOUBLE_EQ(s.removed.precision, 1.0);
    EXPECT_DOUBLE_EQ(s.removed.recall, 1.0);
    EXPECT_DOUBLE_EQ(s.moved.recall, 1.0);
}

TEST(ChangesFile, RoundTripKeepsEveryField) {
    const auto path = (std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "eval" / "changes_roundtrip.json").string();
    std::vector<ChangeRecord> in = {removed(4, "table", 1, 2), moved(5, "sofa", 3, 4, 3.5, 4.2), added(9, "sink", 6, 1)};
    in[1].confidence = 0.75;
    simp::world::saveChangesFile(in, path);
    const auto out = simp::world::loadChangesFile(path);
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[1].kind, "moved");
    EXPECT_EQ(out[1].id_before, 5);
    EXPECT_EQ(out[1].id_after, 5);
    EXPECT_EQ(out[1].confidence, 0.75);
    EXPECT_FALSE(out[0].confidence.has_value());
    EXPECT_FALSE(out[2].id_before.has_value());
    EXPECT_NEAR((out[1].after->center - in[1].after->center).norm(), 0, 1e-12);
    EXPECT_NEAR(simp::geometry::yawOf(*out[1].after), 0.5, 1e-12);
}

TEST(ChangesFile, BeforeWorldIsKeptRelativeToTheFile) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval" / "changes_before_world";
    fs::remove_all(dir);
    fs::create_directories(dir / "Q");
    fs::create_directories(dir / "W");
    const auto path = (dir / "Q" / "changes.json").string();
    simp::world::saveChangesFile({removed(4, "table", 1, 2)}, path, (dir / "W").string());
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"before_world\": \"../W\""), std::string::npos) << text;
    EXPECT_TRUE(fs::equivalent(simp::world::readChangesFile(path).before_world, dir / "W"));
    // The pair moved elsewhere still finds its world.
    const fs::path moved = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval" / "changes_before_world_moved";
    fs::remove_all(moved);
    fs::rename(dir, moved);
    EXPECT_TRUE(fs::equivalent(simp::world::readChangesFile((moved / "Q" / "changes.json").string()).before_world, moved / "W"));
    // Without it: empty, and the entries as always.
    simp::world::saveChangesFile({removed(4, "table", 1, 2)}, (moved / "Q" / "c2.json").string());
    const auto plain = simp::world::readChangesFile((moved / "Q" / "c2.json").string());
    EXPECT_TRUE(plain.before_world.empty());
    EXPECT_EQ(plain.changes.size(), 1u);
}

TEST(ChangesFile, BeforeWorldMustNameADirectory) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval";
    fs::create_directories(dir);
    for (const std::string value : {"3", "\"\""}) {
        const auto path = (dir / "changes_bad_before_world.json").string();
        std::ofstream(path) << "{\"format\": \"simp-changes\", \"version\": 1, \"before_world\": " << value
                            << ", \"changes\": []}";
        try {
            simp::world::readChangesFile(path);
            ADD_FAILURE() << "accepted before_world = " << value;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("before_world"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
}

TEST(ChangeMetrics, SameObjectIdsRecognisesTheWorldItself) {
    simp::world::ObjectMapData W;
    W.class_names = {"table", "sofa"};
    for (int i = 0; i < 3; ++i) {
        simp::world::MapObject o;
        o.id = 10 + i;
        o.class_id = i % 2;
        o.box = makeUprightBox({1.0 + 2 * i, 1, 0.4}, {1.0, 0.6, 0.8}, 0.0);
        W.objects.push_back(o);
    }
    EXPECT_TRUE(simp::eval::sameObjectIds(W, W));
    auto other_ids = W;
    other_ids.objects[1].id = 99;
    EXPECT_FALSE(simp::eval::sameObjectIds(W, other_ids));
    auto moved = W;
    moved.objects[2].box.center.x() += 0.05;
    EXPECT_FALSE(simp::eval::sameObjectIds(W, moved));
    auto renamed = W;
    renamed.class_names = {"sofa", "table"};
    EXPECT_FALSE(simp::eval::sameObjectIds(W, renamed));
    auto fewer = W;
    fewer.objects.pop_back();
    EXPECT_FALSE(simp::eval::sameObjectIds(W, fewer));
}
