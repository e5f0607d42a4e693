#pragma once
/// \file Detections2D.h
/// 2D detections per image, the --detections2d input of simp-labels (doc/labels.md):
///  - CSV: header `image_id,class,x_min,y_min,x_max,y_max,score`, one detection per row;
///  - JSON: {"detections": [{"image_id", "class", "bbox": [x_min, y_min, x_max, y_max], "score"}]}.
/// Boxes in pixels (x right, y down). Classes by name.

#include <cstdint>
#include <string>
#include <vector>

namespace simp::labels {

struct Detection2D {
    std::int64_t image_id = 0;
    std::string class_name;
    double x_min = 0, y_min = 0, x_max = 0, y_max = 0;  ///< px
    double score = 1.0;
};

/// Reads by extension (.csv / .json). Classes are checked against `class_names`.
/// \throw std::runtime_error naming the file and line (CSV) or key (JSON): missing file, wrong
///        column count, non-number, unknown class, inverted box, missing key.
std::vector<Detection2D> readDetections2D(const std::string& path, const std::vector<std::string>& class_names);

}  // namespace simp::labels
