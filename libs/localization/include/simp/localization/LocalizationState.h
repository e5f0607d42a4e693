#pragma once
/// \file LocalizationState.h
/// What the filter can say about itself (not in the paper): `global` (searching), `localized`
/// (the reported pose can be acted on), `lost` (it could not, and the filter is recovering).
///
/// The state rests on two measurements, both reported per step:
///  - the posterior's concentration: the weight fraction and the position spread of the reported
///    cluster (ParticleSummary);
///  - the fit of the evidence: the fraction of the last detections that the reported pose explains
///    (FitWindow): a detection is explained when its likelihood at the pose is at least
///    `explained_ratio` times the false-association floor eta of Eq. combined.
/// A set that collapsed onto a wrong place is concentrated, but it does not explain what the robot
/// sees; a robot carried elsewhere stops being explained within a few detections.

#include <mrpt/poses/CPose2D.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/CObservationObjects3D.h>

#include <deque>
#include <limits>
#include <optional>
#include <vector>
#include <string>

namespace simp::localization {

enum class LocalizationState { Global, Localized, Lost };
/// "global" | "localized" | "lost".
std::string toString(LocalizationState s);

struct StateParams {
    std::size_t fit_window = 12;           ///< detections kept for the fit (the last ones)
    double fit_max_age_s = 15.0;           ///< ... and not older than this (s)
    std::size_t fit_min_detections = 5;    ///< fewer in the window: the fit says nothing
    double explained_ratio = 2.0;          ///< explained: p(z|m,x) >= this x eta
    double localized_min_fit = 0.5;        ///< localized needs at least this fit ...
    double localized_min_weight = 0.6;     ///< ... this cluster weight fraction ...
    double localized_max_std_m = 0.3;      ///< ... a cluster position spread (sqrt of trace) under this (m) ...
    std::size_t localized_min_updates = 3; ///< ... over this many consecutive updates with detections
    std::size_t lost_window = 8;           ///< the lost test looks at this many last detections ...
    double lost_max_fit = 0.0;             ///< localized -> lost when their fit falls to this ...
    /// ... a detection counting as explained there when the estimate or a pose within this (m, x and
    /// y; rad, heading) of it explains it (3 x 3 x 3 grid): an estimate that is off by less than the
    /// bounds is not lost. 0 = at the estimate only.
    double lost_tolerance_m = 0.0;
    double lost_tolerance_rad = 0.0;
    double lost_min_weight = 0.3;          ///< ... or the cluster weight under this ...
    /// ... or a distinct pose (HypothesisSearch) explains the window better than the estimate by
    /// this log-likelihood (nats); and localized needs the estimate to beat every distinct pose by
    /// `rival_margin` (a place that looks alike is not a place the robot can act on).
    double rival_lost_margin = 6.0;
    double rival_margin = 2.0;
    /// > 0: the window counts objects, not detections: detections of one class whose centres (odometry
    /// frame) lie within this distance (m) are one object, explained when any of its detections is.
    /// A moved object seen ten times is then one unexplained object, not ten (a false `lost`), and a
    /// biased object seen ten times is one vote in the fit. 0: every detection counts (the first round).
    double object_radius_m = 0.0;
    /// > 0: a pose near the estimate (HypothesisSearch::climb) that explains the window better by this
    /// (nats) means the set sits beside the right place: not localized (a localized set returns to
    /// `global`), and [SensorResetting] local_fraction of the particles are drawn about that pose.
    /// 0: off.
    double local_margin = 10.0;
    /// > 0: entering `localized` (from `global` or `lost`) also needs no pose near the estimate better
    /// by this (nats): stricter than staying (local_margin), so a set that settles beside the place the
    /// window prefers is not reported as localized. 0: entering uses local_margin too. While lost the
    /// climb runs only for this test.
    double local_entry_margin = 3.0;
    /// ... but only a pose farther than this (m): one closer is the same place refined, within the
    /// set's own spread and the 0.3 m an estimate may be off. 0: any pose the climb finds.
    double local_entry_min_offset_m = 0.2;
};

/// The last detections with the odometry pose of their frame, scored at a pose estimate.
class FitWindow {
   public:
    explicit FitWindow(const StateParams& params = {}) : m_params(params) {}
    /// Adds the used detections of `obs` (camera pose in the robot frame) seen at time t_s with
    /// the robot at `odometry_pose` (odometry frame), but none whose weight (one per detection, if
    /// given) is 0: a detection the filter does not score (DetectionNovelty's unmapped objects).
    void add(const maps::CObjectMap& map, const simp::obs::CObservationObjects3D::Ptr& obs,
             const mrpt::poses::CPose2D& odometry_pose, double t_s, const std::vector<double>* weights = nullptr);
    struct Fit {
        double fraction = 0;        ///< explained / scored, in [0, 1]
        std::size_t scored = 0;     ///< detections (objects, with object_radius_m > 0) in the window
        double recent_fraction = 0; ///< the same over the last lost_window of them
        std::size_t recent_scored = 0;
        /// Window log-likelihood of the best distinct pose minus the estimate's (nats); NaN when
        /// no rival was searched at this update.
        double rival_advantage = std::numeric_limits<double>::quiet_NaN();
        /// Window log-likelihood of the best pose near the estimate (HypothesisSearch::climb) minus
        /// the estimate's (nats), and how far that pose is (m); NaN when not computed.
        double local_gain = std::numeric_limits<double>::quiet_NaN();
        double local_offset_m = std::numeric_limits<double>::quiet_NaN();
    };
    /// Scores the window with the robot at `estimate` (world) now, at odometry pose `odometry_now`:
    /// each detection at estimate (+) (odometry_now^-1 (+) its odometry pose).
    Fit evaluate(const maps::CObjectMap& map, const mrpt::poses::CPose2D& estimate,
                 const mrpt::poses::CPose2D& odometry_now, double t_now_s);
    /// The distinct objects the window's detections show at `estimate` that it explains: explained
    /// detections of one class whose centres (odometry frame) lie within radius_m of each other count
    /// once (the window as left by the last evaluate()).
    std::size_t explainedObjects(const maps::CObjectMap& map, const mrpt::poses::CPose2D& estimate,
                                 const mrpt::poses::CPose2D& odometry_now, double radius_m) const;
    /// The window's detections seen at time t_s (the last frame), each with whether the robot at
    /// `estimate` now, or at a pose within tolerance_m in x and y and tolerance_rad in heading of
    /// it (3 x 3 x 3 grid), explains it: an estimate within the bounds may be off by that much.
    struct Judged {
        const simp::obs::CObservationObjects3D* obs = nullptr;
        std::size_t k = 0;
        mrpt::poses::CPose2D odometry_pose;
        bool explained = false;
    };
    std::vector<Judged> judgeAt(const maps::CObjectMap& map, const mrpt::poses::CPose2D& estimate,
                                const mrpt::poses::CPose2D& odometry_now, double t_s, double tolerance_m,
                                double tolerance_rad) const;
    void clear() { m_items.clear(); }
    std::size_t size() const { return m_items.size(); }
    /// A detection of the window placed in the odometry frame: its map class and box centre (m).
    struct Placed {
        int map_class = -1;
        double x = 0, y = 0;
    };
    std::vector<Placed> placed() const;
    /// Log-likelihood of the whole window (sum over its detections, each at its frame's pose) for
    /// each robot pose `poses[i]` now (world), added to log_lik[i] (resized to poses.size()).
    void scorePoses(const maps::CObjectMap& map, const std::vector<mrpt::math::TPose2D>& poses,
                    const mrpt::poses::CPose2D& odometry_now, std::vector<double>& log_lik) const;

   private:
    struct Item {
        simp::obs::CObservationObjects3D::Ptr obs;
        std::size_t k = 0;
        mrpt::poses::CPose2D odometry_pose;
        double t_s = 0;
        int map_class = -1;
        double odo_x = 0, odo_y = 0;  ///< the detection's centre in the odometry frame (m)
    };
    /// Whether the robot at `estimate` now, or at a pose of the 3 x 3 x 3 grid of tolerance_m /
    /// tolerance_rad about it, explains item `it` (log-likelihood >= log_explained); std::nullopt when
    /// the map does not score it.
    static std::optional<bool> explainedNear(const maps::CObjectMap& map, const Item& it,
                                             const mrpt::poses::CPose2D& estimate,
                                             const mrpt::poses::CPose2D& odometry_now, double tolerance_m,
                                             double tolerance_rad, double log_explained);
    /// log p of item `it` with the robot at `estimate` now (its frame at estimate (+) (odometry_now^-1
    /// (+) its odometry pose)); std::nullopt when the map does not score it.
    static std::optional<double> logLikelihoodAt(const maps::CObjectMap& map, const Item& it,
                                                 const mrpt::poses::CPose2D& estimate,
                                                 const mrpt::poses::CPose2D& odometry_now);
    /// A detection is explained when its log-likelihood is at least this (explained_ratio x eta).
    double logExplained(const maps::CObjectMap& map) const;
    StateParams m_params;
    std::deque<Item> m_items;
};

/// The climb found a pose near the estimate that explains the window better by `margin` nats
/// (false for margin 0 = off, and when the climb did not run: NaN gain).
inline bool betterPoseNearby(const FitWindow::Fit& fit, double margin) { return margin > 0 && fit.local_gain >= margin; }
/// The same, for a better pose farther than `min_offset_m` from the estimate only.
inline bool betterPoseApart(const FitWindow::Fit& fit, double margin, double min_offset_m) {
    return betterPoseNearby(fit, margin) && !(fit.local_offset_m <= min_offset_m);
}

/// The state machine: feed it after every filter update.
class StateMonitor {
   public:
    explicit StateMonitor(const StateParams& params = {}) : m_params(params) {}
    /// Starts in `s` (Global for global localization, Localized for a given initial pose).
    void reset(LocalizationState s) { m_state = s, m_good_updates = 0; }
    /// One update: cluster weight fraction, cluster position spread (m), the window's fit and
    /// whether the update had detections. Returns the new state.
    LocalizationState update(double cluster_weight, double cluster_std_m, const FitWindow::Fit& fit,
                             bool had_detections);
    LocalizationState state() const { return m_state; }

   private:
    StateParams m_params;
    LocalizationState m_state = LocalizationState::Global;
    std::size_t m_good_updates = 0;
};

}  // namespace simp::localization
