#pragma once
/// \file ManhattanHeading.h
/// A heading likelihood from the yaw of every detected box, mapped or not (project addition, not in
/// the paper; [ManhattanHeading] of the localization .ini). Indoor furniture stands square to the
/// walls: the map's objects share a set of axes (alpha + k 90 deg), and so, mostly, do the boxes a
/// detector sees, including those of furniture that was moved or added since the map was made. Turned
/// into the world by a particle's heading phi, a detected box's yaw psi lies near those axes only
/// when phi is right: each detection gives p(psi | phi) = w N(r; 0, sigma) + (1 - w) 2 / pi,
/// r = phi + psi - alpha wrapped to (-45, 45] deg. w comes from the map (the share of its class's
/// objects that are square to the axes) and `outlier_fraction` (moved, rotated, false detections).
/// The Eq. singw object model takes the heading only from the detections it associates with a map
/// object; this model adds the others, which in a changed corridor are most of them
/// (doc/results-localization.md, "Forty-eighth session"). Used only when the map has axes.

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/math/TPose2D.h>
#include <simp/io/OptionTable.h>
#include <simp/localization/FrameLikelihood.h>
#include <simp/maps/CObjectMap.h>

#include <cstddef>
#include <string>
#include <vector>

namespace simp::localization {

/// [ManhattanHeading]: every field is the .ini key of the same name.
struct ManhattanHeadingOptions {
    /// Exponent of a camera frame's heading likelihood (the mean over its detections), relative to
    /// Eq. singw's 1 for the frame's object likelihood. 0 = off (the default: doc/localization.md).
    double weight = 0.0;
    double yaw_sigma_rad = 0.1;  ///< std of a detected box's yaw about its object's (rad)
    /// A map object whose yaw is within this of the map's axes counts as square to them (rad).
    double aligned_tolerance_rad = 0.1;
    /// The model is used only when at least this share of the map's objects is square to its axes
    /// (otherwise the building has no dominant axes and the model stays off).
    double min_aligned_fraction = 0.6;
    /// Share of the detections of a class all square in the map assumed not to be (moved and turned
    /// furniture, false detections): the uniform part of the mixture.
    double outlier_fraction = 0.3;
    /// YawConsensus: a detection votes only when its object's yaw (mean over its track, odometry
    /// frame) is within this of the other objects' (rad). 0 = off: every detection votes, with
    /// DetectionNovelty's weight.
    double consensus_tolerance_rad = 0.1;
    double consensus_window_s = 10.0;      ///< the other objects: tracks seen in the last this many s
    std::size_t consensus_min_tracks = 2;  ///< at least this many of them, else no vote
    /// Only objects detected at least this many times vote or count among the others: a false
    /// detection seldom repeats where it was, an object does.
    std::size_t consensus_min_detections = 3;

    /// The declaration of every key (section [ManhattanHeading]).
    static const io::OptionTable<ManhattanHeadingOptions>& table();
    /// Reads [section]; absent keys keep the defaults. \throw std::invalid_argument naming section and key.
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section = "ManhattanHeading");
};

class ManhattanHeading {
   public:
    /// The map's axes and per-class inlier weights, from `map`'s objects (kept by reference: `map`
    /// must outlive this).
    ManhattanHeading(const maps::CObjectMap& map, const ManhattanHeadingOptions& options);

    /// The map has axes (min_aligned_fraction reached) and weight > 0: logLikelihoods() adds something.
    bool active() const { return m_active; }
    const ManhattanHeadingOptions& options() const { return m_opts; }
    double axisRad() const { return m_axis_rad; }           ///< alpha, in [0, pi / 2)
    double alignedFraction() const { return m_aligned_fraction; }  ///< share of the map's objects square to alpha
    /// w of map class `cls` (0: its objects are not square to the axes, its detections are not used).
    double inlierWeight(int cls) const;
    /// The map class of detection k of `obs` when it is usable and square in the map (w > 0), else -1.
    int squareClassOf(const simp::obs::CObservationObjects3D& obs, std::size_t k) const;

    /// out_log[i] += weight x the weighted mean of log p(psi_k | poses[i].phi) over the usable detections
    /// k, with the observations' weights w_k (their heading_weights when set, else DetectionNovelty's
    /// weights; 0: not used), per camera frame (time
    /// stamp) when per_frame and the frames added, else over all (Eq. singw's grouping). A frame's say
    /// does not grow with its number of detections. Measured (doc/results-localization.md, forty-eighth
    /// session): the sum over the detections, and Eq. singw's (1/K) sum_k w_k, did worse. \return the number of detections used.
    std::size_t addLogLikelihoods(const std::vector<WeightedObservation>& observations, bool per_frame,
                                  const mrpt::math::TPose2D* poses, std::size_t n, double* out_log) const;

    /// log p(psi | phi) of one detection of class `cls` with yaw `psi_robot_rad` in the robot frame.
    double detectionLogLikelihood(int cls, double psi_robot_rad, double phi_rad) const;

   private:
    static constexpr std::size_t kBins = 180;  ///< table of one 90 deg period: 0.5 deg per bin (sigma ~6 deg)
    /// Adds the weighted mean of log p_k over `group`'s usable detections at every pose. \return detections used.
    std::size_t addGroup(const std::vector<const WeightedObservation*>& group, const mrpt::math::TPose2D* poses,
                         std::size_t n, double* out_log) const;
    const maps::CObjectMap& m_map;
    ManhattanHeadingOptions m_opts;
    bool m_active = false;
    double m_axis_rad = 0;
    double m_aligned_fraction = 0;
    std::vector<double> m_inlier_weight;  ///< per map class id
    std::vector<std::vector<double>> m_residual_log;  ///< per class id: log p at residual j x 90 deg / kBins
};

}  // namespace simp::localization
