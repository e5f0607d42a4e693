/// \file ChangePlot.cpp
/// drawChangeMap (Plots.h): the figure of a map update's change report.
#include <opencv2/imgproc.hpp>
#include <simp/eval/Canvas.h>
#include <simp/eval/FigureColors.h>
#include <simp/eval/Legend.h>
#include <simp/eval/Plots.h>
#include <simp/eval/ScaleBar.h>
#include <simp/geometry/Footprint.h>

#include <cstdint>
#include <set>

namespace simp::eval {

cv::Mat3b drawChangeMap(const mrpt::maps::COccupancyGridMap2D& grid, const world::ObjectMapData& map,
                        const std::vector<world::ChangeRecord>& changes, const std::set<std::int64_t>& unseen_ids) {
    // Kind colours far from each other; unchanged objects in grey, not in their class colour
    // (the class palette has reds and greens too).
    namespace fc = obs::figure_colors;
    const cv::Scalar kRemoved = toBgr(fc::kWrong), kMoved = toBgr(fc::kMoved), kAdded = toBgr(fc::kGroundTruth),
                     kUnchanged = toBgr(fc::kUnchanged), kUnseen = toBgr(fc::kUnseen),
                     kDoorClosed = toBgr(fc::kDoorClosed);
    WorldBounds bounds;
    for (const auto& o : map.objects) bounds.add(o.box);
    for (const auto& ch : changes) {
        if (ch.before) bounds.add(*ch.before);
        if (ch.after) bounds.add(*ch.after);
    }
    Canvas c = makeCanvasFor(&grid, bounds);
    cv::Mat3b on_map = c.map();

    std::set<std::int64_t> changed_ids;
    for (const auto& ch : changes)
        if (ch.id_after) changed_ids.insert(*ch.id_after);
    int n_unchanged = 0, n_unseen = 0;
    for (const auto& o : map.objects) {
        if (changed_ids.count(o.id)) continue;
        const bool unseen = unseen_ids.count(o.id) > 0;
        drawPolygon(c, geometry::footprint(o.box), unseen ? kUnseen : kUnchanged, 1, unseen ? 0.25 : 0.15);
        ++(unseen ? n_unseen : n_unchanged);
    }
    int n_removed = 0, n_moved = 0, n_added = 0, n_doors_closed = 0;
    for (const auto& ch : changes) {
        if (ch.kind == "removed" && ch.before) {
            const auto fp = geometry::footprint(*ch.before);
            drawPolygon(c, fp, kRemoved, 2, 0.2);
            // Crossed out: the diagonals of the footprint.
            if (fp.n == 4) {
                const auto px = [&](std::size_t i) { return c.toPixel(fp.v[i].x(), fp.v[i].y()); };
                cv::line(on_map, px(0), px(2), kRemoved, 2);
                cv::line(on_map, px(1), px(3), kRemoved, 2);
            }
            ++n_removed;
        } else if (ch.kind == "moved" && ch.before && ch.after) {
            drawPolygon(c, geometry::footprint(*ch.before), kMoved, 1);
            drawPolygon(c, geometry::footprint(*ch.after), kMoved, 2, 0.45);
            cv::arrowedLine(on_map, c.toPixel(ch.before->center.x(), ch.before->center.y()),
                            c.toPixel(ch.after->center.x(), ch.after->center.y()), kMoved, 2, cv::LINE_AA, 0, 0.25);
            ++n_moved;
        } else if (ch.kind == "added" && ch.after) {
            drawPolygon(c, geometry::footprint(*ch.after), kAdded, 2, 0.45);
            ++n_added;
        } else if (ch.kind == "door_closed" && ch.after) {
            drawPolygon(c, geometry::footprint(*ch.after), kDoorClosed, 3, 1.0);
            ++n_doors_closed;
        }
    }
    drawScaleBar(c);
    std::vector<LegendItem> legend{{"removed (" + std::to_string(n_removed) + ")", kRemoved},
                                                           {"moved (" + std::to_string(n_moved) + ")", kMoved},
                                                           {"added (" + std::to_string(n_added) + ")", kAdded},
                                                           {"door closed (" + std::to_string(n_doors_closed) + ")", kDoorClosed},
                                                           {"unchanged (" + std::to_string(n_unchanged) + ")", kUnchanged},
                                                           {"not in view (" + std::to_string(n_unseen) + ")", kUnseen}};
    drawLegend(c, legend);
    return c.image;
}

}  // namespace simp::eval
