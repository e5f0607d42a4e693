#pragma once
/// \file DetectionNovelty.h
/// Short-term tracks of the objects the robot sees, in the odometry frame (accurate over seconds,
/// needs no map or pose); not in the paper. Two uses:
///  - tempering of repeated detections: a detector's error for one object depends on the viewpoint,
///    so frames taken from nearly the same place repeat it, and multiplying their likelihoods as
///    independent evidence makes the filter sure of a biased pose. A detection's log-likelihood gets
///    the exponent w = clamp(d / decorrelation_distance_m, min_weight, 1), d = how far the robot
///    moved since its track's previous detection: along a path of length L an object contributes
///    about L / decorrelation_distance_m independent detections, whatever the frame rate. A detection
///    that starts a track has w = 1.
///  - objects the map does not hold there (added or moved furniture): a track whose detections the
///    localized estimate leaves unexplained (judge(), while the rest of what the robot sees is
///    explained) is marked unmapped, and its detections get w = 0 (not scored) for as long as the
///    track lives. Near a map object of its class such an object otherwise pulls the estimate by
///    its displacement wherever little else is seen.

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/obs/CObservationObjects3D.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace simp::localization {

struct DetectionNoveltyParams {
    double decorrelation_distance_m = 0.5;  ///< robot travel after which a detection's error is new (m); 0 = off
    double min_weight = 0.1;                ///< weight of an immediate repeat, in (0, 1]
    /// d is also this times the object's displacement in the camera frame (turns); 0 = travel only
    double view_change_weight = 0.0;
    double track_radius_m = 1.0;            ///< same class within this distance (odometry frame, m) = same object
    double track_timeout_s = 20.0;          ///< a track not seen for this long is forgotten (s)
    /// A track is unmapped after this many of its detections were judged (0 = off) ...
    std::size_t unmapped_min_detections = 8;
    double unmapped_min_span_s = 2.0;       ///< ... over at least this time (s) ...
    double unmapped_max_explained = 0.2;    ///< ... of which the estimate explained at most this fraction
    /// Judged only at steps whose state is `localized` (or `lost`, with unmapped_while_lost) and
    /// whose fit ([State], over at least fit_min_detections) is at least this. 0 since the
    /// thirty-ninth session: a changed object that fills the fit window stopped its own judging, then
    /// pulled the set through the false `lost` it caused. (Judging while `lost` marks everything after
    /// a kidnap; measured, not kept: doc/results-localization.md.)
    double unmapped_min_fit = 0.0;
    bool unmapped_while_lost = false;
    /// ... at the estimate or a pose this close to it (m, rad): a detection is unexplained only when
    /// no pose the bounds would accept explains it (a precise class seen from an estimate 0.2 m off).
    double unmapped_tolerance_m = 0.3;
    double unmapped_tolerance_rad = 0.1;
};

/// The track a detection went to (ids start at 1 and are never reused; 0 = none) and its
/// tempering weight before the unmapped mark (w above, 1 when tempering is off).
struct TrackedDetection {
    std::uint64_t track = 0;
    double temper_weight = 1.0;
};

class DetectionNovelty {
   public:
    explicit DetectionNovelty(const DetectionNoveltyParams& params = {}) : m_params(params) {}

    /// Weights of the detections of `obs` (one per detection, in order) taken at time t_s (s) with
    /// the robot at `odometry_pose` (odometry frame); updates the tracks. 1 when tempering is off;
    /// 0 for a detection on an unmapped track. `tracked`, when given, receives each detection's
    /// track (left empty when tempering and the unmapped test are both off: no tracks are kept).
    std::vector<double> weigh(const simp::obs::CObservationObjects3D& obs, const mrpt::poses::CPose2D& odometry_pose,
                              double t_s, std::vector<TrackedDetection>* tracked = nullptr);
    /// Detection k of `obs` (weighed at t_s with the robot at `odometry_pose`) was explained or not
    /// by the estimate: counts for its track's unmapped test.
    void judge(const simp::obs::CObservationObjects3D& obs, std::size_t k, const mrpt::poses::CPose2D& odometry_pose,
               bool explained, double t_s);
    /// Tracks marked unmapped now.
    std::size_t unmappedCount() const;
    /// Forgets every unmapped mark (they were judged against an estimate found wrong).
    void clearUnmapped();

    void clear() { m_tracks.clear(); }

   private:
    struct Track {
        std::uint64_t id = 0;
        std::string class_name;
        Eigen::Vector2d centre_odom_m;    ///< last detected centre (odometry frame)
        Eigen::Vector2d viewpoint_odom_m; ///< robot position at the last detection (odometry frame)
        mrpt::poses::CPose3D camera_odom; ///< pose of the camera of the last detection (odometry frame)
        double last_t_s = 0;
        /// The mean of its detected centres (odometry frame): an unmapped object is matched to it,
        /// as its detections scatter by the detector's noise about the object.
        Eigen::Vector2d sum_odom_m = Eigen::Vector2d::Zero();
        std::size_t detected = 0;
        std::size_t judged = 0, explained = 0;
        double first_judged_t_s = 0;
        bool unmapped = false;
    };
    /// The unmapped track of the class within track_radius_m of `centre` (its last or its mean
    /// centre), else the track of the class whose last centre is nearest within it; or nullptr.
    Track* nearest(const std::string& class_name, const Eigen::Vector2d& centre);
    DetectionNoveltyParams m_params;
    std::vector<Track> m_tracks;
    std::uint64_t m_last_id = 0;
};

}  // namespace simp::localization
