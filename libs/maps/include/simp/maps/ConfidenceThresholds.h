#pragma once
/// \file ConfidenceThresholds.h
/// Per-class minimum detector confidence: detections below it are ignored by the sensor model.

#include <map>
#include <string>

namespace simp::maps {

/// class name -> minimum confidence in [0, 1]; a detection is used when confidence >= threshold.
using ConfidenceThresholds = std::map<std::string, double>;

/// The paper's thresholds for its 14 classes (the authors' nmcl.config, "omni.confidence").
const ConfidenceThresholds& paperConfidenceThresholds();

/// Parses "name:value, name:value, ..." (class names may contain spaces; the value follows the
/// last ':'). Throws std::invalid_argument naming `where` and the offending entry on a missing
/// ':', an empty name, a value that is not a number in [0, 1], or a repeated name.
ConfidenceThresholds parseConfidenceThresholds(const std::string& text, const std::string& where);

/// The inverse of parseConfidenceThresholds ("name:value, ...", sorted by name).
std::string formatConfidenceThresholds(const ConfidenceThresholds& thresholds);

}  // namespace simp::maps
