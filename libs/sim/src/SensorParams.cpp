/// \file SensorParams.cpp
/// The keys of [cameras], [visibility], [detector], [false_positives], [people] and [lidar], declared
/// once (io::OptionTable): key, field, unit, allowed values, meaning (doc/simulator.md's tables).
#include <simp/io/StrictNumber.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/SensorParams.h>

#include <sstream>
#include <stdexcept>

namespace simp::sim {
namespace {

using io::ValueRange;

/// A per-class list "v0 v1 ... v13" (one number >= 0 per class of obs::defaultClassNames()).
std::vector<double> perClassList(const std::string& text, const std::string& at) {
    const std::size_t num_classes = obs::defaultClassNames().size();
    std::vector<double> out;
    std::istringstream is(text);
    for (std::string tok; is >> tok;) {
        const auto v = io::parseFiniteNumber(tok);
        if (!v || *v < 0) throw std::invalid_argument(at + ": '" + tok + "' is not a number >= 0");
        out.push_back(*v);
    }
    if (out.size() != num_classes)
        throw std::invalid_argument(at + ": expected " + std::to_string(num_classes) + " values (one per class), got " +
                                    std::to_string(out.size()));
    return out;
}

std::string listText(const std::vector<double>& v, int precision) {
    std::ostringstream out;
    out.precision(precision);
    for (std::size_t k = 0; k < v.size(); ++k) out << (k ? " " : "") << v[k];
    return out.str();
}

/// A per-class list key of VisibilityParams.
template <class Field>
io::OptionTable<VisibilityParams>& perClass(io::OptionTable<VisibilityParams>& t, const std::string& key, Field field,
                                            const std::string& meaning) {
    return t.custom(
        key, "m", "14 numbers >= 0", meaning,
        [field](VisibilityParams& o, const std::string& text, const std::string& at) {
            if (!text.empty()) o.*field = perClassList(text, at);  // empty: the defaults
        },
        [field](const VisibilityParams& o, int precision) { return listText(o.*field, precision); });
}

}  // namespace

const io::OptionTable<CameraParams>& CameraParams::table() {
    using O = CameraParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("cameras")
            .integer("count", &O::count, ValueRange::between(1, 16), "cameras on a ring around the robot centre")
            .number("first_yaw_deg", &O::first_yaw_deg, "deg", ValueRange::finite(), "yaw of camera 0 (0 = robot forward, 90 = left); camera i at + i * 360 / count")
            .number("mount_radius_m", &O::mount_radius_m, "m", ValueRange::finite(), "distance of each camera from the robot centre along its yaw")
            .number("height_m", &O::height_m, "m", ValueRange::finite(), "camera height above the floor")
            .number("pitch_down_deg", &O::pitch_down_deg, "deg", ValueRange::finite(), "downward tilt")
            .integer("width_px", [](auto& o) -> auto& { return o.intrinsics.ncols; }, "px", ValueRange::between(1, 100000), "image width")
            .integer("height_px", [](auto& o) -> auto& { return o.intrinsics.nrows; }, "px", ValueRange::between(1, 100000), "image height")
            .number("fx", [](auto& o) -> auto& { return o.intrinsics.intrinsicParams(0, 0); }, "px", ValueRange::positive(), "focal length along x")
            .number("fy", [](auto& o) -> auto& { return o.intrinsics.intrinsicParams(1, 1); }, "px", ValueRange::positive(), "focal length along y")
            .number("cx", [](auto& o) -> auto& { return o.intrinsics.intrinsicParams(0, 2); }, "px", ValueRange::finite(), "principal point x")
            .number("cy", [](auto& o) -> auto& { return o.intrinsics.intrinsicParams(1, 2); }, "px", ValueRange::finite(), "principal point y")
            .number("rate_hz", &O::rate_hz, "Hz", ValueRange::positive(), "frame rate of every camera (a divisor of the odometry rate is best)");
    return t;
}

const io::OptionTable<VisibilityParams>& VisibilityParams::table() {
    using O = VisibilityParams;
    static const io::OptionTable<O> t = [] {
        io::OptionTable<O> t("visibility");
        perClass(t, "min_range_m", &O::min_range_m, "per class: minimum horizontal distance camera -> box centre; 0 = no limit");
        perClass(t, "max_range_m", &O::max_range_m, "per class: maximum distance; 0 = `default_max_range_m`");
        t.number("default_max_range_m", &O::default_max_range_m, "m", ValueRange::positive(), "range limit of classes whose maximum is 0")
            .number("min_inside_fraction", &O::min_inside_fraction, "", ValueRange::fraction(), "truncation: fraction of the 8 projected box corners that must fall inside the image")
            .integer("render_downscale", &O::render_downscale, ValueRange::between(1, 64), "image pixels per rendered pixel (per side) of the occlusion renderer (z-buffer)")
            .number("wall_depth_margin_m", &O::wall_depth_margin_m, "m", ValueRange{0, 1, false, true}, "box surfaces up to this far behind the first wall face still count in front of it (a door in its gap)")
            .number("self_margin_m", &O::self_margin_m, "m", ValueRange{0, 1, false, true}, "wall cells this close to the footprint of an object (not a door) are the object drawn into the floor plan, not a wall")
            .number("min_unwalled_fraction", &O::min_unwalled_fraction, "", ValueRange::fraction(), "wall occlusion: fraction of the box's rendered pixels that must lie in front of the walls")
            .number("max_occluded_fraction", &O::max_occluded_fraction, "", ValueRange::fraction(), "object occlusion: dropped when nearer boxes hide more of its pixels in front of the walls");
        return t;
    }();
    return t;
}

const io::OptionTable<DetectorParams>& DetectorParams::table() {
    using O = DetectorParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("detector")
            .number("detection_probability", &O::detection_probability, "", ValueRange::fraction(), "probability that a visible object is detected")
            .number("default_noise_std_m", &O::default_noise_std_m, "m", ValueRange::positive(), "centre std of classes without a noise model")
            .number("z_std_m", &O::z_std_m, "m", ValueRange::atLeast(0), "std of the box centre height")
            .number("size_std_fraction", &O::size_std_fraction, "", ValueRange::atLeast(0), "relative std of each box dimension")
            .number("yaw_std_rad", &O::yaw_std_rad, "rad", ValueRange::atLeast(0), "std of the box yaw")
            .number("wrong_class_probability", &O::wrong_class_probability, "", ValueRange::fraction(), "a true detection gets another class label, scored like a false one")
            .number("confidence_true_mean", &O::confidence_true_mean, "", ValueRange::fraction(), "score of true detections: mean")
            .number("confidence_true_std", &O::confidence_true_std, "", ValueRange::atLeast(0), "score of true detections: std")
            .number("confidence_false_mean", &O::confidence_false_mean, "", ValueRange::fraction(), "score of false detections: mean")
            .number("confidence_false_std", &O::confidence_false_std, "", ValueRange::atLeast(0), "score of false detections: std")
            .number("min_confidence", &O::min_confidence, "", ValueRange::fraction(), "detections scoring below are not reported")
            .number("reference_distance_m", &O::reference_distance_m, "m", ValueRange::positive(), "the class noise model holds at this distance; the along-ray error scales with distance / this")
            .number("persistent_variance_fraction", &O::persistent_variance_fraction, "", ValueRange::fraction(), "fraction of the centre-noise variance that is persistent per object and viewpoint cell")
            .number("viewpoint_bin_deg", &O::viewpoint_bin_deg, "deg", ValueRange::positive(), "viewpoint cells: bearing object -> camera sectors")
            .number("viewpoint_bin_m", &O::viewpoint_bin_m, "m", ValueRange::positive(), "viewpoint cells: distance rings")
            .flag("noise_model_includes_extent", &O::noise_model_includes_extent, "true = centre noise = the model's covariance minus the footprint's (side^2 / 12 per axis)")
            .number("min_centre_noise_fraction", &O::min_centre_noise_fraction, "", ValueRange::aboveUpTo(0, 1), "lower bound of the centre-noise std per axis, as a fraction of the model's std");
    return t;
}

const io::OptionTable<FalsePositiveParams>& FalsePositiveParams::table() {
    using O = FalsePositiveParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("false_positives")
            .number("rate_per_frame", &O::rate_per_frame, "", ValueRange::between(0, 30), "expected phantoms per camera frame (Poisson)")
            .number("range_min_m", &O::range_min_m, "m", ValueRange::positive(), "phantom distance from the camera: minimum")
            .number("range_max_m", &O::range_max_m, "m", ValueRange::positive(), "phantom distance from the camera: maximum")
            .rule("range_max_m", [](const O& o) { return o.range_max_m >= o.range_min_m; }, "be >= range_min_m");
    return t;
}

const io::OptionTable<PeopleParams>& PeopleParams::table() {
    using O = PeopleParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("people")
            .integer("count", &O::count, ValueRange::between(0, 100), "people walking between rooms (class person, never in the map)")
            .number("speed_min_mps", &O::speed_min_mps, "m/s", ValueRange::positive(), "walking speed: minimum")
            .number("speed_max_mps", &O::speed_max_mps, "m/s", ValueRange::positive(), "walking speed: maximum")
            .rule("speed_max_mps", [](const O& o) { return o.speed_max_mps >= o.speed_min_mps; }, "be >= speed_min_mps");
    return t;
}

const io::OptionTable<LidarParams>& LidarParams::table() {
    using O = LidarParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("lidar")
            .flag("enabled", &O::enabled, "write 2D scans (`--lidar` sets it)")
            .number("rate_hz", &O::rate_hz, "Hz", ValueRange::aboveUpTo(0, 1000), "scans per second; at most one per odometry step is written")
            .number("fov_deg", &O::fov_deg, "deg", ValueRange::aboveUpTo(0, 360), "aperture, centred on the sensor's x axis")
            .integer("beams", &O::beams, ValueRange::between(2, 100000), "rays over the aperture (first and last at +-fov/2)")
            .number("max_range_m", &O::max_range_m, "m", ValueRange::aboveUpTo(0, 1000), "rays without a hit within it are invalid")
            .number("range_std_m", &O::range_std_m, "m", ValueRange::between(0, 10), "Gaussian range noise")
            .number("x_m", &O::x_m, "m", ValueRange::open(-10, 10), "sensor position on the robot (robot frame): x")
            .number("y_m", &O::y_m, "m", ValueRange::open(-10, 10), "sensor position on the robot (robot frame): y")
            .number("height_m", &O::height_m, "m", ValueRange::open(0, 10), "scan plane above the floor: objects spanning it are seen")
            .number("yaw_deg", &O::yaw_deg, "deg", ValueRange::finite(), "sensor heading on the robot");
    return t;
}

void CameraParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void VisibilityParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void DetectorParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void FalsePositiveParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void PeopleParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void LidarParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }

}  // namespace simp::sim
