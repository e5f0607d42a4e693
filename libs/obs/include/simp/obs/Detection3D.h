#pragma once
/// \file Detection3D.h
/// One 3D object detection of a camera frame, as a Cube R-CNN style detector outputs it.

#include <simp/geometry/Box3D.h>

#include <cstdint>
#include <optional>
#include <string>

namespace simp::obs {

/// Axis-aligned 2D box in the image (px): x right, y down, min <= max.
struct ImageBox2D {
    float x_min = 0, y_min = 0, x_max = 0, y_max = 0;
};

struct Detection3D {
    std::uint16_t class_id = 0;                ///< index into the observation's class_names
    float confidence = 1.0f;                   ///< detector score in [0, 1]
    geometry::Box3D box_in_camera;             ///< in the camera optical frame (x right, y down, z forward), m
    std::optional<ImageBox2D> box_2d;          ///< optional 2D detection box (px)
    std::optional<std::int64_t> detector_id;   ///< optional detector-specific id (track id, ...)
};

/// Throws std::invalid_argument naming `where` and the field when the detection is not usable:
/// a non-finite number, a size <= 0, a confidence outside [0, 1], a rotation that is not one,
/// a class id >= num_classes, an inverted 2D box.
void validateDetection(const Detection3D& d, std::size_t num_classes, const std::string& where);

}  // namespace simp::obs
