/// \file LocalizeOptions_params.cpp
/// The keys of [State], [DetectionNovelty], [SensorResetting], [HypothesisSearch], [Challenger] and
/// one declaration per key (io::OptionTable), in the order of the old loaders.
#include <simp/localization/LocalizeOptions.h>
#include <simp/localization/Localizer.h>

namespace simp::localization {
namespace {
using io::ValueRange;
const ValueRange kCount = ValueRange::between(1, 1e6);
}  // namespace

const io::OptionTable<StateParams>& stateParamsTable() {
    using O = StateParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("State")
            .integer("fit_window", &O::fit_window, kCount, "detections kept for the fit (the last ones)")
            .number("fit_max_age_s", &O::fit_max_age_s, "s", ValueRange::positive(), "... and not older than this")
            .integer("fit_min_detections", &O::fit_min_detections, kCount, "fewer in the window: the fit says nothing")
            .number("explained_ratio", &O::explained_ratio, "", ValueRange::positive(), "explained: p(z|m,x) >= this x eta")
            .number("localized_min_fit", &O::localized_min_fit, "", ValueRange::fraction(), "localized needs at least this fit ...")
            .number("localized_min_weight", &O::localized_min_weight, "", ValueRange::fraction(), "... this cluster weight fraction ...")
            .number("localized_max_std_m", &O::localized_max_std_m, "m", ValueRange::positive(), "... a cluster position spread under this ...")
            .integer("localized_min_updates", &O::localized_min_updates, kCount, "... over this many consecutive updates with detections")
            .integer("lost_window", &O::lost_window, kCount, "the lost test looks at this many last detections ...")
            .number("lost_max_fit", &O::lost_max_fit, "", ValueRange::fraction(), "localized -> lost when their fit falls to this ...")
            .number("lost_tolerance_m", &O::lost_tolerance_m, "m", ValueRange::nonNegative(),
                    "... a detection explained there also at a pose this far off in x and y ...; 0 = at the estimate only")
            .number("lost_tolerance_rad", &O::lost_tolerance_rad, "rad", ValueRange::nonNegative(), "... and this far turned")
            .number("lost_min_weight", &O::lost_min_weight, "", ValueRange::fraction(), "... or the cluster weight under this ...")
            .number("rival_margin", &O::rival_margin, "nats", ValueRange::nonNegative(), "localized needs the estimate to beat every distinct pose by this")
            .number("rival_lost_margin", &O::rival_lost_margin, "nats", ValueRange::positive(), "... or a distinct pose explains the window better by this")
            .number("object_radius_m", &O::object_radius_m, "m", ValueRange::nonNegative(), "> 0: the window counts objects of this radius, not detections")
            .number("local_margin", &O::local_margin, "nats", ValueRange::nonNegative(), "> 0: a pose near the estimate that explains the window better by this: not localized (and, until first localized, resetting about it); 0 = off")
            .number("local_entry_margin", &O::local_entry_margin, "nats", ValueRange::nonNegative(), "> 0: entering localized also needs no pose near the estimate better by this (stricter than local_margin); 0 = local_margin")
            .number("local_entry_min_offset_m", &O::local_entry_min_offset_m, "m", ValueRange::nonNegative(), "... a pose farther than this from the estimate only (closer: the same place refined); 0 = any")
            .rule("fit_min_detections", [](const O& o) { return o.fit_min_detections <= o.fit_window; }, "be <= fit_window")
            .rule("lost_window", [](const O& o) { return o.lost_window <= o.fit_window; }, "be <= fit_window")
            .rule("lost_max_fit", [](const O& o) { return o.lost_max_fit < o.localized_min_fit; }, "be smaller than localized_min_fit");
    return t;
}

const io::OptionTable<DetectionNoveltyParams>& noveltyParamsTable() {
    using O = DetectionNoveltyParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("DetectionNovelty")
            .number("decorrelation_distance_m", &O::decorrelation_distance_m, "m", ValueRange::nonNegative(),
                    "robot travel after which a detection's error is new; 0 = off")
            .number("min_weight", &O::min_weight, "", ValueRange::aboveUpTo(0, 1), "weight of an immediate repeat")
            .number("view_change_weight", &O::view_change_weight, "", ValueRange::fraction(),
                    "the distance is also this times how far the object moved in the camera's frame (turns); 0 = travel only")
            .number("track_radius_m", &O::track_radius_m, "m", ValueRange::positive(), "same class within this distance = same object")
            .number("track_timeout_s", &O::track_timeout_s, "s", ValueRange::positive(), "a track not seen for this long is forgotten")
            .integer("unmapped_min_detections", &O::unmapped_min_detections, ValueRange::between(0, 1e6),
                     "a track is unmapped (its detections not scored) after this many judged detections ...; 0 = off")
            .number("unmapped_min_span_s", &O::unmapped_min_span_s, "s", ValueRange::nonNegative(), "... over at least this time ...")
            .number("unmapped_max_explained", &O::unmapped_max_explained, "", ValueRange::fraction(), "... of which the estimate explained at most this fraction")
            .number("unmapped_min_fit", &O::unmapped_min_fit, "", ValueRange::fraction(), "judged only while localized with at least this fit (over fit_min_detections) ...")
            .flag("unmapped_while_lost", &O::unmapped_while_lost, "... or also while lost with that fit")
            .number("unmapped_tolerance_m", &O::unmapped_tolerance_m, "m", ValueRange::nonNegative(), "... at the estimate or a pose this close to it")
            .number("unmapped_tolerance_rad", &O::unmapped_tolerance_rad, "rad", ValueRange::nonNegative(), "... and turned this little from it");
    return t;
}

const io::OptionTable<SensorResettingParams>& resettingParamsTable() {
    using O = SensorResettingParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("SensorResetting")
            .number("global_fraction", &O::global_fraction, "", ValueRange::fraction(), "particles replaced per update while searching")
            .number("lost_fraction", &O::lost_fraction, "", ValueRange::fraction(), "... while lost")
            .number("localized_fraction", &O::localized_fraction, "", ValueRange::fraction(), "... while localized")
            .number("local_fraction", &O::local_fraction, "", ValueRange::fraction(), "... drawn about a better pose near the estimate ([State] local_margin), until first localized")
            .number("local_position_std_m", &O::local_position_std_m, "m", ValueRange::nonNegative(), "... with this position spread")
            .number("local_heading_std_rad", &O::local_heading_std_rad, "rad", ValueRange::nonNegative(), "... and heading spread")
            .number("uniform_share", &O::uniform_share, "", ValueRange::fraction(), "of the injected particles, this share uniform over free space")
            .number("position_std_m", [](auto& o) -> auto& { return o.sampler.position_std_m; }, "m", ValueRange::nonNegative(),
                    "spread of a drawn position about the exact fit")
            .number("heading_std_rad", [](auto& o) -> auto& { return o.sampler.heading_std_rad; }, "rad", ValueRange::nonNegative(),
                    "spread of a drawn heading")
            .number("square_ratio", [](auto& o) -> auto& { return o.sampler.square_ratio; }, "", ValueRange::fraction(),
                    "footprints with short / long side >= this are square (heading ambiguous by pi/2)");
    return t;
}

const io::OptionTable<HypothesisSearchParams>& searchParamsTable() {
    using O = HypothesisSearchParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("HypothesisSearch")
            .flag("enabled", &O::enabled, "search distinct poses that explain the fit window")
            .integer("min_window_detections", &O::min_window_detections, kCount, "fewer detections in the window: no search")
            .integer("max_candidates", &O::max_candidates, kCount, "exact fits scored per search (the first ones)")
            .integer("pair_candidates", &O::pair_candidates, ValueRange::between(0, 1e6), "fits of detection pairs on map object pairs scored first (0: off)")
            .number("pair_min_separation_m", [](auto& o) -> auto& { return o.pairs.min_separation_m; }, "m", ValueRange::nonNegative(),
                    "detection pairs closer than this are not used")
            .number("pair_tolerance_m", [](auto& o) -> auto& { return o.pairs.tolerance_m; }, "m", ValueRange::nonNegative(),
                    "|map distance - detection distance| allowed")
            .number("pair_merge_radius_m", [](auto& o) -> auto& { return o.pairs.merge_radius_m; }, "m", ValueRange::nonNegative(),
                    "window detections of one class this close are one object")
            .integer("refine_top", &O::refine_top, kCount, "best distinct candidates refined by a local grid search")
            .number("refine_step_m", &O::refine_step_m, "m", ValueRange::positive(), "first grid step; halved once")
            .number("refine_step_rad", &O::refine_step_rad, "rad", ValueRange::positive(), "first grid step; halved once")
            .number("distinct_distance_m", &O::distinct_distance_m, "m", ValueRange::positive(), "poses farther apart than this ...")
            .number("distinct_heading_rad", &O::distinct_heading_rad, "rad", ValueRange::positive(), "... or turned more than this are distinct")
            .integer("max_hypotheses", &O::max_hypotheses, kCount, "distinct poses kept")
            .flag("while_global", &O::while_global, "also search while global")
            .flag("while_localized", &O::while_localized, "also search while localized (rival test for lost) ...")
            .number("check_period_s", &O::check_period_s, "s", ValueRange::nonNegative(), "... at most this often; always while lost");
    return t;
}

const io::OptionTable<ChallengerParams>& challengerParamsTable() {
    using O = ChallengerParams;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("Challenger")
            .flag("enabled", &O::enabled, "a second particle set searches globally while lost")
            .number("win_margin", &O::win_margin, "nats", ValueRange::nonNegative(), "it replaces the current set when it explains the window better by this")
            .number("agree_distance_m", &O::agree_distance_m, "m", ValueRange::nonNegative(), "closer to the current estimate than this: the same place (no distinct-place tests)")
            .number("reset_fraction", &O::reset_fraction, "", ValueRange::fraction(), "of its particles reset from the detections per update")
            .flag("reset_by_fit", &O::reset_by_fit, "reset_fraction x the share of the window its estimate leaves unexplained")
            .flag("hypothesis_search", &O::hypothesis_search, "until localized: reset about the places that explain the detections since lost best; localized only when no other place explains them as well")
            .integer("particles", &O::particles, ValueRange::between(0, 1e6), "its particles (0: particles_count)")
            .integer("window", &O::window, ValueRange::between(1, 1000), "detections since lost it is judged on (the last ones)")
            .number("window_max_age_s", &O::window_max_age_s, "s", ValueRange::positive(), "... and not older than this")
            .number("replace_max_fit", &O::replace_max_fit, "", ValueRange::fraction(), "it replaces the current set elsewhere only when the current estimate explains at most this share of the window")
            .integer("min_objects", &O::min_objects, ValueRange::between(0, 1000), "... and only when its estimate explains detections of at least this many distinct objects of the window (0: no such condition)")
            .number("object_radius_m", &O::object_radius_m, "m", ValueRange::positive(), "detections of one class this close (odometry frame) are one object for min_objects")
            .integer("scan_window", &O::scan_window, ValueRange::between(0, 10000), "simp+lidar: the scans since `lost` scored at both estimates (0: no scan veto)")
            .number("scan_veto_nats", &O::scan_veto_nats, "nats", ValueRange::between(0, 1e6), "a challenger elsewhere does not take over when those scans prefer the current estimate by more than this (the scan model's weighted log-likelihood)")
            .number("min_view_recall", &O::min_view_recall, "", ValueRange::fraction(), "... nor when the camera frames since lost, at its estimate, showed less than this share of the map objects they should have shown (0: off)")
            .integer("view_min_expected", &O::view_min_expected, ValueRange::between(0, 1e9), "... once they should have shown this many (views: one object in one frame)")
            .number("view_max_range_m", [](auto& o) -> auto& { return o.views.max_range_m; }, "m", ValueRange::positive(), "an object is expected within the range its class was detected at so far in the run, and not farther than this")
            .number("view_seen_radius_m", [](auto& o) -> auto& { return o.views.seen_radius_m; }, "m", ValueRange::positive(), "a detection of its class this close shows an expected object");
    return t;
}

void loadStateParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, StateParams& p) { stateParamsTable().load(cfg, s, p); }
void loadNoveltyParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, DetectionNoveltyParams& p) {
    noveltyParamsTable().load(cfg, s, p);
}
void loadResettingParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, SensorResettingParams& p) {
    resettingParamsTable().load(cfg, s, p);
}
void loadSearchParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, HypothesisSearchParams& p) {
    searchParamsTable().load(cfg, s, p);
}
void loadChallengerParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, ChallengerParams& p) {
    challengerParamsTable().load(cfg, s, p);
}

}  // namespace simp::localization
