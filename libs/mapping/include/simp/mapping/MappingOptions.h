#pragma once
/// \file MappingOptions.h
/// Every threshold of the object map construction (paper Sec. "3D Semantic Map
/// Construction"), loadable from an MRPT .ini section (config_ini/mapping.ini documents
/// each key, its unit and its source). Each key is declared once, in table(): loading, range
/// checks and the dump derive from it.

#include <mrpt/config/CLoadableOptions.h>
#include <simp/io/OptionTable.h>
#include <simp/mapping/WallAlignment.h>

#include <map>
#include <optional>
#include <string>

namespace simp::mapping {

/// Per-class detection filter: a detection of the class is used when its confidence is
/// >= min_confidence and the distance camera -> box centre is in [min_range_m, max_range_m].
/// max_range_m <= 0 disables the class (the authors' convention in mapping_args.json).
struct ClassFilter {
    double min_confidence = 0.5;  ///< detector score in [0, 1]
    double min_range_m = 0.0;     ///< m
    double max_range_m = 5.0;     ///< m; <= 0 = class not mapped
};

/// Which map objects a frame may update.
enum class RoomUpdatePolicy {
    CurrentRoom,  ///< only objects (and detections) in the robot's current room (the paper's)
    All           ///< no room filter
};

/// When the floor-plan prior (wall alignment) applies.
enum class WallAlignMode { Auto, On, Off };

struct MappingOptions : public mrpt::config::CLoadableOptions {
    /// @name Local map integration trigger (the d_xy / d_theta of the paper)
    /// @{
    double trigger_dist_m = 0.2;     ///< integrate m^_g into m_g after the robot moved this far (m); authors' odom_trigerTH[0]
    double trigger_angle_rad = 0.1;  ///< ... or turned this much (rad); authors' odom_trigerTH[1]
    /// @}

    /// @name Association and map update (Eq. costfunc)
    /// @{
    double tau_cost = 0.3;           ///< merge when C < tau_cost; authors' costTH
    double tau_purge = 0.5;          ///< purge when n_match / n_skip < tau_purge (empirical, paper)
    /// A window counts as a miss (n_skip) only when no detection of the object's class lies at its
    /// place (association cost < tau_cost), whatever kept that detection out of the map's evidence
    /// (confidence under the class's threshold, a local object seen in too few frames). false = the
    /// paper: every window the object was active in and unmatched.
    bool skip_needs_no_detection = true;
    int min_local_detections = 1;    ///< a local object needs this many detections to be integrated; authors' totalSeenTH
    /// A local object needs at least this many detections per time step of its window (authors'
    /// purgeDetections: times_matched >= 0.3 detc_cnt): one-off detections never reach the map. 0 = off.
    double min_local_support = 0.3;
    /// Track confirmation (project addition): a map object enters the output map (simp-map's
    /// world, CObjectMap's content) once it aggregates this many detections; until then it is
    /// tentative, kept by the builder to gather matches. One-off stray detections that no later
    /// window re-observes (an object never active again is never purged) stay out. 1 = off.
    int min_confirmed_matches = 3;
    /// ... and has been matched (or made) in this many integration windows, i.e. from viewpoints
    /// trigger_dist_m / trigger_angle_rad apart: one viewpoint's error repeats over its frames, so
    /// a burst of detections from one place is no confirmation. 1 = off.
    int min_confirmed_windows = 2;
    /// Project addition: after each integration, pairs of same-class objects (of the local map,
    /// and of the map objects seen in the window) whose Eq. costfunc cost is below tau_cost are
    /// merged, so that duplicates made by early noisy detections do not persist.
    bool merge_duplicates = true;
    /// @name Duplicate merging (merge_duplicates; the authors' mergeObjects in SIMP.py): a same-class
    /// pair is one object when its centres are closer than duplicate_center_radius_m (per class:
    /// class_duplicate_center_radius_m), or when its Eq. costfunc cost is below duplicate_tau_cost
    /// and its centres are closer than duplicate_max_distance_m. Lowest-cost pairs merge first.
    /// @{
    double duplicate_tau_cost = 0.7;         ///< authors: 0.7
    double duplicate_max_distance_m = 1.0;   ///< authors: 1.0 m
    double duplicate_center_radius_m = 0.5;  ///< authors: 0.5 m (sofa 1.0 m)
    std::map<std::string, double> class_duplicate_center_radius_m{{"sofa", 1.0}};
    /// Project rule: a same-class pair whose 3D intersection is more than this fraction of the
    /// smaller box is one object (solid furniture does not interpenetrate); 0 disables. 0.2:
    /// measured on both offices (doc/results.md); 0.1 also merged real neighbours (tables back
    /// to back, cabinets in a row) whose mapped boxes overlap a little.
    double duplicate_min_overlap = 0.2;
    /// Project rule: a same-class pair that took one detection each in at least this many camera
    /// frames is two objects, whatever the rules above say (a detector reports an object once
    /// per image; CoDetections.h). 0 disables. Measured in doc/mapping.md ("Detected apart").
    int distinct_codetected_frames = 3;
    /// Project rule (twins by support): a built object with fewer than this fraction of the
    /// detections of a same-class neighbour of its room whose noise model (Eq. perclassdist) gives
    /// its centre a likelihood >= twin_min_likelihood is that neighbour's twin: the persistent error
    /// of one or two viewpoints, not a second object (a real neighbour seen from the same places
    /// collects a comparable count). Left out of confirmedMap(), judged on the counts at that time.
    /// 0 disables. Objects of a given map (setMap) are never compared so: their counts are of
    /// earlier sessions. Measured in doc/results.md ("Twins by support").
    double twin_max_support_ratio = 0.1;
    /// The gate of the rule above: the unnormalized Eq. perclassdist likelihood exp(-0.5 m^b) of
    /// the twin's centre under the neighbour's noise; 0.05 = the 95 % region of a Gaussian model.
    double twin_min_likelihood = 0.05;
    /// Project rule (twins never in view): the support ratio of the rule above for a built object
    /// that was never active in the whole run (matched only while hidden, truncated or out of
    /// range, as the mapper's own visibility has it): the neighbour's detections displaced along
    /// the ray behind it. 0 disables (such objects are judged by twin_max_support_ratio).
    double twin_never_active_max_support_ratio = 0.3;
    /// Centre radius of a class (per-class entry, else duplicate_center_radius_m).
    double duplicateCenterRadiusOf(const std::string& class_name) const;
    /// Project rule: objects of a listed class stand between two rooms (a door in its doorway) and
    /// are mapped from both sides, each side's copy in its own room, where the room rule keeps them
    /// apart. Same-class objects of different rooms whose centres are closer than the class's value
    /// (m) are one object. Empty (the authors): objects of other rooms never merge.
    std::map<std::string, double> class_cross_room_merge_radius_m{{"door", 0.5}};
    /// Cross-room merge radius of a class (m); 0 when not listed.
    double crossRoomMergeRadiusOf(const std::string& class_name) const;
    /// @}
    /// I_active: do intersecting map boxes occlude each other? false: boxes that intersect in 3D
    /// are treated as one group that does not hide itself (duplicates become active, get n_skip
    /// and are purged). Project option; measured in doc/results.md.
    bool intersecting_boxes_occlude = true;
    /// C_cen (Eq. costfunc) uses the class covariance times this factor (unitless, > 0). The paper's
    /// p_o1(c_o2 | l) treats o1 as exact; in the builder both o1 (a map / local object) and o2 are
    /// estimates with the class noise, and with per-viewpoint persistent errors a mean of many
    /// detections does not shrink to the truth, so their difference has covariance up to 2 Sigma.
    /// Default 1 (the paper); 2 and 4 measured in doc/results.md (little effect: C_IoU dominates).
    double cost_covariance_scale = 1.0;
    /// Use the class noise mean mu in C_cen. Default false: both objects of the cost are
    /// predictions, so the detector's bias cancels (and mu's direction depends on which of the 4
    /// equivalent box frames an object has).
    bool cost_uses_noise_mean = false;
    /// Remove the detector's class bias (doc/mapping.md "Detector bias"): the builder keeps each
    /// object's mean of detections as its state (association and merging compare like with like)
    /// and its map box is that mean minus the class noise model's mean offset R_o mu (Eq.
    /// shiftdist, class noise frame of the mean), then aligned to the walls. The sensor model adds
    /// R_o mu to a map object; a map of raw means would carry the bias twice. false: the paper's
    /// map of means, aligned in place.
    bool remove_class_bias = true;
    /// On a floor plan that draws only walls (see wall_align auto), an object whose box centre lies
    /// in a wall cell or outside the building is left out of the output map (confirmedMap): no
    /// furniture stands there, and the builder cannot see it to purge it.
    bool hide_objects_in_walls = true;
    double default_noise_sigma_m = 0.2;  ///< isotropic sigma (m, b = 2) of C_cen for classes without a noise model
    /// @}

    /// @name Floor-plan prior (project addition, doc/mapping.md "Wall alignment"): after each
    /// integration, a map object of a listed class with a side parallel to a floor-plan wall, at
    /// most max_gap in front of it or wall_align_max_penetration_m inside, is turned parallel and
    /// moved flush against it (alignToWalls).
    /// @{
    /// auto: on unless the floor plan draws furniture (unknown areas enclosed by walls, as the
    /// authors' GT rendering Map.png does), where a drawn board's front face would pass for the
    /// wall and push the box off its own footprint. on / off: always / never.
    WallAlignMode wall_align = WallAlignMode::Auto;
    /// auto: a floor plan with more enclosed unknown area than this draws furniture (m^2).
    double wall_align_max_enclosed_unknown_m2 = 1.0;
    /// Per class: the largest gap side -> wall face that is closed (m); classes not listed are never aligned.
    /// Default: the classes that stand or hang flush against a wall (boards, cabinets, counters,
    /// sinks, ovens, work tables); not drawers (mobile pedestals), sofas, extinguishers (on
    /// brackets, smaller than the gap), plants. Measured per class in doc/results.md.
    std::map<std::string, double> class_wall_align_max_gap_m{{"board", 0.3}, {"cabinet", 0.3}, {"desk", 0.3},
                                                             {"oven", 0.3},  {"sink", 0.3},    {"table", 0.3}};
    /// The alignment's other parameters, handed to alignToWalls whole (.ini keys wall_align_max_penetration_m,
    /// wall_align_max_yaw_rad, wall_align_max_residual_m, wall_align_rays); its max_gap_m is the class's
    /// entry of class_wall_align_max_gap_m.
    WallAlignmentParams wall_alignment;
    /// The alignment parameters of a class; nullopt when the class is not aligned (or wall_align is
    /// off). With auto, the builder also checks its floor plan.
    std::optional<WallAlignmentParams> wallAlignmentOf(const std::string& class_name) const;
    /// @}

    /// @name Visibility (I_active)
    /// @{
    double truncation_threshold = 0.5;   ///< projected box fraction outside the image above which an object is inactive; authors' truncTH
    double max_occluded_fraction = 0.5;  ///< fraction of the rendered box hidden by other boxes / walls above which it is inactive
    int zbuffer_downscale = 8;           ///< z-buffer pixel = this many image pixels per side (640x480 -> 80x60)
    double wall_depth_margin_m = 0.3;    ///< a box pixel up to this far behind the first wall cell counts as visible (m)
    double wall_cast_max_m = 12.0;       ///< walls farther than this do not occlude (m)
    double near_plane_m = 0.05;          ///< camera near clipping plane (m)
    double default_fx_px = 380.07;       ///< intrinsics used when an observation has none (camera::defaultIntrinsics())
    double default_fy_px = 379.66;
    double default_cx_px = 324.47;
    double default_cy_px = 237.79;
    /// @}

    /// @name Map update across sessions (simp-map --update; MapUpdate.h, doc/mapping.md "Map update")
    /// An object of the earlier map is removed on this session's evidence alone, whatever its
    /// history: it was active (in view, in range, not occluded: I_active) in at least
    /// update_min_missed_windows integration windows without a match, and matched in fewer than
    /// update_max_seen_fraction of the windows that expected it. A removed object with a new
    /// object of its class within update_move_max_distance_m is reported as moved.
    /// @{
    int update_min_missed_windows = 3;         ///< windows; one or two misses are detector misses
    double update_max_seen_fraction = 0.2;     ///< matched / (matched + missed) below this = gone
    double update_move_max_distance_m = 1.5;   ///< m, planar centre distance old -> new of a move
    double update_min_move_m = 0.3;            ///< m; a closer pair is the object re-estimated, no change
    /// A new object of the session enters the updated map (and the report, as added or as the new
    /// place of a moved object) once matched in this many integration windows.
    int update_min_new_windows = 10;
    /// Removal needs the session's misses to be unlikely for a present object: with p the class's
    /// rate of matched windows among this session's expected windows of the map's objects that it
    /// did see, P(<= matched of expected | p) (binomial) must be below this. Classes detected in
    /// few windows (high confidence thresholds, often occluded) need more misses.
    double update_removal_alpha = 0.01;
    /// An object missed in >= update_min_missed_windows windows and matched in fewer than this
    /// fraction of them (too often for update_max_seen_fraction) is moved when a new object of its
    /// class stands within update_move_max_distance_m: detections of its new place, or of a
    /// neighbour, still reach the old object (moves along a wall, a row of cabinets).
    double update_reassociate_max_seen_fraction = 0.3;
    /// A new object of the session closer than this to an object of the earlier map of its class
    /// does not hide it in I_active (it may be its new place: a short move whose new place stands
    /// between the camera and the old one, DisplacedCopies.h); the windows that expected the old
    /// object only so count for a move, never for a removal. 0 = off.
    double update_unhide_max_distance_m = 1.0;
    /// A new object within update_twin_max_distance_m (or the longer horizontal side of the
    /// object's box, if longer: along a desk or a sofa) of an object of the earlier map of its class
    /// that this session matched, and matched in fewer than update_twin_max_window_ratio times as
    /// many windows as it, is that object's twin (the detector's error from some viewpoints), not
    /// an addition: a real object next to it is seen from about as many viewpoints. 0 = off.
    double update_twin_max_distance_m = 1.0;
    double update_twin_max_window_ratio = 0.5;
    /// A new object sharing at least this fraction of the smaller box's volume with an object of
    /// the earlier map of its class that stays is that object seen again (two objects of a class do
    /// not interpenetrate): neither added nor a new place. 0 = off.
    double update_same_overlap_fraction = 0.5;
    /// m; both boxes' horizontal sides are grown by this on each side before that fraction.
    double update_same_overlap_margin_m = 0.1;
    /// An object of the earlier map with at least this fraction of its volume inside the box of an
    /// object of another class, its top not above that box (drawers annotated inside a cabinet;
    /// a cabinet half in a table is in plain view above it), is never removed on misses
    /// alone: whether a detector sees it through the other box is not known (a new object of its
    /// class nearby still makes it moved). 0 = off.
    double update_nested_overlap_fraction = 0.5;
    /// An object of the earlier map matched in at least update_turn_min_windows windows whose heading
    /// this session (circular mean over those windows, SessionTurn.h) differs from its earlier box's
    /// by at least update_turn_min_deg and by update_turn_sigmas standard errors of that mean was
    /// turned, so moved: reported moved, its box the session's. A move whose detections still
    /// associate with the old object is found so. 0 = off.
    double update_turn_min_deg = 10;
    int update_turn_min_windows = 5;
    double update_turn_sigmas = 3;
    /// @}

    /// @name Detection filter
    /// @{
    ClassFilter default_filter;                      ///< classes not listed in per_class
    std::map<std::string, ClassFilter> per_class;    ///< by class name
    /// The filter of a class (per_class entry, else default_filter).
    const ClassFilter& filterOf(const std::string& class_name) const;
    /// @}

    /// @name Rooms
    /// @{
    RoomUpdatePolicy room_policy = RoomUpdatePolicy::CurrentRoom;
    double room_door_width_m = 1.5;      ///< erosion removes openings up to this width (m)
    double room_min_area_m2 = 1.0;       ///< eroded components smaller than this are not rooms (m^2)
    double room_search_radius_m = 0.5;   ///< a point in a wall / furniture cell takes the nearest room within this (m)
    /// A detection whose centre lies in another room but behind a wall as the camera looks, within
    /// this of the robot's room (m), is kept to refine an object it associates with, never to start
    /// one (0 = the paper: rejected). The camera cannot see through walls: it is the depth error of an
    /// object on this side; rejecting it cuts the noise at the wall and biases the estimate away from it.
    double room_behind_wall_margin_m = 0.25;
    /// @}

    /// Defaults: the values above, per-class filters of the authors' mapping_args.json.
    MappingOptions();

    /// Reads section `section`; every key optional (absent = keep the current value).
    /// Per-class filters: keys `class_min_confidence`, `class_min_range_m`, `class_max_range_m`,
    /// each a comma-separated list `name:value` (names may contain spaces).
    /// \throw std::invalid_argument naming the key for a malformed or out-of-range value.
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
    void dumpToTextStream(std::ostream& out) const override;
    /// The declaration of every key (section [mapping]): loading, checks and the dump derive from it.
    static const io::OptionTable<MappingOptions>& table();

    /// \throw std::invalid_argument naming the field when a value is out of its range.
    void validate() const;
};

/// Parses "name:value, name:value" (names trimmed, may contain spaces).
/// \throw std::invalid_argument naming `key` and the entry when malformed.
std::map<std::string, double> parseClassValueList(const std::string& text, const std::string& key);

}  // namespace simp::mapping
