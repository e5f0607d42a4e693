#include <simp/eval/Canvas.h>
#include <simp/eval/Plots.h>
#include <simp/geometry/Footprint.h>

#include <algorithm>
#include <limits>
#include <set>

namespace simp::eval {
namespace {

/// Canvas over the floor plan, or over the objects' extent when there is no floor plan.
Canvas canvasFor(const mrpt::maps::COccupancyGridMap2D& grid, const world::ObjectMapData& objects,
                 const world::ObjectMapData* extra = nullptr) {
    double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
    for (const auto* map : {&objects, extra}) {
        if (!map) continue;
        for (const auto& o : map->objects) {
            x0 = std::min(x0, o.box.center.x()), y0 = std::min(y0, o.box.center.y());
            x1 = std::max(x1, o.box.center.x()), y1 = std::max(y1, o.box.center.y());
        }
    }
    if (x0 > x1) x0 = y0 = 0, x1 = y1 = 1;
    return makeCanvasFor(&grid, x0, y0, x1, y1);
}

}  // namespace

cv::Mat3b drawObjectMap(const world::World& w) { return drawObjectMap(w.floorplan, w.objects); }

cv::Mat3b drawObjectMap(const mrpt::maps::COccupancyGridMap2D& grid, const world::ObjectMapData& objects) {
    Canvas c = canvasFor(grid, objects);
    std::set<int> present;
    for (const auto& o : objects.objects) {
        drawPolygon(c, geometry::footprint(o.box), classColor(o.class_id), 2, 0.35);
        present.insert(o.class_id);
    }
    drawScaleBar(c);
    drawLegend(c, classLegend(objects, present));
    return c.image;
}

cv::Mat3b drawMapEvaluation(const world::World& gt, const world::World& map, const MapMetrics& m) {
    const cv::Scalar kMatched(40, 170, 40), kMissed(220, 120, 0), kFalse(30, 30, 220);
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
