/// \file ChangePlot.cpp
/// drawChangeMap (Plots.h): the figure of a map update's change report.
#include <opencv2/imgproc.hpp>
#include <simp/eval/Canvas.h>
#include <simp/eval/Plots.h>
#include <simp/geometry/Footprint.h>

#include <algorithm>
#include <limits>
#include <cstdint>
#include <set>

namespace simp::eval {

cv::Mat3b drawChangeMap(const mrpt::maps::COccupancyGridMap2D& grid, const world::ObjectMapData& map,
                        const std::vector<world::ChangeRecord>& changes) {
    // Kind colours (BGR) far from each other and from the light class outlines underneath.
    const cv::Scalar kRemoved(30, 30, 220), kMoved(0, 140, 255), kAdded(40, 170, 40);
    double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
    const auto extend = [&](const geometry::Box3D& b) {
        x0 = std::min(x0, b.center.x()), y0 = std::min(y0, b.center.y());
        x1 = std::max(x1, b.center.x()), y1 = std::max(y1, b.center.y());
    };
    for (const auto& o : map.objects) extend(o.box);
    for (const auto& c : changes) {
        if (c.before) extend(*c.before);
        if (c.after) extend(*c.after);
    }
    if (x0 > x1) x0 = y0 = 0, x1 = y1 = 1;
    Canvas c = makeCanvasFor(&grid, x0, y0, x1, y1);

    // Unchanged objects in grey: the class palette shares red and green with the kinds.
    const cv::Scalar kUnchanged(150, 150, 150);
    std::set<std::int64_t> changed_ids;
    for (const auto& ch : changes)
        if (ch.id_after) changed_ids.insert(*ch.id_after);
    int n_unchanged = 0;
    for (const auto& o : map.objects)
        if (!changed_ids.count(o.id)) {
            drawPolygon(c, geometry::footprint(o.box), kUnchanged, 1, 0.15);
            ++n_unchanged;
        }
    int n_removed = 0, n_moved = 0, n_added = 0;
    for (const auto& ch : changes) {
        if (ch.kind == "removed" && ch.before) {
            const auto fp = geometry::footprint(*ch.before);
            drawPolygon(c, fp, kRemoved, 2, 0.2);
            // Crossed out: the diagonals of the footprint.
            if (fp.n == 4) {
                const auto px = [&](std::size_t i) { return c.toPixel(fp.v[i].x(), fp.v[i].y()); };
                cv::line(c.image, px(0), px(2), kRemoved, 2);
                cv::line(c.image, px(1), px(3), kRemoved, 2);
            }
            ++n_removed;
        } else if (ch.kind == "moved" && ch.before && ch.after) {
            drawPolygon(c, geometry::footprint(*ch.before), kMoved, 1);
            drawPolygon(c, geometry::footprint(*ch.after), kMoved, 2, 0.45);
            cv::arrowedLine(c.image, c.toPixel(ch.before->center.x(), ch.before->center.y()),
                            c.toPixel(ch.after->center.x(), ch.after->center.y()), kMoved, 2, cv::LINE_AA, 0, 0.25);
            ++n_moved;
        } else if (ch.kind == "added" && ch.after) {
            drawPolygon(c, geometry::footprint(*ch.after), kAdded, 2, 0.45);
            ++n_added;
        }
    }
    drawScaleBar(c);
    std::vector<std::pair<std::string, cv::Scalar>> legend{{"removed (" + std::to_string(n_removed) + ")", kRemoved},
                                                           {"moved (" + std::to_string(n_moved) + ")", kMoved},
                                                           {"added (" + std::to_string(n_added) + ")", kAdded},
                                                           {"unchanged (" + std::to_string(n_unchanged) + ")", kUnchanged}};
    drawLegend(c, legend);
    return c.image;
}

}  // namespace simp::eval
