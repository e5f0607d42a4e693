#pragma once
/// \file Omni3DPredictions.h
/// Cube R-CNN / Omni3D predictions as JSON (doc/detector-io.md, "Predictions JSON"):
///   {"categories": [names] (optional, default obs::defaultClassNames()),
///    "images": [{"id", "timestamp", "camera"}] (optional),
///    "predictions": [{"image_id" | ("timestamp" and "camera"), "category" (name or id) | "category_id",
///                     "score", "center_cam" [3], "dimensions" [W, H, L], "R_cam" | "pose" (3x3),
///                     "bbox2D" [x0, y0, x1, y1] | "bbox" [x, y, w, h] (optional), "detector_id" (optional)}]}
/// A top-level array is read as the "predictions" list (Omni3D's results file).

#include <simp/detector_io/DetectionSet.h>

#include <string>

namespace simp::detector_io {

/// \throw std::runtime_error naming the file and the key (e.g. "predictions[3].R_cam") on a missing
///        file, invalid JSON, missing key, non-number, unknown class, unknown image id, bad box.
DetectionSet readOmni3DPredictions(const std::string& path);
/// Writes `set` in the same format (images list + predictions with image_id, category by name,
/// category_id, full double precision).
void writeOmni3DPredictions(const std::string& path, const DetectionSet& set);

}  // namespace simp::detector_io
