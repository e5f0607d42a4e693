/// \file MapPlot.cpp
/// drawObjectMap and drawMapEvaluation (Plots.h): object maps over the floor plan.
#include <simp/eval/Canvas.h>
#include <simp/eval/FigureColors.h>
#include <simp/eval/Legend.h>
#include <simp/eval/Plots.h>
#include <simp/eval/ScaleBar.h>
#include <simp/geometry/Footprint.h>

#include <set>

namespace simp::eval {
namespace {

namespace fc = obs::figure_colors;

/// Canvas over the floor plan, or over the objects' extent when there is no floor plan.
Canvas canvasFor(const mrpt::maps::COccupancyGridMap2D& grid, const world::ObjectMapData& objects,
                 const world::ObjectMapData* extra = nullptr) {
    WorldBounds bounds;
    for (const auto* map : {&objects, extra})
        if (map)
            for (const auto& o : map->objects) bounds.add(o.box);
    return makeCanvasFor(&grid, bounds);
}

}  // namespace

cv::Mat3b drawObjectMap(const world::World& w) { return drawObjectMap(w.floorplan, w.objects); }

cv::Mat3b drawObjectMap(const mrpt::maps::COccupancyGridMap2D& grid, const world::ObjectMapData& objects) {
    Canvas c = canvasFor(grid, objects);
    std::set<int> present;
    for (const auto& o : objects.objects) {
        drawPolygon(c, geometry::footprint(o.box), classColor(o.class_id, objects.class_names), 2, 0.35);
        present.insert(o.class_id);
    }
    drawScaleBar(c);
    drawLegend(c, classLegend(objects, present));
    return c.image;
}

cv::Mat3b drawMapEvaluation(const world::World& gt, const world::World& map, const MapMetrics& m) {
    const cv::Scalar kMatched = toBgr(fc::kGroundTruth), kMissed = toBgr(fc::kMissed), kFalse = toBgr(fc::kWrong);
    Canvas c = canvasFor(gt.floorplan, gt.objects, &map.objects);
    for (const auto& match : m.matches) {
        drawPolygon(c, geometry::footprint(gt.objects.objects.at(match.gt_index).box), kMatched, 2, 0.3);
        drawPolygon(c, geometry::footprint(map.objects.objects.at(match.pred_index).box), kMatched, 1);
    }
    for (std::size_t i : m.missed_gt) drawPolygon(c, geometry::footprint(gt.objects.objects.at(i).box), kMissed, 2, 0.3);
    for (std::size_t i : m.false_pred) drawPolygon(c, geometry::footprint(map.objects.objects.at(i).box), kFalse, 2, 0.3);
    drawScaleBar(c);
    drawLegend(c, {{"matched (" + std::to_string(m.matches.size()) + ")", kMatched},
                   {"missed ground truth (" + std::to_string(m.missed_gt.size()) + ")", kMissed},
                   {"false map object (" + std::to_string(m.false_pred.size()) + ")", kFalse}});
    return c.image;
}

}  // namespace simp::eval
