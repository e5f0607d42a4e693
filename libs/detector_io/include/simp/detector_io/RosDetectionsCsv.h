#pragma once
/// \file RosDetectionsCsv.h
/// The authors' ROS detection array as CSV (doc/detector-io.md, "ROS detections CSV"): one row per
/// camera image, `timestamp, camera, {8 corners x (x, y, z) in the camera frame, confidence, class} * N`
/// = 2 + 26 N comma-separated fields. Corners in Omni3D order v0..v7 (Omni3DBox.h); camera = a
/// rig camera name or its index in the rig (0-based); class = class id (index into the class list).
/// Empty lines and lines starting with '#' are skipped; so is a first line starting with "timestamp".

#include <simp/detector_io/DetectionSet.h>

#include <string>

namespace simp::detector_io {

/// Reads the CSV; `class_names` is the label set the class ids index; a numeric camera is
/// resolved to the rig's camera name. Each box is fitted to its corners (boxFromOmni3DCorners()).
/// \throw std::runtime_error naming the file, line (1-based) and column on a missing file, a wrong
///        column count, a non-number, an unknown class or camera, degenerate corners.
DetectionSet readRosDetectionsCsv(const std::string& path, const std::vector<std::string>& class_names,
                                  const CameraRig& rig);
/// Writes one row per image (camera as its name, full double precision, with a '#' header line).
void writeRosDetectionsCsv(const std::string& path, const DetectionSet& set);

}  // namespace simp::detector_io
