// The figure style (doc/figures.md): a class has one colour in every figure whatever its id, the
// scale bar spans its metres at the map's scale, the legend and the scale bar lie right of the map.
#include "PixelCount.h"

#include <gtest/gtest.h>
#include <simp/eval/Canvas.h>
#include <simp/eval/FigureColors.h>
#include <simp/eval/Legend.h>
#include <simp/eval/Plots.h>
#include <simp/eval/PngFile.h>
#include <simp/eval/ScaleBar.h>
#include <simp/geometry/Box3D.h>
#include <simp/obs/ObjectClasses.h>

#include <cmath>
#include <filesystem>

namespace fs = std::filesystem;
using namespace simp::eval;

namespace {

/// A free floor `width_m` x `height_m` with `resolution_m` cells.
mrpt::maps::COccupancyGridMap2D freeFloor(double width_m, double height_m, double resolution_m) {
    mrpt::maps::COccupancyGridMap2D g;
    g.setSize(0.0, width_m, 0.0, height_m, resolution_m, 1.0f);
    return g;
}

simp::world::MapObject object(int id, int class_id, double x, double y) {
    simp::world::MapObject o;
    o.id = id;
    o.class_id = class_id;
    o.box = simp::geometry::makeUprightBox({x, y, 0.4}, {0.8, 0.6, 0.8}, 0.0);
    return o;
}

using simp::eval::test::countColor;

}  // namespace

TEST(FigureStyle, AClassHasOneColourWhateverItsIdInAnyFigure) {
    // The detector's 14 classes: 14 different colours, the same whatever the spelling.
    const auto& names = simp::obs::defaultClassNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        for (std::size_t j = i + 1; j < names.size(); ++j)
            EXPECT_NE(classColor(names[i]), classColor(names[j])) << names[i] << " / " << names[j];
    EXPECT_EQ(classColor("potted plant"), classColor("Potted_Plant"));

    // Two worlds number "chair" differently (1 of {table, chair}; 10 of the detector's list).
    const auto floor = freeFloor(10.0, 6.0, 0.05);
    simp::world::ObjectMapData short_list;
    short_list.class_names = {"table", "chair"};
    short_list.class_noise.resize(2);
    short_list.objects = {object(1, 1, 4.0, 3.0)};
    simp::world::ObjectMapData detector_list;
    detector_list.class_names = names;
    detector_list.class_noise.resize(names.size());
    detector_list.objects = {object(1, simp::obs::classIndexOf(names, "chair"), 4.0, 3.0)};

    // Two figure writers: simp-map's map.png (drawObjectMap) and simp-localize's trajectory.png /
    // simp-sim's overview.png (drawTrajectoryMap).
    const cv::Mat3b map_png = drawObjectMap(floor, short_list);
    MapLayers layers;
    layers.floorplan = &floor;
    layers.objects = &detector_list;
    const cv::Mat3b trajectory_png = drawTrajectoryMap(layers);

    const cv::Scalar chair = classColor("chair");
    EXPECT_EQ(chair, toBgr(simp::obs::classColorRgb(1, short_list.class_names)));
    const cv::Rect map_area(0, 0, 400, 240);  // 200 x 120 cells, 2 px each
    for (const cv::Mat3b* fig : {&map_png, &trajectory_png}) {
        // the chair's legend swatch (22 x 14 px) in the palette's colour, beside the map
        EXPECT_EQ(countColor((*fig)(cv::Rect(400, 0, fig->cols - 400, fig->rows)), chair), 22 * 14);
        // not the colour of class id 1 of the detector's list (door)
        EXPECT_EQ(countColor(*fig, classColor("door")), 0);
    }
    // map.png's outline (2 px) is the palette's colour at the chair's left edge (x = 3.6 m, an
    // axis-aligned edge); trajectory.png's thin outline is anti-aliased, so it is compared below.
    const cv::Point left_edge(static_cast<int>(std::lround(3.6 * 40)), static_cast<int>(std::lround((6.0 - 3.0) * 40)));
    const cv::Vec3b c(static_cast<uchar>(chair[0]), static_cast<uchar>(chair[1]), static_cast<uchar>(chair[2]));
    EXPECT_EQ(map_png(left_edge), c);
    // Each writer draws the chair the same whichever id it has: the map areas are pixel-identical.
    MapLayers short_layers = layers;
    short_layers.objects = &short_list;
    const cv::Mat3b diff_traj = drawTrajectoryMap(short_layers)(map_area) != trajectory_png(map_area);
    EXPECT_EQ(cv::countNonZero(diff_traj.reshape(1)), 0);
    const cv::Mat3b diff_map = drawObjectMap(floor, detector_list)(map_area) != map_png(map_area);
    EXPECT_EQ(cv::countNonZero(diff_map.reshape(1)), 0);
}

TEST(FigureStyle, UnknownClassNamesGetAFixedFallbackColour) {
    const auto a = simp::obs::classColorRgb("forklift");
    EXPECT_EQ(a, simp::obs::classColorRgb("Forklift"));
    EXPECT_NE(std::find(simp::obs::kFallbackClassColors.begin(), simp::obs::kFallbackClassColors.end(), a),
              simp::obs::kFallbackClassColors.end());
    for (const auto& name : simp::obs::defaultClassNames()) EXPECT_NE(simp::obs::classColorRgb(name), a) << name;
    // an id outside the list is "class <id>"
    EXPECT_EQ(simp::obs::classColorRgb(7, {"table"}), simp::obs::classColorRgb("class 7"));
    // the id-only overload reads the detector's list
    EXPECT_EQ(simp::obs::classColorRgb(10), simp::obs::classColorRgb("chair"));
}

TEST(FigureStyle, ScaleBarSpansItsMetresOverTheResolution) {
    struct Case {
        double width_m, resolution_m;
        int px_per_cell;
    };
    for (const Case& k : {Case{10.0, 0.05, 2}, Case{24.35, 0.05, 2}, Case{30.0, 0.1, 3}, Case{3.0, 0.02, 1}}) {
        const auto floor = freeFloor(k.width_m, 6.0, k.resolution_m);
        Canvas c = makeFloorplanCanvas(floor, k.px_per_cell);
        const ScaleBar bar = drawScaleBar(c);
        const double px_per_m = k.px_per_cell / floor.getResolution();
        EXPECT_EQ(bar.length_px, static_cast<int>(std::lround(bar.length_m / floor.getResolution() * k.px_per_cell)));
        EXPECT_EQ(bar.to.x - bar.from.x, bar.length_px);
        EXPECT_NEAR((bar.to.x - bar.from.x) / px_per_m, bar.length_m, 0.5 / px_per_m);
        // the pixels: black from the first tick to the last, white just outside, all right of the map
        const cv::Vec3b black(0, 0, 0), white(255, 255, 255);
        for (int x = bar.from.x; x <= bar.to.x; ++x) EXPECT_EQ(c.image(bar.from.y, x), black) << "column " << x;
        EXPECT_EQ(c.image(bar.from.y, bar.from.x - 1), white);
        EXPECT_EQ(c.image(bar.from.y, bar.to.x + 1), white);
        EXPECT_GE(bar.from.x, c.map_width_px);
        EXPECT_LT(bar.to.x, c.image.cols);
    }
    // 10 m wide at 40 px/m: 2 m = 80 px
    const auto floor = freeFloor(10.0, 6.0, 0.05);
    Canvas c = makeFloorplanCanvas(floor, 2);
    const ScaleBar bar = drawScaleBar(c);
    EXPECT_DOUBLE_EQ(bar.length_m, 2.0);
    EXPECT_EQ(bar.length_px, 80);
    // a map so wide that a fifth of it does not fit the strip: a shorter round length that does
    Canvas wide = makeFloorplanCanvas(freeFloor(200.0, 6.0, 0.1), 2);  // 20 px/m, a fifth = 40 m
    const ScaleBar fitted = drawScaleBar(wide);
    EXPECT_DOUBLE_EQ(fitted.length_m, 10.0);
    EXPECT_EQ(fitted.length_px, 200);
}

TEST(FigureStyle, LegendAndScaleBarLieRightOfTheMapAndNothingSpillsOver) {
    const auto floor = freeFloor(10.0, 6.0, 0.05);
    // A table half beyond the floor plan's right edge and a class with a long name.
    simp::world::ObjectMapData objects;
    objects.class_names = {"table", "a class whose name is far longer than three hundred pixels of text"};
    objects.class_noise.resize(2);
    objects.objects = {object(1, 0, 9.9, 3.0), object(2, 1, 5.0, 3.0)};
    const cv::Mat3b fig = drawObjectMap(floor, objects);
    const int map_w = 400, map_h = 240;
    EXPECT_GT(fig.cols, map_w + 300) << "the strip widened for the long label";
    const cv::Mat3b strip = fig(cv::Rect(map_w, 0, fig.cols - map_w, fig.rows));
    // the table is clipped at the map's edge: in the strip only its swatch has its colour
    EXPECT_EQ(countColor(strip, classColor("table")), 22 * 14);
    // the strip's first columns (between map and legend) stay white over the map's height
    EXPECT_EQ(countColor(strip(cv::Rect(0, 0, Canvas::kStripMargin, map_h)), cv::Scalar(255, 255, 255)),
              Canvas::kStripMargin * map_h);

    Canvas c = makeFloorplanCanvas(floor, 2);
    drawScaleBar(c);
    const cv::Rect legend = drawLegend(c, classLegend(objects, {0, 1}));
    EXPECT_GE(legend.x, c.map_width_px);
    EXPECT_TRUE((legend & c.mapArea()).empty());
    EXPECT_LE(legend.x + legend.width, c.image.cols);
    EXPECT_LE(legend.y + legend.height, c.image.rows);
    EXPECT_GE(legend.y, 40) << "below the scale bar";
    writePng((fs::path(SIMP_TEST_OUTPUT_DIR) / "eval_plots" / "figure_style.png").string(), fig);
}
