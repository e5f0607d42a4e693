#include <simp/localization/SkippedDetections.h>

namespace simp::localization {

void SkippedDetections::add(const std::vector<WeightedObservation>& frame,
                            const mrpt::poses::CPose2D& motion_since_update) {
    for (const auto& o : frame)
        if (o.obs && !o.obs->empty()) m_kept.emplace_back(o, motion_since_update);
}

std::vector<WeightedObservation> SkippedDetections::merge(const std::vector<WeightedObservation>& current,
                                                          const mrpt::poses::CPose2D& motion_at_update) {
    std::vector<WeightedObservation> out = current;
    for (const auto& [kept, motion] : m_kept) {
        // Pose of the skipped frame's robot in the update's robot frame: P_u^-1 (+) P_j.
        const mrpt::poses::CPose2D update_T_frame = motion - motion_at_update;
        auto moved = std::make_shared<simp::obs::CObservationObjects3D>(*kept.obs);
        moved->setCameraPose(mrpt::poses::CPose3D(update_T_frame) + kept.obs->cameraPose());
        out.push_back({moved, kept.weights});
    }
    m_kept.clear();
    return out;
}

}  // namespace simp::localization
