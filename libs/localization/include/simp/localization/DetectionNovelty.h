#pragma once
/// \file DetectionNovelty.h
/// Tempering of repeated detections (not in the paper). A detector's error for one object
/// depends on the viewpoint: frames taken from nearly the same place repeat it, so multiplying
/// their likelihoods as independent evidence makes the filter sure of a biased pose. Each
/// detection is matched to a short-term track of the same object in the odometry frame (which
/// is accurate over seconds and needs no map or pose); its log-likelihood gets the exponent
///   w = clamp(d / decorrelation_distance_m, min_weight, 1),
/// d = how far the robot moved since the track's previous detection. Along a path of length L
/// an object then contributes about L / decorrelation_distance_m independent detections,
/// whatever the frame rate. A detection that starts a track has w = 1.

#include <mrpt/poses/CPose2D.h>
#include <simp/obs/CObservationObjects3D.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace simp::localization {

struct DetectionNoveltyParams {
    double decorrelation_distance_m = 1.0;  ///< robot travel after which a detection's error is new (m); 0 = off
    double min_weight = 0.1;                ///< weight of an immediate repeat, in (0, 1]
    double track_radius_m = 1.0;            ///< same class within this distance (odometry frame, m) = same object
    double track_timeout_s = 20.0;          ///< a track not seen for this long is forgotten (s)
};

class DetectionNovelty {
   public:
    explicit DetectionNovelty(const DetectionNoveltyParams& params = {}) : m_params(params) {}

    /// Weights of the detections of `obs` (one per detection, in order) taken at time t_s (s) with
    /// the robot at `odometry_pose` (odometry frame); updates the tracks. All 1 when off.
    std::vector<double> weigh(const simp::obs::CObservationObjects3D& obs, const mrpt::poses::CPose2D& odometry_pose,
                              double t_s);

    void clear() { m_tracks.clear(); }

   private:
    struct Track {
        std::string class_name;
        Eigen::Vector2d centre_odom_m;    ///< last detected centre (odometry frame)
        Eigen::Vector2d viewpoint_odom_m; ///< robot position at the last detection (odometry frame)
        double last_t_s = 0;
    };
    DetectionNoveltyParams m_params;
    std::vector<Track> m_tracks;
};

}  // namespace simp::localization
