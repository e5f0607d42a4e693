#pragma once
/// \file NoiseModelFiles.h
/// Output files of simp-stats (doc/statistics.md):
///  - class_noise.json: an object map file (format "simp-object-map", doc/formats.md) with the
///    world's classes, the fitted "class_noise" block and no objects; loadObjectMap() reads it and
///    its "class_noise" block can be pasted into a world's objects.json unchanged;
///  - class_noise.csv: the authors' table `category,mx,my,sx,sy,b` in 0.05 m cells (px);
///  - class_noise_stats.csv: per class n, mu, Sigma and their standard errors (m, m^2).

#include <simp/stats/NoiseFit.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::stats {

/// `fits[c]` belongs to `class_names[c]`; nullopt = class not modelled.
void writeClassNoiseJson(const std::string& path, const std::vector<std::string>& class_names,
                         const std::vector<std::optional<NoiseFit>>& fits);
/// mx, my = mu / res; sx, sy = sqrt(Sigma_xx) / res, sqrt(Sigma_yy) / res (the authors' scales are
/// standard deviations in pixels of `resolution_m`); the correlation is only in the JSON.
void writeClassNoiseCsv(const std::string& path, const std::vector<std::optional<NoiseFit>>& fits,
                        double resolution_m = 0.05);
void writeClassNoiseStatsCsv(const std::string& path, const std::vector<std::string>& class_names,
                             const std::vector<std::optional<NoiseFit>>& fits);

}  // namespace simp::stats
