#pragma once
/// \file FigureColors.h
/// The project's one palette (simp/obs/Palette.h) as OpenCV BGR colours for the 2D figures.

#include <opencv2/core.hpp>
#include <simp/obs/Palette.h>

#include <cstddef>
#include <string>
#include <vector>

namespace simp::eval {

/// OpenCV's BGR order of an RGB palette colour.
inline cv::Scalar toBgr(const obs::Rgb& rgb) {
    return {static_cast<double>(rgb[2]), static_cast<double>(rgb[1]), static_cast<double>(rgb[0])};
}

/// BGR colour of the class called `class_name` (obs::classColorRgb: the same in every figure and 3D view).
/// The palette's text and grid colours in OpenCV's BGR (axes, labels, grid lines of every figure).
inline const cv::Scalar kTextBgr = toBgr(obs::figure_colors::kText);
inline const cv::Scalar kGridBgr = toBgr(obs::figure_colors::kGrid);

inline cv::Scalar classColor(const std::string& class_name) { return toBgr(obs::classColorRgb(class_name)); }

/// BGR colour of class `class_id` of the list `class_names` (a world's objects.class_names).
inline cv::Scalar classColor(int class_id, const std::vector<std::string>& class_names) {
    return toBgr(obs::classColorRgb(class_id, class_names));
}

/// BGR colour of class `class_id` of the detector's list (obs::defaultClassNames()).
inline cv::Scalar classColor(int class_id) { return toBgr(obs::classColorRgb(class_id)); }

/// BGR colour of series `i` of a chart (obs::seriesColorRgb).
inline cv::Scalar seriesColor(std::size_t i) { return toBgr(obs::seriesColorRgb(i)); }

}  // namespace simp::eval
