#pragma once
/// \file ParticleSummary.h
/// What the filter reports per frame: the pose estimate of a particle set, its spread and
/// the effective sample size.

#include <simp/localization/LocalizeOptions.h>

#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPosePDFParticles.h>

#include <Eigen/Core>

namespace simp::localization {

struct ParticleSummary {
    mrpt::math::TPose2D estimate;     ///< the reported pose (world frame; m, rad): cluster or mean
    mrpt::math::TPose2D mean;         ///< weighted mean of all particles (circular mean of phi)
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();  ///< weighted covariance of (x, y, phi) (m^2, m rad, rad^2)
    double cluster_weight = 1.0;      ///< fraction of the total weight inside the reported cluster, [0, 1]
    /// weighted covariance of (x, y, phi) of the cluster's particles about the estimate (all particles in mean mode)
    Eigen::Matrix3d cluster_cov = Eigen::Matrix3d::Zero();
    std::size_t particle_count = 0;
    double ess = 0;                   ///< effective sample size 1 / sum(w^2) of the normalized weights, [1, N]
};

/// Cluster estimate: the particles are binned on an xy grid of `cluster_cell_m` and
/// `cluster_phi_bins` heading bins; the bin whose 3x3x3 neighbourhood holds the most weight is
/// the peak; the estimate is the weighted mean of the particles within `cluster_radius_m` and
/// `cluster_max_dphi` of the peak's mean. On a converged (unimodal) set it equals the mean;
/// on a multimodal set it stays on the strongest hypothesis instead of falling between them.
/// Deterministic (no random choices).
ParticleSummary summarizeParticles(const mrpt::poses::CPosePDFParticles& pdf, const ExperimentOptions& opts);

}  // namespace simp::localization
