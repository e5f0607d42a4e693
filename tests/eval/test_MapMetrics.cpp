// Hand-made object maps with known IoU, precision and recall.
#include <gtest/gtest.h>
#include <simp/eval/MapMetrics.h>
#include <simp/geometry/Box3D.h>

#include <cmath>
#include <limits>

using simp::eval::evaluateMap;
using simp::eval::MapMatchParams;
using simp::world::MapObject;
using simp::world::ObjectMapData;

namespace {

/// An upright box with footprint lx x ly centred at (x, y), standing on the floor, height h.
MapObject object(int class_id, double x, double y, double lx, double ly, double h = 1.0, double yaw = 0.0) {
    MapObject o;
    o.class_id = class_id;
    o.box = simp::geometry::makeUprightBox({x, y, h / 2}, {lx, ly, h}, yaw);
    return o;
}

ObjectMapData mapWith(std::vector<std::string> classes, std::vector<MapObject> objects) {
    ObjectMapData m;
    m.class_names = std::move(classes);
    m.class_noise.resize(m.class_names.size());
    for (std::size_t i = 0; i < objects.size(); ++i) objects[i].id = static_cast<std::int64_t>(i);
    m.objects = std::move(objects);
    return m;
}

/// Ground truth: tables T1 (0,0) and T2 (5,0), 2 x 1 m, 1 m high; chair (10,10) 0.5 x 0.5; a sofa.
ObjectMapData knownGroundTruth() {
    return mapWith({"table", "chair", "sofa"},
                   {object(0, 0, 0, 2, 1), object(0, 5, 0, 2, 1), object(1, 10, 10, 0.5, 0.5), object(2, -5, -5, 2, 1)});
}

/// Prediction (another class order): table at (0.5,0), 0.5 m high; a table far from all; the
/// chair shifted by 0.25 m; a plant nobody has; no sofa.
ObjectMapData knownPrediction() {
    return mapWith({"chair", "table", "plant"}, {object(1, 0.5, 0, 2, 1, 0.5), object(1, 20, 20, 2, 1),
                                                 object(0, 10.25, 10, 0.5, 0.5), object(2, 3, 3, 0.4, 0.4)});
}

}  // namespace

TEST(MapMetrics, KnownPerClassAndAverageValues) {
    const auto gt = knownGroundTruth();
    const auto pred = knownPrediction();
    const auto m = evaluateMap(gt, pred);
    ASSERT_EQ(m.per_class.size(), 4u);  // chair, plant, sofa, table

    // table: footprints [-1,1]x[-.5,.5] and [-.5,1.5]x[-.5,.5] overlap 1.5 m^2, union 2.5 m^2 -> 0.6;
    // 3D: 0.75 m^3 / (2 + 1 - 0.75) m^3 = 1/3. One of two predicted matched, one of two GT.
    const auto& table = m.per_class.at("table");
    EXPECT_EQ(table.n_matched, 1u);
    EXPECT_NEAR(table.iou, 0.6, 1e-9);
    EXPECT_NEAR(table.iou_3d, 1.0 / 3.0, 1e-9);
    EXPECT_NEAR(table.precision, 0.5, 1e-12);
    EXPECT_NEAR(table.recall, 0.5, 1e-12);
    // chair: overlap 0.25 x 0.5 = 0.125, union 0.375 -> 1/3.
    const auto& chair = m.per_class.at("chair");
    EXPECT_NEAR(chair.iou, 1.0 / 3.0, 1e-9);
    EXPECT_NEAR(chair.precision, 1.0, 1e-12);
    EXPECT_NEAR(chair.recall, 1.0, 1e-12);
    // sofa: nothing predicted -> precision 0 (documented choice), recall 0, IoU 0.
    const auto& sofa = m.per_class.at("sofa");
    EXPECT_EQ(sofa.n_pred, 0u);
    EXPECT_EQ(sofa.precision, 0.0);
    EXPECT_EQ(sofa.recall, 0.0);
    EXPECT_EQ(sofa.iou, 0.0);
    // plant: no ground truth -> all 0.
    const auto& plant = m.per_class.at("plant");
    EXPECT_EQ(plant.n_gt, 0u);
    EXPECT_EQ(plant.precision, 0.0);
    EXPECT_EQ(plant.recall, 0.0);

    // Averages over the 4 classes.
    EXPECT_NEAR(m.iou, (0.6 + 1.0 / 3.0) / 4.0, 1e-9);
    EXPECT_NEAR(m.precision, (0.5 + 1.0) / 4.0, 1e-12);
    EXPECT_NEAR(m.recall, (0.5 + 1.0) / 4.0, 1e-12);
    EXPECT_EQ(m.matches.size(), 2u);
    EXPECT_EQ(m.missed_gt.size(), 2u);   // T2 and the sofa
    EXPECT_EQ(m.false_pred.size(), 2u);  // the far table and the plant
}

TEST(MapMetrics, CentreDistanceGate) {
    // Boards 4 x 0.2 m shifted by 1.5 m along their length: IoU = 0.5 / (0.8 + 0.8 - 0.5) = 0.4545 > 0,
    // but the centres are 1.5 m apart: no match with the 1.0 m gate, a match with a 2.0 m gate.
    const auto gt = mapWith({"board"}, {object(0, 0, 0, 4, 0.2)});
    const auto pred = mapWith({"board"}, {object(0, 1.5, 0, 4, 0.2)});
    EXPECT_EQ(evaluateMap(gt, pred).per_class.at("board").n_matched, 0u);
    MapMatchParams wide;
    wide.max_center_dist_m = 2.0;
    const auto m = evaluateMap(gt, pred, wide);
    EXPECT_EQ(m.per_class.at("board").n_matched, 1u);
    EXPECT_NEAR(m.iou, 0.5 / 1.1, 1e-9);
}

TEST(MapMetrics, HungarianBeatsGreedyMatching) {
    // Unit squares on the x axis: the IoU of two squares shifted by d is (1 - d) / (1 + d).
    // GT A at 0, B at 7/12; predictions X at 1/3, Y at 21/20.
    // IoU(X,A) = 0.5 (d = 1/3), IoU(X,B) = 0.6 (d = 1/4), IoU(Y,B) = 4/11 (d = 7/15),
    // IoU(Y,A) = 0 (d > 1, inadmissible). Greedy (best IoU first) would take X-B and leave Y
    // alone; the assignment takes X-A and Y-B: two matches, mean IoU (1/2 + 4/11) / 2.
    const auto gt = mapWith({"desk"}, {object(0, 0, 0, 1, 1), object(0, 7.0 / 12.0, 0, 1, 1)});
    const auto pred = mapWith({"desk"}, {object(0, 1.0 / 3.0, 0, 1, 1), object(0, 1.05, 0, 1, 1)});
    const auto m = evaluateMap(gt, pred);
    const auto& desk = m.per_class.at("desk");
    EXPECT_EQ(desk.n_matched, 2u);
    EXPECT_NEAR(desk.iou, (0.5 + 4.0 / 11.0) / 2.0, 1e-9);
    EXPECT_NEAR(desk.precision, 1.0, 1e-12);
    EXPECT_NEAR(desk.recall, 1.0, 1e-12);
}

TEST(MapMetrics, RotatedFootprints) {
    // The same 2 x 1 box rotated by 90 degrees about its centre: the footprints overlap in a 1 x 1
    // square: IoU = 1 / (2 + 2 - 1) = 1/3.
    const auto gt = mapWith({"sofa"}, {object(0, 0, 0, 2, 1)});
    const auto pred = mapWith({"sofa"}, {object(0, 0, 0, 2, 1, 1.0, M_PI / 2)});
    EXPECT_NEAR(evaluateMap(gt, pred).iou, 1.0 / 3.0, 1e-9);
}

TEST(MapMetrics, IdenticalMapsArePerfect) {
    const auto gt = mapWith({"table", "sink"}, {object(0, 0, 0, 2, 1), object(1, 3, 1, 0.6, 0.5)});
    const auto m = evaluateMap(gt, gt);
    EXPECT_NEAR(m.iou, 1.0, 1e-9);
    EXPECT_NEAR(m.iou_3d, 1.0, 1e-9);
    EXPECT_EQ(m.precision, 1.0);
    EXPECT_EQ(m.recall, 1.0);
}

TEST(MapMetrics, BadInputThrowsNamingTheObject) {
    const auto gt = mapWith({"table"}, {object(0, 0, 0, 2, 1)});
    auto bad_class = mapWith({"table"}, {object(3, 0, 0, 2, 1)});
    try {
        evaluateMap(gt, bad_class);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("predicted map: object 0"), std::string::npos) << e.what();
    }
    auto nan_box = mapWith({"table"}, {object(0, 0, 0, 2, 1)});
    nan_box.objects[0].box.center.x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(evaluateMap(nan_box, gt), std::invalid_argument);
    EXPECT_THROW(evaluateMap(mapWith({"table"}, {}), mapWith({"table"}, {})), std::invalid_argument);
    // one empty map is valid: every class scores 0
    const auto m = evaluateMap(gt, mapWith({}, {}));
    EXPECT_EQ(m.per_class.size(), 1u);
    EXPECT_EQ(m.recall, 0.0);
}

TEST(MapMetrics, ClassSelectionLeavesOtherClassesOut) {
    // Same maps as above; evaluating only table and chair drops the plant (no GT: precision 0)
    // and the sofa (nothing predicted: recall 0) from the averages, as the paper's Table I does
    // for classes the mapper does not build.
    const auto gt = knownGroundTruth();
    const auto pred = knownPrediction();
    MapMatchParams only;
    only.classes = {"table", "chair"};
    const auto m = evaluateMap(gt, pred, only);
    ASSERT_EQ(m.per_class.size(), 2u);
    EXPECT_NEAR(m.iou, (0.6 + 1.0 / 3.0) / 2.0, 1e-9);
    EXPECT_NEAR(m.precision, (0.5 + 1.0) / 2.0, 1e-12);
    EXPECT_NEAR(m.recall, (0.5 + 1.0) / 2.0, 1e-12);
    EXPECT_TRUE(m.false_pred.size() == 1u);  // the far table; the plant is not evaluated
    // Selecting only classes that neither map has is an error, not a silent 0.
    MapMatchParams none;
    none.classes = {"piano"};
    EXPECT_THROW(evaluateMap(gt, pred, none), std::invalid_argument);
}
