#include <simp/io/StrictNumber.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/SimParams.h>

#include <cmath>
#include <stdexcept>

namespace simp::sim {

void OdometryParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    rate_hz = cfg.read_double(s, "rate_hz", rate_hz);
    a1 = cfg.read_double(s, "a1", a1);
    a2 = cfg.read_double(s, "a2", a2);
    a3 = cfg.read_double(s, "a3", a3);
    a4 = cfg.read_double(s, "a4", a4);
    minStdXY = cfg.read_double(s, "minStdXY", minStdXY);
    minStdPHI = cfg.read_double(s, "minStdPHI", minStdPHI);
    noise_scale = cfg.read_double(s, "noise_scale", noise_scale);
    if (!(rate_hz > 0 && rate_hz <= 1000)) throw std::invalid_argument("[" + s + "] rate_hz must be in (0, 1000]");
    for (double v : {a1, a2, a3, a4, minStdXY, minStdPHI, noise_scale})
        if (!(v >= 0) || !std::isfinite(v))
            throw std::invalid_argument("[" + s + "] a1..a4, minStdXY, minStdPHI and noise_scale must be finite and >= 0");
}

void SimParams::loadFromConfig(const mrpt::config::CConfigFileBase& cfg) {
    duration_s = cfg.read_double("sequence", "duration_s", duration_s);
    epoch_s = cfg.read_double("sequence", "epoch_s", epoch_s);
    progress = cfg.read_bool("sequence", "progress", progress);
    checkDuration(duration_s, "[sequence] duration_s");
    if (!(epoch_s >= 0 && epoch_s < 4e9)) throw std::invalid_argument("[sequence] epoch_s must be in [0, 4e9)");
    kidnap_at_s = cfg.read_double("sequence", "kidnap_at_s", kidnap_at_s);
    kidnap_min_distance_m = cfg.read_double("sequence", "kidnap_min_distance_m", kidnap_min_distance_m);
    if (!std::isfinite(kidnap_at_s))
        throw std::invalid_argument("[sequence] kidnap_at_s must be a finite number (s after the start; < 0: no kidnap)");
    if (!(kidnap_min_distance_m >= 0 && kidnap_min_distance_m <= 1e3))
        throw std::invalid_argument("[sequence] kidnap_min_distance_m must be in [0, 1000]");
    trajectory.loadFromConfig(cfg, "trajectory");
    odometry.loadFromConfig(cfg, "odometry");
    cameras.loadFromConfig(cfg, "cameras");
    visibility.loadFromConfig(cfg, "visibility", obs::defaultClassNames().size());
    detector.loadFromConfig(cfg, "detector");
    false_positives.loadFromConfig(cfg, "false_positives");
    people.loadFromConfig(cfg, "people");
    lidar.loadFromConfig(cfg, "lidar");
    changes.loadFromConfig(cfg, "changes");
}

void SimParams::validateKidnap(const std::string& what) const {
    if (!std::isfinite(kidnap_at_s)) throw std::invalid_argument(what + " must be a finite number of seconds");
    if (kidnap_at_s > duration_s)
        throw std::invalid_argument(what + ": " + io::numberText(kidnap_at_s) + " s is beyond the duration of " +
                                    io::numberText(duration_s) + " s");
}

}  // namespace simp::sim
