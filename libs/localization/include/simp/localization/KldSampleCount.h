#pragma once
/// \file KldSampleCount.h
/// How many particles a set needs (Fox's KLD sampling, IJRR 2003): the count that keeps the
/// Kullback-Leibler distance between the set and the posterior under epsilon with probability
/// 1 - delta, from the number of bins (MRPT's TKLDParams sizes) the set occupies. While localized
/// the filter resamples to it (Localizer::particleTarget).

#include <mrpt/poses/CPosePDFParticles.h>
#include <mrpt/slam/TKLDParams.h>

#include <cstddef>

namespace simp::localization {

/// Bins of kld's sizes (xy in m, phi in rad) that hold at least one particle.
std::size_t occupiedBinCount(const mrpt::poses::CPosePDFParticles& pdf, const mrpt::slam::TKLDParams& kld);

/// Particles needed for a KLD bound (Fox, IJRR 2003) on the set's occupied bins of kld's bin
/// sizes (xy in m, phi in rad as MRPT's TKLDParams holds it): (k-1)/(2 eps) (1 - 2/(9(k-1)) +
/// sqrt(2/(9(k-1))) z_{1-delta})^3 with k occupied bins.
std::size_t kldParticleCount(const mrpt::poses::CPosePDFParticles& pdf, const mrpt::slam::TKLDParams& kld);

}  // namespace simp::localization
