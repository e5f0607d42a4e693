#pragma once
/// \file ObjectMclParams.h
/// The parameters of ObjectMcl (one struct handed to the filter; the .ini keys are in
/// ExperimentOptions::filter, LocalizeOptions.cpp).

namespace simp::localization {

/// What ObjectMcl does besides MRPT's prediction and weighing. Defaults: the paper's filter (the
/// authors' code); `ExperimentOptions::filter` holds the project's defaults and the .ini keys.
struct ObjectMclParams {
    /// Redraw particles that the motion moved off the free space (needs ObjectMcl::setFreeSpace).
    bool prune_outside_free_space = true;
    /// true: a pruned particle keeps its weight (authors' code); false: it gets the smallest weight
    /// MRPT keeps (max log-weight - PF_options.max_loglikelihood_dyn_range), i.e. p(x off free space) ~ 0.
    bool prune_keeps_weight = true;
    /// true: Eq. singw per camera frame (timestamp), multiplied over the frames of the update
    /// (perFrameLogLikelihoods); false: one geometric mean over all detections of the update.
    bool singw_per_frame = true;
    /// true: every particle weighs the same after resampling (SIR: the copies carry the weights).
    /// false: the copies keep the weights of the particles they copy, as MRPT 2.5's
    /// CParticleFilterCapable::performResampling leaves them (its reset loop runs to its
    /// out_particle_count argument, 0 by default): each resampling then applies the weights twice.
    bool resample_resets_weights = true;
    /// Recovery by random particles (augmented MCL, Thrun et al., "Probabilistic Robotics", Table 8.3;
    /// not in the paper; 0 = off). After each update with K > 0 detections, w_avg = the weighted mean
    /// over the particles of the frame likelihood (Eq. singw) is smoothed into w_slow (rate alpha_slow)
    /// and w_fast (rate alpha_fast); at the next step each particle is replaced, with probability
    /// max(0, 1 - w_fast / w_slow), by a pose drawn uniformly over the free space, with the mean weight.
    /// Requires alpha_slow < alpha_fast, both in [0, 1], and a free space (setFreeSpace).
    double recovery_alpha_slow = 0.0;
    double recovery_alpha_fast = 0.0;
};

}  // namespace simp::localization
