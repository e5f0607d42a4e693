#pragma once
/// \file SkippedDetections.h
/// Detections of the frames the motion trigger skips (paper: d_xy, d_theta), kept for the next
/// filter update instead of being dropped: each is re-expressed in the robot frame of the update
/// through the odometry between its frame and the update.

#include <mrpt/poses/CPose2D.h>
#include <simp/localization/FrameLikelihood.h>

#include <utility>
#include <vector>

namespace simp::localization {

class SkippedDetections {
   public:
    /// Keeps the observations of a skipped frame; `motion_since_update` is the odometry from the
    /// last update's robot pose to this frame's.
    void add(const std::vector<WeightedObservation>& frame, const mrpt::poses::CPose2D& motion_since_update);

    /// The observations of an update: `current` plus every kept one, whose camera pose becomes
    /// T_update_frame (+) T_robot_camera with T_update_frame = motion_at_update^-1 (+)
    /// motion_since_update (robot frame of the update). Clears the buffer.
    std::vector<WeightedObservation> merge(const std::vector<WeightedObservation>& current,
                                           const mrpt::poses::CPose2D& motion_at_update);

    std::size_t size() const { return m_kept.size(); }
    void clear() { m_kept.clear(); }

   private:
    std::vector<std::pair<WeightedObservation, mrpt::poses::CPose2D>> m_kept;
};

}  // namespace simp::localization
