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
    /// Rays shorter than this are left out (m): returns inside the robot's footprint are the robot or
    /// something touching the scanner (a person walking through it), never a wall; aligned to the walls
    /// they slid the pose 0.22 m along a corridor in 0.5 s (doc/lidar.md). The scan model's
    /// [LidarModel] min_range_m leaves them out for the same reason.
    double min_range_m = 0.3;
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
    /// @name Uncertainty gate (alignment_sigma_m = 0: off, the fixed max_correction_* gate instead).
    /// The pose's position and heading variances grow each step with the motion (process_*: sigma
    /// per metre driven and per radian turned, at least process_min_* per step) and shrink with each
    /// accepted alignment, whose own error is alignment_sigma_*. An alignment is accepted when its
    /// correction is within gate_sigmas of the two and applied with the Kalman gain (along the
    /// constrained directions). Why: with the fixed gate, a run of accepted 3-9 cm corrections (a door
    /// leaf the plan lacks, paired with the door's jambs) slid the pose 0.2 m along a corridor, and
    /// every correction back exceeded max_correction_m: lost for good (doc/lidar.md). Here the
    /// rejections let the variance, hence the gate, grow until the walls take the pose back.
    /// @{
    double alignment_sigma_m = 0.03;
    double alignment_sigma_deg = 1.0;
    double gate_sigmas = 4.0;
    double process_m_per_m = 0.05;      ///< position sigma per metre driven
    double process_m_per_rad = 0.01;    ///< position sigma per radian turned
    double process_rad_per_m = 0.05;    ///< heading sigma per metre driven
    double process_rad_per_rad = 0.03;  ///< heading sigma per radian turned
    double process_min_m = 0.005;       ///< position sigma added at least per step (standing still too)
    double process_min_rad = 0.0035;    ///< heading sigma added at least per step
    /// @}

    /// The declaration of every key (section [ICP]).
    static const io::OptionTable<IcpPosesOptions>& table();
    /// Reads [section]; absent keys keep their defaults; bad values throw naming file, section and key.
    void loadFromConfig(const io::StrictIni& cfg, const std::string& section = "ICP");
};

}  // namespace simp::lidar
