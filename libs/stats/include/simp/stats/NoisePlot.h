#pragma once
/// \file NoisePlot.h
/// PNG of one class's noise: the occurrence histogram as a heat map (object frame, x right,
/// y up, origin = object centre marked by a cross) with the fitted 1, 2 and 3 sigma ellipses.

#include <simp/stats/NoiseFit.h>

#include <string>

namespace simp::stats {

/// Writes `path` (PNG, creates parent folders). `pixels_per_cell` >= 1 scales the image.
/// \throw std::runtime_error naming the file when it cannot be written.
void writeNoisePng(const std::string& path, const Histogram2D& histogram, const NoiseFit& fit,
                   const std::string& title, int pixels_per_cell = 8);

}  // namespace simp::stats
