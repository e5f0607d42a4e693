// The map table of `simp-eval batch` (Table I per map and class) on two small maps written as real
// world directories: the simulator's office itself, and the office with one object removed.
#include <gtest/gtest.h>
#include <simp/eval/BatchConfig.h>
#include <simp/eval/BatchMaps.h>
#include <simp/sim/Office.h>
#include <simp/world/World.h>

#include "common/ErrorOf.h"

#include <filesystem>
#include <fstream>
#include <map>

namespace fs = std::filesystem;
using namespace simp::eval;

namespace {

struct BatchMapsFixture : ::testing::Test {
    fs::path root;
    simp::world::World truth;
    std::string removed_class;  // class of the object the second map lacks
    std::size_t n_removed_class = 0, n_classes = 0;

    void SetUp() override {
        root = fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_batch_maps" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(root);
        simp::sim::OfficeParams office;
        office.rooms = 3;
        truth = simp::sim::generateOffice(office, 5);
        simp::world::saveWorld(truth, (root / "gt").string());
        simp::world::saveWorld(truth, (root / "same").string());
        // Remove one object of a class that has several, so its recall is (n - 1) / n.
        std::map<int, std::size_t> count;
        for (const auto& o : truth.objects.objects) ++count[o.class_id];
        n_classes = count.size();
        auto minus = truth;
        for (std::size_t i = 0; i < minus.objects.objects.size(); ++i)
            if (count[minus.objects.objects[i].class_id] >= 2) {
                removed_class = minus.objects.class_names[static_cast<std::size_t>(minus.objects.objects[i].class_id)];
                n_removed_class = count[minus.objects.objects[i].class_id];
                minus.objects.objects.erase(minus.objects.objects.begin() + static_cast<std::ptrdiff_t>(i));
                break;
            }
        ASSERT_FALSE(removed_class.empty()) << "the office has no class with two objects";
        simp::world::saveWorld(minus, (root / "minus").string());
    }

    BatchConfig load(const std::string& batch_keys, const std::string& extra_sections = "") {
        const fs::path ini = root / "batch.ini";
        std::ofstream(ini) << "[batch]\nworld = " << (root / "gt").string() << "\nsequences = " << (root / "Q").string()
                           << "\n" << batch_keys << "\n" << extra_sections;
        return loadBatchConfig(ini.string());
    }
};

}  // namespace

TEST_F(BatchMapsFixture, MapEqualToTruthScoresOneAndARemovedObjectLowersRecall) {
    const auto cfg = load("maps = " + (root / "same").string() + ", " + (root / "minus").string() +
                          "\nmap_names = same minus");
    ASSERT_EQ(cfg.batchMaps().size(), 2u);
    EXPECT_EQ(cfg.batchMaps()[1].ground_truth, (root / "gt").string());  // default: [batch] world
    const auto maps = evaluateBatchMaps(cfg);
    ASSERT_EQ(maps.size(), 2u);

    const auto& same = maps[0].metrics;
    EXPECT_EQ(same.per_class.size(), n_classes);
    EXPECT_NEAR(same.iou, 1.0, 1e-9);
    EXPECT_DOUBLE_EQ(same.precision, 1.0);
    EXPECT_DOUBLE_EQ(same.recall, 1.0);

    const auto& minus = maps[1].metrics;
    const auto& cls = minus.per_class.at(removed_class);
    const double rc = static_cast<double>(n_removed_class - 1) / static_cast<double>(n_removed_class);
    EXPECT_DOUBLE_EQ(cls.recall, rc);
    EXPECT_DOUBLE_EQ(cls.precision, 1.0);  // every object of the map is a true one
    EXPECT_NEAR(cls.iou, 1.0, 1e-9);
    EXPECT_EQ(cls.n_gt, n_removed_class);
    EXPECT_EQ(cls.n_matched, n_removed_class - 1);
    // AVG: every other class keeps recall 1.
    EXPECT_NEAR(minus.recall, (static_cast<double>(n_classes) - 1.0 + rc) / static_cast<double>(n_classes), 1e-12);
    EXPECT_DOUBLE_EQ(minus.precision, 1.0);

    const std::string md = batchMapsMarkdown(maps);
    EXPECT_NE(md.find("| same | 1.00 | 1.00 | 1.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("### minus: `" + (root / "minus").string() + "` vs `" + (root / "gt").string() + "`"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| Rc |"), std::string::npos) << md;

    // The CSV: one line per map and class, and an AVG line per map, the same numbers.
    const std::string csv = batchMapsCsv(maps);
    EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), 1 + 2 * (n_classes + 1));
    char expected[160];
    std::snprintf(expected, sizeof expected, "minus,\"%s\",%zu,%zu,%zu,1.000000,1.000000,%.6f,", removed_class.c_str(),
                  n_removed_class, n_removed_class - 1, n_removed_class - 1, rc);
    EXPECT_NE(csv.find(expected), std::string::npos) << expected << "\n" << csv;
}

TEST_F(BatchMapsFixture, ClassesOfMapMetricsRestrictTheTable) {
    const auto cfg = load("maps = " + (root / "minus").string() + "\nmap_ground_truths = " + (root / "gt").string(),
                          "[map_metrics]\nclasses = " + removed_class + "\nmax_center_dist_m = 0.5\n");
    EXPECT_EQ(cfg.map_metrics.classes, std::vector<std::string>{removed_class});
    EXPECT_DOUBLE_EQ(cfg.map_metrics.max_center_dist_m, 0.5);
    const auto maps = evaluateBatchMaps(cfg);
    ASSERT_EQ(maps[0].metrics.per_class.size(), 1u);
    EXPECT_EQ(maps[0].map.name, "minus");  // default label: the directory's name
    EXPECT_DOUBLE_EQ(maps[0].metrics.recall,
                     static_cast<double>(n_removed_class - 1) / static_cast<double>(n_removed_class));
}

TEST_F(BatchMapsFixture, MissingOrMalformedMapNamesKeyAndPath) {
    const std::string missing = (root / "no_such_map").string();
    auto cfg = load("maps = " + missing);
    std::string e = simp_test::errorOf([&] { evaluateBatchMaps(cfg); });
    EXPECT_NE(e.find("[batch] maps"), std::string::npos) << e;
    EXPECT_NE(e.find(missing), std::string::npos) << e;
    EXPECT_NE(e.find("directory not found"), std::string::npos) << e;

    const fs::path broken = root / "broken";  // a folder with a floor plan but a malformed objects.json
    simp::world::saveWorld(truth, broken.string());
    std::ofstream(broken / "objects.json") << "{\"classes\": [";
    cfg = load("maps = " + broken.string());
    e = simp_test::errorOf([&] { evaluateBatchMaps(cfg); });
    EXPECT_NE(e.find("[batch] maps"), std::string::npos) << e;
    EXPECT_NE(e.find(broken.string()), std::string::npos) << e;
    EXPECT_NE(e.find("not a world directory"), std::string::npos) << e;

    cfg = load("maps = " + (root / "same").string() + "\nmap_ground_truths = " + missing);
    e = simp_test::errorOf([&] { evaluateBatchMaps(cfg); });
    EXPECT_NE(e.find("[batch] map_ground_truths"), std::string::npos) << e;
    EXPECT_NE(e.find(missing), std::string::npos) << e;
}

TEST_F(BatchMapsFixture, MapKeysAreChecked) {
    const auto error = [&](const std::string& keys) { return simp_test::errorOf([&] { load(keys); }); };
    EXPECT_NE(error("maps = a b\nmap_names = x").find("[batch] map_names"), std::string::npos);
    EXPECT_NE(error("map_names = x").find("given without [batch] maps"), std::string::npos);
    EXPECT_NE(error("maps = a b c\nmap_ground_truths = g h").find("[batch] map_ground_truths"), std::string::npos);
    EXPECT_NE(error("maps = x/m y/m").find("two entries are named 'm'"), std::string::npos);
    EXPECT_NE(error("maps = a\nmap_names = x/y").find("cannot label"), std::string::npos);
    EXPECT_EQ(load("maps = out/built/").batchMaps()[0].name, "built");  // a trailing '/' still names it
}
