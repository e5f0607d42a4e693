#pragma once
/// \file HypothesisSearch.h
/// Where else could the robot be? (not in the paper). Candidate poses are generated from the
/// current detections (every exact fit of a detection on a map object of its class,
/// DetectionPoseSampler::candidates) and scored on the whole fit window: the last detections,
/// each moved by the odometry since its frame. The best distinct poses serve twice:
///  - sensor resetting while searching or lost injects particles around them, so a kidnapped
///    robot's new place is found from several seconds of evidence rather than one frame;
///  - the state compares them with the estimate: a rival that explains the window as well is an
///    ambiguity (not localized), one that explains it clearly better means the estimate is lost.
/// Scoring past detections does not count the current update twice: the injected particles get
/// the set's mean weight, and only the current update weighs them.

#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose2D.h>
#include <simp/localization/DetectionPoseSampler.h>
#include <simp/localization/LocalizationState.h>

#include <vector>

namespace simp::localization {

struct HypothesisSearchParams {
    bool enabled = true;                  ///< true: search (doc/localization.md "Hypothesis search")
    std::size_t min_window_detections = 5; ///< fewer detections in the window: no search
    std::size_t max_candidates = 4000;    ///< exact fits scored per search (the first ones)
    /// Also fits of pairs of window detections on pairs of map objects (DetectionPoseSampler::pairFits),
    /// at most this many, scored before the single-detection fits; 0: off.
    std::size_t pair_candidates = 500;
    DetectionPoseSampler::PairFitParams pairs;  ///< pair_min_separation_m, pair_tolerance_m, pair_merge_radius_m
    std::size_t refine_top = 8;           ///< best distinct candidates refined by a local grid search
    double refine_step_m = 0.2;           ///< first grid step (m); halved once
    double refine_step_rad = 0.1;         ///< first grid step (rad); halved once
    double distinct_distance_m = 1.0;     ///< poses farther apart than this (m) ...
    double distinct_heading_rad = 0.5;    ///< ... or turned more than this (rad) are distinct places
    std::size_t max_hypotheses = 4;       ///< distinct poses kept
    bool while_global = true;             ///< also search while `global` (the first search)
    bool while_localized = false;         ///< also search while `localized` (rival test for `lost`) ...
    double check_period_s = 1.0;          ///< ... at most this often (s); always while `lost`
};

/// Two robot poses are the same place when they are at most `max_distance_m` apart and turned by at
/// most `max_turn_rad` (wrapped): a right position with a wrong heading is another place.
bool samePlace(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b, double max_distance_m, double max_turn_rad);

struct Hypothesis {
    mrpt::math::TPose2D pose;   ///< robot pose now (world)
    double log_likelihood = 0;  ///< of the fit window at the pose (nats)
};

class HypothesisSearch {
   public:
    HypothesisSearch(const maps::CObjectMap& map, const DetectionPoseSampler& sampler,
                     const HypothesisSearchParams& params = {});

    /// The best distinct poses, best first (empty when the window is too small or nothing fits).
    std::vector<Hypothesis> search(const FitWindow& window, const std::vector<WeightedObservation>& observations,
                                   const mrpt::poses::CPose2D& odometry_now) const;

    /// Best window log-likelihood among `hypotheses` distinct from `pose`, minus the window's
    /// log-likelihood at `pose`; NaN when every hypothesis is near `pose`.
    double rivalAdvantage(const FitWindow& window, const std::vector<Hypothesis>& hypotheses,
                          const mrpt::math::TPose2D& pose, const mrpt::poses::CPose2D& odometry_now) const;

    /// Hill climb of the window's log-likelihood from `pose` (3 x 3 x 3 grids of refine_step_m /
    /// refine_step_rad, at most `moves` moves per level, the step halved twice): a pose a few
    /// decimetres away that explains the window clearly better says the estimate is biased (the set
    /// sits on a neighbouring mode that the rival test, for distinct places only, cannot see).
    /// Returns the best pose found and its log-likelihood; `own` gets the log-likelihood at `pose`.
    Hypothesis climb(const FitWindow& window, const mrpt::math::TPose2D& pose, const mrpt::poses::CPose2D& odometry_now,
                     double& own, int moves = 6) const;

    bool distinct(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) const;
    const HypothesisSearchParams& params() const { return m_params; }

   private:
    /// Local grid search about h.pose maximizing the window's log-likelihood.
    void refine(const FitWindow& window, const mrpt::poses::CPose2D& odometry_now, Hypothesis& h) const;
    /// The grid climb behind refine (2 levels, 1 move) and climb (3 levels, `moves` moves).
    void climbGrid(const FitWindow& window, const mrpt::poses::CPose2D& odometry_now, Hypothesis& h, int levels,
                   int moves) const;

    const maps::CObjectMap& m_map;
    const DetectionPoseSampler& m_sampler;
    HypothesisSearchParams m_params;
};

}  // namespace simp::localization
