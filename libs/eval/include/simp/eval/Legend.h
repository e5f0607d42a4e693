#pragma once
/// \file Legend.h
/// A figure's legend: coloured swatches with their labels in the strip right of the map area,
/// never over the map (doc/figures.md).

#include <opencv2/core.hpp>
#include <simp/eval/Canvas.h>
#include <simp/world/ObjectMapData.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace simp::eval {

/// One line of a legend: label and BGR colour.
using LegendItem = std::pair<std::string, cv::Scalar>;

/// Draws `items` top-down in the strip right of the map area, below what the strip already holds
/// (the scale bar), one 24 px row each. The image grows (white) to the right when a label is
/// wider than the strip and downwards when the rows need more height than it has.
/// \return the legend's rectangle in image pixels (left of it is the map area, never overlapped).
cv::Rect drawLegend(Canvas& canvas, const std::vector<LegendItem>& items);

/// Legend items of the classes `present` (ids of `objects`), named from `objects.class_names`
/// ("class <id>" when an id has no name), in their palette colour (classColor by name).
std::vector<LegendItem> classLegend(const world::ObjectMapData& objects, const std::set<int>& present);

}  // namespace simp::eval
