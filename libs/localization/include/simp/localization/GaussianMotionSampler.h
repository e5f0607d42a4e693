#pragma once
/// \file GaussianMotionSampler.h
/// The prediction of the filter for MRPT's Gaussian odometry model: each particle moved by a
/// sample of the action's CPosePDFGaussian. The same numbers as MRPT's CPoseRandomSampler
/// (same random draws from mrpt::random::getRandomGenerator(), same arithmetic) composed as
/// CPose2D::operator+ does, without MRPT's per-sample heap vector, class checks and pose objects
/// (a fifth of a whole run's time went to them).

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPosePDFGaussian.h>

namespace simp::localization {

class GaussianMotionSampler {
   public:
    /// Prepares the draws from `pdf` as CPoseRandomSampler::setPosePDF does (eigenvectors of the
    /// covariance scaled by the square roots of its eigenvalues).
    explicit GaussianMotionSampler(const mrpt::poses::CPosePDFGaussian& pdf);
    /// One increment (CPoseRandomSampler::drawSample): three standard normal draws.
    mrpt::math::TPose2D drawIncrement() const;
    /// `pose` (+) one increment, as mrpt::poses::CPose2D(pose) + increment.
    mrpt::math::TPose2D move(const mrpt::math::TPose2D& pose) const;

   private:
    mrpt::math::TPose2D m_mean;
    mrpt::math::CMatrixDouble33 m_scaled_axes;  ///< column i: eigenvector i x sqrt(eigenvalue i)
};

}  // namespace simp::localization
