#include <simp/localization/SkippedDetections.h>

namespace simp::localization {

void SkippedDetections::add(const mrpt::obs::CSensoryFrame& sf, const mrpt::poses::CPose2D& motion_since_update) {
    for (const auto& o : sf) {
        auto det = std::dynamic_pointer_cast<simp::obs::CObservationObjects3D>(o);
        if (det && !det->empty()) m_kept.emplace_back(det, motion_since_update);
    }
}

mrpt::obs::CSensoryFrame::Ptr SkippedDetections::merge(const mrpt::obs::CSensoryFrame::Ptr& current,
                                                       const mrpt::poses::CPose2D& motion_at_update) {
    if (m_kept.empty()) return current;
    auto out = mrpt::obs::CSensoryFrame::Create();
    if (current)
        for (const auto& o : *current) out->insert(o);
    for (const auto& [det, motion] : m_kept) {
        // Pose of the skipped frame's robot in the update's robot frame: P_u^-1 (+) P_j.
        const mrpt::poses::CPose2D update_T_frame = motion - motion_at_update;
        auto moved = std::make_shared<simp::obs::CObservationObjects3D>(*det);
        moved->setCameraPose(mrpt::poses::CPose3D(update_T_frame) + det->cameraPose());
        out->insert(moved);
    }
    m_kept.clear();
    return out;
}

}  // namespace simp::localization
