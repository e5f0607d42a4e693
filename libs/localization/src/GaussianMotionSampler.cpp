#include <simp/localization/GaussianMotionSampler.h>

#include <simp/localization/Angle.h>

#include <Eigen/Dense>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <vector>

namespace simp::localization {

GaussianMotionSampler::GaussianMotionSampler(const mrpt::poses::CPosePDFGaussian& pdf) : m_mean(pdf.mean.asTPose()) {
    // MRPT's CPoseRandomSampler::setPosePDF, call for call, so that the scaled axes have its bits.
    std::vector<double> eig_values;
    pdf.cov.eig_symmetric(m_scaled_axes, eig_values);
    mrpt::math::CMatrixDouble33 d;
    d.setDiagonal(eig_values);
    d = d.asEigen().array().sqrt().matrix();
    m_scaled_axes.matProductOf_AB(m_scaled_axes, d);
}

mrpt::math::TPose2D GaussianMotionSampler::drawIncrement() const {
    auto& rng = mrpt::random::getRandomGenerator();
    double v[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i) {
        const double r = rng.drawGaussian1D_normalized();
        for (int d = 0; d < 3; ++d) v[d] += m_scaled_axes(d, i) * r;
    }
    return {m_mean.x + v[0], m_mean.y + v[1], wrapToPi(m_mean.phi + v[2])};
}

mrpt::math::TPose2D GaussianMotionSampler::move(const mrpt::math::TPose2D& pose) const {
    const mrpt::math::TPose2D inc = drawIncrement();
    double s = 0.0, c = 0.0;
    ::sincos(pose.phi, &s, &c);  // CPose2D::update_cached_cos_sin (MRPT is built with sincos)
    return {pose.x + inc.x * c - inc.y * s, pose.y + inc.x * s + inc.y * c, wrapToPi(pose.phi + inc.phi)};
}

}  // namespace simp::localization
