#pragma once
/// \file ScaleBar.h
/// The scale bar of every map figure: a round length (1, 2 or 5 x 10^k m) drawn with its label at
/// the top of the strip right of the map, at the map's scale (doc/figures.md).

#include <opencv2/core.hpp>
#include <simp/eval/Canvas.h>

namespace simp::eval {

/// Length (m) of a scale bar for a map `map_width_m` wide: the largest 1, 2 or 5 x 10^k m not
/// above a fifth of the width (0.1 m at least).
double scaleBarLength(double map_width_m);

/// The largest 1, 2 or 5 x 10^k m not above `max_m` (0.1 m at least).
double roundLengthAtMost(double max_m);

/// What drawScaleBar drew: `length_m` metres spanning `length_px` = round(length_m * px_per_m)
/// pixels from `from` to `to` (image pixels, one row; the bar's ink covers columns [from.x, to.x]).
struct ScaleBar {
    double length_m = 0;
    int length_px = 0;
    cv::Point from, to;
};

/// Draws the scale bar ("2 m", ...) at the top of the strip right of the map area (the strip is
/// widened to 140 px when narrower): scaleBarLength of the map's width, shortened to the largest
/// round length that fits the strip. The strip's next free row moves below it (drawLegend
/// continues there).
ScaleBar drawScaleBar(Canvas& canvas);

}  // namespace simp::eval
