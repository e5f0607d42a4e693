#include <simp/lidar/IcpOptions.h>

namespace simp::lidar {

void IcpPosesOptions::loadFromConfig(const io::StrictIni& cfg, const std::string& s) {
    scan_decimation = static_cast<int>(cfg.readInteger(s, "scan_decimation", scan_decimation, 1, 1000));
    max_range_m = cfg.readNumber(s, "max_range_m", max_range_m, 0.1, 1000);
    max_iterations = static_cast<int>(cfg.readInteger(s, "max_iterations", max_iterations, 1, 10000));
    threshold_dist_m = cfg.readNumber(s, "threshold_dist_m", threshold_dist_m, 1e-3, 10);
    threshold_ang_deg = cfg.readNumber(s, "threshold_ang_deg", threshold_ang_deg, 0, 90);
    alfa = cfg.readNumber(s, "alfa", alfa, 0.01, 0.99);
    smallest_threshold_dist_m = cfg.readNumber(s, "smallest_threshold_dist_m", smallest_threshold_dist_m, 1e-4, 10);
    min_points = static_cast<int>(cfg.readInteger(s, "min_points", min_points, 3, 100000));
    min_goodness = cfg.readNumber(s, "min_goodness", min_goodness, 0, 1);
    max_correction_m = cfg.readNumber(s, "max_correction_m", max_correction_m, 0, 100);
    max_correction_deg = cfg.readNumber(s, "max_correction_deg", max_correction_deg, 0, 180);
}

}  // namespace simp::lidar
