#pragma once
/// \file YawConsensus.h
/// Which detected boxes may vote on the heading (project addition; [ManhattanHeading] consensus_*
/// keys). ManhattanHeading scores a box's yaw against the map's axes, which is right only for
/// furniture that stands square to them. A moved object turned by 10-20 deg seen alone for a few
/// seconds then turns the filter (doc/results-localization.md, forty-eighth session, c0.15_s114).
/// One object cannot tell a turned object from a wrong heading; several can: in the odometry frame
/// (accurate over seconds) the objects square to the building share one yaw modulo 90 deg, and a
/// turned one stands apart. Each short-term object track (DetectionNovelty's) keeps the mean of
/// its boxes' yaws in the odometry frame; a detection votes on the heading only when its track's
/// mean agrees, within `consensus_tolerance_rad`, with the mean of the other tracks seen in the
/// last `consensus_window_s`, and at least `consensus_min_tracks` such others exist. Only tracks
/// detected `consensus_min_detections` times vote or count: false detections, each at a new place,
/// would otherwise outnumber the objects (doc/localization.md, "Heading from box yaws").

#include <mrpt/poses/CPose2D.h>
#include <simp/localization/DetectionNovelty.h>
#include <simp/localization/ManhattanHeading.h>

#include <cstdint>
#include <vector>

namespace simp::localization {

class YawConsensus {
   public:
    /// The heading weight of each detection of `obs` (taken at t_s with the robot at
    /// `odometry_pose`, tracked as `tracked` by DetectionNovelty::weigh): its tempering weight when
    /// its track agrees with the others, else 0. Updates the tracks' yaws. `heading` tells which
    /// classes are square in the map and holds the keys.
    std::vector<double> weigh(const ManhattanHeading& heading, const simp::obs::CObservationObjects3D& obs, const std::vector<TrackedDetection>& tracked,
                              const mrpt::poses::CPose2D& odometry_pose, double t_s);

    void clear() { m_tracks.clear(); }

   private:
    struct TrackYaw {
        std::uint64_t track = 0;
        double sum_cos4 = 0, sum_sin4 = 0;  ///< of 4 x the boxes' yaws in the odometry frame
        std::size_t detections = 0;
        double last_t_s = 0;
    };
    std::vector<TrackYaw> m_tracks;
};

}  // namespace simp::localization
