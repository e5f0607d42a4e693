#include <simp/io/StrictNumber.h>
#include <simp/sim/SensorParams.h>

#include <mrpt/system/string_utils.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace simp::sim {
namespace {

void check(bool ok, const std::string& section, const std::string& key, const std::string& what) {
    if (!ok) throw std::invalid_argument("[" + section + "] " + key + ": " + what);
}
bool prob(double v) { return v >= 0 && v <= 1; }

/// true / false / 1 / 0 / yes / no; absent keeps `def`; anything else throws naming the key.
bool readStrictBool(const mrpt::config::CConfigFileBase& cfg, const std::string& s, const std::string& key, bool def) {
    const std::string text = mrpt::system::trim(cfg.read_string(s, key, ""));
    if (text.empty()) return def;
    return io::parseBool(text, "[" + s + "] " + key);
}

std::vector<double> readPerClass(const mrpt::config::CConfigFileBase& cfg, const std::string& s, const std::string& key,
                                 const std::vector<double>& def, std::size_t num_classes) {
    const std::string text = cfg.read_string(s, key, "");
    if (text.empty()) return def;
    std::vector<double> out;
    std::istringstream is(text);
    std::string tok;
    while (is >> tok) {
        const auto v = io::parseFiniteNumber(tok);
        check(v && *v >= 0, s, key, "'" + tok + "' is not a number >= 0");
        out.push_back(*v);
    }
    check(out.size() == num_classes, s, key,
          "expected " + std::to_string(num_classes) + " values (one per class), got " + std::to_string(out.size()));
    return out;
}

}  // namespace

void CameraParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    count = cfg.read_int(s, "count", count);
    first_yaw_deg = cfg.read_double(s, "first_yaw_deg", first_yaw_deg);
    mount_radius_m = cfg.read_double(s, "mount_radius_m", mount_radius_m);
    height_m = cfg.read_double(s, "height_m", height_m);
    pitch_down_deg = cfg.read_double(s, "pitch_down_deg", pitch_down_deg);
    const int width_px = cfg.read_int(s, "width_px", static_cast<int>(intrinsics.ncols));
    const int height_px = cfg.read_int(s, "height_px", static_cast<int>(intrinsics.nrows));
    const double fx = cfg.read_double(s, "fx", intrinsics.fx()), fy = cfg.read_double(s, "fy", intrinsics.fy());
    const double cx = cfg.read_double(s, "cx", intrinsics.cx()), cy = cfg.read_double(s, "cy", intrinsics.cy());
    rate_hz = cfg.read_double(s, "rate_hz", rate_hz);
    check(count >= 1 && count <= 16, s, "count", "must be in [1, 16]");
    check(width_px > 0 && height_px > 0, s, "width_px/height_px", "must be > 0");
    check(fx > 0 && fy > 0, s, "fx/fy", "must be > 0");
    intrinsics = camera::makeIntrinsics(width_px, height_px, fx, fy, cx, cy);
    check(rate_hz > 0 && std::isfinite(rate_hz), s, "rate_hz", "must be > 0");
    check(std::isfinite(height_m) && std::isfinite(mount_radius_m), s, "height_m/mount_radius_m", "must be finite");
}

void VisibilityParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s,
                                      std::size_t num_classes) {
    min_range_m = readPerClass(cfg, s, "min_range_m", min_range_m, num_classes);
    max_range_m = readPerClass(cfg, s, "max_range_m", max_range_m, num_classes);
    default_max_range_m = cfg.read_double(s, "default_max_range_m", default_max_range_m);
    min_inside_fraction = cfg.read_double(s, "min_inside_fraction", min_inside_fraction);
    wall_rays = cfg.read_int(s, "wall_rays", wall_rays);
    min_visible_ray_fraction = cfg.read_double(s, "min_visible_ray_fraction", min_visible_ray_fraction);
    self_margin_m = cfg.read_double(s, "self_margin_m", self_margin_m);
    max_occluded_fraction = cfg.read_double(s, "max_occluded_fraction", max_occluded_fraction);
    check(default_max_range_m > 0, s, "default_max_range_m", "must be > 0");
    check(prob(min_inside_fraction), s, "min_inside_fraction", "must be in [0, 1]");
    check(wall_rays >= 1 && wall_rays <= 17, s, "wall_rays", "must be in [1, 17]");
    check(prob(min_visible_ray_fraction), s, "min_visible_ray_fraction", "must be in [0, 1]");
    check(self_margin_m >= 0 && self_margin_m < 1, s, "self_margin_m", "must be in [0, 1)");
    check(prob(max_occluded_fraction), s, "max_occluded_fraction", "must be in [0, 1]");
}

void DetectorParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    detection_probability = cfg.read_double(s, "detection_probability", detection_probability);
    default_noise_std_m = cfg.read_double(s, "default_noise_std_m", default_noise_std_m);
    z_std_m = cfg.read_double(s, "z_std_m", z_std_m);
    size_std_fraction = cfg.read_double(s, "size_std_fraction", size_std_fraction);
    yaw_std_rad = cfg.read_double(s, "yaw_std_rad", yaw_std_rad);
    wrong_class_probability = cfg.read_double(s, "wrong_class_probability", wrong_class_probability);
    confidence_true_mean = cfg.read_double(s, "confidence_true_mean", confidence_true_mean);
    confidence_true_std = cfg.read_double(s, "confidence_true_std", confidence_true_std);
    confidence_false_mean = cfg.read_double(s, "confidence_false_mean", confidence_false_mean);
    confidence_false_std = cfg.read_double(s, "confidence_false_std", confidence_false_std);
    min_confidence = cfg.read_double(s, "min_confidence", min_confidence);
    reference_distance_m = cfg.read_double(s, "reference_distance_m", reference_distance_m);
    persistent_variance_fraction = cfg.read_double(s, "persistent_variance_fraction", persistent_variance_fraction);
    viewpoint_bin_deg = cfg.read_double(s, "viewpoint_bin_deg", viewpoint_bin_deg);
    viewpoint_bin_m = cfg.read_double(s, "viewpoint_bin_m", viewpoint_bin_m);
    noise_model_includes_extent = readStrictBool(cfg, s, "noise_model_includes_extent", noise_model_includes_extent);
    min_centre_noise_fraction = cfg.read_double(s, "min_centre_noise_fraction", min_centre_noise_fraction);
    check(prob(detection_probability), s, "detection_probability", "must be in [0, 1]");
    check(default_noise_std_m > 0, s, "default_noise_std_m", "must be > 0");
    check(z_std_m >= 0 && size_std_fraction >= 0 && yaw_std_rad >= 0, s, "z_std_m/size_std_fraction/yaw_std_rad",
          "must be >= 0");
    check(prob(wrong_class_probability), s, "wrong_class_probability", "must be in [0, 1]");
    check(prob(confidence_true_mean) && prob(confidence_false_mean), s, "confidence_*_mean", "must be in [0, 1]");
    check(confidence_true_std >= 0 && confidence_false_std >= 0, s, "confidence_*_std", "must be >= 0");
    check(prob(min_confidence), s, "min_confidence", "must be in [0, 1]");
    check(reference_distance_m > 0, s, "reference_distance_m", "must be > 0");
    check(prob(persistent_variance_fraction), s, "persistent_variance_fraction", "must be in [0, 1]");
    check(viewpoint_bin_deg > 0 && viewpoint_bin_m > 0, s, "viewpoint_bin_deg/viewpoint_bin_m", "must be > 0");
    check(min_centre_noise_fraction > 0 && min_centre_noise_fraction <= 1, s, "min_centre_noise_fraction",
          "must be in (0, 1]");
}

void FalsePositiveParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    rate_per_frame = cfg.read_double(s, "rate_per_frame", rate_per_frame);
    range_min_m = cfg.read_double(s, "range_min_m", range_min_m);
    range_max_m = cfg.read_double(s, "range_max_m", range_max_m);
    check(rate_per_frame >= 0 && rate_per_frame <= 30, s, "rate_per_frame", "must be in [0, 30]");
    check(range_min_m > 0 && range_max_m >= range_min_m, s, "range_min_m/range_max_m", "need 0 < min <= max");
}

void PeopleParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    count = cfg.read_int(s, "count", count);
    speed_min_mps = cfg.read_double(s, "speed_min_mps", speed_min_mps);
    speed_max_mps = cfg.read_double(s, "speed_max_mps", speed_max_mps);
    check(count >= 0 && count <= 100, s, "count", "must be in [0, 100]");
    check(speed_min_mps > 0 && speed_max_mps >= speed_min_mps, s, "speed_min_mps/speed_max_mps", "need 0 < min <= max");
}

void LidarParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    enabled = readStrictBool(cfg, s, "enabled", enabled);
    rate_hz = cfg.read_double(s, "rate_hz", rate_hz);
    fov_deg = cfg.read_double(s, "fov_deg", fov_deg);
    beams = cfg.read_int(s, "beams", beams);
    max_range_m = cfg.read_double(s, "max_range_m", max_range_m);
    range_std_m = cfg.read_double(s, "range_std_m", range_std_m);
    x_m = cfg.read_double(s, "x_m", x_m);
    y_m = cfg.read_double(s, "y_m", y_m);
    height_m = cfg.read_double(s, "height_m", height_m);
    yaw_deg = cfg.read_double(s, "yaw_deg", yaw_deg);
    check(rate_hz > 0 && rate_hz <= 1000, s, "rate_hz", "must be in (0, 1000]");
    check(fov_deg > 0 && fov_deg <= 360, s, "fov_deg", "must be in (0, 360]");
    check(beams >= 2 && beams <= 100000, s, "beams", "must be in [2, 100000]");
    check(max_range_m > 0 && max_range_m <= 1000, s, "max_range_m", "must be in (0, 1000]");
    check(range_std_m >= 0 && range_std_m <= 10, s, "range_std_m", "must be in [0, 10]");
    check(std::isfinite(x_m) && std::isfinite(y_m) && std::abs(x_m) < 10 && std::abs(y_m) < 10, s, "x_m/y_m",
          "must be finite and within 10 m of the robot centre");
    check(height_m > 0 && height_m < 10, s, "height_m", "must be in (0, 10)");
    check(std::isfinite(yaw_deg), s, "yaw_deg", "must be finite");
}

}  // namespace simp::sim
