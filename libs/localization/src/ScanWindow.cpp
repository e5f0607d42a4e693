#include <simp/localization/ScanLikelihood.h>
#include <simp/localization/ScanWindow.h>

namespace simp::localization {

void ScanWindow::add(mrpt::obs::CObservation2DRangeScan::Ptr scan, const mrpt::poses::CPose2D& odometry_pose) {
    if (m_capacity == 0 || !scan) return;
    m_scans.push_back({std::move(scan), odometry_pose});
    while (m_scans.size() > m_capacity) m_scans.pop_front();
}

void ScanWindow::score(const ScanLikelihood& model, const std::vector<mrpt::math::TPose2D>& poses,
                       const mrpt::poses::CPose2D& odometry_now, std::vector<double>& out) const {
    out.assign(poses.size(), 0.0);
    std::vector<mrpt::math::TPose2D> then(poses.size());
    std::vector<double> log(poses.size());
    for (const auto& e : m_scans) {
        const mrpt::poses::CPose2D back = mrpt::poses::CPose2D() - odometry_now + e.odometry;  // now -> then
        for (std::size_t i = 0; i < poses.size(); ++i) then[i] = (mrpt::poses::CPose2D(poses[i]) + back).asTPose();
        model.logLikelihoods(*e.scan, then.data(), then.size(), log.data(), false);
        for (std::size_t i = 0; i < poses.size(); ++i) out[i] += log[i];
    }
}

}  // namespace simp::localization
