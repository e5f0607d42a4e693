#pragma once
/// \file IcpOptions.h
/// [ICP] of simp-icp-poses' .ini (config_ini/icp-poses.ini): scan-to-floor-plan alignment with
/// mrpt::slam::CICP. Every field is the .ini key of the same name.

#include <simp/io/OptionTable.h>
#include <simp/io/StrictIni.h>

#include <string>

namespace simp::lidar {

struct IcpPosesOptions {
    int scan_decimation = 2;             ///< every n-th ray of a scan is aligned (1081 rays -> 541)
    double max_range_m = 15.0;           ///< rays beyond are left out (m)
    int max_iterations = 60;             ///< CICP::TConfigParams::maxIterations
    double threshold_dist_m = 0.15;      ///< initial pairing distance (m), CICP thresholdDist
    double threshold_ang_deg = 0.0;      ///< pairing distance growing with range (deg), CICP thresholdAng
    double alfa = 0.5;                   ///< CICP ALFA: the thresholds shrink by it on convergence
    double smallest_threshold_dist_m = 0.05;  ///< CICP smallestThresholdDist (m)
    int min_points = 30;                 ///< fewer scan points: odometry only at this step
    double min_goodness = 0.1;           ///< CICP goodness (share of paired points) below: rejected
    double max_correction_m = 0.1;       ///< an alignment moving the odometry prediction farther: rejected (m)
    double max_correction_deg = 5.0;     ///< same for the heading (deg)
    /// The translation of an accepted alignment is applied only along the directions that at least this
    /// many aligned scan points constrain (the eigenvalues of the sum of their wall normals' outer
    /// products, points within threshold_dist_m of a wall): along a corridor the walls fix nothing, and
    /// furniture paired with wall points slid the pose there by up to max_correction_m per step. 0: all.
    double min_constraint_points = 20;

    /// The declaration of every key (section [ICP]).
    static const io::OptionTable<IcpPosesOptions>& table();
    /// Reads [section]; absent keys keep their defaults; bad values throw naming file, section and key.
    void loadFromConfig(const io::StrictIni& cfg, const std::string& section = "ICP");
};

}  // namespace simp::lidar
