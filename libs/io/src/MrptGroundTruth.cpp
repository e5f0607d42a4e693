/// \file MrptGroundTruth.cpp
/// pf-localization's ground-truth file (MrptGroundTruth.h).

#include <simp/io/MrptGroundTruth.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace simp::io {

double mrptGroundTruthTime(double t_s) { return std::floor(t_s) == t_s ? t_s + 1e-6 : t_s; }

void writeMrptGroundTruth(const std::string& path, const std::vector<StampedPose2D>& poses) {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    std::ofstream f(path);
    if (!f) throw std::runtime_error(path + ": cannot be written (pf-localization ground truth)");
    f << "# ground truth for MRPT pf-localization (ground_truth_path_file): t_s x_m y_m phi_rad\n";
    char line[160];
    for (const auto& p : poses) {
        std::snprintf(line, sizeof(line), "%.6f %.9f %.9f %.9f\n", mrptGroundTruthTime(p.t_s), p.pose.x, p.pose.y,
                      p.pose.phi);
        f << line;
    }
    if (!f) throw std::runtime_error(path + ": write failed (pf-localization ground truth)");
}

}  // namespace simp::io
