#include <simp/lidar/IcpOptions.h>

namespace simp::lidar {

const io::OptionTable<IcpPosesOptions>& IcpPosesOptions::table() {
    using O = IcpPosesOptions;
    using io::ValueRange;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("ICP")
            .integer("scan_decimation", &O::scan_decimation, ValueRange::between(1, 1000), "every n-th ray of a scan is aligned")
            .number("max_range_m", &O::max_range_m, "m", ValueRange::between(0.1, 1000), "rays beyond are left out")
            .number("min_range_m", &O::min_range_m, "m", ValueRange::between(0, 100),
                    "rays shorter are left out (returns inside the robot's footprint)")
            .integer("max_iterations", &O::max_iterations, ValueRange::between(1, 10000), "CICP maxIterations")
            .number("threshold_dist_m", &O::threshold_dist_m, "m", ValueRange::between(1e-3, 10), "initial pairing distance, CICP thresholdDist")
            .number("threshold_ang_deg", &O::threshold_ang_deg, "deg", ValueRange::between(0, 90),
                    "pairing distance growing with range, CICP thresholdAng")
            .number("alfa", &O::alfa, "", ValueRange::between(0.01, 0.99), "CICP ALFA: the thresholds shrink by it on convergence")
            .number("smallest_threshold_dist_m", &O::smallest_threshold_dist_m, "m", ValueRange::between(1e-4, 10), "CICP smallestThresholdDist")
            .integer("min_points", &O::min_points, ValueRange::between(3, 100000), "fewer scan points: odometry only at this step")
            .number("min_goodness", &O::min_goodness, "", ValueRange::between(0, 1), "CICP goodness (share of paired points) below: rejected")
            .number("max_correction_m", &O::max_correction_m, "m", ValueRange::between(0, 100),
                    "an alignment moving the odometry prediction farther: rejected")
            .number("max_correction_deg", &O::max_correction_deg, "deg", ValueRange::between(0, 180), "same for the heading")
            .number("min_constraint_points", &O::min_constraint_points, "", ValueRange::between(0, 1e6),
                    "the translation is applied only along directions that this many aligned points' wall normals constrain (0: all)")
            .number("alignment_sigma_m", &O::alignment_sigma_m, "m", ValueRange::between(0, 10),
                    "uncertainty gate: an alignment's position error (0: off, the fixed max_correction_* gate)")
            .number("alignment_sigma_deg", &O::alignment_sigma_deg, "deg", ValueRange::between(1e-3, 90), "uncertainty gate: an alignment's heading error")
            .number("gate_sigmas", &O::gate_sigmas, "", ValueRange::between(0.5, 100), "uncertainty gate: corrections within this many sigmas are accepted")
            .number("process_m_per_m", &O::process_m_per_m, "m/m", ValueRange::between(0, 10), "uncertainty gate: position sigma per metre driven")
            .number("process_m_per_rad", &O::process_m_per_rad, "m/rad", ValueRange::between(0, 10), "uncertainty gate: position sigma per radian turned")
            .number("process_rad_per_m", &O::process_rad_per_m, "rad/m", ValueRange::between(0, 10), "uncertainty gate: heading sigma per metre driven")
            .number("process_rad_per_rad", &O::process_rad_per_rad, "rad/rad", ValueRange::between(0, 10), "uncertainty gate: heading sigma per radian turned")
            .number("process_min_m", &O::process_min_m, "m", ValueRange::between(0, 10), "uncertainty gate: position sigma added at least per step")
            .number("process_min_rad", &O::process_min_rad, "rad", ValueRange::between(0, 10), "uncertainty gate: heading sigma added at least per step");
    return t;
}

void IcpPosesOptions::loadFromConfig(const io::StrictIni& cfg, const std::string& s) { table().load(cfg, s, *this); }

}  // namespace simp::lidar
