// The figures: sizes, the colours of what they show, PNG files.
#include "PixelCount.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <simp/eval/Canvas.h>
#include <simp/eval/FigureColors.h>
#include <simp/eval/Plots.h>
#include <simp/eval/PngFile.h>
#include <simp/eval/ScaleBar.h>
#include <simp/obs/ObjectClasses.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace simp::eval;
namespace fc = simp::obs::figure_colors;

namespace {

/// A 10 m x 6 m free floor with a wall along x at y = 5 m, 0.05 m cells.
simp::world::World smallWorld() {
    simp::world::World w;
    w.floorplan.setSize(0.0, 10.0, 0.0, 6.0, 0.05, 1.0f);
    const int wall_cy = 100;  // cell row [5.00, 5.05) m
    for (int cx = 0; cx < static_cast<int>(w.floorplan.getSizeX()); ++cx) w.floorplan.setCell(cx, wall_cy, 0.0f);
    w.objects.class_names = {"table", "chair"};
    w.objects.class_noise.resize(2);
    simp::world::MapObject table;
    table.box = simp::geometry::makeUprightBox({3, 2, 0.4}, {2, 1, 0.8}, 0.3);
    simp::world::MapObject chair;
    chair.class_id = 1;
    chair.box = simp::geometry::makeUprightBox({7, 3, 0.4}, {0.5, 0.5, 0.8}, 0);
    w.objects.objects = {table, chair};
    return w;
}

using simp::eval::test::countColor;

}  // namespace

TEST(Plots, FloorplanCanvasMapsWorldToPixels) {
    const auto w = smallWorld();
    const Canvas c = makeFloorplanCanvas(w.floorplan, 2, 300);
    EXPECT_EQ(c.map_width_px, 400);  // 200 cells x 2
    EXPECT_EQ(c.image.rows, 240);
    EXPECT_EQ(c.image.cols, 700);
    EXPECT_EQ(c.toPixel(0.0, 6.0), cv::Point(0, 0));      // top-left = (x_min, y_max)
    EXPECT_EQ(c.toPixel(10.0, 0.0), cv::Point(400, 240));  // bottom-right
    // the wall at y = 5 m is black, free space white
    EXPECT_EQ(c.image(c.toPixel(5.0, 5.02).y, 200), cv::Vec3b(0, 0, 0));
    EXPECT_EQ(c.image(c.toPixel(5.0, 3.0).y, 200), cv::Vec3b(255, 255, 255));
}

TEST(Plots, TrajectoryFigureShowsBothPathsAndWritesPng) {
    const auto w = smallWorld();
    std::vector<simp::io::StampedPose2D> gt, est;
    for (int k = 0; k <= 20; ++k) {
        gt.push_back({0.5 * k, {1.0 + 0.4 * k, 1.0, 0.0}});
        est.push_back({0.5 * k, {k < 6 ? 8.0 : 1.0 + 0.4 * k, k < 6 ? 4.0 : 1.1, 0.0}});
    }
    const auto m = evaluateTrajectory(gt, est);
    ASSERT_TRUE(m.converged);
    const cv::Mat3b fig = drawTrajectoryFigure(gt, est, m, {}, &w);
    EXPECT_EQ(fig.cols, 700);
    EXPECT_EQ(fig.rows, 240 + 320);  // floor plan + error panel
    EXPECT_GT(countColor(fig, toBgr(fc::kGroundTruth)), 50);  // ground truth green
    EXPECT_GT(countColor(fig, toBgr(fc::kConvergence)), 20);   // convergence marker / line
    const auto png = (fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_plots" / "traj.png").string();
    writePng(png, fig);
    const cv::Mat back = cv::imread(png);
    EXPECT_EQ(back.size(), fig.size());
    // without a world: a blank canvas around the trajectories
    // without a world: a blank canvas around the trajectories (x in [1, 9] m, y in [1, 4] m, 1 m
    // margins, 1000 px / 8 m = 125 px/m), legend 300 px to the right
    const cv::Mat3b blank = drawTrajectoryFigure(gt, est, m, {}, nullptr);
    EXPECT_EQ(blank.cols, 10 * 125 + 300);
    EXPECT_EQ(blank.rows, 5 * 125 + 320);
}

TEST(Plots, ObjectMapAndMapEvaluationColours) {
    const auto w = smallWorld();
    const cv::Mat3b map_fig = drawObjectMap(w);
    EXPECT_GT(countColor(map_fig, classColor("table")), 30);  // table outline + legend swatch
    EXPECT_GT(countColor(map_fig, classColor("chair")), 30);

    auto pred = w;
    pred.objects.objects.pop_back();  // chair missed
    simp::world::MapObject ghost;
    ghost.box = simp::geometry::makeUprightBox({8, 1, 0.4}, {1, 1, 0.8}, 0);  // a false table
    pred.objects.objects.push_back(ghost);
    const auto m = evaluateMap(w.objects, pred.objects);
    ASSERT_EQ(m.matches.size(), 1u);
    ASSERT_EQ(m.missed_gt.size(), 1u);
    ASSERT_EQ(m.false_pred.size(), 1u);
    const cv::Mat3b eval_fig = drawMapEvaluation(w, pred, m);
    EXPECT_GT(countColor(eval_fig, toBgr(fc::kGroundTruth)), 30);  // matched
    EXPECT_GT(countColor(eval_fig, toBgr(fc::kMissed)), 30);       // missed
    EXPECT_GT(countColor(eval_fig, toBgr(fc::kWrong)), 30);        // false
}

TEST(Plots, UnwritablePathThrowsNamingIt) {
    const cv::Mat3b img(10, 10, cv::Vec3b(0, 0, 0));
    try {
        writePng((fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_plots" / "x.notanimage").string(), img);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("x.notanimage"), std::string::npos) << e.what();
    }
}

TEST(Plots, ScaleBarIsARoundLengthNearAFifthOfTheMap) {
    EXPECT_DOUBLE_EQ(scaleBarLength(10.0), 2.0);
    EXPECT_DOUBLE_EQ(scaleBarLength(26.0), 5.0);
    EXPECT_DOUBLE_EQ(scaleBarLength(60.0), 10.0);
    EXPECT_DOUBLE_EQ(scaleBarLength(3.0), 0.5);
    EXPECT_DOUBLE_EQ(scaleBarLength(0.2), 0.1);  // never below 0.1 m
}

TEST(Plots, MapFigureKeepsTheLegendBesideTheMapAndCarriesAScaleBar) {
    auto w = smallWorld();
    // 14 classes present: the legend needs more rows (scale bar + 14 x 24 px) than the 240 px map has
    w.objects.class_names.clear();
    w.objects.objects.clear();
    for (int k = 0; k < 14; ++k) {
        w.objects.class_names.push_back(simp::obs::defaultClassNames()[static_cast<std::size_t>(k)]);
        simp::world::MapObject o;
        o.id = k;
        o.class_id = k;
        o.box = simp::geometry::makeUprightBox({3.0 + 0.45 * k, 2.5, 0.4}, {0.3, 0.3, 0.8}, 0);
        w.objects.objects.push_back(o);
    }
    w.objects.class_noise.resize(14);
    const cv::Mat3b fig = drawObjectMap(w);
    const int map_w = 400, map_h = 240;  // 200 x 120 cells, 2 px each
    ASSERT_GT(fig.rows, map_h);          // grew for the legend
    const cv::Mat3b map_area = fig(cv::Rect(0, 0, map_w, map_h)), side = fig(cv::Rect(map_w, 0, fig.cols - map_w, fig.rows));
    for (int k = 0; k < 14; ++k) EXPECT_GE(countColor(side, classColor(k)), 22 * 14) << "legend swatch of class " << k;
    // nothing of the legend or the scale bar on the map: its corners (free floor) stay white
    EXPECT_EQ(countColor(map_area(cv::Rect(0, 0, 120, 30)), cv::Scalar(255, 255, 255)), 120 * 30);
    EXPECT_EQ(countColor(map_area(cv::Rect(0, map_h - 40, 160, 40)), cv::Scalar(255, 255, 255)), 160 * 40);
    // the scale bar (black) at the top of the strip: 2 m for a 10 m wide map, 80 px at 40 px/m, 3 px thick
    const int black = countColor(side(cv::Rect(0, 20, side.cols, 20)), cv::Scalar(0, 0, 0));
    EXPECT_GE(black, 2 * 40 * 3) << "a 2 m bar at 40 px/m, 3 px thick";
    writePng((fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_plots" / "map_14_classes.png").string(), fig);
}

TEST(Plots, TrajectoryMapShowsGroundTruthWhenGivenEstimateParticlesAndALegend) {
    const auto w = smallWorld();
    MapLayers layers;
    layers.floorplan = &w.floorplan;
    layers.objects = &w.objects;
    for (int k = 0; k <= 20; ++k) {
        layers.ground_truth.push_back({0.5 * k, {1.0 + 0.4 * k, 1.0, 0.0}});
        layers.estimate.push_back({0.5 * k, {1.0 + 0.4 * k, 1.5, 0.0}});
    }
    for (int k = 0; k < 50; ++k) layers.particles.push_back({8.5 + 0.01 * k, 4.0, 0.0});
    const cv::Scalar gt = toBgr(fc::kGroundTruth), est = toBgr(fc::kEstimate), particles = toBgr(fc::kParticles);
    const cv::Mat3b fig = drawTrajectoryMap(layers);
    const cv::Mat3b map_area = fig(cv::Rect(0, 0, 400, 240)), side = fig(cv::Rect(400, 0, fig.cols - 400, fig.rows));
    EXPECT_GT(countColor(map_area, gt), 100);
    EXPECT_GT(countColor(map_area, est), 100);
    EXPECT_GT(countColor(map_area, particles), 20);
    for (const auto& c : {gt, est, particles, classColor("table"), classColor("chair")})
        EXPECT_GE(countColor(side, c), 22 * 14) << "legend swatch " << c;
    writePng((fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_plots" / "trajectory_map.png").string(), fig);

    layers.ground_truth.clear();  // no ground truth: neither drawn nor in the legend
    EXPECT_EQ(countColor(drawTrajectoryMap(layers), gt), 0);
}

TEST(Plots, ChangeMapShowsTheObjectsTheSessionNeverSawApart) {
    auto w = smallWorld();
    w.objects.objects[0].id = 1;  // table: checked this session, unchanged
    w.objects.objects[1].id = 2;  // chair: never in view
    WorldBounds bounds;  // the figure's own canvas, to find the objects' pixels
    for (const auto& o : w.objects.objects) bounds.add(o.box);
    const Canvas canvas = makeCanvasFor(&w.floorplan, bounds);
    const cv::Point table = canvas.toPixel(3.0, 2.0), chair = canvas.toPixel(7.0, 3.0);
    const auto purpleness = [](const cv::Vec3b& bgr) { return int(bgr[0]) - int(bgr[1]); };  // blue over green

    const cv::Mat3b plain = drawChangeMap(w.floorplan, w.objects, {});
    const cv::Mat3b marked = drawChangeMap(w.floorplan, w.objects, {}, {2});
    ASSERT_EQ(plain.size(), marked.size());
    // Unchanged objects are filled grey (blue = green); the one never in view is filled purple.
    EXPECT_LE(std::abs(purpleness(plain(chair))), 2);
    EXPECT_GE(purpleness(marked(chair)), 15);
    EXPECT_EQ(marked(table), plain(table));
    // An object the report changes is drawn as the change, even when listed as never in view.
    simp::world::ChangeRecord removed;
    removed.kind = "removed";
    removed.id_before = 2;
    removed.class_name = "chair";
    removed.before = w.objects.objects[1].box;
    auto after = w.objects;
    after.objects.pop_back();
    EXPECT_EQ(cv::norm(drawChangeMap(w.floorplan, after, {removed}, {2}), drawChangeMap(w.floorplan, after, {removed}),
                      cv::NORM_INF),
              0.0);
}
